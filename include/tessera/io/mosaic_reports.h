// What `tessera mosaic` and `tessera planar-mosaic` write to report.json and tiles.json, for
// library users: plain report structs holding the library's own figures (layout, statistics,
// quality), built from its results (`make_mosaic_report`, `make_mosaic_tiles_report`, …), and one
// JSON writer per file compiled into Tessera::core (nlohmann-json stays private). The keys and
// their meanings are doc/formats.md's; the CLI writes through these and nothing else.
#pragma once

#include <tessera/fields/smoothest_field.h>
#include <tessera/io/mesh_repair.h>
#include <tessera/mosaic/cut_tiles.h>
#include <tessera/mosaic/planar_mosaic.h>
#include <tessera/mosaic/planar_quality.h>
#include <tessera/mosaic/quality_report.h>
#include <tessera/mosaic/surface_mosaic.h>
#include <tessera/mosaic/tile.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace tessera {

/// A tile's colour as 0-255 channels.
inline std::array<int, 3> tile_rgb(const Color& c) {
  auto byte = [](double x) { return int(std::lround(255 * std::clamp(x, 0.0, 1.0))); };
  return {{byte(c.r), byte(c.g), byte(c.b)}};
}

/// The options of a surface mosaic as the command line named them.
struct Mosaic_report_options {
  std::string energy = "soft-box", start = "lattice", count = "exact", colors = "region";
  unsigned seed = 1;
  bool teleport = false;
  long long max_iterations = 150;
};

/// "thin_parts" of the field, when it was guided along thin parts (`thin_part_constraints()`).
struct Mosaic_report_thin_parts {
  std::size_t guided_vertices = 0;
  /// Of those, on curved bands with no short loop around them.
  std::size_t curved_band_vertices = 0;
  double guided_area_fraction = 0;
  /// Infinite (written as null) when no part is anisotropic.
  double fewest_tiles_around = 0;
  double median_guided_tiles_around = 0;
};

/// "refined_mesh" of the field, when the mesh's edges were split for it (`refine_coarse_mesh()`).
struct Mosaic_report_refinement {
  std::size_t vertices_before = 0, vertices_added = 0;
  double longest_edge_before = 0, max_edge_length = 0;
};

/// "creases" of the field, when no --features was given: the creases at 60° read at the tiles'
/// scale (`tile_scale_creases()`), and whether they were taken as feature lines.
struct Mosaic_report_creases {
  std::size_t lines = 0;
  double length_spacings = 0, long_share = 0;
  bool features = false;
};

/// The direction field a surface mosaic follows.
struct Mosaic_report_field {
  int symmetry = 4;
  std::size_t hard_constraints = 0, soft_constraints = 0, feature_lines = 0, color_regions = 0;
  double energy = 0;
  std::optional<Mosaic_report_thin_parts> thin_parts;
  std::optional<Mosaic_report_refinement> refined_mesh;
  std::optional<Mosaic_report_creases> creases;
};

/// "cut_tiles" of the report, when the tiles were cut apart (`cut_tiles()`).
struct Mosaic_report_cut {
  double grout_width = 0;
  Cut_tiles_result cut;
};

/// report.json of `tessera mosaic`.
struct Mosaic_report {
  std::string mesh;
  Mesh_changes repairs;
  Mosaic_report_options options;
  Mosaic_report_field field;
  Mosaic_layout layout;
  Surface_mosaic_stats stats;
  double seconds_field = 0; ///< written with the stats' seconds
  Mosaic_quality quality;
  std::optional<Mosaic_report_cut> cut_tiles;
};

/// One tile of tiles.json of `tessera mosaic`.
struct Mosaic_tile_report {
  std::array<double, 3> center{}, normal{}, x_axis{};
  std::array<double, 2> size{};
  std::size_t face = 0, region = 0;
  std::array<int, 3> color{};
  std::vector<std::array<double, 2>> outline; ///< written only when not empty
};

/// tiles.json of `tessera mosaic`.
struct Mosaic_tiles_report {
  std::vector<Mosaic_tile_report> tiles;
};

/// The options of a planar mosaic as the command line named them, with the library's values.
struct Planar_mosaic_report_options {
  std::size_t tiles = 0, iterations = 0, barrier_iterations = 0;
  double delta = 0, aspect = 1;
  std::string shape, colors, fit;
  unsigned seed = 1;
};

