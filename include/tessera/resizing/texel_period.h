// The period of a geometric texture (the distance between neighbouring texels), read from the
// surface: the scale that texture segmentation, detail extraction and synthesis need, so a user
// does not have to give a sample size.
#pragma once

#include <tessera/internal/named_parameters.h>
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
  const auto vpm = internal::vertex_point_map(tm, np);
  const auto index = CGAL::get_initialized_vertex_index_map(tm, np);
  if (faces(tm).empty())
    return {};
  return internal::texel_period_over(internal::mean_curvature_samples(tm, vpm, index),
                                     [](std::size_t) { return true; });
}

} // namespace tessera
