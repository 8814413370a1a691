// Implementation of tessera::write_cube_projection_obj (see tessera/generators/uv_layouts.h).
#pragma once

#include <tessera/generators/uv_layouts.h>

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/boost/graph/helpers.h>
#include <cmath>
#include <cstddef>
#include <limits>
#include <ostream>
#include <sstream>
#include <unordered_map>
#include <utility>
#include <vector>

namespace tessera {

template <typename TriangleMesh>
std::ostream& write_cube_projection_obj(std::ostream& out, const TriangleMesh& tm,
                                        std::vector<int>* side_of_face) {
  const auto vpm = get(CGAL::vertex_point, tm);
  const auto vim = CGAL::get_initialized_vertex_index_map(tm);
  out.precision(std::numeric_limits<double>::max_digits10);
  for (auto v : vertices(tm)) {
    const auto& p = get(vpm, v);
    out << "v " << CGAL::to_double(p.x()) << " " << CGAL::to_double(p.y()) << " "
        << CGAL::to_double(p.z()) << "\n";
  }
  std::unordered_map<std::size_t, std::size_t> vt; // vertex · 6 + side → vt
  std::ostringstream face_lines;
  if (side_of_face)
    side_of_face->clear();
  for (auto f : faces(tm)) {
    const auto n = CGAL::Polygon_mesh_processing::compute_face_normal(f, tm);
    const double c[3] = {CGAL::to_double(n.x()), CGAL::to_double(n.y()), CGAL::to_double(n.z())};
    int axis = 0;
    for (int k = 1; k < 3; ++k)
      if (std::abs(c[k]) > std::abs(c[axis]))
        axis = k;
    const int side = 2 * axis + (c[axis] < 0 ? 1 : 0);
    if (side_of_face)
      side_of_face->push_back(side);
    // The other two axes, in the order that keeps the projected face counterclockwise.
    int a = (axis + 1) % 3, b = (axis + 2) % 3;
    if (c[axis] < 0)
      std::swap(a, b);
    face_lines << "f";
    for (auto v : CGAL::vertices_around_face(halfedge(f, tm), tm)) {
      const std::size_t i = std::size_t(get(vim, v));
      const auto [it, inserted] = vt.emplace(i * 6 + std::size_t(side), vt.size());
      if (inserted) {
        const auto& p = get(vpm, v);
        const double q[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                             CGAL::to_double(p.z())};
        out << "vt " << q[a] << " " << q[b] << "\n";
      }
      face_lines << " " << i + 1 << "/" << it->second + 1;
    }
    face_lines << "\n";
  }
  out << face_lines.str();
  return out;
}

} // namespace tessera
