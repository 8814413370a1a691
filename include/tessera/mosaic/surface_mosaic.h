// Surface mosaics: equal rectangular tiles laid on a triangle mesh along a direction field, by
// particle repulsion in a Manhattan metric measured in local charts (Lai, Hu, Martin, "Surface
// Mosaics", The Visual Computer 22, 2006). `surface_mosaic()` runs the whole method;
// `Surface_mosaic` is the same optimization as a stateful object that can be iterated step by step
// (for progress or interaction).
#pragma once

#include <tessera/fields/feature_lines.h>
#include <tessera/mosaic/internal/feature_segments.h>
#include <tessera/mosaic/internal/point_search.h>
#include <tessera/mosaic/manhattan_charts.h>
#include <tessera/mosaic/tile.h>
#include <tessera/progress.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <tessera/internal/named_parameters.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace tessera {

/// The pair energy the tiles minimize. x, y are the aspect-normalized coordinates of one tile seen
/// from another in a chart (x along the field).
enum class Mosaic_energy {
  /// E = exp(−2(x⁴ + y⁴)/σ⁴), a separable "soft box": near 1 while two tiles' cells overlap,
  /// falling
  /// off steeply once they only touch. Its lowest-energy lattice is the field-aligned square grid.
  soft_box,
  /// Lai et al. eqs. 2–3 as published: E = exp(−d²/2σ²), d the Manhattan distance at 45° to the
  /// field,
  /// F_i = Σ_j (p_i − p_j) E_ij. Every pair at one L∞ distance weighs the same, so a square grid's
  /// 8
  /// neighbours all sit at the shortest distance, and rows squeezed along one axis (overlapping
  /// tiles)
  /// have lower energy than the grid: the layout turns into "worms" (doc/mosaic.md shows both).
  gaussian_manhattan
};

/// Where the tiles start (`Surface_mosaic_options::initialization`) and how many are laid
/// (`Surface_mosaic_options::count`).
enum class Mosaic_initialization { automatic, position_field, lattice, error_diffusion };
enum class Mosaic_count { about, exact, at_most };

/// Options of `surface_mosaic()` and `Surface_mosaic`. Lengths are in units of the layout's spacing
/// √(A/N) or of σ = 0.9·spacing where said.

