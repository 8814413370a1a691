// The surface as tiles see it: smoothed at their scale. A field smoothest at the mesh's scale
// follows the holonomy of every small bump (the armadillo's scales), which neighbouring tiles
// show as turns; solved on positions smoothed at the tile's scale, its rows follow the shape
// rather than its texture. A flat tile, likewise, rests on the bumps under its whole footprint,
// not on the one small face under its centre: tiles laid on the smoothed positions, then put back
// onto the surface, take the plane of their footprint.
#pragma once

#include <tessera/fields/feature_lines.h>
#include <tessera/internal/cotangent_laplacian.h>
#include <tessera/internal/named_parameters.h>
#include <tessera/internal/parallel.h>
#include <tessera/mosaic/tile.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/property_map.h>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/Sparse>

#include <algorithm>
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
  /// from 3.13° to under 3° and the bull's from 2.10° to about 1.8°, changing no other figure
  /// much; half this time did little. 0 leaves the surface as it is.
  double time = 0.08;
  /// Relative residual at which the conjugate-gradient solve stops. The system is well
  /// conditioned at this time (its mass term dominates at edges shorter than a spacing), so it
  /// takes a few tens of iterations.
  double tolerance = 1e-8;
};

/// What `tile_scale_points()` did.
struct Tile_scale_result {
  /// False when the positions were copied as they are: `time` 0, a surface without faces or not
  /// of triangles, degenerate faces (no cotangent), or a solve that did not converge, which
  /// `message` says.
  bool smoothed = false;
  std::string message;
  /// The largest and the mean distance a vertex moved, in spacings.
  double largest_move = 0, mean_move = 0;
  /// The conjugate-gradient iterations of the solve (the most of the three coordinates).
  std::size_t iterations = 0;
};

/// Writes into `smoothed` (a writable vertex property map of points) the positions of `tm`
/// smoothed at the scale of `spacing` (the tiles' spacing, `Mosaic_layout::spacing`): one
/// implicit step of mean curvature flow of time t = `options.time` × spacing², (M + t K) x = M x0
/// with K the cotangent stiffness matrix and M the lumped (barycentric) vertex areas. The
/// vertices of the border and of `features` stay where they are, so that borders do not shrink
/// and feature lines (creases) stay sharp; the system is solved for the others' displacement by
/// Eigen's conjugate gradient (it is symmetric positive definite). Unlike
/// `CGAL::Polygon_mesh_processing::smooth_shape()`, which solves the same step with a
/// general-purpose solver, closed meshes are not scaled back to their volume afterwards: the
/// field only needs directions, and the plain step is 7-10 times faster at 26k-44k vertices. The
/// mesh is not changed.
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
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Point = typename boost::property_traits<PointMap>::value_type;
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
  const double t = options.time * spacing * spacing;
  if (!(options.time > 0) || !(spacing > 0) || !std::isfinite(t) || faces(tm).empty() ||
      !CGAL::is_triangle_mesh(tm)) {
    result.message = "not smoothed: no positive time and spacing, or not a triangle mesh";
    return result;
  }
  // Vertex i of `ordered` at row i of x0; the free ones numbered again by `slot`.
  auto index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  std::vector<vertex_descriptor> ordered;
  ordered.reserve(num_vertices(tm));
  Eigen::MatrixX3d x0(Eigen::Index(num_vertices(tm)), 3);
  for (vertex_descriptor v : vertices(tm)) {
    const auto p = get(vpm, v);
    x0.row(Eigen::Index(ordered.size())) << CGAL::to_double(p.x()), CGAL::to_double(p.y()),
        CGAL::to_double(p.z());
    put(index, v, ordered.size());
    ordered.push_back(v);
  }
  const auto [laplacian, mass] = internal::cotangent_laplacian(tm, index, [&](std::size_t i) {
    const auto r = x0.row(Eigen::Index(i));
    return internal::Epick_point_3(r[0], r[1], r[2]);
  });
  if (!mass.allFinite() ||
      !Eigen::Map<const Eigen::VectorXd>(laplacian.valuePtr(), laplacian.nonZeros()).allFinite()) {
    result.message = "not smoothed: degenerate faces (a cotangent is not finite)";
    return result;
  }
  std::vector<Eigen::Index> slot(ordered.size(), -1);
  Eigen::Index free = 0;
  for (std::size_t i = 0; i < ordered.size(); ++i)
    if (!get(fixed, ordered[i]))
      slot[i] = free++;
  // The displacement d = x − x0 of the free vertices, those held staying at d = 0:
  // (M_ff + t K_ff) d_f = −t (K x0)_f, with K = −L. Its right-hand side is small next to x0, so
  // the relative tolerance is relative to the move, not to the coordinates.
  const Eigen::MatrixX3d laplacian_x0 = laplacian * x0;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(std::size_t(laplacian.nonZeros()));
  Eigen::MatrixX3d rhs(free, 3);
  for (Eigen::Index j = 0; j < laplacian.outerSize(); ++j) {
    if (slot[std::size_t(j)] < 0)
      continue;
    rhs.row(slot[std::size_t(j)]) = t * laplacian_x0.row(j);
    entries.emplace_back(slot[std::size_t(j)], slot[std::size_t(j)], mass[j]);
    for (Eigen::SparseMatrix<double>::InnerIterator it(laplacian, j); it; ++it)
      if (slot[std::size_t(it.row())] >= 0)
        entries.emplace_back(slot[std::size_t(it.row())], slot[std::size_t(j)], -t * it.value());
  }
  Eigen::SparseMatrix<double> system(free, free);
  system.setFromTriplets(entries.begin(), entries.end());
  // The three coordinates solved in parallel, one solver each (a solve writes its iteration
  // count into the solver). On the 104k vertices of the 40k-tile benchmark the whole step went
  // from 0.41 to 0.16-0.18 s, mostly from the leaner Laplacian assembly; the parallel solves
  // themselves save little.
  using Solver = Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper>;
  Eigen::MatrixX3d displacement(free, 3);
  std::array<Eigen::ComputationInfo, 3> info{};
  std::array<std::size_t, 3> iterations{};
  internal::parallel_blocks(
      3,
      [&](std::size_t first, std::size_t last) {
        for (std::size_t c = first; c < last; ++c) {
          Solver solver;
          solver.setTolerance(options.tolerance);
          solver.compute(system);
          displacement.col(Eigen::Index(c)) = solver.solve(rhs.col(Eigen::Index(c)));
          info[c] = solver.info();
          iterations[c] = std::size_t(solver.iterations());
        }
      },
      1);
  result.iterations = *std::max_element(iterations.begin(), iterations.end());
  if (std::any_of(info.begin(), info.end(), [](auto i) { return i != Eigen::Success; }) ||
      !displacement.allFinite()) {
    result.message = "not smoothed: the conjugate-gradient solve did not converge";
    return result;
  }
  double largest = 0, sum = 0;
  for (std::size_t i = 0; i < ordered.size(); ++i) {
    if (slot[i] < 0)
      continue;
    const Eigen::RowVector3d d = displacement.row(slot[i]);
    const Eigen::RowVector3d x = x0.row(Eigen::Index(i)) + d;
    put(smoothed, ordered[i], Point(x[0], x[1], x[2]));
    largest = std::max(largest, d.norm());
    sum += d.norm();
  }
  result.smoothed = true;
  result.largest_move = largest / spacing;
  result.mean_move = sum / double(ordered.size()) / spacing;
  return result;
}

