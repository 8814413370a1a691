// Raster images for the planar mosaics: plain RGB and single-channel pixel buffers, and reading
// PNG, JPEG and BMP through OpenCV's imgcodecs (compiled into libtessera, so OpenCV stays out of
// the headers).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tessera {

/// An 8-bit RGB image, row-major, 3 bytes per pixel; pixel (x, y) is column x of row y, and its
/// centre has coordinates (x, y) in the planar mosaic's pixel frame.
struct Rgb_image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;

  Rgb_image() = default;
  Rgb_image(int w, int h) : width(w), height(h), pixels(std::size_t(w) * std::size_t(h) * 3, 0) {}
  bool empty() const { return width <= 0 || height <= 0; }
  std::array<std::uint8_t, 3> at(int x, int y) const {
    const std::size_t i = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3;
    return {{pixels[i], pixels[i + 1], pixels[i + 2]}};
  }
  void set(int x, int y, std::array<std::uint8_t, 3> c) {
    const std::size_t i = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3;
    pixels[i] = c[0], pixels[i + 1] = c[1], pixels[i + 2] = c[2];
  }
};

/// An 8-bit single-channel image (edge masks, barrier masks, region labels), row-major.
struct Gray_image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;

  Gray_image() = default;
  Gray_image(int w, int h, std::uint8_t value = 0)
      : width(w), height(h), pixels(std::size_t(w) * std::size_t(h), value) {}
  bool empty() const { return width <= 0 || height <= 0; }
  std::uint8_t at(int x, int y) const { return pixels[std::size_t(y) * std::size_t(width) + x]; }
  std::uint8_t& at(int x, int y) { return pixels[std::size_t(y) * std::size_t(width) + x]; }
};

enum class Image_read_status { ok, cannot_open, empty_file, cannot_decode, too_large };

struct Image_read_options {
  /// Larger images are refused before their pixels are allocated (width × height).
  std::size_t max_pixels = std::size_t(1) << 26;
};

struct Image_read_result {
  Image_read_status status = Image_read_status::ok;
  std::string message;
  Rgb_image image;
  explicit operator bool() const { return status == Image_read_status::ok; }
};

/// Decodes a PNG, JPEG or BMP image held in memory with OpenCV's imgcodecs, after checking the
/// size its header gives against `max_pixels` (other formats are refused: their decoders would
/// allocate before any check); an alpha channel is dropped, grey images become RGB.
Image_read_result decode_image(const std::vector<std::uint8_t>& bytes,
                               const Image_read_options& options = {});

/// Reads and decodes the image file at `path`; every failure comes back as a status and a message
/// that names the file.
Image_read_result read_image(const std::string& path, const Image_read_options& options = {});

} // namespace tessera
