// Edge curves and the direction field of planar mosaics, on OpenCV's imgproc (Canny, contours,
// the exact Euclidean distance transform).
#include <tessera/mosaic/planar_field.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace tessera {
namespace {

cv::Mat as_mat(const Gray_image& g) {
  return cv::Mat(g.height, g.width, CV_8U, const_cast<std::uint8_t*>(g.pixels.data()));
}

cv::Mat grey_of(const Rgb_image& image) {
  cv::Mat rgb(image.height, image.width, CV_8UC3, const_cast<std::uint8_t*>(image.pixels.data()));
  cv::Mat grey;
  cv::cvtColor(rgb, grey, cv::COLOR_RGB2GRAY);
  return grey;
}

} // namespace

Gray_image rasterize_edges(const Edge_curves& curves, int width, int height) {
  Gray_image mask(std::max(width, 0), std::max(height, 0), 0);
  if (mask.empty())
    return mask;
  cv::Mat m = as_mat(mask);
  // cv::polylines takes integer points with `shift` fractional bits: 8 keeps sub-pixel positions.
  constexpr int shift = 8;
  for (const auto& line : curves.polylines) {
    std::vector<cv::Point> points;
    for (const auto& p : line)
      if (std::isfinite(p[0]) && std::isfinite(p[1]) && std::fabs(p[0]) < 1e6 &&
          std::fabs(p[1]) < 1e6)
        points.emplace_back(int(std::lround(p[0] * (1 << shift))),
                            int(std::lround(p[1] * (1 << shift))));
    if (points.size() == 1)
      points.push_back(points.front());
    if (points.size() >= 2)
      cv::polylines(m, std::vector<std::vector<cv::Point>>{points}, false, cv::Scalar(255), 1,
                    cv::LINE_8, shift);
  }
  return mask;
}

Gray_image edge_mask_from_image(const Rgb_image& picture) {
  Gray_image mask(picture.width, picture.height, 0);
  if (picture.empty())
    return mask;
  const cv::Mat grey = grey_of(picture);
  std::size_t light = 0;
  for (int y = 0; y < grey.rows; ++y)
    for (int x = 0; x < grey.cols; ++x)
      light += grey.at<std::uint8_t>(y, x) >= 128;
  const bool edges_are_light = 2 * light <= mask.pixels.size();
  for (int y = 0; y < grey.rows; ++y)
    for (int x = 0; x < grey.cols; ++x)
      mask.at(x, y) = ((grey.at<std::uint8_t>(y, x) >= 128) == edges_are_light) ? 255 : 0;
  return mask;
}

Edge_curves detect_edges(const Rgb_image& image, const Edge_detection_options& options) {
  Edge_curves curves;
  if (image.empty())
    return curves;
  cv::Mat grey = grey_of(image);
  if (options.blur_sigma > 0)
    cv::GaussianBlur(grey, grey, cv::Size(0, 0), options.blur_sigma);
  double low = options.low_threshold, high = options.high_threshold;
  if (low <= 0 || high <= 0) {
    std::vector<std::uint8_t> values(grey.begin<std::uint8_t>(), grey.end<std::uint8_t>());
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(values.size() / 2),
                     values.end());
    const double m = std::max<double>(values[values.size() / 2], 16);
    low = 0.66 * m, high = 1.33 * m;
  }
  cv::Mat edges;
  cv::Canny(grey, edges, low, high, 3, true);
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(edges, contours, cv::RETR_LIST, cv::CHAIN_APPROX_NONE);
  const double min_length =
      options.min_length > 0 ? options.min_length : 0.02 * std::min(image.width, image.height);
  for (const auto& c : contours) {
    // A one-pixel-wide chain comes back as a closed contour that runs along it and back.
    if (cv::arcLength(c, true) / 2 < min_length)
      continue;
    std::vector<std::array<double, 2>> line;
    line.reserve(c.size());
    for (const cv::Point& p : c)
      line.push_back({{double(p.x), double(p.y)}});
    curves.polylines.push_back(std::move(line));
  }
  return curves;
}

Planar_field constant_planar_field(int width, int height, double angle) {
  Planar_field f;
  f.width = std::max(width, 0), f.height = std::max(height, 0);
  const std::size_t n = std::size_t(f.width) * std::size_t(f.height);
  f.angle.assign(n, float(angle));
  f.distance.assign(n, std::numeric_limits<float>::infinity());
  return f;
}

