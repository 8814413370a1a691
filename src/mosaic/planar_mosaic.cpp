// Hausner's decorative mosaics: rejection-sampled sites, Lloyd's iterations of the
// rotated-Manhattan Voronoi diagram with edge barriers first, then tiles placed, oriented and
// coloured.
#include <tessera/mosaic/planar_mosaic.h>
#include <tessera/mosaic/planar_voronoi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <random>

namespace tessera {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

Planar_mosaic_result failure(Planar_mosaic_status status, std::string message) {
  Planar_mosaic_result r;
  r.status = status;
  r.message = std::move(message);
  return r;
}

int clamp_pixel(double v, int size) {
  return std::clamp(int(std::lround(v)), 0, size - 1);
}

// How deep two rectangular tiles, each inset by a quarter pixel, overlap, along the separating-axis
// direction where they overlap least (the axis is a side direction of `a` for axis < 2, of `b`
// otherwise); depth ≤ 0 when they do not overlap. Overlaps below half a pixel, the resolution of
// the picture, are not worth cutting a tile for.
struct Overlap {
  double depth;
  int axis;
  double along; // (b − a)·axis direction
};

Overlap rectangles_overlap(const Planar_tile& a, const Planar_tile& b) {
  constexpr double inset = 0.25;
  const double ca = std::cos(a.angle), sa = std::sin(a.angle);
  const double cb = std::cos(b.angle), sb = std::sin(b.angle);
  const double axes[4][2] = {{ca, sa}, {-sa, ca}, {cb, sb}, {-sb, cb}};
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double aw = std::max(0.0, a.width / 2 - inset), ah = std::max(0.0, a.height / 2 - inset);
  const double bw = std::max(0.0, b.width / 2 - inset), bh = std::max(0.0, b.height / 2 - inset);
  Overlap best{1e300, 0, 0};
  for (int k = 0; k < 4; ++k) {
    const double* L = axes[k];
    const double ra =
        aw * std::fabs(ca * L[0] + sa * L[1]) + ah * std::fabs(-sa * L[0] + ca * L[1]);
    const double rb =
        bw * std::fabs(cb * L[0] + sb * L[1]) + bh * std::fabs(-sb * L[0] + cb * L[1]);
    const double along = dx * L[0] + dy * L[1];
    const double depth = ra + rb - std::fabs(along);
    if (depth < best.depth)
      best = {depth, k, along};
  }
  return best;
}

// Cuts a strip `depth` deep off the side of `t` that faces along ±axis `k` (0: across its width,
// 1: across its height); `sign` is +1 for the side in the axis's direction.
void cut_tile(Planar_tile& t, int k, double sign, double depth) {
  const double c = std::cos(t.angle), s = std::sin(t.angle);
  const double ux = k == 0 ? c : -s, uy = k == 0 ? s : c;
  (k == 0 ? t.width : t.height) -= depth;
  t.x -= sign * depth / 2 * ux, t.y -= sign * depth / 2 * uy;
}

// The largest f in [0, hi] for which `fits(f)` holds, `fits` being monotone (true for small f).
template <typename Fits> double largest_fitting_scale(double hi, Fits fits) {
  if (fits(hi))
    return hi;
  double lo = 0;
  for (int k = 0; k < 20; ++k) {
    const double mid = (lo + hi) / 2;
    (fits(mid) ? lo : hi) = mid;
  }
  return lo;
}

// Mosaicist's fitting. A tile with an edge pixel more than half a pixel inside is shrunk about its
// centre until it has none; then each overlapping pair is separated by cutting a strip off the
// tile whose side is the direction of least overlap (ellipses: both shrink by one factor until
// their rectangles no longer overlap). A tile cut below `min_scale` of a side is left out.
void fit_planar_tiles(std::vector<Planar_tile>& tiles, const Gray_image& edges,
                      Planar_tile_shape shape, double min_scale, Planar_mosaic_stats& stats) {
  const std::size_t n = tiles.size();
  const std::vector<Planar_tile> original = tiles;
  auto scaled = [&](std::size_t i, double f) {
    Planar_tile t = tiles[i];
    t.width *= f, t.height *= f;
    return t;
  };
  if (!edges.empty())
    for (std::size_t i = 0; i < n; ++i) {
      const Planar_tile& t = tiles[i];
      std::vector<std::array<int, 2>> near;
      for_each_pixel_near(t, edges.width, edges.height, [&](int x, int y) {
        if (edges.at(x, y))
          near.push_back({{x, y}});
      });
      const double f = largest_fitting_scale(1.0, [&](double g) {
        const Planar_tile_footprint s(scaled(i, g), shape, 0.5);
        return std::none_of(near.begin(), near.end(),
                            [&](const std::array<int, 2>& p) { return s.contains(p[0], p[1]); });
      });
      tiles[i] = scaled(i, f);
    }
  // Pairs through a grid of cells as large as the largest tile's diagonal.
  double cell = 1;
  for (const Planar_tile& t : tiles)
    cell = std::max(cell, std::hypot(t.width, t.height));
  std::map<std::pair<long, long>, std::vector<std::size_t>> grid;
  auto key = [&](const Planar_tile& t) {
    return std::make_pair(long(std::floor(t.x / cell)), long(std::floor(t.y / cell)));
  };
  for (std::size_t i = 0; i < n; ++i)
    grid[key(tiles[i])].push_back(i);
  for (std::size_t i = 0; i < n; ++i) {
    const auto [kx, ky] = key(original[i]);
    for (long gx = kx - 1; gx <= kx + 1; ++gx)
      for (long gy = ky - 1; gy <= ky + 1; ++gy) {
        const auto it = grid.find({gx, gy});
        if (it == grid.end())
          continue;
        for (std::size_t j : it->second) {
          if (j <= i)
            continue;
          const Overlap o = rectangles_overlap(tiles[i], tiles[j]);
          if (o.depth <= 0)
            continue;
          if (shape == Planar_tile_shape::ellipse) {
            const Planar_tile ti = tiles[i], tj = tiles[j];
            const double f = largest_fitting_scale(1.0, [&](double g) {
              Planar_tile a = ti, b = tj;
              a.width *= g, a.height *= g, b.width *= g, b.height *= g;
              return rectangles_overlap(a, b).depth <= 0;
            });
            for (std::size_t m : {i, j})
              tiles[m].width *= f, tiles[m].height *= f;
          } else if (o.axis < 2) {
            cut_tile(tiles[i], o.axis, o.along > 0 ? 1 : -1, o.depth + 1e-9);
          } else {
            cut_tile(tiles[j], o.axis - 2, o.along > 0 ? -1 : 1, o.depth + 1e-9);
          }
        }
      }
  }
  double area = 0, removed = 0;
  std::vector<Planar_tile> kept;
  kept.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = original[i].width * original[i].height, b = tiles[i].width * tiles[i].height;
    area += a;
    if (tiles[i].width < min_scale * original[i].width ||
        tiles[i].height < min_scale * original[i].height) {
      ++stats.tiles_dropped, removed += a;
      continue;
    }
    if (b < a * (1 - 1e-12))
      ++stats.tiles_shrunk, removed += a - b;
    kept.push_back(tiles[i]);
  }
  stats.area_removed = area > 0 ? removed / area : 0;
  tiles = std::move(kept);
}

