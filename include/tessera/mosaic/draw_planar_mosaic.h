// Pictures of planar mosaics with cairo: the tiles over grout as PNG or SVG, and the direction
// field drawn over the image with its edge curves.
#pragma once

#include <tessera/io/image.h>
#include <tessera/mosaic/planar_field.h>
#include <tessera/mosaic/planar_mosaic.h>
#include <tessera/render/scene.h>

#include <string>
#include <vector>

namespace tessera {

struct Planar_drawing_options {
  Planar_tile_shape shape = Planar_tile_shape::square;
  /// The grout: the colour between the tiles.
  Color grout{0.25, 0.24, 0.23};
  /// Output pixels per image pixel.
  double scale = 1;
  /// `draw_planar_field`: image pixels between its strokes (at least 4).
  double stroke_spacing = 16;
};

/// The tiles of a width × height mosaic over grout, written to `path`: PNG or SVG by its extension.
Render_result draw_planar_mosaic(const std::vector<Planar_tile>& tiles, int width, int height,
                                 const std::string& path,
                                 const Planar_drawing_options& options = {});

/// The image, faded, with the field drawn as short strokes every `options.stroke_spacing` pixels
/// and the edge pixels of `edge_mask` in red; PNG, `options.scale` output pixels per image pixel.
/// The strokes are crossed for square tiles (`options.shape`: their directions repeat every π/2),
/// single for the others; `options.grout` is not used.
Render_result draw_planar_field(const Rgb_image& image, const Planar_field& field,
                                const Gray_image& edge_mask, const std::string& path,
                                const Planar_drawing_options& options = {});

} // namespace tessera
