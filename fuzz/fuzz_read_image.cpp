// libFuzzer target for the image reader of the planar mosaics: any bytes are decoded (or refused
// with a status), and a decoded image goes on through the edge mask and the direction field.
#include <tessera/io/image.h>
#include <tessera/mosaic/planar_field.h>

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  tessera::Image_read_options options;
  options.max_pixels = 1 << 16; // keeps each run short; the limit itself is part of what is tested
  const tessera::Image_read_result r =
      tessera::decode_image(std::vector<std::uint8_t>(data, data + size), options);
  if (!r)
    return 0;
  const tessera::Planar_field f =
      tessera::planar_direction_field(tessera::edge_mask_from_image(r.image));
  if (f.width != r.image.width || f.height != r.image.height)
    __builtin_trap();
  return 0;
}
