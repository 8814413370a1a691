// How much a deformation distorts each vertex's neighbourhood: the ratio of the two singular values
// of the deformation gradient fitted to its 1-ring in the tangent plane (1 for a similarity, 2
// where a 2x stretch runs along the surface). It makes "preserves the important parts" checkable.
#pragma once

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Dense>

#include <cmath>
#include <limits>

namespace tessera {

/// Writes into `ratio` (a vertex property map of double) σ1/σ2 ≥ 1 for each vertex: the singular
/// values of the 3×2 map B from the original tangent plane to the deformed positions that best
/// carries the 1-ring's edges, B = (Σ e′uᵀ)(Σ u uᵀ)⁻¹ with u the original edges in a tangent basis
/// and e′ the deformed ones. Vertices whose ring is degenerate get NaN.
template <typename TriangleMesh, typename OriginalPointMap, typename DeformedPointMap,
          typename RatioMap>
void local_stretch_ratios(const TriangleMesh& tm, OriginalPointMap original,
                          DeformedPointMap deformed, RatioMap ratio) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  for (auto v : vertices(tm)) {
    put(ratio, v, std::numeric_limits<double>::quiet_NaN());
    if (halfedge(v, tm) == boost::graph_traits<TriangleMesh>::null_halfedge())
      continue;
    const auto n = PMP::compute_vertex_normal(v, tm, CGAL::parameters::vertex_point_map(original));
    Eigen::Vector3d normal(CGAL::to_double(n.x()), CGAL::to_double(n.y()), CGAL::to_double(n.z()));
    if (!(normal.norm() > 0))
      continue;
    normal.normalize();
    Eigen::Vector3d t1 = normal.unitOrthogonal();
    Eigen::Vector3d t2 = normal.cross(t1);
    Eigen::Matrix2d uu = Eigen::Matrix2d::Zero();
    Eigen::Matrix<double, 3, 2> eu = Eigen::Matrix<double, 3, 2>::Zero();
    const auto& p0 = get(original, v);
    const auto& q0 = get(deformed, v);
    for (auto w : CGAL::vertices_around_target(halfedge(v, tm), tm)) {
      const auto& p = get(original, w);
      const auto& q = get(deformed, w);
      const Eigen::Vector3d e(CGAL::to_double(p.x() - p0.x()), CGAL::to_double(p.y() - p0.y()),
                              CGAL::to_double(p.z() - p0.z()));
      const Eigen::Vector3d e2(CGAL::to_double(q.x() - q0.x()), CGAL::to_double(q.y() - q0.y()),
                               CGAL::to_double(q.z() - q0.z()));
      const Eigen::Vector2d u(e.dot(t1), e.dot(t2));
      uu += u * u.transpose();
      eu += e2 * u.transpose();
    }
    if (!(std::abs(uu.determinant()) > 1e-12 * uu.squaredNorm()))
      continue;
    const Eigen::Matrix<double, 3, 2> b = eu * uu.inverse();
    const Eigen::JacobiSVD<Eigen::Matrix<double, 3, 2>> svd(b);
    const auto s = svd.singularValues();
    if (s[1] > 0)
      put(ratio, v, s[0] / s[1]);
  }
}

} // namespace tessera
