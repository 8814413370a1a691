// Edge costs for shortest cutting paths: Euclidean length, or the curvature-weighted length
// d(e) * (1 - c * |alpha(e)| / pi) of Favreau et al. 2009, section 5.3, which makes paths prefer
// creases (alpha is the dihedral deviation angle between the faces at e, 0 on flat parts).
// Any user edge property map with non-negative values can be used instead.
#pragma once

#include <CGAL/boost/graph/helpers.h>

#include <tessera/internal/named_parameters.h>
#include <tessera/topology/internal/double_geometry.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace tessera {

enum class Edge_cost_kind { euclidean, curvature };

struct Edge_cost_options {
  Edge_cost_kind kind = Edge_cost_kind::euclidean;
  /// The weight c in [0, 1] of the curvature term (used with `Edge_cost_kind::curvature`).
  double curvature_weight = 0.5;
};

/// Dihedral deviation angle in [0, pi] at edge `e`: the angle between the normals of its two
/// faces (0 where the surface is flat, and on border edges). Computed in double.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
double dihedral_deviation(typename boost::graph_traits<TriangleMesh>::edge_descriptor e,
                          const TriangleMesh& tm,
                          const NamedParameters& np = CGAL::parameters::default_values()) {
  const auto h = halfedge(e, tm);
  if (is_border_edge(h, tm))
    return 0.0;
  const auto vpm = internal::vertex_point_map(tm, np);
  auto face_normal = [&](auto g) {
    return internal::unit_normal(internal::to_double_array(get(vpm, source(g, tm))),
                                 internal::to_double_array(get(vpm, target(g, tm))),
                                 internal::to_double_array(get(vpm, target(next(g, tm), tm))));
  };
  const auto n1 = face_normal(h), n2 = face_normal(opposite(h, tm));
  const double c = n1[0] * n2[0] + n1[1] * n2[1] + n1[2] * n2[2];
  return std::acos(std::clamp(c, -1.0, 1.0));
}

/// The cost of edge `e` (see `Edge_cost_kind`), computed in double.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
double edge_cost(typename boost::graph_traits<TriangleMesh>::edge_descriptor e,
                 const TriangleMesh& tm, const Edge_cost_options& options = {},
                 const NamedParameters& np = CGAL::parameters::default_values()) {
  const auto vpm = internal::vertex_point_map(tm, np);
  const auto h = halfedge(e, tm);
  const auto p = internal::to_double_array(get(vpm, source(h, tm)));
  const auto q = internal::to_double_array(get(vpm, target(h, tm)));
  const double d = std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                             (p[2] - q[2]) * (p[2] - q[2]));
  if (options.kind != Edge_cost_kind::curvature)
    return d;
  const double pi = std::acos(-1.0);
  const double c = std::clamp(options.curvature_weight, 0.0, 1.0);
  return d * (1.0 - c * dihedral_deviation(e, tm, np) / pi);
}

/// A factor f such that every edge costs at least f times its Euclidean length: 1 for Euclidean
/// costs, 1 - c for curvature-weighted ones (the dihedral term is at most c).
inline double edge_cost_lower_bound(const Edge_cost_options& options) {
  return options.kind == Edge_cost_kind::curvature
             ? 1.0 - std::clamp(options.curvature_weight, 0.0, 1.0)
             : 1.0;
}

/// Fills `costs` (a writable edge property map of double) for every edge of `tm`.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh, typename EdgeCostMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
void compute_edge_costs(const TriangleMesh& tm, EdgeCostMap costs,
                        const Edge_cost_options& options = {},
                        const NamedParameters& np = CGAL::parameters::default_values()) {
  for (auto e : edges(tm))
    put(costs, e, edge_cost(e, tm, options, np));
}

} // namespace tessera
