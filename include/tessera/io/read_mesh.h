// Reading a triangle mesh from OFF, OBJ, PLY or STL through CGAL's IO, with the checks every Tessera
// algorithm relies on: finite coordinates, a manifold oriented surface, triangles only.
// Bad input comes back as a status and one human-readable line, never as an exception or a crash.
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <string>
#include <vector>

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
  non_manifold
};

/// Options of `read_mesh()`.
struct Read_mesh_options {
  /// Split polygonal faces into triangles (the user is told through `triangulated_faces`).
  /// When false, polygonal input is rejected with `Read_status::invalid_face`.
  bool triangulate = true;
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

namespace internal {

/// True when a text file holds a token such as "nan", "-inf" or "Infinity": stream parsers stop at
/// such tokens, so this tells a user why a file that looks right does not read.
inline bool has_non_finite_token(const std::string& path) {
  std::ifstream in(path);
  std::string token;
  while (in >> token) {
    std::string t;
    for (char c : token)
      if (c != '+' && c != '-') t += char(std::tolower(static_cast<unsigned char>(c)));
    if (t == "nan" || t == "inf" || t == "infinity") return true;
  }
  return false;
}

} // namespace internal

/// Reads `path` into `tm` (which is cleared first). The mesh must be a manifold, orientable surface
/// (closed or bordered, any number of components) with finite coordinates; polygonal faces are
/// triangulated when `options.triangulate` is set.
template <typename TriangleMesh>
Read_mesh_result read_mesh(const std::string& path, TriangleMesh& tm,
                           const Read_mesh_options& options = {}) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using Point = typename boost::property_traits<
      typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type>::value_type;

  Read_mesh_result result;
  auto fail = [&](Read_status s, std::string msg) {
    result.status = s;
    result.message = path + ": " + std::move(msg);
    return result;
  };

  const std::string ext = file_extension(path);
  if (!is_supported_mesh_extension(ext))
    return fail(Read_status::unsupported_extension,
                "unsupported extension '" + ext + "' (expected .off, .obj, .ply or .stl)");
  {
    std::ifstream probe(path, std::ios::binary);
    if (!probe)
      return fail(Read_status::file_not_found, "cannot open file (missing or unreadable)");
    if (probe.peek() == std::ifstream::traits_type::eof())
      return fail(Read_status::empty_file, "file is empty");
  }

  // Coordinates are read as doubles whatever the mesh kernel, so NaN and inf can be detected.
  std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> coords;
  std::vector<std::vector<std::size_t>> polygons;
  bool parsed = false;
  try {
    parsed = CGAL::IO::read_polygon_soup(path, coords, polygons, CGAL::parameters::verbose(false));
  } catch (const std::exception&) {
    parsed = false;
  }
  if (!parsed && internal::has_non_finite_token(path))
    return fail(Read_status::non_finite_coordinates, "holds a NaN or infinite coordinate");
  if (!parsed)
    return fail(Read_status::parse_error, "not a valid " + ext.substr(1) + " file");
  result.input_vertices = coords.size();
  result.input_faces = polygons.size();
  if (polygons.empty())
    return fail(Read_status::no_faces, "file holds no faces");

  for (std::size_t i = 0; i < coords.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(coords[i][k]))
        return fail(Read_status::non_finite_coordinates,
                    "vertex " + std::to_string(i) + " has a NaN or infinite coordinate");
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    const auto& poly = polygons[f];
    if (poly.size() < 3)
      return fail(Read_status::invalid_face,
                  "face " + std::to_string(f) + " has fewer than 3 vertices");
    for (std::size_t v : poly)
      if (v >= coords.size())
        return fail(Read_status::invalid_face,
                    "face " + std::to_string(f) + " refers to a vertex that does not exist");
    if (poly.size() > 3) {
      if (!options.triangulate)
        return fail(Read_status::invalid_face,
                    "face " + std::to_string(f) + " is not a triangle");
      ++result.triangulated_faces;
    }
  }

  std::vector<Point> points;
  points.reserve(coords.size());
  for (const auto& c : coords)
    points.emplace_back(c.x(), c.y(), c.z());

  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons)) {
    // Duplicated faces or a face listed twice with opposite orientations make a soup that is not
    // a mesh but is still a manifold surface after a consistent re-orientation: try that first,
    // and reject only what really is non-manifold.
    auto reoriented = polygons;
    auto pts = points;
    const bool orientable = PMP::orient_polygon_soup(pts, reoriented);
    if (!orientable || pts.size() != points.size() ||
        !PMP::is_polygon_soup_a_polygon_mesh(reoriented))
      return fail(Read_status::non_manifold,
                  "not a manifold orientable surface (an edge shared by more than two faces, a "
                  "pinched vertex, or inconsistent orientation)");
    polygons.swap(reoriented);
  }

  clear(tm);
  PMP::polygon_soup_to_polygon_mesh(points, polygons, tm);
  if (result.triangulated_faces > 0)
    PMP::triangulate_faces(tm);
  if (!CGAL::is_valid_polygon_mesh(tm))
    return fail(Read_status::non_manifold, "the faces do not form a valid surface");
  return result;
}

} // namespace tessera
