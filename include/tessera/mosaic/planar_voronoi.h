// Voronoi diagrams on a pixel grid under a per-site rotated L1 metric (Hausner, "Simulating
// decorative mosaics", SIGGRAPH 2001, §3): site i is at distance α_i·(β|x′| + |y′|/β) from the
// pixel x, with (x′, y′) = R(−θ_i)·(x − p_i) the pixel in the site's frame. Each site rasterizes
// its cone over a window around it (in parallel over bands of rows) and keeps the pixels it is
// nearest to.
#pragma once

#include <tessera/io/image.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace tessera {

/// A site: position in pixel coordinates, the angle θ of its x′ axis, and its scale α (distances
/// from it are multiplied by α, so a larger α gives a smaller cell).
struct Planar_site {
  double x = 0, y = 0;
  double angle = 0;
  double scale = 1;
};

struct Planar_voronoi_options {
  /// β of the metric: cells of a regular layout are β² times longer along y′ than along x′.
  double beta = 1;
  /// The expected spacing of sites of scale 1, in pixels; 0 takes √(pixels / sites). Each site's
  /// first window has a half-side of this times max(β, 1/β)/α_i, and grows as needed.
  double window = 0;
  /// Grow windows until a bound proves that no site outside a pixel's covering windows can be
  /// nearer to it, so the labels are exact whatever the cells' shapes (see `planar_voronoi`).
  /// Lloyd's iterations of `planar_mosaic` leave it off: the border rule alone already misses
  /// fewer than one pixel in a thousand, and only with frames that vary from site to site.
  bool certify = true;
};

/// The diagram: `labels[i]` is the site nearest to pixel i (ties go to the lower index), or −1 on a
/// barrier pixel; `distance[i]` is that site's distance to the pixel.
struct Planar_voronoi {
  int width = 0, height = 0;
  std::vector<int> labels;
  std::vector<float> distance;
  /// Windows that had to grow because the site's cell reached their border, and rasterization
  /// passes over the image (1 when no window grew).
  std::size_t grown_windows = 0, passes = 0;

  int label_at(int x, int y) const { return labels[std::size_t(y) * std::size_t(width) + x]; }
};

/// The distance of pixel (x, y) from `site` under the metric of the diagram.
inline double planar_site_distance(const Planar_site& site, double beta, double x, double y) {
  const double c = std::cos(site.angle), s = std::sin(site.angle);
  const double dx = x - site.x, dy = y - site.y;
  return site.scale *
         std::max(beta * std::fabs(c * dx + s * dy), std::fabs(-s * dx + c * dy) / beta);
}

/// Labels every pixel of a width × height grid with its nearest site. Pixels where `barrier` is
/// nonzero (when given; same size as the grid) belong to no site. Every cell that reaches its
/// window's border is rasterized again over a window twice as large, which gives the exact
/// nearest-site labelling whenever cells are star-shaped about their sites (always for a constant
/// angle and scale). With `certify`, windows also grow until a lower bound on each site's distance
/// outside its window, α·min(β, 1/β)·|p − p_i|/√2, is at least the labelled distance of every
/// 16 × 16 block there: then the labelling is exact for any frames and scales.
Planar_voronoi planar_voronoi(int width, int height, const std::vector<Planar_site>& sites,
                              const Planar_voronoi_options& options = {},
                              const Gray_image* barrier = nullptr);

} // namespace tessera
