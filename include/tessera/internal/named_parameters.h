// Reading CGAL named parameters the way CGAL's own algorithms do, so every Tessera algorithm
// accepts a user's `vertex_point_map` (and falls back to the mesh's internal point map).
#pragma once

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>

namespace tessera::internal {

/// The `vertex_point_map` named parameter of `np`, or `tm`'s internal point map.
template <typename FaceGraph, typename NamedParameters>
auto vertex_point_map(const FaceGraph& tm, const NamedParameters& np) {
  return CGAL::parameters::choose_parameter(
      CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
      get_const_property_map(CGAL::vertex_point, tm));
}

/// The `vertex_point_map` named parameter of `np`, or `tm`'s internal point map, writable: for
/// algorithms that add vertices.
template <typename FaceGraph, typename NamedParameters>
auto writable_vertex_point_map(FaceGraph& tm, const NamedParameters& np) {
  return CGAL::parameters::choose_parameter(
      CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
      get_property_map(CGAL::vertex_point, tm));
}

} // namespace tessera::internal