struct Surface_mosaic_options {
  /// Tile size or count, aspect and grout.
  Mosaic_tile_size tiles;
  Mosaic_energy energy = Mosaic_energy::soft_box;
  /// Symmetry of the field the tiles follow: 4 for square tiles, 2 for rectangles; 0 chooses
  /// (4 when the aspect is 1, else 2).
  int symmetry = 0;
  /// k of the k nearest tiles each tile interacts with (Lai et al.: 20).
  std::size_t neighbors = 20;
  /// Step t of p' = p + t·F (Lai et al.: 1; with the paper's energy 0.25 to 0.5 stops the layout
  /// from oscillating).
  double step = 1;
  /// No tile moves farther than this (× spacing) in one iteration: keeps tiles from jumping across
  /// thin parts of the surface while the first, crowded layout spreads out.
  double max_step = 0.5;
  /// Strength of the push that separates overlapping cells (soft-box energy only; 0 switches it
  /// off).
  double separation = 2;
  /// Stopping rule: the optimization ends when the mean displacement of an iteration falls below
  /// `tolerance` × spacing, or the tiles' mean net move over the last 5 iterations does, per
  /// iteration (they jitter in place), or after `max_iterations`.
  std::size_t max_iterations = 150;
  double tolerance = 5e-3;
  /// Called after each iteration of the optimization: stage "iterations", `done` the iterations
  /// so far, `total` `max_iterations` (the stopping rule may end it sooner; `stats()` then says
  /// `converged`).
  Progress_callback progress;
  /// Chart radius and core radius (× σ) and the field rotation that stops a chart (radians). A
  /// tile's neighbours must lie in its chart up to where their pull vanishes: about 3σ for the
  /// paper's Gaussian (Lai et al.: charts of about 5σ), 1.5σ for the soft box. 0 chooses 5 and 2
  /// for the paper's energy, 3 and 1.2 for the soft box: smaller charts wrap less around thin
  /// parts.
  double chart_radius = 0;
  double chart_core_radius = 0;
  double max_chart_rotation = 1.5707963267948966;
  /// Repulsion from feature lines (mirror images, Lai et al. §5.2) within `feature_reach` × the
  /// longer tile side.
  bool feature_repulsion = true;
  double feature_reach = 3;
  /// A fixed, never written tile at every field singularity, acting with the Euclidean distance so
  /// that tiles lay out radially around it (Lai et al. §5.1).
  bool singularity_tiles = true;
  /// Teleportation (Lai et al. §4.1): every `teleport_every` iterations from `teleport_after` on,
  /// tiles of the closest pairs move into the largest holes. 0 switches it off.
  std::size_t teleport_every = 0;
  std::size_t teleport_after = 30;
  /// Initial positions: `automatic` (default) is `position_field`, or `lattice` with a tile size
  /// field (the position field has one spacing). `position_field` puts a tile at every point of a
  /// field-aligned lattice of the spacing solved over the whole surface (Jakob et al., "Instant
  /// Field-Aligned Meshes", 2015), with feature lines midway between two rows (unless `at_most`,
  /// a lattice short of the count is solved again with rows closer, never closer than 0.965 of
  /// the spacing); its rows close around tubes. `lattice` grows rows and columns one cell apart
  /// along the field from a seed in each region (fronts meet out of phase). `error_diffusion` is
  /// Lai et al.'s §3.2 (random points in each face, as many as its share of the count).
  Mosaic_initialization initialization = Mosaic_initialization::automatic;
  /// `about` (default) lets the lattice decide, as Lai et al. let the count float: a lattice
  /// short of N is grown again with rows closer together (never closer than a tile side), every
  /// lattice point and every hole a cell wide get a tile, crowded tiles are left out at the end
  /// (the result's tile count says how many; within a few percent of N where the surface is wider
  /// than a few tiles). `exact` lays N tiles (crowding them where the surface does not take whole
  /// rows); `at_most` adds tiles only in holes a cell wide and never more than N. With `about`
  /// the count ends at most `most_over_count` over N.
  Mosaic_count count = Mosaic_count::about;
  /// Unless `Mosaic_count::exact`, after the optimization: tiles whose rectangles overlap or come
  /// closer than `min_tile_gap` × the grout width are pushed apart for at most `separation_passes`
  /// passes a round (0 switches the whole step off), a tile whose overlaps still add up to more
  /// than `max_tile_crowding` × its side is shrunk or left out, and what overlap is left is
  /// trimmed off (`separate_tiles()`). (Since pairs are measured by the bend of their planes
  /// (`internal::bent_length()`), 0.15 and 0.55: on the 19 meshes of doc/mosaic.md, two seeds
  /// each, 0.3 and 0.4 left coverage below 0.85 in 6 runs of 38, 0.2 and 0.5 in none but a bare
  /// patch 2.6 tiles wide on one, 0.15 and 0.55 missed no target: coverage 0.854–0.898, at most
  /// 0.84 % overlap. The trimming deals with smaller crowding; at 0.25 crowding the ten meshes
  /// lost 0.5–1 % of coverage to tiles shrunk or left out.)
  std::size_t separation_passes = 30;
  double min_tile_gap = 0.15;
  double max_tile_crowding = 0.55;
  /// A crowded tile is shrunk by its crowding (a smaller tile where the surface is thinner than
  /// the rows need: legs, horns, tails) unless that leaves it smaller than this fraction of the
  /// tile size, when it is left out instead; bare patches get tiles down to it too. 1 never
  /// shrinks a tile. (0.35: with tiles up to 120° apart measured, at 0.5 the thin tips of the
  /// bull and the cow were left bare, coverage 0.812 and 0.836 instead of 0.836 and 0.849.)
  double min_tile_scale = 0.35;
  /// With `Mosaic_count::about`, bare patches get tiles only while the count stays within this
  /// fraction over N; past it the smallest are left bare (`Mosaic_count::at_most` stops at N).
  /// (0.08: at 3000 tiles the filling added 1.7–7.1 % of N net on the 19 organic meshes of
  /// doc/mosaic.md and 2–10.5 % on the 21 CAD parts, most where creases cut the surface into
  /// bands a few tiles wide; part.off went to 10.5 %.)
  double most_over_count = 0.08;
  /// Seed of the random initial positions: equal seeds give equal mosaics.
  unsigned seed = 1;
};

enum class Mosaic_status {
  ok,
  empty_mesh, ///< no faces, or no area
  not_triangle_mesh,
  invalid_options, ///< tile size/count, grout, symmetry or another option out of range
  invalid_field    ///< the field has non-finite vectors
};

