// Reading a triangle mesh from OFF, OBJ, PLY or STL through CGAL's IO, with the checks every
// Tessera algorithm relies on: finite coordinates, a manifold oriented surface, triangles only. Bad
// input comes back as a status and one human-readable line, never as an exception or a crash.
#pragma once

#include <tessera/io/mesh_repair.h>

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <string>

namespace tessera {

enum class Read_status {
  ok,
  file_not_found,
  unsupported_extension,
  empty_file,
  parse_error,
  no_faces,
  non_finite_coordinates,
  invalid_face,
  non_manifold,
  /// The file can be repaired into a surface, but `Read_mesh_options::repair` is `none`.
  needs_repair,
  /// Coordinates beyond 1e150 in magnitude, a mesh smaller than 1e-150 across, or every face of
  /// zero area: squared lengths overflow or vanish in double precision, so no command could
  /// compute on it (rescale the mesh).
  degenerate_geometry
};

/// Options of `read_mesh()`.
struct Read_mesh_options {
  /// Split polygonal faces into triangles (the user is told through `triangulated_faces`).
  /// When false, polygonal input is rejected with `Read_status::invalid_face`.
  bool triangulate = true;
  /// What may be repaired; what may not is refused with a message naming the defect.
  Mesh_repair repair = Mesh_repair::safe;
};

/// Summary of `read_mesh()`.
struct Read_mesh_result {
  Read_status status = Read_status::ok;
  /// One line saying what was wrong (empty when `status == ok`).
  std::string message;
  std::size_t input_vertices = 0;
  std::size_t input_faces = 0;
  /// Number of input faces with more than three sides that were triangulated.
  std::size_t triangulated_faces = 0;
  /// Repairs made to reach a valid surface (see `Read_mesh_options::repair`).
  Mesh_changes changes;
  explicit operator bool() const { return status == Read_status::ok; }
};

/// Lower-case extension of `path` including the dot, or "" when there is none.
inline std::string file_extension(const std::string& path) {
  const auto slash = path.find_last_of("/\\");
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return {};
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

/// True for the extensions `read_mesh()` and `write_mesh()` handle.
inline bool is_supported_mesh_extension(const std::string& ext) {
  return ext == ".off" || ext == ".obj" || ext == ".ply" || ext == ".stl";
}

/// Reads `path` into `tm`, which is cleared first and stays empty when reading fails. The mesh
/// must be a manifold, orientable surface (closed or bordered, any number of components) with
/// finite coordinates; polygonal faces are triangulated when `options.triangulate` is set. Defects
/// that can be mended without moving a point are repaired as `options.repair` allows and counted
/// in `Read_mesh_result::changes`; vertex ids then differ from the file's. A clean file is read as
/// it is.
template <typename TriangleMesh>
Read_mesh_result read_mesh(const std::string& path, TriangleMesh& tm,
                           const Read_mesh_options& options = {});

} // namespace tessera

#include <tessera/io/internal/read_mesh_impl.h>
