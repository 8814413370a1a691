// Measuring whether a resize preserved a geometric texture (issue 16's measure): texels are the
// connected groups of vertices whose detail height exceeds a threshold; each one's footprint aspect
// and size come from the principal axes of its vertices. Simple scaling by 2 along x doubles the
// aspect and keeps the count; texture-preserving resizing keeps aspect and size and adds texels.
#pragma once

#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace tessera {

struct Texel_footprint {
  std::size_t vertices = 0;
  /// √(λ1/λ2) of the two largest principal variances of the texel's vertex positions (1 for a
  /// round texel).
  double aspect = 1;
  /// 2·(λ1·λ2)^(1/4): the radius of a uniformly sampled disc with the same variances.
  double size = 0;
};

struct Texel_measure {
  std::vector<Texel_footprint> texels;
  double median_aspect = 0;
  double median_size = 0;
};

/// Texels of `tm` where `height` (a vertex property map of double, e.g. the detail height or a
/// generator's ground truth) exceeds `threshold`, connected along edges; groups of fewer than
/// `min_vertices` vertices are left out. Positions are read from `vpm`.
template <typename TriangleMesh, typename VertexPointMap, typename HeightMap>
Texel_measure measure_texels(const TriangleMesh& tm, VertexPointMap vpm, HeightMap height,
                             double threshold, std::size_t min_vertices = 4) {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  auto seen = get(CGAL::dynamic_vertex_property_t<bool>(), tm);
  for (vertex_descriptor v : vertices(tm))
    put(seen, v, false);
  Texel_measure out;
  std::vector<vertex_descriptor> stack, group;
  for (vertex_descriptor s : vertices(tm)) {
    if (get(seen, s) || !(get(height, s) > threshold))
      continue;
    group.clear();
    stack.assign(1, s);
    put(seen, s, true);
    while (!stack.empty()) {
      const vertex_descriptor v = stack.back();
      stack.pop_back();
      group.push_back(v);
      if (halfedge(v, tm) == boost::graph_traits<TriangleMesh>::null_halfedge())
        continue;
      for (vertex_descriptor w : CGAL::vertices_around_target(halfedge(v, tm), tm))
        if (!get(seen, w) && get(height, w) > threshold) {
          put(seen, w, true);
          stack.push_back(w);
        }
    }
    if (group.size() < min_vertices)
      continue;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (vertex_descriptor v : group) {
      const auto& p = get(vpm, v);
      mean +=
          Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    }
    mean /= double(group.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (vertex_descriptor v : group) {
      const auto& p = get(vpm, v);
      const Eigen::Vector3d d =
          Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())) -
          mean;
      covariance += d * d.transpose() / double(group.size());
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
    const double l1 = std::max(eigen.eigenvalues()[2], 0.0),
                 l2 = std::max(eigen.eigenvalues()[1], 0.0);
    Texel_footprint t;
    t.vertices = group.size();
    t.aspect = l2 > 0 ? std::sqrt(l1 / l2) : 0;
    t.size = 2 * std::pow(l1 * l2, 0.25);
    out.texels.push_back(t);
  }
  auto median = [&](auto field) {
    std::vector<double> values;
    for (const Texel_footprint& t : out.texels)
      values.push_back(field(t));
    if (values.empty())
      return 0.0;
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(values.size() / 2),
                     values.end());
    return values[values.size() / 2];
  };
  out.median_aspect = median([](const Texel_footprint& t) { return t.aspect; });
  out.median_size = median([](const Texel_footprint& t) { return t.size; });
  return out;
}

} // namespace tessera