/// What a mosaic run did, besides the tiles.
struct Surface_mosaic_stats {
  std::size_t iterations = 0;
  bool converged = false;
  /// Σ_i Σ_{j ∈ kNN(i)} E_ij of each iteration (eq. 2, before that iteration's move).
  std::vector<double> energy;
  /// Mean displacement of each iteration, in units of the spacing (of the local size with a size
  /// field).
  std::vector<double> mean_displacement;
  /// Each tile's net move over each 5 iterations, per iteration, averaged (same units): what the
  /// stopping rule reads besides `mean_displacement`.
  std::vector<double> net_displacement;
  std::size_t charts = 0, failed_charts = 0, regions = 0, virtual_tiles = 0, teleported = 0;
  /// After the optimization (`run()`): tiles moved off a feature line their rectangle still
  /// crossed, tiles no such move cleared that were cut to the line instead (one side pulled in, at
  /// least `min_tile_scale` left), and tiles left out because neither cleared it.
  std::size_t moved_off_features = 0, cut_at_features = 0, removed_at_features = 0;
  /// `separate_tiles()` (at most N tiles): passes run, tiles left out where they had no room, and
  /// pairs of tiles still closer than the least gap at the end.
  std::size_t separation_passes = 0, left_out_crowded = 0, close_pairs = 0;
  /// Tiles `separate_tiles()` made smaller instead of leaving them out (sizes in `tiles()`).
  std::size_t shrunk_tiles = 0;
  /// Tiles `separate_tiles()` trimmed at the end: sides cut back where they still overlapped a
  /// neighbour (each such tile is a shorter rectangle; sizes in `tiles()`).
  std::size_t trimmed_tiles = 0;
  /// Tiles `separate_tiles()` added in bare patches at the end, each as large as the room there
  /// takes (at least `min_tile_scale` of the size).
  std::size_t filled_patches = 0;
  /// Tiles shrunk or trimmed that grew back at the very end, each side on its own, where the room
  /// around them had widened (`grow_tiles()`).
  std::size_t grown_tiles = 0;
  /// The position-field start: levels of its hierarchy and the lattice points it placed (before
  /// holes were filled).
  std::size_t lattice_levels = 0, lattice_points = 0;
  double seconds_setup = 0, seconds_initialization = 0, seconds_optimization = 0,
         seconds_separation = 0;
};

template <typename FaceDescriptor> struct Surface_mosaic_result {
  Mosaic_status status = Mosaic_status::ok;
  std::string message;
  std::vector<Mosaic_tile<FaceDescriptor>> tiles;
  Mosaic_layout layout;
  Surface_mosaic_stats stats;
  explicit operator bool() const { return status == Mosaic_status::ok; }
};

/// The optimization of Lai et al. as an object: construct (initial layout), `iterate()` as often as
/// wanted, read `tiles()`. The mesh, the field and the feature lines must outlive it.
/// Named parameters: `vertex_point_map`, `geom_traits`, and `scalar_map`: a vertex map of
/// positive numbers, the tile size relative to the layout's (Lai et al.'s size control: 2 lays
/// tiles twice as wide and high there). Tiles take the size interpolated at their centre; the
/// layout's spacing is then that of size 1, chosen so that about N tiles cover the surface (Σ area
/// / size² = N · spacing²); sizes should vary over several tiles, not jump. The position-field
/// start does not take it.
template <typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
class Surface_mosaic {
public:
  using GT = boost::graph_traits<TriangleMesh>;
  using face_descriptor = typename GT::face_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using Tile = Mosaic_tile<face_descriptor>;
  using Result = Surface_mosaic_result<face_descriptor>;
  using VPM = typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type;
  using Traits = typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type;

  /// `field` is a vertex property map of vectors (a cross field for square tiles, a line field for
  /// rectangles, e.g. from `smoothest_field()`); `features` are the lines tiles align with and do
  /// not cross (e.g. from `feature_lines()`): they split the surface into regions solved
  /// independently.
  template <typename VertexFieldMap>
  Surface_mosaic(const TriangleMesh& tm, const VertexFieldMap& field,
                 const std::vector<Feature_line<halfedge_descriptor>>& features,
                 const Surface_mosaic_options& options = {},
                 const NamedParameters& np = CGAL::parameters::default_values());
  Mosaic_status status() const { return status_; }
  const std::string& message() const { return message_; }
  const Mosaic_layout& layout() const { return layout_; }
  const Surface_mosaic_stats& stats() const { return stats_; }
  bool converged() const { return stats_.converged; }
  std::size_t number_of_tiles() const { return points_.size(); }

