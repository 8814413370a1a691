// The surface as tiles see it: smoothed at their scale. A field smoothest at the mesh's scale
// follows the holonomy of every small bump (the armadillo's scales), which neighbouring tiles
// show as turns; solved on positions smoothed at the tile's scale, its rows follow the shape
// rather than its texture. A flat tile, likewise, rests on the bumps under its whole footprint,
// not on the one small face under its centre: tiles laid on the smoothed positions, then put back
// onto the surface, take the plane of their footprint.
#pragma once

#include <tessera/fields/feature_lines.h>
#include <tessera/internal/named_parameters.h>
#include <tessera/mosaic/tile.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/smooth_shape.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/property_map.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace tessera {

/// Options of `tile_scale_points()`.
struct Tile_scale_options {
  /// Time of the one implicit step of mean curvature flow ∂x/∂t = Δx (Δ the Laplace–Beltrami
  /// operator), in tile spacings squared. The step keeps 1 / (1 + 4π² · time · (s/λ)²) of a bump
  /// of wavelength λ (s the spacing): at 0.08 a quarter of a bump one spacing wide, 56 % of one two
  /// spacings wide, 83 % of one four wide; it moves the side of a tube of radius r by about
  /// time · s² / r (a sixth of a spacing on a leg three tiles around). On the 19 meshes of
  /// doc/mosaic.md at 3000 tiles, the field solved there took the armadillo's median course drift
  /// from 3.13° to 2.95° and the bull's from 2.10° to 1.82°, changing no other figure much; half
  /// this time did little. 0 leaves the surface as it is.
  double time = 0.08;
};

/// What `tile_scale_points()` did.
struct Tile_scale_result {
  /// False when the positions were copied as they are: `time` 0, a surface without faces, or a
  /// smoothing whose result was not finite (degenerate faces), which `message` says.
  bool smoothed = false;
  std::string message;
  /// The largest and the mean distance a vertex moved, in spacings.
  double largest_move = 0, mean_move = 0;
};

/// Writes into `smoothed` (a writable vertex property map of points) the positions of `tm`
/// smoothed at the scale of `spacing` (the tiles' spacing, `Mosaic_layout::spacing`): one
/// implicit step of mean curvature flow (`CGAL::Polygon_mesh_processing::smooth_shape()`, cotangent
/// Laplacian and lumped masses) of time `options.time` × spacing². The vertices of the border and
/// of `features` stay where they are, so that borders do not shrink and feature lines (creases)
/// stay sharp. The mesh is not changed.
///
/// The field (`smoothest_field_with_thin_parts()`) takes `smoothed` as its `vertex_point_map`, as
/// `tessera mosaic` does by default. A `Surface_mosaic` given it too lays its tiles in the planes
/// of the smoothed surface, and `place_tiles_on_surface()` then puts them back onto `tm`
/// (`tessera mosaic --smooth-planes`): on the 19 meshes at 3000 tiles that took the median course
/// drift down by a further 0.1-0.6° (armadillo 2.31°) and the overlap to 0.05-0.39 %, but tips
/// that the flow shrinks (fingers, toes) got fewer tiles than their area takes, leaving bare
/// patches up to 3 tiles wide (man, femur) where they had been at most 1.7.
///
/// Named parameters: `vertex_point_map` (the positions read).
template <typename TriangleMesh, typename PointMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Tile_scale_result tile_scale_points(
    const TriangleMesh& tm, double spacing,
    const std::vector<
        Feature_line<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>>& features,
    PointMap smoothed, const Tile_scale_options& options = {},
    const NamedParameters& np = CGAL::parameters::default_values()) {
  const auto vpm = internal::vertex_point_map(tm, np);
  auto fixed = get(CGAL::dynamic_vertex_property_t<bool>(), tm);
  for (auto v : vertices(tm)) {
    put(smoothed, v, get(vpm, v));
    put(fixed, v,
        halfedge(v, tm) == boost::graph_traits<TriangleMesh>::null_halfedge() ||
            bool(CGAL::is_border(v, tm)));
  }
  for (const auto& line : features)
    for (auto h : line.halfedges) {
      put(fixed, source(h, tm), true);
      put(fixed, target(h, tm), true);
    }
  Tile_scale_result result;
  if (!(options.time > 0) || !(spacing > 0) || !std::isfinite(options.time * spacing * spacing) ||
      faces(tm).empty() || !CGAL::is_triangle_mesh(tm)) {
    result.message = "not smoothed: no positive time and spacing, or not a triangle mesh";
    return result;
  }
  // smooth_shape() takes the mesh by non-const reference but writes only through the point map
  // it is given, here `smoothed`. It solves (M − t L) x = M x0 with L of weights cot α + cot β
  // and M of a sixth of the adjacent faces' areas: M⁻¹L is 4Δ, so its time is a quarter of ours.
  CGAL::Polygon_mesh_processing::smooth_shape(
      const_cast<TriangleMesh&>(tm), options.time * spacing * spacing / 4,
      CGAL::parameters::vertex_point_map(smoothed).vertex_is_constrained_map(fixed));
  double largest = 0, sum = 0;
  bool finite = true;
  for (auto v : vertices(tm)) {
    if (get(fixed, v)) // the iterative solve returns them only to its tolerance
      put(smoothed, v, get(vpm, v));
    const auto p = get(smoothed, v), q = get(vpm, v);
    const double d = std::sqrt(CGAL::to_double(CGAL::squared_distance(p, q)));
    finite = finite && std::isfinite(d);
    largest = std::max(largest, d);
    sum += d;
  }
  if (!finite) {
    for (auto v : vertices(tm))
      put(smoothed, v, get(vpm, v));
    result.message = "not smoothed: the smoothing gave non-finite positions (degenerate faces)";
    return result;
  }
  result.smoothed = true;
  result.largest_move = largest / spacing;
  result.mean_move = vertices(tm).empty() ? 0 : sum / double(num_vertices(tm)) / spacing;
  return result;
}

/// Moves each tile's centre onto `tm`: the point at its face and barycentric coordinates, read
/// through the positions of `np`. Tiles laid on positions from `tile_scale_points()` have their
/// centres on the smoothed surface; their plane (normal and axes) stays that of the smoothed
/// surface, the plane of their footprint.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh, typename FaceDescriptor,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
void place_tiles_on_surface(const TriangleMesh& tm, std::vector<Mosaic_tile<FaceDescriptor>>& tiles,
                            const NamedParameters& np = CGAL::parameters::default_values()) {
  const auto vpm = internal::vertex_point_map(tm, np);
  for (Mosaic_tile<FaceDescriptor>& t : tiles) {
    std::array<double, 3> c{{0, 0, 0}};
    std::size_t k = 0;
    for (auto v : vertices_around_face(halfedge(t.face, tm), tm)) {
      if (k == 3)
        break;
      const auto p = get(vpm, v);
      c[0] += t.barycentric[k] * CGAL::to_double(p.x());
      c[1] += t.barycentric[k] * CGAL::to_double(p.y());
      c[2] += t.barycentric[k] * CGAL::to_double(p.z());
      ++k;
    }
    t.center = c;
  }
}

} // namespace tessera
