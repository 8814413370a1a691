// Degree-2 jets fitted to each vertex's k-ring by CGAL's Monge_via_jet_fitting (Cazals, Pouget
// 2005): principal curvatures, directions and normals, shared by the fields' curvature guide and
// the resizing's vulnerability.
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <cstddef>
#include <vector>

namespace tessera::internal {

using Jet_fitting =
    CGAL::Monge_via_jet_fitting<CGAL::Exact_predicates_inexact_constructions_kernel>;

/// Calls `visit(v, monge_form)` for each vertex v whose `rings`-ring has the 6 points a degree-2
/// jet needs; `point(v)` gives a vertex's position as an Epick point.
template <typename TriangleMesh, typename PointOf, typename Visitor>
void fit_vertex_jets(const TriangleMesh& tm, std::size_t rings, PointOf&& point, Visitor&& visit) {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  auto mark = get(CGAL::dynamic_vertex_property_t<bool>(), tm);
  for (vertex_descriptor v : vertices(tm))
    put(mark, v, false);
  std::vector<vertex_descriptor> ring;
  std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> points;
  for (vertex_descriptor v : vertices(tm)) {
    if (halfedge(v, tm) == boost::graph_traits<TriangleMesh>::null_halfedge())
      continue;
    ring.assign(1, v);
    put(mark, v, true);
    for (std::size_t level = 0, begin = 0; level < rings; ++level) {
      const std::size_t end = ring.size();
      for (std::size_t k = begin; k < end; ++k)
        for (vertex_descriptor w : CGAL::vertices_around_target(halfedge(ring[k], tm), tm))
          if (!get(mark, w)) {
            put(mark, w, true);
            ring.push_back(w);
          }
      begin = end;
    }
    points.clear();
    for (vertex_descriptor w : ring) {
      put(mark, w, false);
      points.push_back(point(w));
    }
    if (points.size() < 6)
      continue;
    Jet_fitting fitting;
    visit(v, fitting(points.begin(), points.end(), 2, 2));
  }
}

} // namespace tessera::internal