void color_tile(Planar_tile& tile, const Rgb_image& image, const Planar_mosaic_options& options) {
  const int w = image.width, h = image.height;
  tile.color = image.at(clamp_pixel(tile.x, w), clamp_pixel(tile.y, h));
  if (options.coloring != Planar_tile_coloring::area)
    return;
  double sum[3] = {0, 0, 0}, count = 0;
  for_each_tile_pixel(tile, options.shape, w, h, [&](int x, int y) {
    const auto rgb = image.at(x, y);
    sum[0] += rgb[0], sum[1] += rgb[1], sum[2] += rgb[2], count += 1;
  });
  if (count > 0)
    for (std::size_t c = 0; c < 3; ++c)
      tile.color[c] = std::uint8_t(std::lround(sum[c] / count));
}

// The tile turned to the field's median direction over the pixels it covers (edge pixels, whose
// field is borrowed, left out), which minimizes the mean angle between the tile and the field under
// it (the report's orientation error); `period` is the tile's symmetry, π/2 or π. Starting from the
// field's mean over the cell, two rounds (the covered pixels change as the tile turns).
void orient_by_footprint(Planar_tile& tile, Planar_tile_shape shape, const Planar_field& field,
                         const Gray_image& edges, double period) {
  const bool with_edges = !edges.empty();
  std::vector<double> offsets;
  for (int round = 0; round < 2; ++round) {
    offsets.clear();
    for_each_tile_pixel(tile, shape, field.width, field.height, [&](int x, int y) {
      if (!(with_edges && edges.at(x, y)))
        offsets.push_back(std::remainder(double(field.angle_at(x, y)) - tile.angle, period));
    });
    if (offsets.empty())
      return;
    auto mid = offsets.begin() + std::ptrdiff_t(offsets.size() / 2);
    std::nth_element(offsets.begin(), mid, offsets.end());
    tile.angle = std::remainder(tile.angle + *mid, 2 * M_PI);
  }
}

} // namespace

