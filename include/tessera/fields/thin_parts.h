// Guidance for the field on parts of the surface only a few tiles around (legs, horns, tails,
// handles, tubes): there the smoothest field has no preferred angle, so rows wind around the part
// at random angles. The part's axis and girth are read at the tile's scale from the area-weighted
// covariance of face normals over a patch one tile spacing wide (a cylinder's normals spread around
// it and not along it; a sphere's spread evenly), which ignores the small-scale noise that 2-ring
// curvature fits pick up. Given the field solved without them, the guides come with soft
// constraints that hold it elsewhere, so that a model's body keeps its field while its legs turn.
#pragma once

#include <tessera/fields/smoothest_field.h>

#include <tessera/fields/internal/thin_parts_impl.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace tessera {

/// How `thin_part_constraints()` measures a part's girth.
enum class Thin_part_girth {
  /// The length of the loop cut by the plane across the axis (where the normal spread reads
  /// fewer than twice `guide_below_tiles_around` tiles around).
  sliced,
  /// The girth of the cylinder whose normals spread as the patch's do.
  normal_spread
};

/// Options of `thin_part_constraints()`.
struct Thin_part_options {
  /// Width of the patch the axis and girth are measured on: the mosaic's tile spacing. Required.
  double spacing = 0;
  /// Radius of the patch, in spacings: larger patches average out more of a coarse mesh's facets,
  /// smaller ones follow bends of the part more closely.
  double patch_radius = 1.25;
  /// How the girth is measured: by the loop that the plane across the part's axis cuts from the
  /// surface (`sliced`), or by the normal spread alone (`normal_spread`, faster, but a fold of a
  /// model's flank reads as thin as a leg, and girths below 3.1 tiles all read 3.1).
  Thin_part_girth girth = Thin_part_girth::sliced;
  /// Parts fewer tiles around than this get some guidance along their axis, ...
  /// (10 and 7 with sliced girths. With the normal spread alone, 8 and 5: at 10 and 7 a model's
  /// neck and flank folds were guided too, and on the 19 meshes of doc/mosaic.md the mosaics'
  /// course drift rose, 1.78° to 1.92° on the bull; slicing tells them from legs.)
  double guide_below_tiles_around = 10;
  /// ... parts fewer than this the full `weight`; the weight ramps smoothly between.
  double full_below_tiles_around = 7;
  /// With sliced girths: curved bands that no short loop goes around (a fillet, a cylindrical
  /// wall, a fold of a flank) whose normals spread as a part fewer than this many tiles around
  /// would are guided along their axis too, full weight below 5/8 of it; 0 (the default) leaves
  /// them alone. `tessera mosaic` sets 8 on meshes whose creases it takes as feature lines: there
  /// such bands are the CAD part's own curved surfaces, and rows along their axes follow its
  /// shape (couplingdown's drift 1.58° → 1.17°); on organic meshes they are folds, and guiding
  /// them cost the armadillo 0.1–0.2° of drift (doc/mosaic.md, "Girth by slicing").
  double curved_bands_below_tiles_around = 0;
  /// Soft weight (relative to the field's smoothness at the vertex) of a fully guided vertex.
  double weight = 0.1;
  /// With `thin_part_constraints_holding()`: soft weight of the pull toward the field being held
  /// at a vertex the guidance leaves alone (where it ramps in, the two weights share this much).
  double hold_weight = 0.1;
};

/// What `thin_part_constraints()` found.
template <typename TriangleMesh> struct Thin_part_result {
  Field_status status = Field_status::ok;
  std::string message;
  /// Soft constraints along the axes of thin parts, at most one per vertex; with
  /// `thin_part_constraints_holding()` also those that hold the field elsewhere.
  std::vector<typename Smoothest_field_solver<TriangleMesh>::Constraint> constraints;
  /// Vertices guided along a thin part's axis (or a curved band's:
  /// `Thin_part_options::curved_bands_below_tiles_around`).
  std::size_t guided_vertices = 0;
  /// Of those, the vertices on curved bands with no short loop around them.
  std::size_t curved_band_vertices = 0;
  /// Vertices pulled toward the held field (`thin_part_constraints_holding()`; 0 otherwise).
  std::size_t held_vertices = 0;
  /// Fraction of the surface area whose vertices are guided.
  double guided_area_fraction = 0;
  /// Fewest tiles around any part (the girth at the thinnest place over the spacing); infinite on a
  /// surface without thin parts. With `Thin_part_girth::normal_spread` the estimate saturates at
  /// 2π · patch_radius / 2.5 (3.1 with the default patch): a patch that wraps the part cannot tell
  /// thinner girths apart.
  double fewest_tiles_around = 0;
  /// Area-weighted median of the tiles around over the guided vertices of thin parts (0 when none
  /// is guided; curved bands left out): how thin the guided parts typically are, where
  /// `fewest_tiles_around` is one place.
  double median_guided_tiles_around = 0;
  explicit operator bool() const { return status == Field_status::ok; }
};

