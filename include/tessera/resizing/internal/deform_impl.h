// Implementation of tessera::deform_by_handles (see tessera/resizing/deform.h).
#pragma once

#include <tessera/resizing/deform.h>

#include <CGAL/boost/graph/helpers.h>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>
#include <tessera/internal/named_parameters.h>
#include <tessera/resizing/internal/deform_with.h>

namespace tessera {

template <typename TriangleMesh, typename VertexPointMap>
std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>
select_vertices(const TriangleMesh& tm, VertexPointMap vpm, const Vertex_selection& selection,
                std::size_t* out_of_range) {
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> all(
      vertices(tm).begin(), vertices(tm).end());
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> out;
  if (selection.kind == Vertex_selection::Kind::indices) {
    std::size_t bad = 0;
    for (std::size_t i : selection.indices) {
      if (i < all.size())
        out.push_back(all[i]);
      else
        ++bad;
    }
    if (out_of_range)
      *out_of_range = bad;
    return out;
  }
  for (auto v : all) {
    const auto& p = get(vpm, v);
    const double x[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    bool inside = true;
    if (selection.kind == Vertex_selection::Kind::sphere) {
      double d2 = 0;
      for (std::size_t c = 0; c < 3; ++c)
        d2 += (x[c] - selection.center[c]) * (x[c] - selection.center[c]);
      inside = d2 <= selection.radius * selection.radius;
    } else {
      for (std::size_t c = 0; c < 3; ++c)
        inside = inside && x[c] >= selection.min[c] && x[c] <= selection.max[c];
    }
    if (inside)
      out.push_back(v);
  }
  return out;
}

template <typename TriangleMesh, typename NamedParameters>
Deformation_result
deform_by_handles(TriangleMesh& tm, const std::vector<Deformation_handle>& handles,
                  const Deformation_options& options, const NamedParameters& np) {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  const auto vpm = internal::writable_vertex_point_map(tm, np);
  Deformation_result result;
  if (faces(tm).empty()) {
    result.status = Deformation_status::empty_mesh;
    result.message = "the mesh has no faces";
    return result;
  }
  std::vector<std::vector<vertex_descriptor>> selected;
  std::vector<Handle_transform> transforms;
  for (std::size_t h = 0; h < handles.size(); ++h) {
    std::size_t out_of_range = 0;
    selected.push_back(select_vertices(tm, vpm, handles[h].vertices, &out_of_range));
    transforms.push_back(handles[h].transform);
    if (selected.back().empty() || out_of_range > 0) {
      result.status = Deformation_status::empty_handle;
      result.message = "handle " + std::to_string(h) +
                       (out_of_range > 0 ? " has " + std::to_string(out_of_range) +
                                               " vertex indices out of range"
                                         : " selects no vertex");
      return result;
    }
  }
  std::vector<vertex_descriptor> region;
  if (options.region_of_interest)
    region = select_vertices(tm, vpm, *options.region_of_interest);
  else
    region.assign(vertices(tm).begin(), vertices(tm).end());
  switch (options.method) {
  case Deformation_method::spokes_and_rims:
    return internal::deform_with<CGAL::SPOKES_AND_RIMS>(tm, vpm, region, selected, transforms,
                                                        options);
  case Deformation_method::smoothed_arap:
    return internal::deform_with<CGAL::SRE_ARAP>(tm, vpm, region, selected, transforms, options);
  default:
    return internal::deform_with<CGAL::ORIGINAL_ARAP>(tm, vpm, region, selected, transforms,
                                                      options);
  }
}

inline std::array<double, 3> Handle_transform::apply(const std::array<double, 3>& p,
                                                     const std::array<double, 3>& c) const {
  std::array<double, 3> d{(p[0] - c[0]) * scale, (p[1] - c[1]) * scale, (p[2] - c[2]) * scale};
  double n = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  const std::array<double, 3> k = n > 0
                                      ? std::array<double, 3>{axis[0] / n, axis[1] / n, axis[2] / n}
                                      : std::array<double, 3>{0, 0, 1};
  const double along = (p[0] - c[0]) * k[0] + (p[1] - c[1]) * k[1] + (p[2] - c[2]) * k[2];
  const double theta = angle + twist * along;
  // Rodrigues' rotation of d about k by theta.
  const double cs = std::cos(theta), sn = std::sin(theta);
  const double kd = k[0] * d[0] + k[1] * d[1] + k[2] * d[2];
  const std::array<double, 3> kxd{k[1] * d[2] - k[2] * d[1], k[2] * d[0] - k[0] * d[2],
                                  k[0] * d[1] - k[1] * d[0]};
  std::array<double, 3> out{};
  for (std::size_t i = 0; i < 3; ++i)
    out[i] = c[i] + translation[i] + d[i] * cs + kxd[i] * sn + k[i] * kd * (1 - cs);
  return out;
}

} // namespace tessera
