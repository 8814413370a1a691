// Degree-2 jets fitted to each vertex's k-ring by CGAL's Monge_via_jet_fitting (Cazals, Pouget
// 2005): principal curvatures, directions and normals, shared by the fields' curvature guide and
// the resizing's vulnerability.
#pragma once

#include <tessera/internal/parallel.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <algorithm>
#include <cstddef>
#include <optional>
#include <vector>

namespace tessera::internal {

using Jet_fitting =
    CGAL::Monge_via_jet_fitting<CGAL::Exact_predicates_inexact_constructions_kernel>;

/// Calls `visit(v, monge_form)` for each vertex v whose `rings`-ring has the 6 points a degree-2
/// jet needs, in the order of `vertices(tm)`; `point(v)` gives a vertex's position as an Epick
/// point (called from several threads: it must only read). The fits, independent of each other,
/// run in parallel; the visits follow serially, so visitors need not be thread-safe.
template <typename TriangleMesh, typename PointOf, typename Visitor>
void fit_vertex_jets(const TriangleMesh& tm, std::size_t rings, PointOf&& point, Visitor&& visit) {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  const std::vector<vertex_descriptor> all(vertices(tm).begin(), vertices(tm).end());
  std::vector<std::optional<Jet_fitting::Monge_form>> forms(all.size());
  parallel_blocks(all.size(), [&](std::size_t first, std::size_t last) {
    std::vector<vertex_descriptor> ring;
    std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> points;
    for (std::size_t i = first; i < last; ++i) {
      const vertex_descriptor v = all[i];
      if (halfedge(v, tm) == boost::graph_traits<TriangleMesh>::null_halfedge())
        continue;
      // The k-ring by breadth-first search; rings are small (19 vertices for k = 2 on a regular
      // mesh), so membership is a linear scan rather than a per-thread mark on every vertex.
      ring.assign(1, v);
      for (std::size_t level = 0, begin = 0; level < rings; ++level) {
        const std::size_t end = ring.size();
        for (std::size_t k = begin; k < end; ++k)
          for (vertex_descriptor w : CGAL::vertices_around_target(halfedge(ring[k], tm), tm))
            if (std::find(ring.begin(), ring.end(), w) == ring.end())
              ring.push_back(w);
        begin = end;
      }
      if (ring.size() < 6)
        continue;
      points.clear();
      for (vertex_descriptor w : ring)
        points.push_back(point(w));
      Jet_fitting fitting;
      forms[i] = fitting(points.begin(), points.end(), 2, 2);
    }
  });
  for (std::size_t i = 0; i < all.size(); ++i)
    if (forms[i])
      visit(all[i], *forms[i]);
}

} // namespace tessera::internal
