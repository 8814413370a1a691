// Rotated-Manhattan Voronoi labelling of a pixel grid: each site's pyramid rasterized over its
// window, bands of rows in parallel (TBB), windows grown until no cell touches its window's border.
#include <tessera/mosaic/planar_voronoi.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace tessera {
namespace {

// Rows per band: small enough for both cores to share the work evenly, large enough that a window
// crosses few bands.
constexpr int band_rows = 8;

struct Window {
  int x0, x1, y0, y1;            // inclusive, clipped to the image
  bool left, right, top, bottom; // the unclipped border lies inside the image on that side
};

Window window_of(const Planar_site& s, double r, int w, int h) {
  const int fx0 = int(std::floor(s.x - r)), fx1 = int(std::ceil(s.x + r));
  const int fy0 = int(std::floor(s.y - r)), fy1 = int(std::ceil(s.y + r));
  return {std::max(fx0, 0), std::min(fx1, w - 1), std::max(fy0, 0), std::min(fy1, h - 1),
          fx0 >= 0,         fx1 <= w - 1,         fy0 >= 0,         fy1 <= h - 1};
}

} // namespace

Planar_voronoi planar_voronoi(int width, int height, const std::vector<Planar_site>& sites,
                              const Planar_voronoi_options& options, const Gray_image* barrier) {
  Planar_voronoi v;
  if (width <= 0 || height <= 0)
    return v;
  v.width = width, v.height = height;
  const std::size_t npix = std::size_t(width) * std::size_t(height);
  v.labels.assign(npix, -1);
  v.distance.assign(npix, std::numeric_limits<float>::infinity());
  const std::size_t n = sites.size();
  if (n == 0)
    return v;

  const double beta = options.beta > 0 ? options.beta : 1.0;
  // A regular cell of spacing s reaches s·max(β, 1/β)/√2 from its site; the window starts a bit
  // beyond that and grows where a cell proves larger.
  const double base = (options.window > 0 ? options.window : std::sqrt(double(npix) / double(n))) *
                      std::max(beta, 1 / beta);
  struct Frame {
    float x, y, c, s, ax, ay;
  };
  std::vector<Frame> frames(n);
  std::vector<double> radius(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double scale = sites[i].scale > 0 ? sites[i].scale : 1.0;
    frames[i] = {float(sites[i].x),
                 float(sites[i].y),
                 float(std::cos(sites[i].angle)),
                 float(std::sin(sites[i].angle)),
                 float(scale * beta),
                 float(scale / beta)};
    radius[i] = base / scale;
  }
  const double image_radius = std::hypot(double(width), double(height));
  std::vector<Window> windows(n);

  // Rasterizes the pyramids of `active` sites (increasing indices) over their windows into the
  // z-buffer. Ties go to the lower index, so the labels do not depend on the order of passes or
  // the thread schedule.
  const int bands = (height + band_rows - 1) / band_rows;
  auto rasterize = [&](const std::vector<int>& active) {
    std::vector<std::vector<int>> band_sites(static_cast<std::size_t>(bands));
    for (int i : active) {
      const Window& win = windows[std::size_t(i)];
      if (win.x0 > win.x1 || win.y0 > win.y1)
        continue;
      for (int b = win.y0 / band_rows; b <= win.y1 / band_rows; ++b)
        band_sites[std::size_t(b)].push_back(i);
    }
    tbb::parallel_for(tbb::blocked_range<int>(0, bands), [&](const tbb::blocked_range<int>& range) {
      for (int b = range.begin(); b != range.end(); ++b) {
        const int row0 = b * band_rows, row1 = std::min(height - 1, row0 + band_rows - 1);
        for (int i : band_sites[std::size_t(b)]) {
          const Window& win = windows[std::size_t(i)];
          const Frame f = frames[std::size_t(i)];
          for (int y = std::max(row0, win.y0); y <= std::min(row1, win.y1); ++y) {
            const float dy = float(y) - f.y;
            // Along the row the two rotated coordinates are affine in x.
            const float u0 = f.s * dy - f.c * f.x, v0 = f.c * dy + f.s * f.x;
            float* dist = v.distance.data() + std::size_t(y) * std::size_t(width);
            int* lab = v.labels.data() + std::size_t(y) * std::size_t(width);
            for (int x = win.x0; x <= win.x1; ++x) {
              const float fx = float(x);
              const float d =
                  std::max(f.ax * std::fabs(u0 + f.c * fx), f.ay * std::fabs(v0 - f.s * fx));
              const bool nearer = d < dist[x] || (d == dist[x] && i < lab[x]);
              dist[x] = nearer ? d : dist[x];
              lab[x] = nearer ? i : lab[x];
            }
          }
        }
      }
    });
  };

  // The certificate that makes the labels exact whatever the cells' shapes. Site j's distance is at
  // least k_j·|p − p_j|, k_j = α_j·min(β, 1/β)/√2, so a pixel outside j's window at Euclidean
  // distance e from it can be nearer to j than to its label only if k_j·e < the z-buffer there.
  // Per block of pixels, the block's largest z-buffer value against k_j times the distance to the
  // block's part outside the window: where the bound fails, the window grows over the block.
  constexpr int block = 16;
  const int bw = (width + block - 1) / block, bh = (height + block - 1) / block;
  std::vector<float> block_max(std::size_t(bw) * std::size_t(bh));
  const double k_metric = std::min(beta, 1 / beta) / std::sqrt(2.0) * (1 - 1e-5);
  auto certify = [&](std::vector<int>& grow) {
    std::fill(block_max.begin(), block_max.end(), 0.f);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        float& m = block_max[std::size_t(y / block) * std::size_t(bw) + std::size_t(x / block)];
        m = std::max(m, v.distance[std::size_t(y) * std::size_t(width) + std::size_t(x)]);
      }
    const float global_max = *std::max_element(block_max.begin(), block_max.end());
    for (std::size_t i = 0; i < n; ++i) {
      if (radius[i] >= image_radius)
        continue;
      const Planar_site& s = sites[i];
      const double k = (sites[i].scale > 0 ? sites[i].scale : 1.0) * k_metric;
      const double reach = global_max / k;
      // The unclipped window: pixels [fx0, fx1] x [fy0, fy1] were rasterized by site i.
      const int fx0 = int(std::floor(s.x - radius[i])), fx1 = int(std::ceil(s.x + radius[i]));
      const int fy0 = int(std::floor(s.y - radius[i])), fy1 = int(std::ceil(s.y + radius[i]));
      auto distance_to = [&](int x0, int x1, int y0, int y1) {
        if (x0 > x1 || y0 > y1)
          return 1e300;
        const double dx = std::max({double(x0) - s.x, 0.0, s.x - double(x1)});
        const double dy = std::max({double(y0) - s.y, 0.0, s.y - double(y1)});
        return std::hypot(dx, dy);
      };
      bool fails = false;
      const int bx0 = std::max(0, int((s.x - reach) / block)),
                bx1 = std::min(bw - 1, int((s.x + reach) / block));
      const int by0 = std::max(0, int((s.y - reach) / block)),
                by1 = std::min(bh - 1, int((s.y + reach) / block));
      for (int by = by0; by <= by1 && !fails; ++by)
        for (int bx = bx0; bx <= bx1 && !fails; ++bx) {
          const int x0 = bx * block, x1 = std::min(width, x0 + block) - 1;
          const int y0 = by * block, y1 = std::min(height, y0 + block) - 1;
          // The block's pixels outside the window: left, right, above, below it.
          const double e = std::min({distance_to(x0, std::min(x1, fx0 - 1), y0, y1),
                                     distance_to(std::max(x0, fx1 + 1), x1, y0, y1),
                                     distance_to(x0, x1, y0, std::min(y1, fy0 - 1)),
                                     distance_to(x0, x1, std::max(y0, fy1 + 1), y1)});
          fails = k * e < block_max[std::size_t(by) * std::size_t(bw) + std::size_t(bx)];
        }
      if (fails) {
        radius[i] *= 2;
        grow.push_back(int(i));
      }
    }
  };

  std::vector<int> active(n);
  for (std::size_t i = 0; i < n; ++i)
    active[i] = int(i);
  while (!active.empty()) {
    ++v.passes;
    for (int i : active)
      windows[std::size_t(i)] =
          window_of(sites[std::size_t(i)], radius[std::size_t(i)], width, height);
    rasterize(active);

    // A cell that reaches its window's border may go on beyond it: that site is rasterized again
    // over a window twice as large (on top of the z-buffer, which stays valid).
    active.clear();
    for (std::size_t i = 0; i < n; ++i) {
      const Window& win = windows[i];
      if (win.x0 > win.x1 || win.y0 > win.y1 || radius[i] >= image_radius)
        continue;
      const int id = int(i);
      auto row_has = [&](int y) {
        const int* lab = v.labels.data() + std::size_t(y) * std::size_t(width);
        return std::find(lab + win.x0, lab + win.x1 + 1, id) != lab + win.x1 + 1;
      };
      auto col_has = [&](int x) {
        for (int y = win.y0; y <= win.y1; ++y)
          if (v.labels[std::size_t(y) * std::size_t(width) + std::size_t(x)] == id)
            return true;
        return false;
      };
      if ((win.top && row_has(win.y0)) || (win.bottom && row_has(win.y1)) ||
          (win.left && col_has(win.x0)) || (win.right && col_has(win.x1))) {
        radius[i] *= 2;
        active.push_back(id);
      }
    }
    // A pixel no window reached: every window grows (only with cells far from star-shaped).
    if (active.empty() && std::find(v.labels.begin(), v.labels.end(), -1) != v.labels.end())
      for (std::size_t i = 0; i < n; ++i)
        if (radius[i] < image_radius)
          radius[i] *= 2, active.push_back(int(i));
    if (active.empty() && options.certify)
      certify(active);
    v.grown_windows += active.size();
  }

  if (barrier && barrier->width == width && barrier->height == height)
    for (std::size_t p = 0; p < npix; ++p)
      if (barrier->pixels[p])
        v.labels[p] = -1;
  return v;
}

} // namespace tessera