/// report.json of `tessera planar-mosaic`.
struct Planar_mosaic_report {
  std::string image_path;
  int image_width = 0, image_height = 0;
  std::string edge_source; ///< "auto", "none" or the edge file
  std::size_t edge_curves = 0, edge_pixels = 0;
  std::size_t tiles = 0;
  double tile_side = 0;
  Planar_mosaic_report_options options;
  Planar_mosaic_quality quality;
  Planar_mosaic_stats stats; ///< its fitting, energy, grown windows and seconds
  double seconds_total = 0;
};

/// tiles.json of `tessera planar-mosaic` (pixel units).
struct Planar_mosaic_tiles_report {
  std::vector<Planar_tile> tiles;
};

/// Writes `report` as JSON (one key a line); false when the stream failed.
bool write_mosaic_report(std::ostream& out, const Mosaic_report& report);
/// Writes `report` as JSON, one tile a line; false when the stream failed.
bool write_mosaic_tiles_report(std::ostream& out, const Mosaic_tiles_report& report);
/// Writes `report` as JSON (one key a line); false when the stream failed.
bool write_planar_mosaic_report(std::ostream& out, const Planar_mosaic_report& report);
/// Writes `report` as JSON with its units, one tile a line; false when the stream failed.
bool write_planar_mosaic_tiles_report(std::ostream& out, const Planar_mosaic_tiles_report& report);

/// The tiles of a surface mosaic (`Surface_mosaic::tiles()`, possibly cut by `cut_tiles()`).
template <typename FaceDescriptor>
Mosaic_tiles_report
make_mosaic_tiles_report(const std::vector<Mosaic_tile<FaceDescriptor>>& tiles) {
  Mosaic_tiles_report r;
  for (const auto& t : tiles)
    r.tiles.push_back({t.center, t.normal, t.x_axis, t.size, std::size_t(t.face), t.region,
                       tile_rgb(t.color), t.outline});
  return r;
}

/// The report of a surface mosaic of `mesh` (a path, as given) on the field `field` of symmetry
/// `symmetry` with `feature_lines` lines and `color_regions` colour regions; `stats` and `layout`
/// from the `Surface_mosaic`, `quality` from `mosaic_quality()`. The options and `cut_tiles` are
/// set by the caller.
inline Mosaic_report make_mosaic_report(const std::string& mesh, const Mesh_changes& repairs,
                                        const Smoothest_field_result& field, int symmetry,
                                        std::size_t feature_lines, std::size_t color_regions,
                                        const Mosaic_layout& layout,
                                        const Surface_mosaic_stats& stats,
                                        const Mosaic_quality& quality, double seconds_field = 0) {
  Mosaic_report r;
  r.mesh = mesh;
  r.repairs = repairs;
  r.field = {symmetry,      field.hard_constraints, field.soft_constraints,
             feature_lines, color_regions,          field.energy,
             std::nullopt,  std::nullopt,           std::nullopt};
  r.layout = layout;
  r.stats = stats;
  r.seconds_field = seconds_field;
  r.quality = quality;
  return r;
}

/// The report of `planar_mosaic(image, edges, options)` with its quality; `image_path` and
/// `edge_source` as given, `edge_curves` the polylines rasterized into `edges` (0 for a mask).
/// The options' names and `seconds_total` are set by the caller.
inline Planar_mosaic_report make_planar_mosaic_report(
    const std::string& image_path, const Rgb_image& image, const std::string& edge_source,
    std::size_t edge_curves, const Gray_image& edges, const Planar_mosaic_options& options,
    const Planar_mosaic_result& result, const Planar_mosaic_quality& quality) {
  Planar_mosaic_report r;
  r.image_path = image_path;
  r.image_width = image.width;
  r.image_height = image.height;
  r.edge_source = edge_source;
  r.edge_curves = edge_curves;
  r.edge_pixels = std::size_t(std::count_if(edges.pixels.begin(), edges.pixels.end(),
                                            [](std::uint8_t v) { return v != 0; }));
  r.tiles = result.tiles.size();
  r.tile_side = result.tile_side;
  r.options.tiles = options.tiles;
  r.options.iterations = options.iterations;
  r.options.barrier_iterations = options.barrier_iterations;
  r.options.delta = options.delta;
  r.options.aspect = options.beta;
  r.options.seed = options.seed;
  r.quality = quality;
  r.stats = result.stats;
  return r;
}

} // namespace tessera
