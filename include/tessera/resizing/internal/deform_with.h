// The call of CGAL's Surface_mesh_deformation behind deform_by_handles(), for one algorithm tag.
// Included by deform.h after the types it uses (Handle_transform, Deformation_options, …).
#pragma once

#include <CGAL/Surface_mesh_deformation.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <vector>

namespace tessera {
namespace internal {

template <CGAL::Deformation_algorithm_tag Tag, typename TriangleMesh, typename VertexPointMap>
Deformation_result deform_with(
    TriangleMesh& tm, VertexPointMap vpm,
    const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& region,
    const std::vector<std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>>&
        handles,
    const std::vector<Handle_transform>& transforms, const Deformation_options& options) {
  using Clock = std::chrono::steady_clock;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  using Deformation =
      CGAL::Surface_mesh_deformation<TriangleMesh, CGAL::Default, CGAL::Default, Tag, CGAL::Default,
                                     CGAL::Default, CGAL::Default, VertexPointMap>;
  Deformation_result result;
  auto start = Clock::now();
  Deformation deformation(tm, get(CGAL::vertex_index, tm), get(CGAL::halfedge_index, tm), vpm);
  deformation.insert_roi_vertices(region.begin(), region.end());
  std::vector<std::array<double, 3>> targets;
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> moved;
  for (std::size_t h = 0; h < handles.size(); ++h) {
    std::array<double, 3> centre = transforms[h].center;
    if (!transforms[h].has_center) {
      centre = {0, 0, 0};
      for (auto v : handles[h])
        for (std::size_t c = 0; c < 3; ++c)
          centre[c] += CGAL::to_double(get(vpm, v)[int(c)]) / double(handles[h].size());
    }
    for (auto v : handles[h]) {
      deformation.insert_control_vertex(v);
      const auto& p = get(vpm, v);
      targets.push_back(transforms[h].apply(
          {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}, centre));
      moved.push_back(v);
    }
  }
  result.handle_vertices = moved.size();
  result.region_vertices = deformation.roi_vertices().size();
  if (!deformation.preprocess()) {
    result.status = Deformation_status::preprocess_failed;
    result.message =
        "CGAL's deformation could not factor its system (does every part of the region "
        "of interest touch a handle or a fixed vertex?)";
    return result;
  }
  result.preprocess_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  start = Clock::now();
  for (std::size_t i = 0; i < moved.size(); ++i)
    deformation.set_target_position(moved[i], Point(targets[i][0], targets[i][1], targets[i][2]));
  deformation.deform(options.iterations, options.tolerance);
  result.deform_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  for (std::size_t i = 0; i < moved.size(); ++i) {
    const auto& p = get(vpm, moved[i]);
    double d2 = 0;
    for (int c = 0; c < 3; ++c)
      d2 += std::pow(CGAL::to_double(p[c]) - targets[i][std::size_t(c)], 2);
    result.max_handle_error = std::max(result.max_handle_error, std::sqrt(d2));
  }
  return result;
}

} // namespace internal

} // namespace tessera
