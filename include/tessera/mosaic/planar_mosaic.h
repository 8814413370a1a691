// Planar decorative mosaics (Hausner, "Simulating decorative mosaics", SIGGRAPH 2001): square or
// rectangular tiles at the sites of a centroidal Voronoi diagram under a Manhattan metric rotated
// by the direction field of the image's edge curves, so rows of tiles follow the edges as in opus
// vermiculatum. Lloyd's iterations on the CPU (planar_voronoi.h), with edge avoidance (§6).
#pragma once

#include <tessera/io/image.h>
#include <tessera/mosaic/planar_field.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tessera {

enum class Planar_tile_shape { square, rectangle, ellipse };
/// Tile colour: the image's pixel at the tile's centre (flat-colour images) or the mean over the
/// tile (photographs).
enum class Planar_tile_coloring { point, area };
/// What happens to tiles that would straddle an edge curve or overlap a neighbour once placed:
/// `shrink` cuts them smaller about their centre until they don't, as a mosaicist cuts tiles
/// (down to `min_fit_scale`, below which the tile is left out); `none` keeps Hausner's tiles as
/// they are.
enum class Planar_tile_fitting { none, shrink };

struct Planar_mosaic_options {
  /// Number of tiles n.
  std::size_t tiles = 1000;
  /// Size factor δ: the tile side is δ·√(hw/n) (Hausner §3; 0.8 in most of the paper's figures).
  double delta = 0.8;
  /// Aspect factor β of the metric: tiles are d/β across the rows (along the field) and d·β along
  /// them. `shape` square needs β = 1.
  double beta = 1;
  Planar_tile_shape shape = Planar_tile_shape::square;
  Planar_tile_coloring coloring = Planar_tile_coloring::point;
  /// Lloyd iterations in all; the first `barrier_iterations` of them treat the pixels within
  /// `barrier_width`·d/2 of an edge as belonging to no tile (§6), which pushes straddling cells off
  /// the edges; the rest close the gaps the barrier left.
  std::size_t iterations = 20;
  std::size_t barrier_iterations = 14;
  double barrier_width = 0.5;
  /// Beyond Hausner: after each move, a site closer to an edge than half its tile (plus half a
  /// pixel) is pushed along the field to that distance, so tiles end up beside the edges rather
  /// than on them.
  bool keep_off_edges = true;
  Planar_tile_fitting fitting = Planar_tile_fitting::shrink;
  double min_fit_scale = 0.3;
  /// Variable tile sizes (§3, Figure 7 of the paper): `region_labels` (same size as the image)
  /// gives each pixel a region index into `region_sizes`, each a factor on the tile side. Sites
  /// start by rejection sampling with acceptance (s_min/s)², so each region gets tiles of its size.
  Gray_image region_labels;
  std::vector<double> region_sizes;
  /// Starting sites (pixel coordinates) instead of random ones, e.g. a previous result's tile
  /// centres to go on iterating; their number then replaces `tiles`.
  std::vector<std::array<double, 2>> initial_sites;
  unsigned seed = 1;
};

/// One tile in pixel coordinates: centre, angle of its `width` side (radians; the field's
/// direction, its median over the pixels the tile covers, runs across the rows), its sides,
/// colour and region.
struct Planar_tile {
  double x = 0, y = 0, angle = 0;
  double width = 0, height = 0;
  std::array<std::uint8_t, 3> color{{0, 0, 0}};
  int region = 0;
};

enum class Planar_mosaic_status { ok, empty_image, invalid_options, size_mismatch };

struct Planar_mosaic_stats {
  std::size_t iterations = 0, grown_windows = 0;
  /// Tiles cut smaller by the fitting, tiles left out, and the fraction of the tiles' area removed.
  std::size_t tiles_shrunk = 0, tiles_dropped = 0;
  double area_removed = 0;
  /// The CVD energy after each iteration: the sum over the pixels of their distance to their
  /// site, divided by the number of labelled pixels.
  std::vector<double> energy;
  double seconds_field = 0, seconds_initialization = 0, seconds_iterations = 0, seconds_tiles = 0,
         seconds_fitting = 0;
};