namespace internal {

/// No field to hold: `thin_part_constraints()`.
struct No_held_field {};

template <typename TriangleMesh, typename HeldField, typename NamedParameters>
Thin_part_result<TriangleMesh>
thin_part_constraints(const TriangleMesh& tm, const Thin_part_options& options,
                      const HeldField& held, const NamedParameters& np) {
  constexpr bool holding = !std::is_same_v<HeldField, No_held_field>;
  Thin_part_result<TriangleMesh> result;
  if (!(options.spacing > 0) || !std::isfinite(options.spacing)) {
    result.status = Field_status::invalid_options;
    result.message = "thin parts: the spacing must be a positive number";
    return result;
  }
  if (!(options.full_below_tiles_around < options.guide_below_tiles_around) ||
      !(options.full_below_tiles_around > 0) || !(options.weight > 0) ||
      !(options.patch_radius > 0) || (holding && !(options.hold_weight > 0))) {
    result.status = Field_status::invalid_options;
    result.message = "thin parts: need 0 < full_below_tiles_around < guide_below_tiles_around, "
                     "a positive weight, hold weight and patch radius";
    return result;
  }
  Thin_part_estimator<TriangleMesh> estimator(
      tm, options.spacing, options.patch_radius * options.spacing, np,
      options.girth == Thin_part_girth::sliced ? options.guide_below_tiles_around : 0.0);
  estimator.estimate();
  result.fewest_tiles_around = estimator.fewest_tiles_around();
  double guided_area = 0, part_area = 0, total_area = 0; // part_area: thin parts', not bands
  std::vector<std::pair<double, double>> guided;         // (tiles around, area)
  for (auto v : vertices(tm)) {
    const auto& e = estimator.at(v);
    total_area += e.area;
    double t = (options.guide_below_tiles_around - e.tiles_around) /
               (options.guide_below_tiles_around - options.full_below_tiles_around);
    // A curved band with no loop around it: guided by its spread, when asked to.
    const double band = options.curved_bands_below_tiles_around;
    double t_band = 0;
    if (band > 0 && options.girth == Thin_part_girth::sliced && !std::isfinite(e.tiles_around))
      t_band = (band - e.spread_tiles_around) / (band * 3 / 8);
    // The guide's share ramps in smoothly (smoothstep of t).
    double share = 0;
    if (std::max(t, t_band) > 0 && e.axis_valid) {
      const double s = std::min(std::max(t, t_band), 1.0);
      share = s * s * (3 - 2 * s);
      guided_area += e.area;
      if (t > 0) {
        guided.emplace_back(e.tiles_around, e.area);
        part_area += e.area;
      } else
        ++result.curved_band_vertices;
      result.constraints.push_back({v, e.axis, Constraint_kind::soft, options.weight * share});
      ++result.guided_vertices;
    }
    if constexpr (holding) {
      const auto x = get(held, v);
      const double hw = options.hold_weight * (1 - share);
      const double l2 = x.x() * x.x() + x.y() * x.y() + x.z() * x.z();
      if (hw > 0 && l2 > 0 && std::isfinite(l2)) { // no direction at a zero of the field
        using Constraint = typename Smoothest_field_solver<TriangleMesh>::Constraint;
        using Vector = decltype(Constraint::direction);
        result.constraints.push_back({v, Vector(x.x(), x.y(), x.z()), Constraint_kind::soft, hw});
        ++result.held_vertices;
      }
    }
  }
  result.guided_area_fraction = total_area > 0 ? guided_area / total_area : 0;
  std::sort(guided.begin(), guided.end());
  double below = 0;
  for (const auto& [tiles, area] : guided)
    if ((below += area) >= 0.5 * part_area) {
      result.median_guided_tiles_around = tiles;
      break;
    }
  return result;
}

} // namespace internal