  /// Runs up to `k` iterations of eq. 3 (fewer when the stopping rule is met); returns how many
  /// ran.
  std::size_t iterate(std::size_t k);

  /// Iterates until the stopping rule or `max_iterations`, then separates the tiles
  /// (`separate_tiles()`) and clears the feature lines (`clear_features()`).
  void run();

  /// Unless `Mosaic_count::exact`: pushes apart every pair of tiles (same region, or connected
  /// components of the surface that overlap: within 45° and half a tile of each other's plane;
  /// normals less than 135° apart; past 90°, around the tip or edge of a part thinner than a tile,
  /// the other rectangle foreshortened into the tile's plane) whose rectangles overlap or come
  /// closer than `min_tile_gap` × the grout width, seen in the plane of either at their distance
  /// along the surface (the arc that bends evenly from one's plane to the other's), each rectangle
  /// grown to its footprint where the surface curves (the arc that projects into it, as the quality
  /// report counts), by the shortest translation that separates the two rectangles grown by half
  /// that gap (separating axes: both tiles' axes), half to each; all pairs at once, each move
  /// walked along the region and off its feature lines. The passes of a round stop when no pair is
  /// that close, when a pass takes less than 2 % off the summed overlap, or after
  /// `separation_passes`. Then the most crowded tiles (overlaps adding up to more than
  /// `max_tile_crowding` of a side) are made smaller by their crowding, or left out below
  /// `min_tile_scale` (never two overlapping ones at once), and another round runs for the room
  /// this made, up to six rounds (each measuring only around the tiles it changed), then one round
  /// over every tile. Then bare patches get tiles as large as the room there takes, at least
  /// `min_tile_scale` of the size: points a quarter spacing apart, each measured against the tiles
  /// around it on its side of the surface (so the tiles across a leg or a tail do not hide it) by
  /// separating axes along the surface, the widest first and each against the tiles laid before it
  /// (`stats.filled_patches`), and a round of passes runs again. Then a tile that still overlaps a
  /// neighbour is trimmed: each side that overlaps is cut back by half the overlap (the neighbour
  /// takes the other half), as a mosaicist nips a tessera to fit, so such a tile becomes a slightly
  /// shorter rectangle
  /// (`stats.trimmed_tiles`). Last, tiles shrunk or trimmed grow back, one at a time and each axis
  /// on its own (the shorter first), about the centre, as far as the room around them now takes,
  /// never over a feature line (`stats.grown_tiles`).
  ///
  /// Where the lattice's rows do not fit a region (narrow bands between creases, fronts of the
  /// growth that meet out of phase, parts thinner than a few rows) the repulsion leaves tiles
  /// overlapping their neighbours by a few percent of a side; this moves such overlaps into the
  /// grout around, shrinks or leaves out a tile where there is no room for it, and trims the
  /// rest. With `Mosaic_count::exact` it does nothing: N cells add up to the whole area, so
  /// pushing tiles apart only spreads the overlap (on the knot it rose from 1.5 to 1.7 % of the
  /// area). Returns the passes run.
  std::size_t separate_tiles();

  /// Moves every tile whose rectangle a feature line of its region crosses (the repulsion keeps
  /// tile centres off the lines, but a corner can reach over one where the field turns near it or
  /// at the free end of a crease inside a region) along one of its axes, by the least amount that
  /// leaves half a grout width between the tile and every such segment, as a mosaicist would,
  /// where it fits there beside the tiles around it; a tile no such move clears (walked along its
  /// region) is cut to the line instead, as a mosaicist cuts a tessera to an edge: one side pulled
  /// in by the least amount that clears, the opposite side kept, at least `min_tile_scale` of the
  /// size left; a tile neither clears is moved where a clearing move leaves the most room (at least
  /// `min_tile_scale`), and left out where none does. Unless `Mosaic_count::exact`, the overlap
  /// those moves made is trimmed as `separate_tiles()` trims, and then tiles grow into the room
  /// left (about the centre, then each side alone with the opposite side kept, into a sliver of
  /// bare surface on one side) and bare patches are filled as there, neither over a line.
  /// Returns how many tiles moved, were cut or were left out.
  std::size_t clear_features();

