// The quality report of a planar mosaic: how much of the image the tiles cover and how much they
// overlap, tiles that straddle an edge curve, how well tiles follow the field, and how close the
// tiles' colours are to the image (CIELAB ΔE). Measured on the image's pixel grid.
#pragma once

#include <tessera/io/image.h>
#include <tessera/mosaic/planar_field.h>
#include <tessera/mosaic/planar_mosaic.h>

#include <cstddef>
#include <vector>

namespace tessera {

struct Planar_mosaic_quality {
  /// Fractions of the image's pixels (centres) under at least one tile and under two or more.
  double coverage = 0, overlap = 0;
  /// Tiles with an edge pixel more than half a pixel inside them (the curves are drawn one pixel
  /// wide, so half a pixel is their resolution).
  std::size_t straddling_tiles = 0;
  /// Per tile, the mean over its pixels of the angle between the tile and the field there (modulo
  /// the tiles' symmetry: 90° for `square` tiles, even when fitting cut them, 180° otherwise);
  /// median and 95th percentile, degrees.
  double orientation_error_median = 0, orientation_error_p95 = 0;
  /// Mean CIELAB ΔE (CIE 1976) between each covered pixel and the colour of the tile over it.
  double color_error = 0;
  double seconds = 0;
};

/// Measures `tiles` of `shape` against the image, its edge pixels (`edge_mask` nonzero; may be
/// empty) and its field.
Planar_mosaic_quality planar_mosaic_quality(const Rgb_image& image, const Gray_image& edge_mask,
                                            const Planar_field& field,
                                            const std::vector<Planar_tile>& tiles,
                                            Planar_tile_shape shape);

} // namespace tessera