/// Soft constraints that turn the field along the axis of every part fewer than
/// `options.guide_below_tiles_around` tiles around, so that tiles lie in rows along and around it
/// (one of a 4-field's directions follows the axis, the other the girth).
///
/// The axis is read from the normal covariance C = Σ area · n nᵀ over the faces whose centroids
/// lie within `options.patch_radius` spacings of a sample vertex (connected through edges): its
/// eigenvector of the least eigenvalue. With eigenvalues λ1 ≥ λ2 ≥ λ3, a cylinder of radius r
/// gives (λ2 − λ3) / λ1 as a known function of spacing / r, inverted here for a first girth.
/// Where that reads fewer than twice `guide_below_tiles_around` tiles around, the girth is then
/// (by default, `Thin_part_girth::sliced`) the length of the loop that the plane through the
/// sample across the axis cuts from the surface around it, traced face by face and given up past
/// `guide_below_tiles_around` spacings or at a border: a leg is as thin as the loop around it,
/// while a fold of a flank, whose normals spread as a leg's do, has no short loop around it.
/// Samples are taken half a spacing apart; every vertex takes the estimate of the sample that
/// covered it.
///
/// Solved with these alone, a field fits them everywhere: the soft guides then decide its angle on
/// the whole surface, not only on the thin parts. `thin_part_constraints_holding()` keeps a field
/// elsewhere.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Thin_part_result<TriangleMesh>
thin_part_constraints(const TriangleMesh& tm, const Thin_part_options& options,
                      const NamedParameters& np = CGAL::parameters::default_values()) {
  return internal::thin_part_constraints(tm, options, internal::No_held_field{}, np);
}

/// The guides of `thin_part_constraints()`, and at every vertex they do not fully guide a soft
/// constraint toward `held` (a solved field, read through a vertex property map of vectors), of
/// weight `options.hold_weight` less the guide's share where it ramps in. A field solved with
/// these (and the constraints `held` was solved with) turns along the thin parts and stays `held`
/// away from them.
///
/// Why: the smoothest field without constraints is an eigenvector (Knöppel et al.), whose angle is
/// free; with soft constraints only, the solve fits them instead, and the guides on a model's legs
/// turn its body too. On the bull at 3000 tiles the mosaic's course drift between neighbours
/// rose from 2.0° to 3.3° that way, and is 2.1° with the field held (doc/mosaic.md).
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh, typename VertexFieldMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Thin_part_result<TriangleMesh>
thin_part_constraints_holding(const TriangleMesh& tm, const Thin_part_options& options,
                              const VertexFieldMap& held,
                              const NamedParameters& np = CGAL::parameters::default_values()) {
  return internal::thin_part_constraints(tm, options, held, np);
}

/// What `smoothest_field_with_thin_parts()` did.
template <typename TriangleMesh> struct Thin_part_field_result {
  /// The solve that wrote the field: the second one when any vertex was guided, else the first.
  Smoothest_field_result field;
  /// The first solve, with the caller's constraints alone (the field that is held).
  Smoothest_field_result unguided;
  /// The guides and holds (`thin_part_constraints_holding()` on the first solve's field).
  Thin_part_result<TriangleMesh> thin_parts;
  /// True when the field was solved again with them (some vertex was guided).
  bool guided = false;
  explicit operator bool() const { return field && thin_parts; }
  /// Why it failed (empty when it did not).
  const std::string& message() const {
    return !unguided ? unguided.message : !thin_parts ? thin_parts.message : field.message;
  }
};

/// The smoothest field meeting `constraints`, turned along the parts of the surface fewer than
/// `thin_options.guide_below_tiles_around` tiles around and held elsewhere: solves with
/// `constraints`, then, if `thin_part_constraints_holding()` guides any vertex on that field,
/// solves again with its constraints added. Writes the result into `field` (a writable vertex
/// property map of vectors). Both solves share one `Smoothest_field_solver`, so the connection
/// Laplacian is assembled once. The guides and holds weigh on every vertex, so the second solve is
/// by conjugate gradients from the first field (`Smoothest_field_options::iterative_when_held`);
/// with that off, it is a numeric factorization only: the guides and holds are soft, so the
/// hard-constrained vertices, and with them the matrix's sparsity pattern, stay those of the first
/// (its ordering and symbolic analysis are kept).
///
/// This is the field `tessera mosaic` lays tiles along by default; `thin_options.spacing` is the
/// tile spacing.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh, typename VertexFieldMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Thin_part_field_result<TriangleMesh> smoothest_field_with_thin_parts(
    const TriangleMesh& tm,
    const std::vector<typename Smoothest_field_solver<TriangleMesh>::Constraint>& constraints,
    VertexFieldMap field, const Thin_part_options& thin_options,
    const Smoothest_field_options& field_options = {},
    const NamedParameters& np = CGAL::parameters::default_values()) {
  Thin_part_field_result<TriangleMesh> result;
  Smoothest_field_solver<TriangleMesh> solver(tm, field_options, np);
  result.field = result.unguided = solver.solve(constraints, field);
  if (!result.unguided)
    return result;
  result.thin_parts = thin_part_constraints_holding(tm, thin_options, field, np);
  if (!result.thin_parts || result.thin_parts.guided_vertices == 0)
    return result;
  auto guided = constraints;
  guided.insert(guided.end(), result.thin_parts.constraints.begin(),
                result.thin_parts.constraints.end());
  result.field = solver.solve(guided, field);
  result.guided = true;
  return result;
}

} // namespace tessera
