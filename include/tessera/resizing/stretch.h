// How much a deformation distorts each vertex's neighbourhood: the ratio of the two singular values
// of the deformation gradient fitted to its 1-ring in the tangent plane (1 for a similarity, 2
// where a 2x stretch runs along the surface). It makes "preserves the important parts" checkable.
#pragma once

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

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

/// How much a vertex resisted a resize: the largest of its vulnerabilities `w` (per axis, 0..1)
/// along the axes the resize changes (`scale` ≠ 1); 0 when none changes.
template <typename Vulnerability>
double resisted_vulnerability(const Vulnerability& w, const std::array<double, 3>& scale) {
  double resisted = 0;
  for (std::size_t c = 0; c < 3; ++c)
    if (scale[c] != 1)
      resisted = std::max(resisted, double(w[int(c)]));
  return resisted;
}

/// The local stretch ratios of a resize (`local_stretch_ratios()` from `original` to
/// `deformed`), split between the vertices that resisted it (`resisted_vulnerability()` ≥
/// `threshold`) and the free ones; each vertex's resisted vulnerability in vertex order.
struct Stretch_by_vulnerability {
  std::vector<double> vulnerable, free, resisted;
};

/// Splits the local stretch ratios of a resize by `scale` between the vulnerable and the free
/// vertices of `tm`, by the per-axis vulnerabilities in `vulnerability` (a vertex property map
/// of three numbers: `std::array<double, 3>`, `Point_3`, …; as `resize()` writes them).
template <typename TriangleMesh, typename OriginalPointMap, typename DeformedPointMap,
          typename VulnerabilityMap>
Stretch_by_vulnerability
stretch_by_vulnerability(const TriangleMesh& tm, OriginalPointMap original,
                         DeformedPointMap deformed, VulnerabilityMap vulnerability,
                         const std::array<double, 3>& scale, double threshold = 0.5) {
  auto ratio = get(CGAL::dynamic_vertex_property_t<double>(), tm);
  local_stretch_ratios(tm, original, deformed, ratio);
  Stretch_by_vulnerability out;
  for (auto v : vertices(tm)) {
    const double w = resisted_vulnerability(get(vulnerability, v), scale);
    out.resisted.push_back(w);
    (w >= threshold ? out.vulnerable : out.free).push_back(get(ratio, v));
  }
  return out;
}

} // namespace tessera
