// Gaussian and signed mean curvature per vertex from degree-2 jets (fields/internal/jet_fitting.h),
// shared by the texel period (texel_period.h) and the texture segmentation's features
// (internal/texture_segmentation_impl.h).
#pragma once

#include <tessera/fields/internal/jet_fitting.h>
#include <tessera/resizing/internal/texel_period.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <algorithm>
#include <array>
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

/// The samples `texel_period_over` reads, per vertex by `index`, with 2-ring jets.
template <typename TriangleMesh, typename VertexPointMap, typename VertexIndexMap>
Mean_curvature_samples mean_curvature_samples(const TriangleMesh& tm, VertexPointMap vpm,
                                              VertexIndexMap index) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  const std::size_t n = std::size_t(num_vertices(tm));
  auto point = [&](vertex_descriptor w) {
    const auto& p = get(vpm, w);
    return Kernel::Point_3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  };
  Mean_curvature_samples s;
  s.position.resize(n);
  s.normal.assign(n, Kernel::Vector_3(0, 0, 0));
  s.area.assign(n, 0);
  s.h.assign(n, 0);
  s.fitted.assign(n, 0);
  for (vertex_descriptor v : vertices(tm))
    s.position[get(index, v)] = point(v);
  for (auto e : edges(tm))
    s.mean_edge_length += CGAL::to_double(
        PMP::edge_length(halfedge(e, tm), tm, CGAL::parameters::vertex_point_map(vpm)));
  s.mean_edge_length /= double(std::max<std::size_t>(1, num_edges(tm)));
  // Each vertex's area: a third of its triangles'.
  for (auto f : faces(tm)) {
    std::array<std::size_t, 3> c{};
    std::size_t k = 0;
    for (vertex_descriptor w : CGAL::vertices_around_face(halfedge(f, tm), tm))
      if (k < 3)
        c[k++] = get(index, w);
    const double a =
        std::sqrt(CGAL::squared_area(s.position[c[0]], s.position[c[1]], s.position[c[2]]));
    for (std::size_t i : c)
      s.area[i] += a / 3;
  }
  fit_signed_curvatures(tm, vpm, 2, point,
                        [&](vertex_descriptor v, double, double mean, const Kernel::Vector_3& nd) {
                          const std::size_t i = get(index, v);
                          s.h[i] = mean;
                          s.normal[i] = nd;
                          s.fitted[i] = 1;
                        });
  return s;
}

} // namespace internal
} // namespace tessera