  /// Moves one tile of each of the closest pairs into the largest holes (Lai et al. §4.1); returns
  /// how many tiles moved. A hole is a face centroid whose nearest tile is farther than 0.85 × the
  /// spacing.
  std::size_t teleport();

  /// The tiles as they are now: centre, normal (its face's), x axis (the field interpolated at the
  /// centre, in the tile's plane), size, face, region, and the region's colour.
  std::vector<Tile> tiles() const;

  /// Everything a caller reads after a run.
  Result result() const;

private:
  using Clock = std::chrono::steady_clock;
  // Private types and every member function's body: internal/surface_mosaic_impl.h (set-up,
  // optimization, results), internal/surface_mosaic_start_impl.h (the start) and
  // internal/surface_mosaic_separation_impl.h (the separation).
  struct Separation;
  struct Box_overlap;
  struct Extent;

  // Set-up and the initial tiles.
  template <typename VertexFieldMap>
  void setup(const VertexFieldMap& field,
             const std::vector<Feature_line<halfedge_descriptor>>& features,
             const NamedParameters& np);
  std::vector<std::uint32_t> largest_holes(const internal::Point_search& search,
                                           double min_spacings, std::size_t limit) const;
  std::vector<std::uint32_t> widest_apart(std::vector<std::pair<double, std::uint32_t>> holes,
                                          std::size_t limit) const;
  std::vector<internal::Surface_point> lattice_points();
  std::vector<internal::Surface_point> lattice_points(double scale, std::size_t& grown) const;
  std::vector<internal::Surface_point> position_field_points();
  std::vector<internal::Surface_point> fit_count(std::vector<internal::Surface_point> out);
  void remove_tiles(const std::vector<char>& keep);
  void forget_neighbors();
  void forget_tile_state();

  // `clear_features()`.
  Extent extent_at(const internal::Surface_point& p, const std::array<double, 2>& shrink) const;
  std::array<double, 4> needed_moves(const internal::Surface_point& p,
                                     const std::array<double, 2>& shrink) const;
  bool cut_at_features(std::size_t i);
  // Whether `needed_moves()` found no line to clear.
  static bool clear_of_lines(const std::array<double, 4>& need) {
    return std::all_of(need.begin(), need.end(), [](double t) { return t <= 0; });
  }

  // `separate_tiles()`.
  double separation_gap() const;
  double half_side(std::size_t i, int axis, double gap) const;
  std::size_t measure_crowding(Separation& sep);
  void measure_tile(std::size_t i, double gap, double reach, double side, Separation& sep,
                    std::uint32_t& pairs, double& depth) const;
  bool share_room(std::uint32_t region_a, std::uint32_t region_b, double facing,
                  double plane_distance) const;
  std::size_t spread_tiles(Separation& sep, bool all = true);
  std::size_t shrink_crowded_tiles(Separation& sep);
  std::size_t trim_overlapping_tiles(Separation& sep);
  std::size_t fill_bare_patches(bool off_lines = false);
  std::size_t fill_budget() const;
  // A tile as `fill_bare_patches()` measures room against it: point, centre, axes, normal, half
  // sides with half the gap, region.
  struct Room_tile {
    internal::Surface_point at;
    internal::Vec3 centre, x, y, normal;
    std::array<double, 2> half;
    std::uint32_t region;
  };
  int fill_subdivision(std::uint32_t f) const;
  // A tile about to be laid or widened, as `room_against()` measures it: point, frame, size,
  // region, and how it grows (scales base + s · dir per axis).
  struct Room_probe {
    internal::Surface_point at;
    internal::Vec3 q, x, y, normal;
    double h = 1;
    std::uint32_t region = 0;
    std::array<double, 2> base{{0, 0}}, dir{{1, 1}};
  };
  std::vector<Room_tile> room_tiles() const;
  Room_tile room_tile(std::size_t i) const;
  Room_probe room_probe(const internal::Surface_point& p) const;
  bool under(const Room_tile& t, const internal::Vec3& q, std::uint32_t f, double gap) const;
  bool too_close(const Room_tile& t, const internal::Vec3& q, std::uint32_t f, double gap) const;
  std::size_t grow_tiles(bool sides = false);
  bool grow_side(std::size_t i, int axis, double sign, const internal::Point_search& search,
                 std::vector<Room_tile>& tiles);
  bool clear_of_lines_by_grout(const internal::Surface_point& p,
                               const std::array<double, 2>& scales) const;
  double clear_scale(const internal::Surface_point& p, const std::array<double, 2>& base,
                     const std::array<double, 2>& dir, double lo, double hi) const;
  double room_at(const Room_probe& p, const internal::Point_search& search,
                 const std::vector<Room_tile>& tiles, std::uint32_t skip) const;
  double room_against(const Room_probe& p, const Room_tile& t, double gap) const;
  static double footprint_stretch(double q, double s, double w);
  static Box_overlap box_overlap(const std::array<double, 2>& a, const std::array<double, 2>& b,
                                 double ax, double ay, double dx, double dy);

