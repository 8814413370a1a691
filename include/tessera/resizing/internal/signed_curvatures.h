// Gaussian and signed mean curvature per vertex from degree-2 jets (fields/internal/jet_fitting.h),
// shared by the texel period (texel_period.h) and the texture segmentation's features
// (internal/texture_segmentation_impl.h).
#pragma once

#include <tessera/fields/internal/jet_fitting.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>

#include <cmath>
#include <cstddef>

namespace tessera {
namespace internal {

/// Fits a jet to each vertex's `rings`-ring (`point(v)`: its position as an Epick point) and calls
/// `visit(v, K, H, normal)` for each vertex whose principal curvatures and Monge normal are finite,
/// in the order of `vertices(tm)`: K = k1·k2, H = (k1 + k2)/2 signed against the mesh's vertex
/// normal (the Monge normal's orientation is arbitrary), and that vertex normal (of `vpm`'s
/// points).
template <typename TriangleMesh, typename VertexPointMap, typename PointOf, typename Visitor>
void fit_signed_curvatures(const TriangleMesh& tm, VertexPointMap vpm, std::size_t rings,
                           PointOf&& point, Visitor&& visit) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using Vector = CGAL::Exact_predicates_inexact_constructions_kernel::Vector_3;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  fit_vertex_jets(tm, rings, point, [&](vertex_descriptor v, const auto& form) {
    const double k1 = form.principal_curvatures(0), k2 = form.principal_curvatures(1);
    const auto m = form.normal_direction();
    if (!std::isfinite(k1) || !std::isfinite(k2) || !std::isfinite(m.x()))
      return;
    const auto nv = PMP::compute_vertex_normal(v, tm, CGAL::parameters::vertex_point_map(vpm));
    const Vector nd(CGAL::to_double(nv.x()), CGAL::to_double(nv.y()), CGAL::to_double(nv.z()));
    visit(v, k1 * k2,
          (m.x() * nd.x() + m.y() * nd.y() + m.z() * nd.z() < 0 ? -0.5 : 0.5) * (k1 + k2), nd);
  });
}

} // namespace internal
} // namespace tessera