/// Moves each tile's centre onto `tm`: the point at its face and barycentric coordinates, read
/// through the positions of `np` (`CGAL::Polygon_mesh_processing::construct_point()`). Tiles laid
/// on positions from `tile_scale_points()` have their centres on the smoothed surface; their
/// plane (normal and axes) stays that of the smoothed surface, the plane of their footprint.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh, typename FaceDescriptor,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
void place_tiles_on_surface(const TriangleMesh& tm, std::vector<Mosaic_tile<FaceDescriptor>>& tiles,
                            const NamedParameters& np = CGAL::parameters::default_values()) {
  for (Mosaic_tile<FaceDescriptor>& t : tiles) {
    // `barycentric` follows vertices_around_face(halfedge(f)), from its target; a CGAL face
    // location's coordinates start at its source.
    const auto& b = t.barycentric;
    const auto p = CGAL::Polygon_mesh_processing::construct_point(
        std::make_pair(t.face, std::array<double, 3>{{b[2], b[0], b[1]}}), tm, np);
    t.center = {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
  }
}

/// Options of `tile_scale_creases()`.
struct Tile_scale_crease_options {
  /// Dihedral angle (degrees, between face normals) above which an edge is a crease.
  double angle_degrees = 60;
  /// A crease line at least this many tile spacings long is one a viewer sees as an edge of the
  /// shape; a shorter one may be a fold of a coarse triangulation.
  double long_line = 5;
  /// The creases are features when lines at least `long_line` long hold this share of their
  /// length, and they total at least `least_length` spacings. (On CGAL's data at 3000 tiles the
  /// share is 0.91–1.00 on CAD parts with creases, 0.00–0.34 on coarse organic meshes, whose
  /// creases are short folds of the triangulation; doc/mosaic.md.)
  double long_share = 0.8;
  double least_length = 10;
};

/// How the sharp creases of a mesh read at the tiles' scale.
struct Tile_scale_creases {
  /// True when they are edges of the shape that rows should follow (a CAD part), false when they
  /// are short folds of the triangulation of a smooth surface, or none.
  bool features = false;
  /// Crease lines found (`feature_lines()` with creases only), their total length in tile
  /// spacings, and the share of it in lines at least `long_line` spacings long.
  std::size_t lines = 0;
  double length = 0, long_share = 0;
};

/// Reads the creases of `tm` sharper than `options.angle_degrees` at the scale of tiles `spacing`
/// apart: the feature lines a surface mosaic should keep its tiles off and lay its rows along,
/// when the user named none. A crease is seen as an edge of the shape, not as the triangulation,
/// by the length of its line; a mesh reads as creased when most of its crease length lies in long
/// lines.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Tile_scale_creases
tile_scale_creases(const TriangleMesh& tm, double spacing,
                   const Tile_scale_crease_options& options = {},
                   const NamedParameters& np = CGAL::parameters::default_values()) {
  Tile_scale_creases out;
  if (!(spacing > 0))
    return out;
  Feature_line_options fo;
  fo.boundary = false;
  fo.color_boundaries = false;
  fo.creases = true;
  fo.crease_angle_degrees = options.angle_degrees;
  double in_long = 0;
  for (const auto& line : feature_lines(
           tm, fo, [](auto) { return 0; }, np)) {
    double length = 0;
    for (const auto h : line.halfedges)
      length += CGAL::to_double(CGAL::Polygon_mesh_processing::edge_length(h, tm, np));
    length /= spacing;
    ++out.lines;
    out.length += length;
    if (length >= options.long_line)
      in_long += length;
  }
  out.long_share = out.length > 0 ? in_long / out.length : 0;
  out.features = out.length >= options.least_length && out.long_share >= options.long_share;
  return out;
}

} // namespace tessera
