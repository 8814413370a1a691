// Edge costs for shortest cutting paths: Euclidean length, or the curvature-weighted length
// d(e) * (1 - c * |alpha(e)| / pi) of Favreau et al. 2009, section 5.3, which makes paths prefer
// creases (alpha is the dihedral deviation angle between the faces at e, 0 on flat parts).
// Any user edge property map with non-negative values can be used instead.
#pragma once

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cmath>

namespace tessera {

enum class Edge_cost_kind { euclidean, curvature };

struct Edge_cost_options {
  Edge_cost_kind kind = Edge_cost_kind::euclidean;
  /// The weight c in [0, 1] of the curvature term (used with `Edge_cost_kind::curvature`).
  double curvature_weight = 0.5;
};

/// Dihedral deviation angle in [0, pi] at edge `e`: the angle between the normals of its two
/// faces (0 where the surface is flat, and on border edges).
template <typename TriangleMesh>
double dihedral_deviation(typename boost::graph_traits<TriangleMesh>::edge_descriptor e,
                          const TriangleMesh& tm) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  const auto h = halfedge(e, tm);
  if (is_border_edge(h, tm)) return 0.0;
  const auto n1 = PMP::compute_face_normal(face(h, tm), tm);
  const auto n2 = PMP::compute_face_normal(face(opposite(h, tm), tm), tm);
  const double c = CGAL::to_double(n1 * n2);
  return std::acos(std::clamp(c, -1.0, 1.0));
}

/// Fills `costs` (a writable edge property map of double) for every edge of `tm`.
template <typename TriangleMesh, typename EdgeCostMap>
void compute_edge_costs(const TriangleMesh& tm, EdgeCostMap costs,
                        const Edge_cost_options& options = {}) {
  const auto vpm = get(CGAL::vertex_point, tm);
  const double pi = std::acos(-1.0);
  const double c = std::clamp(options.curvature_weight, 0.0, 1.0);
  for (auto e : edges(tm)) {
    const auto h = halfedge(e, tm);
    const double d = std::sqrt(CGAL::to_double(
        CGAL::squared_distance(get(vpm, source(h, tm)), get(vpm, target(h, tm)))));
    double w = d;
    if (options.kind == Edge_cost_kind::curvature)
      w = d * (1.0 - c * std::abs(dihedral_deviation(e, tm)) / pi);
    put(costs, e, w);
  }
}

} // namespace tessera
