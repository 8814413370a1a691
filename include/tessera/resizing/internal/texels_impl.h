// Implementation of tessera::measure_texels (see tessera/resizing/texels.h).
#pragma once

#include <tessera/resizing/texels.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/property_map.h>
#include <boost/iterator/counting_iterator.hpp>
#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace tessera {

template <typename TriangleMesh, typename VertexPointMap, typename HeightMap>
Texel_measure measure_texels(const TriangleMesh& tm, VertexPointMap vpm, HeightMap height,
                             double threshold, std::size_t min_vertices) {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  auto seen = get(CGAL::dynamic_vertex_property_t<bool>(), tm);
  for (vertex_descriptor v : vertices(tm))
    put(seen, v, false);
  auto texel_of = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  for (vertex_descriptor v : vertices(tm))
    put(texel_of, v, std::size_t(-1));
  auto point_of = [&](vertex_descriptor v) {
    const auto& p = get(vpm, v);
    return Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  };
  Texel_measure out;
  std::vector<Eigen::Vector3d> origin;
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
    const std::size_t id = out.texels.size();
    for (vertex_descriptor v : group)
      put(texel_of, v, id);
    Texel_footprint t;
    t.vertices = group.size();
    out.texels.push_back(t);
    origin.push_back(point_of(group.front()));
  }

  // The footprints: the part of each face where the height, linear over the face, exceeds the
  // threshold, with its area and second moments, summed per texel. Independent of how the
  // surface is sampled, unlike moments of vertex positions.
  const std::size_t count = out.texels.size();
  std::vector<double> area(count, 0);
  std::vector<Eigen::Vector3d> first(count, Eigen::Vector3d::Zero());
  std::vector<Eigen::Matrix3d> second(count, Eigen::Matrix3d::Zero());
  for (auto f : faces(tm)) {
    std::array<Eigen::Vector3d, 3> p;
    std::array<double, 3> h;
    std::size_t k = 0, id = count;
    for (vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, tm), tm)) {
      if (k == 3)
        break;
      p[k] = point_of(v);
      h[k] = double(get(height, v)) - threshold;
      if (h[k] > 0 && get(texel_of, v) < count)
        id = get(texel_of, v);
      ++k;
    }
    if (k != 3 || id == count)
      continue;
    // Clip the triangle to h > 0 (a triangle or a quadrilateral), then fan it.
    std::vector<Eigen::Vector3d> polygon;
    for (std::size_t a = 0; a < 3; ++a) {
      const std::size_t b = (a + 1) % 3;
      if (h[a] > 0)
        polygon.push_back(p[a] - origin[id]);
      if ((h[a] > 0) != (h[b] > 0)) {
        const double s = h[a] / (h[a] - h[b]);
        polygon.push_back(p[a] + s * (p[b] - p[a]) - origin[id]);
      }
    }
    for (std::size_t c = 1; c + 1 < polygon.size(); ++c) {
      const Eigen::Vector3d &a = polygon[0], &b = polygon[c], &d = polygon[c + 1];
      const double A = 0.5 * (b - a).cross(d - a).norm();
      const Eigen::Vector3d sum = a + b + d;
      area[id] += A;
      first[id] += A / 3 * sum;
      // ∫ x xᵀ over a triangle: A/12 (a aᵀ + b bᵀ + d dᵀ + s sᵀ), s = a + b + d.
      second[id] +=
          A / 12 *
          (a * a.transpose() + b * b.transpose() + d * d.transpose() + sum * sum.transpose());
    }
  }
  for (std::size_t i = 0; i < count; ++i) {
    Texel_footprint& t = out.texels[i];
    t.area = area[i];
    t.center = {{origin[i].x(), origin[i].y(), origin[i].z()}};
    if (!(area[i] > 0))
      continue;
    const Eigen::Vector3d mean = first[i] / area[i];
    t.center = {{origin[i].x() + mean.x(), origin[i].y() + mean.y(), origin[i].z() + mean.z()}};
    const Eigen::Matrix3d covariance = second[i] / area[i] - mean * mean.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
    const double l1 = std::max(eigen.eigenvalues()[2], 0.0),
                 l2 = std::max(eigen.eigenvalues()[1], 0.0);
    t.aspect = l2 > 0 ? std::sqrt(l1 / l2) : 0;
    t.size = 2 * std::pow(l1 * l2, 0.25);
  }
  // Each texel's nearest neighbour among the centres (CGAL's kd-tree).
  if (count >= 2) {
    using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
    std::vector<Kernel::Point_3> centres;
    for (const Texel_footprint& t : out.texels)
      centres.emplace_back(t.center[0], t.center[1], t.center[2]);
    using Point_map = CGAL::Pointer_property_map<Kernel::Point_3>::const_type;
    using Traits =
        CGAL::Search_traits_adapter<std::size_t, Point_map, CGAL::Search_traits_3<Kernel>>;
    using Search = CGAL::Orthogonal_k_neighbor_search<Traits>;
    const Point_map map(centres.data());
    typename Search::Tree tree(boost::counting_iterator<std::size_t>(0),
                               boost::counting_iterator<std::size_t>(count),
                               typename Search::Tree::Splitter(), Traits(map));
    tree.build();
    for (std::size_t i = 0; i < count; ++i) {
      // The two nearest: the texel itself and its neighbour.
      Search search(tree, centres[i], 2, 0, true, typename Search::Distance(map));
      for (const auto& found : search)
        if (found.first != i)
          out.texels[i].spacing = std::sqrt(found.second);
    }
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
  if (count >= 2)
    out.median_spacing = median([](const Texel_footprint& t) { return t.spacing; });
  return out;
}

} // namespace tessera
