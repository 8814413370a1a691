// The direction field of a planar decorative mosaic (Hausner, "Simulating decorative mosaics",
// SIGGRAPH 2001, §4): the gradient of the distance to the nearest edge curve, so rows of tiles run
// parallel to the edges. Edge curves come as polylines, a mask image, or from Canny's detector.
#pragma once

#include <tessera/io/image.h>

#include <array>
#include <cmath>
#include <vector>

namespace tessera {

/// Edge curves in pixel coordinates (the centre of pixel (x, y) is the point (x, y)).
struct Edge_curves {
  std::vector<std::vector<std::array<double, 2>>> polylines;
};

/// The curves drawn one pixel wide (8-connected) into a mask of the given size: 255 on a curve,
/// 0 elsewhere. Points outside the image are clipped.
Gray_image rasterize_edges(const Edge_curves& curves, int width, int height);

/// An edge mask read from a picture: after thresholding at mid-grey, the pixels of the smaller
/// class are the edges, so both white curves on black and black curves on white work.
Gray_image edge_mask_from_image(const Rgb_image& picture);

struct Edge_detection_options {
  /// Gaussian blur before Canny, in pixels (0: none).
  double blur_sigma = 1.5;
  /// Canny's hysteresis thresholds on the gradient magnitude; 0 chooses them from the image's
  /// median grey value m as 0.66·m and 1.33·m.
  double low_threshold = 0, high_threshold = 0;
  /// Chains of edge pixels shorter than this (pixels) are dropped; 0 means 2% of the image's
  /// smaller side.
  double min_length = 0;
};

/// Edge curves found by Canny's detector, as chains of connected edge pixels; only chains at
/// least `min_length` long are kept.
Edge_curves detect_edges(const Rgb_image& image, const Edge_detection_options& options = {});

/// Per-pixel direction field: `angle[i]` is the direction (radians, in (−π, π]) of the gradient of
/// the distance to the edge curves at pixel i, and `distance[i]` the exact Euclidean distance
/// (pixels) from pixel i to the nearest edge pixel. Without edges the field is constant, angle 0,
/// and the distance infinite.
struct Planar_field {
  int width = 0, height = 0;
  std::vector<float> angle;
  std::vector<float> distance;

  bool empty() const { return width <= 0 || height <= 0; }
  float angle_at(int x, int y) const { return angle[std::size_t(y) * std::size_t(width) + x]; }
  float distance_at(int x, int y) const {
    return distance[std::size_t(y) * std::size_t(width) + x];
  }
};

struct Planar_field_options {
  /// Scale σ (pixels) over which the curves' direction is estimated: the integration scale of the
  /// edge mask's structure tensor. It smooths away the staircase of a rasterized curve and rounds
  /// corners within about σ. 0 takes the central differences of the pixel distance instead.
  double tangent_scale = 4;
};

/// The direction field of the edge pixels of `edge_mask` (nonzero pixels are edges); §4 of
/// Hausner's paper. The gradient of the distance to a smooth curve at p is the curve's normal at
/// the nearest point q (or the direction from q to p beyond a curve's end or around a corner).
/// The field takes that normal, estimated at the nearest edge pixel (OpenCV's labelled distance
/// transform) from the structure tensor at `tangent_scale`, rather than the differences of the
/// distance to pixel centres: near a rasterized curve those point at individual pixels of its
/// staircase and scatter by 5–11° (measured against circles and lines drawn at known angles; the
/// normal keeps within about 1°). A pixel whose nearest edge pixel lies more than 20° (and 2
/// pixels) to the side of that normal takes the direction from q to p.
Planar_field planar_direction_field(const Gray_image& edge_mask,
                                    const Planar_field_options& options = {});

/// A constant field (all pixels at `angle`), for tests and for images without edges.
Planar_field constant_planar_field(int width, int height, double angle);

/// |a − b| for orientations with `period` (π/2 for squares, π for rectangles), in [0, period/2].
inline double orientation_difference(double a, double b, double period) {
  double d = std::fmod(std::fabs(a - b), period);
  return d > period / 2 ? period - d : d;
}

} // namespace tessera
