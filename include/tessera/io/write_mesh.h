// Writing a FaceGraph to OFF, OBJ, PLY or STL through CGAL's IO at full double precision, and to
// OFF with exact rational coordinates (for results of exact-kernel runs).
#pragma once

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

/// Writes `tm` to `path`, the format chosen by the extension. Returns false (and writes nothing
/// useful) on an unsupported extension or an I/O failure.
template <typename FaceGraph> bool write_mesh(const std::string& path, const FaceGraph& tm) {
  if (!is_supported_mesh_extension(file_extension(path)))
    return false;
  return CGAL::IO::write_polygon_mesh(path, tm, CGAL::parameters::stream_precision(17));
}

namespace internal {

// A number as exact text: a lazy exact number as its exact value, a double as the rational it is
// (a double is a dyadic rational; its 17-digit decimal is not), anything else as it prints.
template <typename ET> void write_exact_number(std::ostream& os, const CGAL::Lazy_exact_nt<ET>& x) {
  os << CGAL::exact(x);
}
template <typename T> void write_exact_number(std::ostream& os, const T& x) {
  if constexpr (std::is_floating_point_v<T>)
    os << typename CGAL::internal::Exact_field_selector<double>::Type(double(x));
  else
    os << x;
}

} // namespace internal

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
  return bool(out);
}

} // namespace tessera
