// Implementation of tessera::extract_detail (see tessera/resizing/texture_detail.h).
#pragma once

#include <tessera/resizing/texture_detail.h>

#include <tessera/internal/named_parameters.h>
#include <tessera/resizing/internal/fairing_impl.h>
#include <tessera/resizing/texture_segmentation.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>
#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <string>
#include <vector>

namespace tessera {

template <typename TriangleMesh, typename VertexTextureMap, typename BasePointMap,
          typename HeightMap, typename NamedParameters>
Detail_extraction_result extract_detail(const TriangleMesh& tm, VertexTextureMap is_texture,
                                        BasePointMap base, HeightMap height,
                                        const Detail_extraction_options& options,
                                        const NamedParameters& np) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  const auto vpm = internal::vertex_point_map(tm, np);
  Detail_extraction_result result;
  if (faces(tm).empty()) {
    result.status = Detail_extraction_status::empty_mesh;
    result.message = "the mesh has no faces";
    return result;
  }
  // Unknowns: the texture vertices, in the order of vertices(tm).
  std::vector<vertex_descriptor> free;
  for (vertex_descriptor v : vertices(tm)) {
    put(base, v, get(vpm, v));
    put(height, v, 0.0);
    if (get(is_texture, v))
      free.push_back(v);
  }
  result.texture_vertices = free.size();
  if (free.empty()) {
    result.status = Detail_extraction_status::no_texture;
    result.message = "no vertex is marked as texture";
    return result;
  }
  double total_length = 0;
  for (auto e : edges(tm))
    total_length += PMP::edge_length(halfedge(e, tm), tm, CGAL::parameters::vertex_point_map(vpm));
  result.mean_edge_length = total_length / double(num_edges(tm));

  if (options.fairing == Fairing_operator::low_pass) {
    double period = options.texel_period;
    if (!(period > 0))
      period = estimate_texel_period(tm, np).period;
    if (!(period > 0)) {
      result.status = Detail_extraction_status::solve_failed;
      result.message = "no texel period could be found on the surface; give one "
                       "(Detail_extraction_options::texel_period)";
      return result;
    }
    result.texel_period = period;
    std::vector<double> plateau;
    if (!internal::low_pass_fairing(tm, vpm, base, free,
                                    options.low_pass_strength * std::pow(period / (2 * CGAL_PI), 4),
                                    plateau)) {
      result.status = Detail_extraction_status::solve_failed;
      result.message = "the fairing matrix could not be factored";
      return result;
    }
    result.iterations = 1;
    // A low pass keeps the texture's mean height: bumps on a plate leave the base raised by
    // their mean over the region, a plateau that falls to the plate at the region's border
    // (whose bend the resize's vulnerability then protects). The base is moved along its normal
    // so the median detail of each connected texture region's interior (where the plateau is
    // over 0.9) is 0: the base runs along the ground between bumps, or the top between grooves.
    internal::ground_base(tm, vpm, base, free, plateau);
  } else if (!internal::iterative_fairing(tm, vpm, base, free,
                                          options.fairing == Fairing_operator::laplacian, options,
                                          result)) {
    result.status = Detail_extraction_status::solve_failed;
    result.message = "the fairing matrix could not be factored";
    return result;
  }
  for (vertex_descriptor v : free) {
    const auto normal = PMP::compute_vertex_normal(v, tm, CGAL::parameters::vertex_point_map(base));
    const double h = CGAL::to_double((get(vpm, v) - get(base, v)) * normal);
    put(height, v, h);
    result.max_height = std::max(result.max_height, std::abs(h));
  }
  return result;
}

} // namespace tessera
