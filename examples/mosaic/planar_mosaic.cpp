// Reads an image (default: the cat photograph in tests/data/images), finds its edge curves with
// Canny, lays 1500 square tiles along them (Hausner, "Simulating decorative mosaics", 2001), prints
// the report and writes planar-mosaic.png.
#include <tessera/io/image.h>
#include <tessera/mosaic/draw_planar_mosaic.h>
#include <tessera/mosaic/planar_field.h>
#include <tessera/mosaic/planar_mosaic.h>
#include <tessera/mosaic/planar_quality.h>

#include <iostream>

int main(int argc, char** argv) {
  const std::string path = argc > 1 ? argv[1] : TESSERA_EXAMPLE_DATA_DIR "/images/chelsea.png";
  const tessera::Image_read_result read = tessera::read_image(path);
  if (!read) {
    std::cerr << read.message << "\n";
    return 1;
  }
  const tessera::Rgb_image& image = read.image;
  tessera::Planar_mosaic_options options;
  options.tiles = 1500;
  const tessera::Gray_image edges = tessera::rasterize_edges(
      tessera::detect_mosaic_edges(image, options), image.width, image.height);
  const tessera::Planar_mosaic_result mosaic = tessera::planar_mosaic(image, edges, options);
  if (!mosaic) {
    std::cerr << mosaic.message << "\n";
    return 1;
  }
  const tessera::Planar_mosaic_quality q =
      tessera::planar_mosaic_quality(image, edges, mosaic.field, mosaic.tiles, options.shape);
  std::cout << path << ": " << mosaic.tiles.size() << " tiles of side " << mosaic.tile_side
            << " px\ncoverage " << q.coverage << ", overlap " << q.overlap << ", "
            << q.straddling_tiles << " tiles straddling edges, orientation error median "
            << q.orientation_error_median << " degrees, colour error " << q.color_error << "\n";
  const tessera::Render_result drawn =
      tessera::draw_planar_mosaic(mosaic.tiles, image.width, image.height, "planar-mosaic.png");
  if (!drawn) {
    std::cerr << drawn.message << "\n";
    return 1;
  }
  std::cout << "wrote planar-mosaic.png\n";
  return 0;
}