double planar_tile_side(int width, int height, const Planar_mosaic_options& options) {
  const double n = double(std::max<std::size_t>(
      options.initial_sites.empty() ? options.tiles : options.initial_sites.size(), 1));
  return options.delta * std::sqrt(double(std::max(width, 0)) * double(std::max(height, 0)) / n);
}

Edge_curves detect_mosaic_edges(const Rgb_image& image, const Planar_mosaic_options& options,
                                Edge_detection_options edge_options) {
  if (!(edge_options.min_length > 0))
    edge_options.min_length = 3 * planar_tile_side(image.width, image.height, options);
  return detect_edges(image, edge_options);
}

bool planar_tile_contains(const Planar_tile& t, Planar_tile_shape shape, double px, double py,
                          double inset) {
  return Planar_tile_footprint(t, shape, inset).contains(px, py);
}

Planar_mosaic_result planar_mosaic(const Rgb_image& image, const Gray_image& edge_mask,
                                   const Planar_mosaic_options& options) {
  if (image.empty())
    return failure(Planar_mosaic_status::empty_image, "the image has no pixels");
  if (!edge_mask.empty() && (edge_mask.width != image.width || edge_mask.height != image.height))
    return failure(Planar_mosaic_status::size_mismatch,
                   "the edge mask is " + std::to_string(edge_mask.width) + " x " +
                       std::to_string(edge_mask.height) + " but the image " +
                       std::to_string(image.width) + " x " + std::to_string(image.height));
  const auto t0 = std::chrono::steady_clock::now();
  Planar_field field = edge_mask.empty() ? constant_planar_field(image.width, image.height, 0)
                                         : planar_direction_field(edge_mask);
  const double seconds_field = seconds_since(t0);
  Planar_mosaic_result r = planar_mosaic(image, edge_mask, std::move(field), options);
  r.stats.seconds_field = seconds_field;
  return r;
}

