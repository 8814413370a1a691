// Writing a FaceGraph to OFF, OBJ, PLY or STL through CGAL's IO at full double precision (each
// double as the shortest text that reads back to it), and to OFF with exact rational coordinates
// (for results of exact-kernel runs).
#pragma once

#include <tessera/io/internal/exact_number.h>
#include <tessera/io/internal/shortest_doubles.h>
#include <tessera/io/read_mesh.h>

#include <CGAL/Lazy_exact_nt.h>
#include <CGAL/Number_types/internal/Exact_type_selector.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Dynamic_property_map.h>

#include <fstream>
#include <string>
#include <type_traits>

namespace tessera {

/// Writes `tm` to `path`, the format chosen by the extension (any case; PLY and STL binary, as
/// CGAL writes them by file name; in OFF and OBJ each coordinate is the shortest decimal that
/// reads back to the same double). Returns false (and writes nothing useful) on an unsupported
/// extension or an I/O failure, a full disk included.
template <typename FaceGraph> bool write_mesh(const std::string& path, const FaceGraph& tm) {
  const std::string ext = file_extension(path);
  if (!is_supported_mesh_extension(ext))
    return false;
  // CGAL's writers by file name return before their stream is closed, so the write of the last
  // buffer (where a full disk shows) is not checked: the stream is opened, closed and checked here.
  const bool binary = ext == ".ply" || ext == ".stl";
  std::ofstream os(path, binary ? std::ios::out | std::ios::binary : std::ios::out);
  if (!os)
    return false;
  CGAL::IO::set_mode(os, binary ? CGAL::IO::BINARY : CGAL::IO::ASCII);
  internal::write_shortest_doubles(os);
  const auto np = CGAL::parameters::stream_precision(17);
  bool written = false;
  if (ext == ".off")
    written = CGAL::IO::write_OFF(os, tm, np);
  else if (ext == ".obj")
    written = CGAL::IO::write_OBJ(os, tm, np);
  else if (ext == ".ply")
    written = CGAL::IO::write_PLY(os, tm, np);
  else
    written = CGAL::IO::write_STL(os, tm, np);
  os.close();
  return written && !os.fail();
}

/// Writes `tm` as OFF text whose coordinates are exact: rationals `p/q` (or integers), which
/// `read_exact_polygon_mesh()` and `tessera check --exact` read back without rounding. Vertex ids
/// follow `tm`'s vertex iteration order. Viewers that read only decimal numbers need
/// `write_mesh()`'s file.
template <typename FaceGraph> bool write_exact_off(const std::string& path, const FaceGraph& tm) {
  std::ofstream out(path);
  if (!out)
    return false;
  const auto vpm = get(CGAL::vertex_point, tm);
  // Ids in iteration order (a Surface_mesh with removed elements has gaps in its indices).
  auto id = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  std::size_t next = 0;
  for (auto v : vertices(tm))
    put(id, v, next++);
  out << "OFF\n# exact coordinates (rationals p/q) written by Tessera\n"
      << num_vertices(tm) << " " << num_faces(tm) << " 0\n";
  for (auto v : vertices(tm)) {
    const auto& p = get(vpm, v);
    for (int d = 0; d < 3; ++d) {
      internal::write_exact_number(out, p[d]);
      out << (d < 2 ? ' ' : '\n');
    }
  }
  for (auto f : faces(tm)) {
    out << degree(f, tm);
    for (auto v : CGAL::vertices_around_face(halfedge(f, tm), tm))
      out << ' ' << get(id, v);
    out << '\n';
  }
  out.close(); // the last buffer's write (a full disk) shows here
  return !out.fail();
}

} // namespace tessera
