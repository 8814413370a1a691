// Planar mosaic quality: every tile rasterized over its bounding box on the pixel grid.
#include <tessera/mosaic/planar_quality.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace tessera {
namespace {

double percentile(std::vector<double> v, double q) {
  if (v.empty())
    return 0;
  const std::size_t k = std::min(v.size() - 1, std::size_t(q * double(v.size() - 1) + 0.5));
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
  return v[k];
}

// RGB bytes to CIELAB (L in [0, 100]) through OpenCV, for n colours at once.
cv::Mat to_lab(const std::uint8_t* rgb, int rows, int cols) {
  cv::Mat bytes(rows, cols, CV_8UC3, const_cast<std::uint8_t*>(rgb)), unit, lab;
  bytes.convertTo(unit, CV_32FC3, 1.0 / 255);
  cv::cvtColor(unit, lab, cv::COLOR_RGB2Lab);
  return lab;
}

} // namespace

Planar_mosaic_quality planar_mosaic_quality(const Rgb_image& image, const Gray_image& edge_mask,
                                            const Planar_field& field,
                                            const std::vector<Planar_tile>& tiles,
                                            Planar_tile_shape shape) {
  const auto t0 = std::chrono::steady_clock::now();
  Planar_mosaic_quality q;
  if (image.empty())
    return q;
  const int w = image.width, h = image.height;
  const bool edges = edge_mask.width == w && edge_mask.height == h;
  const bool with_field = field.width == w && field.height == h;
  const cv::Mat image_lab = to_lab(image.pixels.data(), h, w);
  std::vector<std::uint8_t> tile_rgb;
  for (const Planar_tile& t : tiles)
    tile_rgb.insert(tile_rgb.end(), t.color.begin(), t.color.end());
  const cv::Mat tile_lab =
      tiles.empty() ? cv::Mat() : to_lab(tile_rgb.data(), 1, int(tiles.size()));

  const double period = shape == Planar_tile_shape::square ? M_PI / 2 : M_PI;
  std::vector<std::uint8_t> count(std::size_t(w) * std::size_t(h), 0);
  std::vector<double> orientation;
  orientation.reserve(tiles.size());
  double color_error = 0, colored = 0;
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const Planar_tile& t = tiles[i];
    const cv::Vec3f c = tile_lab.at<cv::Vec3f>(0, int(i));
    double angle_sum = 0, angle_n = 0;
    bool straddles = false;
    for_each_tile_pixel(t, shape, w, h, [&](int x, int y) {
      std::uint8_t& n = count[std::size_t(y) * std::size_t(w) + x];
      if (n < 255)
        ++n;
      if (n == 1) {
        const cv::Vec3f p = image_lab.at<cv::Vec3f>(y, x);
        color_error += double(cv::norm(p - c)), colored += 1;
      }
      if (edges && edge_mask.at(x, y)) {
        if (planar_tile_contains(t, shape, x, y, 0.5))
          straddles = true;
        return; // the field on an edge pixel is borrowed from a neighbour
      }
      if (with_field)
        angle_sum += orientation_difference(t.angle, field.angle_at(x, y), period), angle_n += 1;
    });
    q.straddling_tiles += straddles;
    if (angle_n > 0)
      orientation.push_back(angle_sum / angle_n * 180 / M_PI);
  }
  std::size_t covered = 0, overlapped = 0;
  for (std::uint8_t n : count)
    covered += n >= 1, overlapped += n >= 2;
  q.coverage = double(covered) / double(count.size());
  q.overlap = double(overlapped) / double(count.size());
  q.color_error = colored > 0 ? color_error / colored : 0;
  q.orientation_error_median = percentile(orientation, 0.5);
  q.orientation_error_p95 = percentile(orientation, 0.95);
  q.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return q;
}

} // namespace tessera
