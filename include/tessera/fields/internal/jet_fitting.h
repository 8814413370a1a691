// Degree-2 jets fitted to each vertex's k-ring by CGAL's Monge_via_jet_fitting (Cazals, Pouget
// 2005): principal curvatures, directions and normals, shared by the fields' curvature guide and
// the resizing's vulnerability.
#pragma once

#include <tessera/internal/parallel.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/boost/graph/named_params_helper.h>

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
  // A fit reads at most this many points: a wider ring is thinned evenly (every k-th vertex in
  // breadth-first order, so each ring keeps its share and the fit its reach). A 6-ring of a
  // regular mesh (127 vertices) is fitted whole; a 17-ring (919) would cost 7 times as much for
  // the same quadric.
  constexpr std::size_t max_points = 256;
  const std::vector<vertex_descriptor> all(vertices(tm).begin(), vertices(tm).end());
  const auto index = CGAL::get_initialized_vertex_index_map(tm);
  std::size_t bound = 0;
  for (vertex_descriptor v : all)
    bound = std::max(bound, std::size_t(get(index, v)) + 1);
  std::vector<std::optional<Jet_fitting::Monge_form>> forms(all.size());
  parallel_blocks(all.size(), [&](std::size_t first, std::size_t last) {
    std::vector<vertex_descriptor> ring;
    std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> points;
    // Which vertices the current ring holds: `seen[w] == stamp` (no clearing between vertices).
    std::vector<std::size_t> seen(bound, 0);
    std::size_t stamp = 0;
    for (std::size_t i = first; i < last; ++i) {
      const vertex_descriptor v = all[i];
      if (halfedge(v, tm) == boost::graph_traits<TriangleMesh>::null_halfedge())
        continue;
      ++stamp;
      ring.assign(1, v);
      seen[get(index, v)] = stamp;
      for (std::size_t level = 0, begin = 0; level < rings; ++level) {
        const std::size_t end = ring.size();
        for (std::size_t k = begin; k < end; ++k)
          for (vertex_descriptor w : CGAL::vertices_around_target(halfedge(ring[k], tm), tm))
            if (seen[get(index, w)] != stamp) {
              seen[get(index, w)] = stamp;
              ring.push_back(w);
            }
        begin = end;
      }
      if (ring.size() < 6)
        continue;
      const std::size_t step = (ring.size() + max_points - 1) / max_points;
      points.clear();
      for (std::size_t k = 0; k < ring.size(); k += step)
        points.push_back(point(ring[k]));
      Jet_fitting fitting;
      forms[i] = fitting(points.begin(), points.end(), 2, 2);
    }
  });
  for (std::size_t i = 0; i < all.size(); ++i)
    if (forms[i])
      visit(all[i], *forms[i]);
}

} // namespace tessera::internal