  // The optimization and what it shares with the other steps.
  static double seconds(Clock::time_point a, Clock::time_point b);
  void fail(Mosaic_status s, std::string m);
  static internal::Vec3 tangent(const internal::Vec3& x, const internal::Vec3& normal);
  void refresh_neighbors(bool force, bool periodic = true);
  std::vector<std::uint32_t> movers() const;
  void requery_neighbors(const std::vector<std::uint32_t>& tiles);
  double face_size(std::uint32_t f) const;
  double size_at(const internal::Surface_point& p) const;
  double tile_scale(std::size_t i, int axis) const;
  std::array<double, 2> chart_difference(std::uint32_t i, std::uint32_t j,
                                         const Manhattan_chart& ci,
                                         const std::array<double, 2>& uvi,
                                         const std::array<internal::Vec3, 2>& frame) const;
  internal::Vec3 tile_x_axis(const internal::Surface_point& p) const;
  void keep_off_features(std::uint32_t i);
  void step();
  internal::Vec3 force(std::uint32_t i, double& energy);
  double move_by(const std::vector<internal::Vec3>& move);

  const TriangleMesh& tm_;
  Surface_mosaic_options options_;
  VPM vpm_;
  Mosaic_status status_ = Mosaic_status::ok;
  std::string message_;
  int symmetry_ = 4;
  Mosaic_layout layout_;
  Surface_mosaic_stats stats_;
  double reach_ = 0;
  std::unique_ptr<internal::Surface_arrays<TriangleMesh>> surface_;
  std::unique_ptr<internal::Face_field<TriangleMesh>> face_field_;
  std::unique_ptr<Manhattan_chart_atlas<TriangleMesh>> atlas_;
  std::unique_ptr<internal::Feature_segments<TriangleMesh>> features_;
  std::vector<internal::Vec3> vertex_field_, virtual_pos_;
  std::vector<std::uint32_t> virtual_region_;
  std::vector<internal::Surface_point> points_;
  std::vector<internal::Vec3> pos_;
  std::vector<std::uint32_t> chart_;
  internal::Point_search knn_;
  std::vector<std::uint32_t> neighbors_;
  std::vector<internal::Vec3> last_move_;
  // Each tile's sides over the size there (separate_tiles() shrinks and trims them).
  std::vector<std::array<double, 2>> scale_;
  std::vector<double> vertex_size_; // the size field at the vertices (empty: size 1 everywhere)
  // The largest size of the field (1 without one; below 1 when every size is: the spacing is that
  // of size 1, which may then be far larger than any tile).
  double largest_size_ = 1;
  std::vector<double> gain_;
  std::vector<double> nearest_;
  std::vector<std::uint32_t> nearest_index_;
  std::vector<internal::Vec3> built_pos_; // the tiles' positions when the lists were built
  // The stopping rule's window: positions at its start, iterations run in it.
  static constexpr std::size_t stop_window = 5;
  std::vector<internal::Vec3> window_pos_;
  std::size_t window_iterations_ = 0;
  double moved_since_refresh_ = 0;
  std::size_t iterations_since_refresh_ = 0;
};

/// Lays out a surface mosaic in one call: initialization, optimization until the stopping rule,
/// tiles.
template <typename TriangleMesh, typename VertexFieldMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Surface_mosaic_result<typename boost::graph_traits<TriangleMesh>::face_descriptor> surface_mosaic(
    const TriangleMesh& tm, const VertexFieldMap& field,
    const std::vector<
        Feature_line<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>>& features,
    const Surface_mosaic_options& options = {},
    const NamedParameters& np = CGAL::parameters::default_values()) {
  Surface_mosaic<TriangleMesh, NamedParameters> mosaic(tm, field, features, options, np);
  mosaic.run();
  return mosaic.result();
}

} // namespace tessera

#include <tessera/mosaic/internal/surface_mosaic_impl.h>