struct Planar_mosaic_result {
  Planar_mosaic_status status = Planar_mosaic_status::ok;
  std::string message;
  std::vector<Planar_tile> tiles;
  /// The field the tiles follow, and the base tile side d = δ·√(hw/n) (before region sizes).
  Planar_field field;
  double tile_side = 0;
  Planar_mosaic_stats stats;
  explicit operator bool() const { return status == Planar_mosaic_status::ok; }
};

/// The mosaic of `image` with tiles aligned to the edges of `edge_mask` (nonzero pixels; an empty
/// mask gives a constant field).
Planar_mosaic_result planar_mosaic(const Rgb_image& image, const Gray_image& edge_mask,
                                   const Planar_mosaic_options& options = {});

/// The same with a field computed by the caller (`edge_mask` then only places the barrier).
Planar_mosaic_result planar_mosaic(const Rgb_image& image, const Gray_image& edge_mask,
                                   Planar_field field, const Planar_mosaic_options& options);

/// Whether the point (px, py) lies inside `tile` shrunk by `inset` pixels on every side (a negative
/// inset grows it); ellipses are inscribed in the tile's rectangle.
bool planar_tile_contains(const Planar_tile& tile, Planar_tile_shape shape, double px, double py,
                          double inset = 0);

/// `planar_tile_contains` for many points of one tile: the tile's frame computed once.
class Planar_tile_footprint {
public:
  Planar_tile_footprint(const Planar_tile& tile, Planar_tile_shape shape, double inset = 0)
      : x_(tile.x), y_(tile.y), c_(std::cos(tile.angle)), s_(std::sin(tile.angle)),
        a_(tile.width / 2 - inset), b_(tile.height / 2 - inset),
        ellipse_(shape == Planar_tile_shape::ellipse) {}
  bool contains(double px, double py) const {
    if (a_ <= 0 || b_ <= 0)
      return false;
    const double dx = px - x_, dy = py - y_;
    const double u = c_ * dx + s_ * dy, v = c_ * dy - s_ * dx;
    if (ellipse_)
      return (u * u) / (a_ * a_) + (v * v) / (b_ * b_) <= 1;
    return std::fabs(u) <= a_ && std::fabs(v) <= b_;
  }

private:
  double x_, y_, c_, s_, a_, b_;
  bool ellipse_;
};

/// Calls f(x, y) for every pixel of a `width` × `height` image in the square window around the
/// tile's circumscribed circle (plus a pixel): the candidates for `planar_tile_contains`.
template <class F> void for_each_pixel_near(const Planar_tile& tile, int width, int height, F&& f) {
  const double reach = std::hypot(tile.width, tile.height) / 2 + 1;
  const int y0 = std::max(0, int(std::floor(tile.y - reach))),
            y1 = std::min(height - 1, int(tile.y + reach));
  const int x0 = std::max(0, int(std::floor(tile.x - reach))),
            x1 = std::min(width - 1, int(tile.x + reach));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x)
      f(x, y);
}

/// Calls f(x, y) for every pixel of a `width` × `height` image whose centre the tile covers.
template <class F>
void for_each_tile_pixel(const Planar_tile& tile, Planar_tile_shape shape, int width, int height,
                         F&& f) {
  const Planar_tile_footprint footprint(tile, shape);
  for_each_pixel_near(tile, width, height, [&](int x, int y) {
    if (footprint.contains(x, y))
      f(x, y);
  });
}

/// The base tile side d = δ·√(hw/n) of a mosaic of a `width` × `height` image (before region
/// sizes).
double planar_tile_side(int width, int height, const Planar_mosaic_options& options);

/// Canny's edge curves of `image` (detect_edges) for a mosaic with `options`: unless
/// `edge_options.min_length` is set, chains shorter than three tile sides are dropped, since a row
/// of tiles cannot follow a curve shorter than a few tiles (the small loops of a photograph's
/// texture turn the field within a tile).
Edge_curves detect_mosaic_edges(const Rgb_image& image, const Planar_mosaic_options& options,
                                Edge_detection_options edge_options = {});

} // namespace tessera