Planar_mosaic_result planar_mosaic(const Rgb_image& image, const Gray_image& edge_mask,
                                   Planar_field field, const Planar_mosaic_options& options) {
  using Status = Planar_mosaic_status;
  if (image.empty())
    return failure(Status::empty_image, "the image has no pixels");
  const int w = image.width, h = image.height;
  const std::size_t npix = std::size_t(w) * std::size_t(h);
  if (field.width != w || field.height != h)
    return failure(Status::size_mismatch, "the field and the image differ in size");
  if (!edge_mask.empty() && (edge_mask.width != w || edge_mask.height != h))
    return failure(Status::size_mismatch, "the edge mask and the image differ in size");
  const std::size_t tile_count =
      options.initial_sites.empty() ? options.tiles : options.initial_sites.size();
  for (const auto& p : options.initial_sites)
    if (!(p[0] >= 0 && p[0] <= w - 1 && p[1] >= 0 && p[1] <= h - 1))
      return failure(Status::invalid_options, "an initial site lies outside the image");
  if (tile_count == 0 || tile_count > npix / 4)
    return failure(Status::invalid_options,
                   "the tile count must be between 1 and a quarter of the pixels (" +
                       std::to_string(npix / 4) + ")");
  if (!(options.delta > 0 && options.delta <= 2))
    return failure(Status::invalid_options, "delta must be in (0, 2]");
  if (!(options.beta > 0 && options.beta < 100))
    return failure(Status::invalid_options, "beta must be positive");
  if (options.shape == Planar_tile_shape::square && options.beta != 1)
    return failure(Status::invalid_options, "square tiles need beta = 1 (use rectangles)");
  if (options.barrier_iterations > options.iterations)
    return failure(Status::invalid_options, "barrier_iterations is more than iterations");
  if (!(options.barrier_width >= 0 && options.barrier_width < 10))
    return failure(Status::invalid_options, "barrier_width must be in [0, 10)");
  const bool regions = !options.region_labels.empty();
  if (regions) {
    if (options.region_labels.width != w || options.region_labels.height != h)
      return failure(Status::size_mismatch, "the region map and the image differ in size");
    for (double s : options.region_sizes)
      if (!(s > 0 && s < 100))
        return failure(Status::invalid_options, "region sizes must be positive factors");
    const std::uint8_t top =
        *std::max_element(options.region_labels.pixels.begin(), options.region_labels.pixels.end());
    if (std::size_t(top) >= options.region_sizes.size())
      return failure(Status::invalid_options,
                     "the region map has region " + std::to_string(top) + " but only " +
                         std::to_string(options.region_sizes.size()) + " sizes are given");
  }
  auto size_at = [&](int x, int y) {
    return regions ? options.region_sizes[options.region_labels.at(x, y)] : 1.0;
  };

  Planar_mosaic_result r;
  r.stats.seconds_field = 0;
  // Spacing c·s in a region of size s, with c chosen so the regions hold n sites in all:
  // Σ_r A_r / (c·s_r)² = n.
  double inverse_square_sizes = 0, s_min = 1e300;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double s = size_at(x, y);
      inverse_square_sizes += 1 / (s * s);
      s_min = std::min(s_min, s);
    }
  const double c = std::sqrt(inverse_square_sizes / double(tile_count));
  r.tile_side = options.delta * c;

  // Initialization: uniform random sites, kept with probability (s_min / s)².
  auto t = std::chrono::steady_clock::now();
  std::mt19937 rng(options.seed);
  std::uniform_real_distribution<double> ux(0, w - 1), uy(0, h - 1), accept(0, 1);
  std::vector<Planar_site> sites;
  sites.reserve(tile_count);
  for (const auto& p : options.initial_sites)
    sites.push_back({p[0], p[1], 0, 1 / size_at(clamp_pixel(p[0], w), clamp_pixel(p[1], h))});
  while (sites.size() < tile_count) {
    const double x = ux(rng), y = uy(rng);
    const double s = size_at(clamp_pixel(x, w), clamp_pixel(y, h));
    if (accept(rng) <= (s_min / s) * (s_min / s))
      sites.push_back({x, y, 0, 1 / s});
  }
  // The barrier: pixels within barrier_width·d/2 of an edge, d the local tile side.
  Gray_image barrier;
  if (!edge_mask.empty() && options.barrier_iterations > 0 && options.barrier_width > 0) {
    barrier = Gray_image(w, h, 0);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        barrier.at(x, y) =
            field.distance_at(x, y) < options.barrier_width * r.tile_side * size_at(x, y) / 2 ? 255
                                                                                              : 0;
  }
  r.stats.seconds_initialization = seconds_since(t);

  // Lloyd's iterations: label, then move each site to the centroid of its cell. The site's frame
  // is the field averaged over its cell (the n-fold circular mean for n-fold symmetric tiles).
  t = std::chrono::steady_clock::now();
  Planar_voronoi_options voronoi_options;
  voronoi_options.beta = options.beta;
  voronoi_options.window = c;
  voronoi_options.certify = false;
  const std::size_t n = sites.size();
  std::vector<double> sx(n), sy(n), count(n), mean_cos(n), mean_sin(n);
  const double symmetry = options.beta == 1 ? 4 : 2;
  // The field as n-fold symmetric unit vectors (cos nφ, sin nφ), once: the cells' circular means.
  std::vector<float> field_cos(npix), field_sin(npix);
  for (std::size_t p = 0; p < npix; ++p)
    field_cos[p] = std::cos(float(symmetry) * field.angle[p]),
    field_sin[p] = std::sin(float(symmetry) * field.angle[p]);
  auto frame_angle = [&](std::size_t i) {
    const Planar_site& s = sites[i];
    return count[i] > 0 ? std::atan2(mean_sin[i], mean_cos[i]) / symmetry
                        : double(field.angle_at(clamp_pixel(s.x, w), clamp_pixel(s.y, h)));
  };
  for (std::size_t k = 0; k < options.iterations; ++k) {
    for (std::size_t i = 0; i < n; ++i) {
      sites[i].angle = frame_angle(i);
      sites[i].scale = 1 / size_at(clamp_pixel(sites[i].x, w), clamp_pixel(sites[i].y, h));
    }
    const bool with_barrier = k < options.barrier_iterations && !barrier.empty();
    const Planar_voronoi v =
        planar_voronoi(w, h, sites, voronoi_options, with_barrier ? &barrier : nullptr);
    r.stats.grown_windows += v.grown_windows;
    for (auto* a : {&sx, &sy, &count, &mean_cos, &mean_sin})
      std::fill(a->begin(), a->end(), 0.0);
    double energy = 0, labelled = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const std::size_t p = std::size_t(y) * std::size_t(w) + std::size_t(x);
        const int l = v.labels[p];
        if (l < 0)
          continue;
        const std::size_t i = std::size_t(l);
        sx[i] += x, sy[i] += y, count[i] += 1;
        mean_cos[i] += field_cos[p], mean_sin[i] += field_sin[p];
        energy += v.distance[p], labelled += 1;
      }
    r.stats.energy.push_back(labelled > 0 ? energy / labelled : 0);
    for (std::size_t i = 0; i < n; ++i) {
      Planar_site& s = sites[i];
      if (count[i] > 0)
        s.x = sx[i] / count[i], s.y = sy[i] / count[i];
      if (!options.keep_off_edges)
        continue;
      const int px = clamp_pixel(s.x, w), py = clamp_pixel(s.y, h);
      const double clearance = r.tile_side * size_at(px, py) / options.beta / 2 + 0.5;
      const double d = field.distance_at(px, py);
      if (d < clearance) {
        const double a = field.angle_at(px, py);
        s.x = std::clamp(s.x + (clearance - d) * std::cos(a), 0.0, double(w - 1));
        s.y = std::clamp(s.y + (clearance - d) * std::sin(a), 0.0, double(h - 1));
      }
    }
    ++r.stats.iterations;
  }
  r.stats.seconds_iterations = seconds_since(t);

  // Tiles: side δ·c·s, oriented by the field under them, coloured from the image.
  t = std::chrono::steady_clock::now();
  r.tiles.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Planar_site& s = sites[i];
    const int px = clamp_pixel(s.x, w), py = clamp_pixel(s.y, h);
    Planar_tile tile;
    tile.x = s.x, tile.y = s.y;
    tile.angle = frame_angle(i);
    const double side = r.tile_side * size_at(px, py);
    tile.width = side / options.beta, tile.height = side * options.beta;
    tile.region = regions ? options.region_labels.at(px, py) : 0;
    orient_by_footprint(tile, options.shape, field, edge_mask, 2 * M_PI / symmetry);
    r.tiles.push_back(tile);
  }
  r.stats.seconds_tiles = seconds_since(t);

  t = std::chrono::steady_clock::now();
  if (options.fitting == Planar_tile_fitting::shrink)
    fit_planar_tiles(r.tiles, edge_mask, options.shape, options.min_fit_scale, r.stats);
  r.stats.seconds_fitting = seconds_since(t);

  t = std::chrono::steady_clock::now();
  for (Planar_tile& tile : r.tiles)
    color_tile(tile, image, options);
  r.stats.seconds_tiles += seconds_since(t);
  r.field = std::move(field);
  return r;
}

} // namespace tessera