namespace {

// The field from the central differences of the distance to pixel centres; where they are
// undefined (on edge pixels and on the medial axis between curves) a pixel takes the angle of the
// nearest pixel where they are defined.
void distance_gradient_field(Planar_field& f) {
  const int w = f.width, h = f.height;
  cv::Mat undefined(h, w, CV_8U, cv::Scalar(0));
  bool any_defined = false;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(w) + x;
      const float d = f.distance[i];
      const float gx = x > 0 && x + 1 < w ? (f.distance[i + 1] - f.distance[i - 1]) / 2
                       : x > 0            ? d - f.distance[i - 1]
                       : x + 1 < w        ? f.distance[i + 1] - d
                                          : 0.f;
      const float gy = y > 0 && y + 1 < h ? (f.distance[i + w] - f.distance[i - w]) / 2
                       : y > 0            ? d - f.distance[i - w]
                       : y + 1 < h        ? f.distance[i + w] - d
                                          : 0.f;
      // Central differences of an exact distance have length close to 1 wherever one edge point
      // is nearest; on edge pixels and where two are (the medial axis) they shrink.
      if (d > 0 && gx * gx + gy * gy > 0.5f) {
        f.angle[i] = std::atan2(gy, gx);
        any_defined = true;
      } else {
        undefined.at<std::uint8_t>(y, x) = 255;
      }
    }
  if (!any_defined) {
    std::fill(f.angle.begin(), f.angle.end(), 0.f);
    return;
  }
  // Labels of the zero pixels of `undefined`, which are the defined ones.
  cv::Mat unused, labels;
  cv::distanceTransform(undefined, unused, labels, cv::DIST_L2, cv::DIST_MASK_5,
                        cv::DIST_LABEL_PIXEL);
  std::vector<float> angle_of_label(std::size_t(w) * std::size_t(h) + 1, 0.f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (!undefined.at<std::uint8_t>(y, x))
        angle_of_label[std::size_t(labels.at<int>(y, x))] =
            f.angle[std::size_t(y) * std::size_t(w) + x];
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (undefined.at<std::uint8_t>(y, x))
        f.angle[std::size_t(y) * std::size_t(w) + x] =
            angle_of_label[std::size_t(labels.at<int>(y, x))];
}

// The field from the curves' normals at the nearest edge pixel (see the header).
void curve_normal_field(Planar_field& f, const cv::Mat& not_edge, double tangent_scale) {
  const int w = f.width, h = f.height;
  // Structure tensor of the (slightly blurred) mask: its major eigenvector is the curve's normal.
  // Scharr's kernel keeps the estimate isotropic (Sobel's biased a line at 33° by 1.2°).
  cv::Mat mask;
  cv::compare(not_edge, 0, mask, cv::CMP_EQ);
  mask.convertTo(mask, CV_32F, 1.0 / 255);
  cv::GaussianBlur(mask, mask, cv::Size(0, 0), 1.0);
  cv::Mat gx, gy;
  cv::Scharr(mask, gx, CV_32F, 1, 0);
  cv::Scharr(mask, gy, CV_32F, 0, 1);
  cv::Mat jxx = gx.mul(gx), jxy = gx.mul(gy), jyy = gy.mul(gy);
  for (cv::Mat* j : {&jxx, &jxy, &jyy})
    cv::GaussianBlur(*j, *j, cv::Size(0, 0), tangent_scale);

  // The nearest edge pixel of every pixel: labels of the zero pixels of `not_edge`.
  cv::Mat unused, labels;
  cv::distanceTransform(not_edge, unused, labels, cv::DIST_L2, cv::DIST_MASK_5,
                        cv::DIST_LABEL_PIXEL);
  struct Edge_pixel {
    int x = 0, y = 0;
    float normal = 0;
  };
  std::vector<Edge_pixel> edge_of_label(std::size_t(w) * std::size_t(h) + 1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (!not_edge.at<std::uint8_t>(y, x)) {
        const float a = jxx.at<float>(y, x), b = jxy.at<float>(y, x), c = jyy.at<float>(y, x);
        // Coherence (λ1 − λ2)/(λ1 + λ2): about 1 along a curve, small at an isolated pixel or a
        // corner, which have no normal (NaN: the direction from q to p is taken).
        const float coherence = std::sqrt((a - c) * (a - c) + 4 * b * b) / std::max(a + c, 1e-12f);
        edge_of_label[std::size_t(labels.at<int>(y, x))] = {
            x, y,
            coherence > 0.5f ? 0.5f * std::atan2(2 * b, a - c)
                             : std::numeric_limits<float>::quiet_NaN()};
      }
  // tan 20°: how far to the side of the normal the nearest edge pixel may lie before p counts as
  // beyond the curve's end (or around a corner), where the distance's gradient points from q to p.
  constexpr double side_ratio = 0.36, side_min = 2;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Edge_pixel& q = edge_of_label[std::size_t(labels.at<int>(y, x))];
      const double nx = std::cos(q.normal), ny = std::sin(q.normal);
      const double px = x - q.x, py = y - q.y;
      const double along = px * nx + py * ny, side = py * nx - px * ny;
      float& angle = f.angle[std::size_t(y) * std::size_t(w) + x];
      if (std::isnan(q.normal))
        angle = px != 0 || py != 0 ? float(std::atan2(py, px)) : 0.f;
      else if (std::fabs(side) > std::max(side_min, side_ratio * std::fabs(along)))
        angle = float(std::atan2(py, px));
      else
        angle = along >= 0 ? q.normal : float(std::remainder(double(q.normal) + M_PI, 2 * M_PI));
    }
}

} // namespace

Planar_field planar_direction_field(const Gray_image& edge_mask,
                                    const Planar_field_options& options) {
  if (edge_mask.empty())
    return {};
  const int w = edge_mask.width, h = edge_mask.height;
  if (std::none_of(edge_mask.pixels.begin(), edge_mask.pixels.end(),
                   [](std::uint8_t v) { return v; }))
    return constant_planar_field(w, h, 0);

  // distanceTransform measures the distance to the nearest zero pixel: edges are the zeros.
  cv::Mat not_edge;
  cv::compare(as_mat(edge_mask), 0, not_edge, cv::CMP_EQ);
  cv::Mat dist;
  cv::distanceTransform(not_edge, dist, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);

  Planar_field f;
  f.width = w, f.height = h;
  f.distance.assign(dist.begin<float>(), dist.end<float>());
  f.angle.assign(std::size_t(w) * std::size_t(h), 0.f);
  if (options.tangent_scale > 0)
    curve_normal_field(f, not_edge, options.tangent_scale);
  else
    distance_gradient_field(f);
  return f;
}

} // namespace tessera
