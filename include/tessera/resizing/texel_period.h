// The period of a geometric texture (the distance between neighbouring texels), read from the
// surface: the scale that texture segmentation, detail extraction and synthesis need, so a user
// does not have to give a sample size.
#pragma once

#include <tessera/resizing/internal/signed_curvatures.h>
#include <tessera/resizing/internal/texel_period.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace tessera {

/// The period of `tm`'s geometric texture from the autocorrelation of its mean curvature (CGAL's
/// jet fitting on 2-rings, centred on its median), by direction in each vertex's tangent plane:
/// see `Texel_period`. A surface with no texture gives `periodic == false` (the period is then
/// twice the autocorrelation's central lobe); an empty mesh, or one where no jet could be fitted,
/// gives `period == 0`.
///
/// Named parameters: `vertex_point_map`, `vertex_index_map`.
template <typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Texel_period estimate_texel_period(const TriangleMesh& tm,
                                   const NamedParameters& np = CGAL::parameters::default_values()) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Point = Kernel::Point_3;
  const auto vpm = CGAL::parameters::choose_parameter(
      CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
      get_const_property_map(CGAL::vertex_point, tm));
  const auto index = CGAL::get_initialized_vertex_index_map(tm, np);
  if (faces(tm).empty())
    return {};
  const std::size_t n = std::size_t(num_vertices(tm));
  auto point = [&](vertex_descriptor w) {
    const auto& p = get(vpm, w);
    return Point(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  };
  std::vector<Point> position(n);
  std::vector<Kernel::Vector_3> normal(n, Kernel::Vector_3(0, 0, 0));
  std::vector<double> area(n, 0), h(n, 0);
  std::vector<char> fitted(n, 0);
  CGAL::Bbox_3 box;
  for (vertex_descriptor v : vertices(tm)) {
    position[get(index, v)] = point(v);
    box += position[get(index, v)].bbox();
  }
  double length = 0;
  for (auto e : edges(tm))
    length += CGAL::to_double(
        PMP::edge_length(halfedge(e, tm), tm, CGAL::parameters::vertex_point_map(vpm)));
  length /= double(std::max<std::size_t>(1, num_edges(tm)));
  // Each vertex's area: a third of its triangles'.
  for (auto f : faces(tm)) {
    std::array<std::size_t, 3> c{};
    std::size_t k = 0;
    for (vertex_descriptor w : CGAL::vertices_around_face(halfedge(f, tm), tm))
      if (k < 3)
        c[k++] = get(index, w);
    const double a = std::sqrt(CGAL::squared_area(position[c[0]], position[c[1]], position[c[2]]));
    for (std::size_t i : c)
      area[i] += a / 3;
  }
  // H per vertex, signed against the mesh's vertex normal (the Monge normal's orientation is
  // arbitrary).
  internal::fit_signed_curvatures(
      tm, vpm, 2, point, [&](vertex_descriptor v, double, double mean, const Kernel::Vector_3& nd) {
        const std::size_t i = get(index, v);
        h[i] = mean;
        normal[i] = nd;
        fitted[i] = 1;
      });
  std::vector<double> values;
  for (std::size_t i = 0; i < n; ++i)
    if (fitted[i])
      values.push_back(h[i]);
  if (values.empty())
    return {};
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(values.size() / 2),
                   values.end());
  const double median = values[values.size() / 2];
  for (std::size_t i = 0; i < n; ++i)
    h[i] = fitted[i] ? h[i] - median : 0;
  const double diagonal =
      std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                CGAL::square(box.zmax() - box.zmin()));
  return internal::texel_period_from_curvature(position, normal, area, h, fitted, length, diagonal);
}

} // namespace tessera
