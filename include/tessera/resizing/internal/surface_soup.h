// The surface as arrays for the compiled volume code, and the checks that keep input TetGen would
// fail or crash on away from it.
#pragma once

#include <tessera/resizing/tet_mesh.h>

#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace tessera {
namespace internal {

template <typename TriangleMesh, typename VertexPointMap>
void surface_soup(const TriangleMesh& tm, VertexPointMap vpm,
                  std::vector<std::array<double, 3>>& points,
                  std::vector<std::array<std::size_t, 3>>& triangles) {
  auto index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  points.clear();
  triangles.clear();
  for (auto v : vertices(tm)) {
    put(index, v, points.size());
    const auto& p = get(vpm, v);
    points.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
  }
  for (auto f : faces(tm)) {
    std::array<std::size_t, 3> t{};
    std::size_t k = 0;
    for (auto v : CGAL::vertices_around_face(halfedge(f, tm), tm))
      if (k < 3)
        t[k++] = get(index, v);
    triangles.push_back(t);
  }
}

// What would make TetGen fail or crash: no faces, a border, a face that is not a triangle, a
// self-intersection.
template <typename TriangleMesh, typename VertexPointMap>
Tetrahedralize_result check_tetrahedralization_input(const TriangleMesh& tm, VertexPointMap vpm) {
  Tetrahedralize_result result;
  if (faces(tm).empty()) {
    result.status = Tetrahedralize_status::empty_input;
    result.message = "the mesh has no faces";
  } else if (!CGAL::is_closed(tm) || !CGAL::is_triangle_mesh(tm)) {
    result.status = Tetrahedralize_status::not_closed;
    result.message = "a volume mesh needs a closed triangle surface (this one has a border or "
                     "faces that are not triangles)";
  } else if (CGAL::Polygon_mesh_processing::does_self_intersect(
                 tm, CGAL::parameters::vertex_point_map(vpm))) {
    result.status = Tetrahedralize_status::self_intersecting;
    result.message = "the surface intersects itself, so it bounds no volume TetGen can mesh "
                     "(repair it first, e.g. with CGAL's autorefine or remove_self_intersections)";
  }
  return result;
}

} // namespace internal

} // namespace tessera
