// The implementation of `Surface_mosaic` (tessera/mosaic/surface_mosaic.h): the bodies of its
// member functions and its private types. Internal: the public header holds the types and the
// documented entry points; nothing here is meant to be called directly.
#pragma once

#include <tessera/mosaic/surface_mosaic.h>

#include <tessera/fields/singularities.h>
#include <tessera/internal/parallel.h>
#include <tessera/mosaic/internal/error_diffusion.h>
#include <tessera/mosaic/internal/position_field.h>
#include <tessera/mosaic/internal/segment_box.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <deque>
#include <limits>
#include <random>
#include <unordered_map>

namespace tessera {

// The state of `separate_tiles()`'s passes: each tile's axes, its move (half of each separating
// translation), its crowding (the depths of its overlaps with the gap, over its longer side),
// and how far each of its sides overlaps a neighbour without the gap (+x, −x, +y, −y).
template <typename TriangleMesh, typename NamedParameters>
struct Surface_mosaic<TriangleMesh, NamedParameters>::Separation {
  std::vector<internal::Vec3> xs, ys, move;
  std::vector<double> crowding;
  std::vector<std::array<double, 4>> overlap;
  // Only tiles in a close pair at the last measure, and their neighbours, can be in one now:
  // later passes skip the others' pairs (fandisk at 10k tiles: 0.71 → 0.59 s).
  std::vector<char> active;
  double summed_overlap = 0; // Σ of the pairs' depths without the gap
};

// Two rectangles in i's plane: half sides `a` (axis-aligned, at the origin) and `b` (x axis
// (ax, ay), centre (dx, dy)). By separating axes (both rectangles' axes): the least overlap
// along them (≤ 0 when they are apart), that axis, and half of the translation of the first
// that separates them along it.
template <typename TriangleMesh, typename NamedParameters>
struct Surface_mosaic<TriangleMesh, NamedParameters>::Box_overlap {
  double depth;
  std::array<double, 2> axis, push;
};

// Tile p's half sides and margin (half the grout) at `shrink` times the size there (per axis),
// and a radius that holds every point of the tile's slab (a smaller box missed a border under a
// tile's corner, below its plane, that the quality report saw).
template <typename TriangleMesh, typename NamedParameters>
struct Surface_mosaic<TriangleMesh, NamedParameters>::Extent {
  std::array<double, 2> size;
  double hx, hy, margin, radius;
};

template <typename TriangleMesh, typename NamedParameters>
template <typename VertexFieldMap>
Surface_mosaic<TriangleMesh, NamedParameters>::Surface_mosaic(
    const TriangleMesh& tm, const VertexFieldMap& field,
    const std::vector<Feature_line<halfedge_descriptor>>& features,
    const Surface_mosaic_options& options, const NamedParameters& np)
    : tm_(tm), options_(options), vpm_(internal::vertex_point_map(tm, np)) {
  setup(field, features, np);
}

template <typename TriangleMesh, typename NamedParameters>
std::size_t Surface_mosaic<TriangleMesh, NamedParameters>::iterate(std::size_t k) {
  if (status_ != Mosaic_status::ok)
    return 0;
  const auto t0 = Clock::now();
  std::size_t done = 0;
  for (; done < k && !stats_.converged; ++done) {
    const std::size_t it = stats_.iterations;
    if (options_.teleport_every > 0 && it >= options_.teleport_after &&
        (it - options_.teleport_after) % options_.teleport_every == 0 && it > 0)
      stats_.teleported += teleport();
    if (window_pos_.size() != pos_.size()) {
      window_pos_ = pos_;
      window_iterations_ = 0;
    }
    step();
    ++stats_.iterations;
    const bool may_stop = options_.teleport_every == 0 || it > options_.teleport_after;
    if (stats_.mean_displacement.back() < options_.tolerance && may_stop)
      stats_.converged = true;
    // The tiles' net move over the last `stop_window` iterations: where they only jitter (pushed
    // back and forth by about half a percent of the spacing on organic meshes, two percent beside
    // feature walls), the mean displacement of each iteration levels off at that jitter, and
    // stopped only where it dipped below the tolerance: 77-103 iterations on the bull and the cow,
    // the cap of 150 on fandisk with its creases, for no visible change after some 25.
    if (++window_iterations_ == stop_window) {
      const std::size_t n = pos_.size();
      double net = 0;
      for (std::size_t i = 0; i < n; ++i)
        net += internal::norm(pos_[i] - window_pos_[i]) / size_at(points_[i]);
      net /= double(std::max<std::size_t>(n, 1)) * layout_.spacing * double(stop_window);
      stats_.net_displacement.push_back(net);
      if (net < options_.tolerance && may_stop)
        stats_.converged = true;
      window_pos_ = pos_;
      window_iterations_ = 0;
    }
    if (options_.progress)
      options_.progress({"iterations", stats_.iterations, options_.max_iterations});
  }
  stats_.seconds_optimization += seconds(t0, Clock::now());
  stats_.charts = atlas_->size();
  stats_.failed_charts = atlas_->failed();
  return done;
}

template <typename TriangleMesh, typename NamedParameters>
void Surface_mosaic<TriangleMesh, NamedParameters>::run() {
  if (stats_.iterations < options_.max_iterations)
    iterate(options_.max_iterations - stats_.iterations);
  separate_tiles();
  clear_features();
}

template <typename TriangleMesh, typename NamedParameters>
std::size_t Surface_mosaic<TriangleMesh, NamedParameters>::separate_tiles() {
  if (status_ != Mosaic_status::ok || points_.empty() || options_.separation_passes == 0 ||
      options_.count == Mosaic_count::exact)
    return 0;
  const auto t0 = Clock::now();
  struct Timer {
    Surface_mosaic_stats& stats;
    Clock::time_point t0;
    ~Timer() { stats.seconds_separation += seconds(t0, Clock::now()); }
  } timer{stats_, t0};
  scale_.resize(points_.size(), {{1.0, 1.0}});
  Separation sep;
  spread_tiles(sep);
  // Six rounds: with footprints measured along the surface (thin parts) the crowding could run
  // to twelve at 200k triangles / 40k tiles, 0.5 s more, for coverage within ±0.002 on the ten
  // meshes of doc/mosaic.md. Each round measures only around the tiles it shrank or left out;
  // then one round over every tile gives the pairs elsewhere the passes that each round gave
  // them when it measured every tile (bull, cow and knot2, three seeds each: the same coverage
  // and overlap as then, without it 0.05 % more overlap; 0.7-0.9 s less than then at 40k).
  int rounds = 0;
  while (rounds < 6 && shrink_crowded_tiles(sep) > 0) {
    spread_tiles(sep, false);
    ++rounds;
  }
  if (rounds > 0)
    spread_tiles(sep);
  // One filling: a second and a third added 47 and 18 tiles to 798 at 40k tiles (9 and 9 to 253
  // on the bull at 3000) for 0.7 s each.
  if (fill_bare_patches() > 0)
    spread_tiles(sep);
  // (The trimming measures every tile as the passes left them: the close pairs.)
  stats_.close_pairs = trim_overlapping_tiles(sep);
  stats_.grown_tiles = grow_tiles();
  return stats_.separation_passes;
}

// Bare patches left where tiles were left out (thin parts, fronts out of phase, tiles at odd
// angles): a point of the surface (a few per face, centroids of its faces split k × k) where a
// tile of at least `min_tile_scale` of the size fits between the tiles around it gets one, as
// large as the room there takes, as a mosaicist fills a gap with a smaller tessera; the widest
// first, each measured against the tiles laid before it too. Returns how many were added.
template <typename TriangleMesh, typename NamedParameters>
std::size_t Surface_mosaic<TriangleMesh, NamedParameters>::fill_bare_patches() {
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  internal::Point_search search(pos_);
  const double gap = separation_gap();
  const std::vector<Room_tile> tiles = room_tiles();
  // Candidates: face f split into k × k (k from its longest edge over a quarter of the local
  // spacing, at most 4), the centroids of the parts.
  std::vector<std::uint32_t> first(s.number_of_faces() + 1, 0);
  for (std::uint32_t f = 0; f < s.number_of_faces(); ++f)
    first[f + 1] = first[f] + std::uint32_t(fill_subdivision(f) * fill_subdivision(f));
  std::vector<internal::Surface_point> at(first.back());
  std::vector<double> room(first.back(), 0);
  internal::parallel_blocks(s.number_of_faces(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f) {
      const int k = fill_subdivision(std::uint32_t(f));
      std::uint32_t c = first[f];
      // Most faces lie under one tile, the one nearest to their centroid: no room in them.
      std::size_t nearest = 0;
      search.nearest(s.centroid(std::uint32_t(f)), 1, [&](std::size_t j, double) { nearest = j; });
      const Room_tile& t = tiles[nearest];
      if (under(t, s.point(std::uint32_t(f), 0), std::uint32_t(f), gap) &&
          under(t, s.point(std::uint32_t(f), 1), std::uint32_t(f), gap) &&
          under(t, s.point(std::uint32_t(f), 2), std::uint32_t(f), gap)) {
        std::fill(room.begin() + c, room.begin() + first[f + 1], -1.0);
        continue;
      }
      for (int a = 0; a < k; ++a)
        for (int b = 0; a + b < k; ++b)
          for (int up = 0; up < 2 && a + b + up < k; ++up, ++c) {
            // Sub-triangle (a, b) upright or, when up = 1, the one flipped beside it.
            const double u = (a + (up ? 2.0 : 1.0) / 3) / k, v = (b + (up ? 2.0 : 1.0) / 3) / k;
            at[c] = internal::Surface_point{std::uint32_t(f), {{1 - u - v, u, v}}};
            // Most points lie under the tile nearest to their face or to them: no room there.
            const internal::Vec3 q = s.position(at[c]);
            room[c] = under(t, q, std::uint32_t(f), gap) ? -1.0 : 0.0;
            if (room[c] == 0)
              search.nearest(q, 1, [&](std::size_t j, double) {
                room[c] = too_close(tiles[j], q, std::uint32_t(f), gap) ? -1.0 : 0.0;
              });
          }
    }
  });
  // The others are measured in their faces' charts: those not grown yet are grown first, here
  // (growing one is not safe on several threads).
  std::vector<std::uint32_t> bare;
  for (std::uint32_t f = 0; f < s.number_of_faces(); ++f)
    for (std::uint32_t c = first[f]; c < first[f + 1]; ++c)
      if (room[c] == 0) {
        bare.push_back(f);
        break;
      }
  atlas_->chart_indices_of(bare);
  internal::parallel_blocks(at.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t c = begin; c < end; ++c)
      if (room[c] == 0)
        room[c] = room_at(room_probe(at[c]), search, tiles, internal::no_index);
  });
  std::vector<std::pair<double, std::uint32_t>> order;
  for (std::uint32_t c = 0; c < at.size(); ++c)
    if (room[c] >= options_.min_tile_scale)
      order.push_back({-room[c], c});
  std::sort(order.begin(), order.end());
  // The tiles laid here, in a grid of cells a spacing wide (tiles farther apart cannot touch).
  const double cell = layout_.spacing * largest_size_ *
                      std::max(std::sqrt(layout_.aspect), 1 / std::sqrt(layout_.aspect));
  std::unordered_map<std::int64_t, std::vector<std::uint32_t>> grid;
  auto key = [&](const internal::Vec3& q, int dx, int dy, int dz) {
    const auto c = [&](int axis, int d) {
      return (std::int64_t(std::floor(q[axis] / cell)) + d) & 0x1fffff;
    };
    return (c(0, dx) << 42) | (c(1, dy) << 21) | c(2, dz);
  };
  std::size_t added = 0;
  std::vector<Room_tile> laid;
  laid.reserve(order.size());
  for (const auto& o : order) {
    const internal::Surface_point& p = at[o.second];
    const Room_probe probe = room_probe(p);
    const internal::Vec3& q = probe.q;
    double r = -o.first;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = grid.find(key(q, dx, dy, dz));
          if (it != grid.end())
            for (const std::uint32_t t : it->second)
              r = std::min(r, room_against(probe, laid[t], gap));
        }
    if (r < options_.min_tile_scale)
      continue;
    laid.push_back({p,
                    q,
                    probe.x,
                    probe.y,
                    probe.normal,
                    {{0.5 * (layout_.tile_size[0] * probe.h * r + gap),
                      0.5 * (layout_.tile_size[1] * probe.h * r + gap)}},
                    probe.region});
    grid[key(q, 0, 0, 0)].push_back(std::uint32_t(laid.size() - 1));
    points_.push_back(p);
    pos_.push_back(q);
    chart_.push_back(atlas_->chart_index_of(p.face));
    scale_.push_back({{r, r}});
    ++added;
  }
  if (added > 0)
    forget_neighbors();
  stats_.filled_patches += added;
  return added;
}

// Tiles shrunk or trimmed more than their neighbours now need (the room around them changed
// as tiles moved, were left out or filled in) grow back, up to the room there, one at a time so
// that two neighbours never grow into the same room. Returns how many grew.
template <typename TriangleMesh, typename NamedParameters>
std::size_t Surface_mosaic<TriangleMesh, NamedParameters>::grow_tiles() {
  const std::size_t n = points_.size();
  if (scale_.size() != n)
    return 0;
  internal::Point_search search(pos_);
  const double gap = separation_gap();
  std::vector<Room_tile> tiles = room_tiles();
  std::size_t grown = 0;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (!(std::min(scale_[i][0], scale_[i][1]) < 1))
      continue;
    // Each side on its own, the shorter first (trimming shortens a tile along one axis; a tile
    // shrunk or filled in smaller is short along both).
    Room_probe probe = room_probe(points_[i]);
    bool changed = false;
    const int first = scale_[i][0] <= scale_[i][1] ? 0 : 1;
    for (int axis : {first, 1 - first}) {
      if (!(scale_[i][axis] < 1))
        continue;
      probe.base = scale_[i];
      probe.base[axis] = 0;
      probe.dir = {{0, 0}};
      probe.dir[axis] = 1;
      const double r = room_at(probe, search, tiles, i); // (at most 1)
      if (!(r > scale_[i][axis] + 1e-3))
        continue;
      scale_[i][axis] = r;
      changed = true;
    }
    if (!changed)
      continue;
    tiles[i].half = {{half_side(i, 0, gap), half_side(i, 1, gap)}};
    ++grown;
  }
  return grown;
}

// Every tile as `room_at()` measures room against it.
template <typename TriangleMesh, typename NamedParameters>
std::vector<typename Surface_mosaic<TriangleMesh, NamedParameters>::Room_tile>
Surface_mosaic<TriangleMesh, NamedParameters>::room_tiles() const {
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  const double gap = separation_gap();
  std::vector<Room_tile> tiles(points_.size());
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const internal::Vec3 x = tile_x_axis(points_[i]), normal = s.normal(points_[i].face);
    tiles[i] = {points_[i],
                pos_[i],
                x,
                internal::cross(normal, x),
                normal,
                {{half_side(i, 0, gap), half_side(i, 1, gap)}},
                s.region(points_[i].face)};
  }
  return tiles;
}

// Whether q, a point of face f, lies under tile t (inside its rectangle less half the gap, near
// its plane, on its side of the surface and in its region).
template <typename TriangleMesh, typename NamedParameters>
bool Surface_mosaic<TriangleMesh, NamedParameters>::under(const Room_tile& t,
                                                          const internal::Vec3& q, std::uint32_t f,
                                                          double gap) const {
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  if (t.region != s.region(f) || internal::dot(t.normal, s.normal(f)) <= 0)
    return false;
  const internal::Vec3 d = q - t.centre;
  const double hx = t.half[0] - 0.5 * gap, hy = t.half[1] - 0.5 * gap;
  return std::abs(internal::dot(d, t.x)) <= hx && std::abs(internal::dot(d, t.y)) <= hy &&
         std::abs(internal::dot(d, t.normal)) <= std::min(hx, hy);
}

// Whether q, a point of face f, is too close to tile t for a tile of `min_tile_scale` there: the
// circle inscribed in such a tile (any turn) would reach t's rectangle and gap. (Distances along a
// curved surface exceed the chord: a quarter's margin.)
template <typename TriangleMesh, typename NamedParameters>
bool Surface_mosaic<TriangleMesh, NamedParameters>::too_close(const Room_tile& t,
                                                              const internal::Vec3& q,
                                                              std::uint32_t f, double gap) const {
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  if (t.region != s.region(f) || internal::dot(t.normal, s.normal(f)) <= 0)
    return false;
  const internal::Vec3 d = q - t.centre;
  const double dx = std::max(0.0, std::abs(internal::dot(d, t.x)) - t.half[0]),
               dy = std::max(0.0, std::abs(internal::dot(d, t.y)) - t.half[1]);
  const double inscribed = 0.5 * options_.min_tile_scale * face_size(f) *
                           std::min(layout_.tile_size[0], layout_.tile_size[1]);
  return 1.25 * (std::hypot(dx, dy) - 0.5 * gap) < inscribed;
}

// How many parts along each edge `fill_bare_patches()` splits face f into.
template <typename TriangleMesh, typename NamedParameters>
int Surface_mosaic<TriangleMesh, NamedParameters>::fill_subdivision(std::uint32_t f) const {
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  double longest = 0;
  for (int k = 0; k < 3; ++k)
    longest = std::max(longest, internal::norm(s.point(f, (k + 1) % 3) - s.point(f, k)));
  const double step = 0.25 * layout_.spacing * face_size(f);
  return int(std::clamp(std::ceil(longest / step), 1.0, 4.0));
}

// What `room_against()` needs of a tile about to be laid at p: its point, frame, size, region
// and where it lies in its face's chart.
template <typename TriangleMesh, typename NamedParameters>
typename Surface_mosaic<TriangleMesh, NamedParameters>::Room_probe
Surface_mosaic<TriangleMesh, NamedParameters>::room_probe(const internal::Surface_point& p) const {
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  Room_probe r;
  r.at = p;
  r.q = s.position(p);
  r.normal = s.normal(p.face);
  r.x = tile_x_axis(p);
  r.y = internal::cross(r.normal, r.x);
  r.h = size_at(p);
  r.region = s.region(p.face);
  r.chart = &atlas_->chart(atlas_->chart_index_of(p.face));
  r.slot = r.chart->slot(p.face);
  if (r.slot != internal::no_index)
    r.uv = r.chart->uv_at(r.slot, p.bary);
  return r;
}

// The largest scale (at most 1; s of `room_against()` when p grows a tile) of a tile laid at `p`
// (turned along the field there) that keeps the gap to the tiles of `tiles` near it (the 12 nearest
// centres in `search`, but `skip`) on the same side of the surface and in its region; negative when
// p is under a tile.
template <typename TriangleMesh, typename NamedParameters>
double Surface_mosaic<TriangleMesh, NamedParameters>::room_at(const Room_probe& p,
                                                              const internal::Point_search& search,
                                                              const std::vector<Room_tile>& tiles,
                                                              std::uint32_t skip) const {
  const double gap = separation_gap();
  double r = 1;
  search.nearest(p.q, 12, [&](std::size_t j, double) {
    if (j != skip)
      r = std::min(r, room_against(p, tiles[j], gap));
  });
  return r;
}

// The largest s for which a tile laid at `p` with scales p.base + s · p.dir (s itself for a new
// tile) keeps the gap to tile t: by separating axes, the s at which the two rectangles just touch
// along the axis that separates them best, their distance taken along the surface (in p's chart)
// and their footprints stretched where it curves, as `measure_tile()` does; a tile turned more than
// 90° from p (around a part thinner than a tile) foreshortened as `measure_tile()` sees it.
// Infinite for a tile more than 120° away (the other side of the surface) or in another region,
// or one that an axis the growth does not move along already separates.
template <typename TriangleMesh, typename NamedParameters>
double Surface_mosaic<TriangleMesh, NamedParameters>::room_against(const Room_probe& p,
                                                                   const Room_tile& t,
                                                                   double gap) const {
  const double far = std::numeric_limits<double>::infinity();
  const double facing = internal::dot(t.normal, p.normal);
  if (t.region != p.region || facing <= -0.5)
    return far;
  const internal::Vec3 d = t.centre - p.q;
  double dx = internal::dot(d, p.x), dy = internal::dot(d, p.y);
  const double reach = 2 * layout_.spacing * largest_size_ *
                       std::max(std::sqrt(layout_.aspect), 1 / std::sqrt(layout_.aspect));
  if (std::abs(internal::dot(d, p.normal)) > reach)
    return far;
  double ax = internal::dot(t.x, p.x), ay = internal::dot(t.x, p.y);
  const double al = std::sqrt(ax * ax + ay * ay);
  if (!(al > 1e-9))
    return far;
  ax /= al, ay /= al;
  std::array<double, 2> half = t.half;
  if (facing <= 0) {
    // Past 90° (around a part thinner than a tile), t's rectangle as p's plane sees it, each side
    // foreshortened by its axis's projection, as `measure_tile()` measures such pairs.
    half[0] *= al;
    half[1] *= std::hypot(internal::dot(t.y, p.x), internal::dot(t.y, p.y));
  }
  double k = 1;
  const double seen = std::sqrt(dx * dx + dy * dy);
  const std::uint32_t st =
      p.slot == internal::no_index ? internal::no_index : p.chart->slot(t.at.face);
  if (seen > 0 && st != internal::no_index) {
    const auto b = p.chart->uv_at(st, t.at.bary);
    const double along = std::hypot(p.uv[0] - b[0], p.uv[1] - b[1]);
    if (along > seen) {
      const double w = 0.5 * p.h *
                       (layout_.tile_size[0] * std::abs(dx) + layout_.tile_size[1] * std::abs(dy)) /
                       seen;
      k = footprint_stretch(seen / along, along, w);
      dx *= along / seen, dy *= along / seen;
    }
  }
  const std::array<std::array<double, 2>, 4> axes{{{{1, 0}}, {{0, 1}}, {{ax, ay}}, {{-ay, ax}}}};
  double best = -far;
  for (const auto& u : axes) {
    const double rt =
        half[0] * std::abs(u[0] * ax + u[1] * ay) + half[1] * std::abs(u[1] * ax - u[0] * ay);
    const double along = std::abs(u[0] * dx + u[1] * dy);
    // The tile's half extent along u at scales base + s · dir: fixed + s · unit.
    const double ex = 0.5 * p.h * layout_.tile_size[0] * std::abs(u[0]),
                 ey = 0.5 * p.h * layout_.tile_size[1] * std::abs(u[1]);
    const double unit = ex * p.dir[0] + ey * p.dir[1], fixed = ex * p.base[0] + ey * p.base[1];
    const double margin = 0.5 * gap * (std::abs(u[0]) + std::abs(u[1]));
    const double room = along / k - rt - margin - fixed;
    if (unit > 1e-12 * p.h)
      best = std::max(best, room / unit);
    else if (room >= 0) // an axis the growth does not move along separates them
      return far;
  }
  return best;
}

template <typename TriangleMesh, typename NamedParameters>
std::size_t Surface_mosaic<TriangleMesh, NamedParameters>::clear_features() {
  if (status_ != Mosaic_status::ok || !features_)
    return 0;
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  std::vector<char> keep(points_.size(), 1);
  std::size_t changed = 0;
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const internal::Surface_point p = points_[i];
    const std::array<double, 2> shrink =
        i < scale_.size() ? scale_[i] : std::array<double, 2>{{1.0, 1.0}};
    const std::array<double, 4> need = needed_moves(p, shrink);
    const double radius = extent_at(p, shrink).radius;
    if (std::all_of(need.begin(), need.end(), [](double t) { return t <= 0; }))
      continue;
    ++changed;
    std::array<int, 4> order{{0, 1, 2, 3}};
    std::sort(order.begin(), order.end(), [&](int a, int b) { return need[a] < need[b]; });
    const internal::Vec3 x = tile_x_axis(p);
    const internal::Vec3 y = internal::cross(s.normal(p.face), x);
    bool cleared = false;
    for (const int k : order) {
      if (!(need[k] > 0) || need[k] > 2 * radius)
        continue;
      const internal::Vec3 axis = (k < 2 ? x : y);
      const internal::Surface_point q = s.walk(p, ((k % 2 == 0 ? 1.0 : -1.0) * need[k]) * axis).p;
      const std::array<double, 4> left = needed_moves(q, shrink);
      if (std::all_of(left.begin(), left.end(), [](double t) { return t <= 0; })) {
        points_[i] = q;
        pos_[i] = s.position(q);
        chart_[i] = atlas_->chart_index_of(q.face);
        cleared = true;
        break;
      }
    }
    if (cleared)
      ++stats_.moved_off_features;
    else
      keep[i] = 0, ++stats_.removed_at_features;
  }
  if (stats_.removed_at_features > 0)
    remove_tiles(keep);
  return changed;
}

// Tile p's extent at `shrink` times the size there (see `Extent`).
template <typename TriangleMesh, typename NamedParameters>
typename Surface_mosaic<TriangleMesh, NamedParameters>::Extent
Surface_mosaic<TriangleMesh, NamedParameters>::extent_at(
    const internal::Surface_point& p, const std::array<double, 2>& shrink) const {
  const double h = size_at(p);
  Extent e;
  e.size = {{layout_.tile_size[0] * h * shrink[0], layout_.tile_size[1] * h * shrink[1]}};
  e.hx = 0.5 * e.size[0], e.hy = 0.5 * e.size[1];
  e.margin = 0.5 * (layout_.spacing * std::sqrt(layout_.aspect) - layout_.tile_size[0]) * h;
  e.radius = internal::tile_reach(e.size) + e.margin;
  return e;
}

// The in-plane extent of the segments crossing tile p's rectangle: how far the tile must move
// along +x, −x, +y, −y to clear them all by the margin (0 when none crosses).
template <typename TriangleMesh, typename NamedParameters>
std::array<double, 4> Surface_mosaic<TriangleMesh, NamedParameters>::needed_moves(
    const internal::Surface_point& p, const std::array<double, 2>& shrink) const {
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  const Extent ext = extent_at(p, shrink);
  const double hx = ext.hx, hy = ext.hy, margin = ext.margin;
  std::array<double, 4> need{{0, 0, 0, 0}};
  const internal::Vec3 at = s.position(p), n = s.normal(p.face), x = tile_x_axis(p);
  const internal::Vec3 y = internal::cross(n, x);
  features_->segments_near(
      s.region(p.face), at, ext.radius, [&](const internal::Vec3& a3, const internal::Vec3& b3) {
        std::array<double, 2> a, b;
        if (!internal::segment_crosses_tile(a3 - at, b3 - at, x, y, n, ext.size, a, b))
          return;
        // The part of the segment inside the band |y| ≤ hy + margin bounds the move along x,
        // and the part inside |x| ≤ hx + margin the move along y.
        for (int axis = 0; axis < 2; ++axis) {
          const int other = 1 - axis;
          const double half = axis == 0 ? hx : hy, band = (axis == 0 ? hy : hx) + margin;
          double t0 = 0, t1 = 1;
          const double d = b[other] - a[other];
          if (d == 0) {
            if (std::abs(a[other]) > band)
              continue;
          } else {
            double u0 = (-band - a[other]) / d, u1 = (band - a[other]) / d;
            if (u0 > u1)
              std::swap(u0, u1);
            t0 = std::max(t0, u0), t1 = std::min(t1, u1);
            if (t0 > t1)
              continue;
          }
          const double c0 = a[axis] + t0 * (b[axis] - a[axis]),
                       c1 = a[axis] + t1 * (b[axis] - a[axis]);
          const double lo = std::min(c0, c1), hi = std::max(c0, c1);
          need[2 * axis] = std::max(need[2 * axis], hi + half + margin);         // along +axis
          need[2 * axis + 1] = std::max(need[2 * axis + 1], half + margin - lo); // along −axis
        }
      });
  return need;
}

template <typename TriangleMesh, typename NamedParameters>
std::size_t Surface_mosaic<TriangleMesh, NamedParameters>::teleport() {
  if (status_ != Mosaic_status::ok || points_.empty())
    return 0;
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  refresh_neighbors(true);
  const std::vector<std::uint32_t> hole_faces = largest_holes(knn_, 0.85, points_.size());
  // Tiles of the closest pairs: cells overlapping by more than a quarter of their side.
  std::vector<std::pair<double, std::uint32_t>> crowded;
  for (std::uint32_t i = 0; i < points_.size(); ++i)
    if (nearest_.size() == points_.size() &&
        nearest_[i] < manhattan_distance(0.75 * layout_.spacing, 0))
      crowded.push_back({nearest_[i], i});
  std::sort(crowded.begin(), crowded.end());
  std::vector<char> taken(points_.size(), 0);
  std::size_t moved = 0;
  for (const auto& c : crowded) {
    if (moved == hole_faces.size())
      break;
    const std::uint32_t i = c.second;
    if (taken[i] || taken[nearest_index_[i]])
      continue;
    taken[i] = taken[nearest_index_[i]] = 1;
    const std::uint32_t f = hole_faces[moved++];
    points_[i] = internal::Surface_point{f, {{1.0 / 3, 1.0 / 3, 1.0 / 3}}};
    pos_[i] = s.position(points_[i]);
    chart_[i] = atlas_->chart_index_of(f);
    if (gain_.size() == points_.size()) {
      gain_[i] = 1;
      last_move_[i] = internal::Vec3{{0, 0, 0}};
    }
  }
  if (moved > 0)
    refresh_neighbors(true);
  return moved;
}

template <typename TriangleMesh, typename NamedParameters>
std::vector<typename Surface_mosaic<TriangleMesh, NamedParameters>::Tile>
Surface_mosaic<TriangleMesh, NamedParameters>::tiles() const {
  std::vector<Tile> out;
  if (status_ != Mosaic_status::ok)
    return out;
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  out.reserve(points_.size());
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const internal::Surface_point& p = points_[i];
    Tile t;
    // A tile is glued flat onto the face its centre lies in.
    t.center = pos_[i];
    t.normal = s.normal(p.face);
    t.x_axis = tile_x_axis(p);
    t.size = {{layout_.tile_size[0] * tile_scale(i, 0), layout_.tile_size[1] * tile_scale(i, 1)}};
    t.face = s.face_of(p.face);
    // Internally corner k is the source of the k-th halfedge from halfedge(face); the tile's
    // coordinates follow vertices_around_face(halfedge(face)), which starts at its target
    // (found by the property sweep: the documented order gave points off the centre).
    t.barycentric = {{p.bary[1], p.bary[2], p.bary[0]}};
    t.region = s.region(p.face);
    t.color = distinct_color(t.region);
    out.push_back(t);
  }
  return out;
}

template <typename TriangleMesh, typename NamedParameters>
typename Surface_mosaic<TriangleMesh, NamedParameters>::Result
Surface_mosaic<TriangleMesh, NamedParameters>::result() const {
  Result r;
  r.status = status_;
  r.message = message_;
  r.layout = layout_;
  r.stats = stats_;
  r.tiles = tiles();
  return r;
}

template <typename TriangleMesh, typename NamedParameters>
template <typename VertexFieldMap>
void Surface_mosaic<TriangleMesh, NamedParameters>::setup(
    const VertexFieldMap& field, const std::vector<Feature_line<halfedge_descriptor>>& features,
    const NamedParameters& np) {
  const TriangleMesh& tm = tm_;
  const Surface_mosaic_options& options = options_;
  const auto t0 = Clock::now();
  if (faces(tm).empty())
    return fail(Mosaic_status::empty_mesh, "the mesh has no faces");
  if (!CGAL::is_triangle_mesh(tm))
    return fail(Mosaic_status::not_triangle_mesh, "the mesh is not a triangle mesh");
  symmetry_ = options.symmetry != 0 ? options.symmetry : mosaic_field_symmetry(options.tiles);
  if (symmetry_ != 2 && symmetry_ != 4)
    return fail(Mosaic_status::invalid_options, "the symmetry must be 2 or 4");
  const bool paper = options.energy == Mosaic_energy::gaussian_manhattan;
  const double chart_radius = options.chart_radius > 0 ? options.chart_radius : paper ? 5 : 3;
  const double core_radius = options.chart_core_radius > 0 ? options.chart_core_radius
                             : paper                       ? 2
                                                           : 1.2;
  if (options.neighbors < 1 || !(options.step > 0) || !(options.max_step > 0) ||
      options.chart_radius < 0 || options.chart_core_radius < 0 || core_radius >= chart_radius)
    return fail(Mosaic_status::invalid_options, "neighbors, step, max_step and the chart radii "
                                                "must be positive, the core inside the chart");
  for (auto v : vertices(tm)) {
    const internal::Vec3 x = internal::to_vec3(get(field, v));
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
      return fail(Mosaic_status::invalid_field, "the field has a non-finite vector");
  }
  surface_ = std::make_unique<internal::Surface_arrays<TriangleMesh>>(tm, vpm_, features);
  double area = surface_->total_area();
  if constexpr (!CGAL::parameters::is_default_parameter<NamedParameters,
                                                        CGAL::internal_np::scalar_t>::value) {
    const auto size_map = CGAL::parameters::get_parameter(np, CGAL::internal_np::scalar_map);
    const internal::Surface_arrays<TriangleMesh>& s = *surface_;
    vertex_size_.resize(s.number_of_vertices());
    for (std::uint32_t v = 0; v < s.number_of_vertices(); ++v) {
      vertex_size_[v] = double(get(size_map, s.vertex_of(v)));
      if (!std::isfinite(vertex_size_[v]) || !(vertex_size_[v] > 0))
        return fail(Mosaic_status::invalid_options,
                    "the tile size field must be positive and finite (vertex " + std::to_string(v) +
                        ")");
    }
    if (options.initialization == Mosaic_initialization::position_field)
      return fail(Mosaic_status::invalid_options,
                  "the position-field start does not take a tile size field");
    // The layout's spacing is that of size 1: N tiles of the local sizes cover the surface.
    area = 0;
    for (std::uint32_t f = 0; f < s.number_of_faces(); ++f)
      area += s.area(f) / std::pow(face_size(f), 2);
    largest_size_ = *std::max_element(vertex_size_.begin(), vertex_size_.end());
  }
  if (auto why = mosaic_layout(options.tiles, area, layout_))
    return fail(Mosaic_status::invalid_options, *why);
  if (layout_.aspect != 1 && symmetry_ == 4)
    return fail(Mosaic_status::invalid_options,
                "rectangular tiles need a 2-symmetric (line) field");
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  face_field_ = std::make_unique<internal::Face_field<TriangleMesh>>(s, field, symmetry_);
  vertex_field_.resize(s.number_of_vertices());
  for (std::uint32_t v = 0; v < s.number_of_vertices(); ++v)
    vertex_field_[v] = internal::to_vec3(get(field, s.vertex_of(v)));
  Manhattan_chart_options co;
  // Charts hold the neighbours of the largest tiles (the pull of smaller ones ends sooner).
  co.radius = chart_radius * layout_.sigma * largest_size_;
  co.core_radius = core_radius * layout_.sigma * largest_size_;
  co.max_rotation = options.max_chart_rotation;
  // A third of the chart radius: a band around a part thinner than the chart meets itself a
  // girth apart, at least a spacing; curvature moves a corner far less (see the option).
  co.seam_tolerance = co.radius / 3;
  atlas_ = std::make_unique<Manhattan_chart_atlas<TriangleMesh>>(s, *face_field_, co);
  reach_ =
      options.feature_reach * std::max(layout_.tile_size[0], layout_.tile_size[1]) * largest_size_;
  if (options.feature_repulsion && !features.empty())
    features_ = std::make_unique<internal::Feature_segments<TriangleMesh>>(s, features, reach_);
  if (options.singularity_tiles) {
    const auto sing = field_singularities(tm, field, symmetry_);
    for (const auto& sg : sing.singularities) {
      const std::uint32_t f = s.id(sg.face);
      virtual_pos_.push_back(s.centroid(f));
      virtual_region_.push_back(s.region(f));
    }
  }
  stats_.regions = s.number_of_regions();
  stats_.virtual_tiles = virtual_pos_.size();
  const auto t1 = Clock::now();
  stats_.seconds_setup = seconds(t0, t1);
  if (options.initialization == Mosaic_initialization::position_field)
    points_ = fit_count(position_field_points());
  else if (options.initialization == Mosaic_initialization::lattice)
    points_ = lattice_points();
  else {
    // With a size field, the density goes as 1 / size².
    std::vector<double> weight;
    for (std::uint32_t f = 0; f < s.number_of_faces() && !vertex_size_.empty(); ++f)
      weight.push_back(1 / std::pow(face_size(f), 2));
    points_ = internal::error_diffusion_points(s, layout_.tile_count, options.seed, weight);
  }
  // Tiles in Hilbert order (CGAL's median policy, deterministic): each tile's neighbours then
  // lie close in memory, and so do the charts they are looked up in. The forces and the
  // separation read a neighbour's face, barycentric coordinates and chart coordinates per pair,
  // and in the start's order (rows grown breadth first) those were cache misses.
  {
    std::vector<CGAL::Epick::Point_3> at;
    at.reserve(points_.size());
    for (const internal::Surface_point& p : points_) {
      const internal::Vec3 q = s.position(p);
      at.emplace_back(q[0], q[1], q[2]);
    }
    std::vector<std::size_t> order(points_.size());
    for (std::size_t i = 0; i < order.size(); ++i)
      order[i] = i;
    using Point_map = CGAL::Pointer_property_map<CGAL::Epick::Point_3>::type;
    CGAL::hilbert_sort(
        order.begin(), order.end(),
        CGAL::Spatial_sort_traits_adapter_3<CGAL::Epick, Point_map>(CGAL::make_property_map(at)),
        CGAL::Hilbert_sort_median_policy());
    std::vector<internal::Surface_point> sorted;
    sorted.reserve(points_.size());
    pos_.reserve(points_.size());
    for (std::size_t i : order) {
      sorted.push_back(points_[i]);
      pos_.push_back({{at[i].x(), at[i].y(), at[i].z()}});
    }
    points_.swap(sorted);
  }
  std::vector<std::uint32_t> start_faces;
  for (const internal::Surface_point& p : points_)
    start_faces.push_back(p.face);
  chart_ = atlas_->chart_indices_of(start_faces);
  stats_.seconds_initialization = seconds(t1, Clock::now());
  stats_.charts = atlas_->size();
}

// Holes: face centroids farther than `min_spacings` × the local spacing from every point of
// `search`, the widest first (in local spacings), each more than a local spacing from the holes
// before it; at most `limit` of them.
template <typename TriangleMesh, typename NamedParameters>
std::vector<std::uint32_t> Surface_mosaic<TriangleMesh, NamedParameters>::largest_holes(
    const internal::Point_search& search, double min_spacings, std::size_t limit) const {
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  auto spacing_at = [&](std::uint32_t f) { return layout_.spacing * face_size(f); };
  // Each face's distance to the nearest point, on every core (a query per face: at 200k faces
  // the lattice start's hole rounds took most of its time on one).
  std::vector<double> nearest(s.number_of_faces(), std::numeric_limits<double>::infinity());
  internal::parallel_blocks(s.number_of_faces(), [&](std::size_t first, std::size_t last) {
    for (std::size_t f = first; f < last; ++f)
      search.nearest(s.centroid(std::uint32_t(f)), 1,
                     [&](std::size_t, double d2) { nearest[f] = std::sqrt(d2); });
  });
  std::vector<std::pair<double, std::uint32_t>> holes;
  for (std::uint32_t f = 0; f < s.number_of_faces(); ++f) {
    const double local = spacing_at(f);
    if (nearest[f] > min_spacings * local)
      holes.push_back({-nearest[f] / local, f});
  }
  return widest_apart(std::move(holes), limit);
}

// The faces of `holes` ((−width, face) pairs), the widest first, each more than a local spacing
// from those before it; at most `limit` of them.
template <typename TriangleMesh, typename NamedParameters>
std::vector<std::uint32_t> Surface_mosaic<TriangleMesh, NamedParameters>::widest_apart(
    std::vector<std::pair<double, std::uint32_t>> holes, std::size_t limit) const {
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  std::sort(holes.begin(), holes.end());
  std::vector<internal::Vec3> chosen;
  std::vector<std::uint32_t> faces;
  for (const auto& h : holes) {
    if (faces.size() == limit)
      break;
    const internal::Vec3 c = s.centroid(h.second);
    const double local = layout_.spacing * face_size(h.second);
    bool apart = true;
    for (const auto& o : chosen)
      apart = apart && internal::norm(o - c) > local;
    if (!apart)
      continue;
    chosen.push_back(c);
    faces.push_back(h.second);
  }
  return faces;
}

// Lattice initialization: from a seed in each region (the face closest to the region's area
// centroid), tiles are laid breadth first one cell apart along the field's two directions (a
// step walked along the surface, `Surface_arrays::walk`), skipping a place closer than 0.75 cell
// to a tile already laid (in that tile's frame) or where the walk met a border or feature line
// more than a twelfth of a cell short (the step left the region). Where the fronts of the growth
// meet, the lattices' phases differ: tiles closer than a cell or gaps. Beyond N, the most crowded
// tiles go; below N, tiles are added at the largest holes (only holes a cell wide with
// `Mosaic_count::at_most`). Lai et al. start from random points (§3.2), from which the
// repulsion settles into grains of rows squeezed along one axis (on the "eight", half the tiles
// had their nearest neighbour at 0.93 of a tile side or closer, where the grid puts it at 1.05),
// and rows are not created or removed by the repulsion; a lattice start leaves defects only
// where fronts meet.
template <typename TriangleMesh, typename NamedParameters>
std::vector<internal::Surface_point>
Surface_mosaic<TriangleMesh, NamedParameters>::lattice_points() {
  // A lattice that holds fewer than N tiles (its rows diverge over curved parts, its fronts meet
  // out of phase) is grown again with rows closer together (by the square root of the
  // shortfall), so the grout narrows evenly instead of the missing tiles crowding into holes
  // (exactly N) or their area staying bare (about N); never closer than a tile side, where tiles
  // would touch. With the default count the lattice aims at 2 % over N: the separation leaves
  // out more crowded tiles than it adds in bare patches (net 1.6 % of the lattice, median of the
  // ten meshes of doc/mosaic.md), and coverage follows the count. (Exactly N, on the eight:
  // overlap 3.3 % → 2.3 %. About N, on the ten: coverage up 0.003–0.018 where the lattice fell
  // 3–4 % short. Further rounds gave nothing.)
  const double aim = options_.count == Mosaic_count::about ? 1.02 : 1.0;
  std::size_t grown = 0;
  std::vector<internal::Surface_point> points = lattice_points(1, grown);
  if (options_.count != Mosaic_count::at_most && grown < aim * layout_.tile_count) {
    const double scale = std::max(std::sqrt(1 - layout_.grout),
                                  std::sqrt(double(grown) / (aim * double(layout_.tile_count))));
    points = lattice_points(scale, grown);
  }
  return fit_count(std::move(points));
}

template <typename TriangleMesh, typename NamedParameters>
std::vector<internal::Surface_point>
Surface_mosaic<TriangleMesh, NamedParameters>::lattice_points(double scale,
                                                              std::size_t& grown) const {
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  const double root = std::sqrt(layout_.aspect);
  const double step_u = scale * layout_.spacing * root, step_v = scale * layout_.spacing / root;
  // The hash grid's cells hold the reach of the largest tiles.
  const double cell = std::max(step_u, step_v) * largest_size_;
  std::vector<internal::Surface_point> out;
  std::vector<internal::Vec3> where;
  std::vector<double> sizes; // the size field at each laid tile
  std::vector<std::array<internal::Vec3, 2>> frames;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> grid;
  auto key = [&](long x, long y, long z) {
    return (std::uint64_t(x & 0x1fffff) << 42) | (std::uint64_t(y & 0x1fffff) << 21) |
           std::uint64_t(z & 0x1fffff);
  };
  auto cell_of = [&](const internal::Vec3& p) {
    return std::array<long, 3>{{long(std::floor(p[0] / cell)), long(std::floor(p[1] / cell)),
                                long(std::floor(p[2] / cell))}};
  };
  auto frame_at = [&](const internal::Surface_point& p) {
    const internal::Vec3 x = tile_x_axis(p);
    return std::array<internal::Vec3, 2>{{x, internal::cross(s.normal(p.face), x)}};
  };
  // Calls visit(j) for every laid tile j in the 27 grid cells around q that faces the same way
  // as `normal` (not the far side of a thin part).
  auto for_each_near = [&](const internal::Vec3& q, const internal::Vec3& normal, auto&& visit) {
    const auto c = cell_of(q);
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy)
        for (long dz = -1; dz <= 1; ++dz) {
          const auto it = grid.find(key(c[0] + dx, c[1] + dy, c[2] + dz));
          if (it != grid.end())
            for (const std::uint32_t j : it->second)
              if (internal::dot(s.normal(out[j].face), normal) >= 0.5)
                visit(j);
        }
  };
  // (`size`: the size field at q; a place is taken at the larger of its size and tile j's.)
  auto free_at = [&](const internal::Vec3& q, const internal::Vec3& normal, double size) {
    bool free = true;
    for_each_near(q, normal, [&](std::uint32_t j) {
      // Taken when inside 0.75 cell of tile j in its plane and, in space, closer than 0.75 of
      // the longer cell side: on a part a few tiles around, the next tile of a row seen in j's
      // plane is much nearer than it is.
      const internal::Vec3 d = q - where[j];
      const double h = std::max(size, sizes[j]);
      if (std::abs(internal::dot(d, frames[j][0])) < 0.75 * step_u * h &&
          std::abs(internal::dot(d, frames[j][1])) < 0.75 * step_v * h &&
          internal::norm(d) < 0.75 * std::max(step_u, step_v) * h)
        free = false;
    });
    return free;
  };
  auto lay = [&](const internal::Surface_point& p) {
    const internal::Vec3 q = s.position(p);
    const auto c = cell_of(q);
    grid[key(c[0], c[1], c[2])].push_back(std::uint32_t(out.size()));
    out.push_back(p);
    where.push_back(q);
    frames.push_back(frame_at(p));
    sizes.push_back(size_at(p));
  };
  // Seeds: per region, the face closest to its area centroid; with a size field, the closest of
  // those with the smallest size, so that rows grow from small tiles towards larger ones (where
  // `fit_count()` thins them) and never leave gaps narrower than a cell between them.
  std::vector<internal::Vec3> centroid(s.number_of_regions(), internal::Vec3{{0, 0, 0}});
  std::vector<double> area(s.number_of_regions(), 0);
  for (std::uint32_t f = 0; f < s.number_of_faces(); ++f) {
    centroid[s.region(f)] = centroid[s.region(f)] + s.area(f) * s.centroid(f);
    area[s.region(f)] += s.area(f);
  }
  std::vector<std::uint32_t> seed(s.number_of_regions(), internal::no_index);
  std::vector<double> best(s.number_of_regions(), std::numeric_limits<double>::infinity());
  std::vector<double> smallest(best);
  for (std::uint32_t f = 0; f < s.number_of_faces(); ++f) {
    const std::uint32_t r = s.region(f);
    const double d = internal::norm(s.centroid(f) - (1 / area[r]) * centroid[r]);
    const double h = face_size(f);
    if (h < smallest[r] * (1 - 1e-9) || (h <= smallest[r] * (1 + 1e-9) && d < best[r]))
      best[r] = d, seed[r] = f, smallest[r] = std::min(smallest[r], h);
  }
  // The seed of the options places the first tile at a random point of that face, which shifts
  // the region's whole lattice.
  std::mt19937 rng(options_.seed);
  std::uniform_real_distribution<double> unit(0, 1);
  std::deque<std::uint32_t> queue;
  for (std::uint32_t r = 0; r < s.number_of_regions(); ++r)
    if (seed[r] != internal::no_index && area[r] > 0) {
      double a = unit(rng), b = unit(rng);
      if (a + b > 1)
        a = 1 - a, b = 1 - b;
      queue.push_back(std::uint32_t(out.size()));
      lay(internal::Surface_point{seed[r], {{a, b, 1 - a - b}}});
    }
  // The four places a cell away from tile i along its axes (`left`: a step left the region).
  struct Step {
    internal::Surface_point p;
    internal::Vec3 q;
    bool left;
  };
  auto steps_from = [&](std::uint32_t i) {
    const internal::Surface_point from = out[i];
    const std::array<internal::Vec3, 2> fr = frames[i];
    // A cell of the size at the tile it starts from; each quarter below takes the size where it
    // starts, so that a size field's cells add up along the row.
    const double hu = step_u * sizes[i], hv = step_v * sizes[i];
    std::array<Step, 4> result;
    int m = 0;
    for (const auto& d : {hu * fr[0], -hu * fr[0], hv * fr[1], -hv * fr[1]}) {
      // A cell along the surface in four walks, each along the row's direction in the tangent
      // plane of the face reached, so the row follows that direction rather than a geodesic.
      Step& st = result[std::size_t(m++)];
      st.p = from;
      st.q = where[i];
      st.left = false;
      for (int k = 0; k < 4 && !st.left; ++k) {
        const internal::Vec3 n = s.normal(st.p.face);
        const internal::Vec3 t = d - internal::dot(d, n) * n;
        const double l = internal::norm(t);
        if (!(l > 0)) {
          st.left = true;
          break;
        }
        const double quarter = 0.25 * internal::norm(d) * size_at(st.p) / sizes[i];
        const auto walked = s.walk(st.p, (quarter / l) * t);
        st.p = walked.p;
        st.q = s.position(st.p);
        st.left = walked.short_by > std::max(hu, hv) / 12; // left the region
      }
    }
    return result;
  };
  // Breadth first, a wave at a time: the steps from every tile of a wave depend only on that
  // tile, so they are taken on every core (the projections are most of the time: 200k triangles
  // and 40k tiles, 1.7 s on one), then laid in the queue's order, which keeps the result of
  // taking one tile at a time.
  while (!queue.empty()) {
    const std::vector<std::uint32_t> wave(queue.begin(), queue.end());
    queue.clear();
    std::vector<std::array<Step, 4>> steps(wave.size());
    internal::parallel_blocks(
        wave.size(),
        [&](std::size_t first, std::size_t last) {
          for (std::size_t w = first; w < last; ++w)
            steps[w] = steps_from(wave[w]);
        },
        16);
    for (const std::array<Step, 4>& from : steps)
      for (const Step& st : from) {
        if (st.left || !free_at(st.q, s.normal(st.p.face), size_at(st.p)))
          continue;
        queue.push_back(std::uint32_t(out.size()));
        lay(st.p);
      }
  }
  grown = out.size();
  return out;
}

// The tiles of a position field's lattice (`internal::position_field_points`): the field at the
// vertices, the lattice's spacings those of a cell (√η·spacing along the field, spacing/√η
// across), feature lines and open borders as the edges between faces of different regions or of
// none.
template <typename TriangleMesh, typename NamedParameters>
std::vector<internal::Surface_point>
Surface_mosaic<TriangleMesh, NamedParameters>::position_field_points() {
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  internal::Position_field_surface in;
  const std::size_t nv = s.number_of_vertices(), nf = s.number_of_faces();
  in.points.resize(nv);
  in.normals.assign(nv, internal::Vec3{{0, 0, 0}});
  for (std::uint32_t v = 0; v < nv; ++v)
    in.points[v] = s.vertex_point(v);
  in.directions = vertex_field_;
  in.faces.resize(nf);
  in.face_normals.resize(nf);
  in.face_regions.resize(nf);
  for (std::uint32_t f = 0; f < nf; ++f) {
    in.faces[f] = s.corners(f);
    in.face_normals[f] = s.normal(f);
    in.face_regions[f] = s.region(f);
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = s.corners(f)[k];
      in.normals[v] = in.normals[v] + s.area(f) * s.normal(f);
      // Each feature edge once (from the face with the smaller index, or the only one).
      const std::uint32_t g = s.across(f, k);
      if (s.neighbor(f, k) == internal::no_index && (g == internal::no_index || f < g))
        in.feature_edges.push_back({{v, s.corners(f)[(k + 1) % 3]}});
    }
  }
  internal::Position_field_options po;
  po.spacing_x = layout_.spacing * std::sqrt(layout_.aspect);
  po.spacing_y = layout_.spacing / std::sqrt(layout_.aspect);
  po.symmetry = symmetry_;
  po.seed = options_.seed;
  internal::Position_field_stats ps;
  std::vector<internal::Surface_point> out;
  for (const internal::Lattice_point& p : internal::position_field_points(in, po, &ps))
    out.push_back(internal::Surface_point{p.face, s.barycentric(p.face, p.at)});
  stats_.lattice_levels = ps.levels;
  stats_.lattice_points = out.size();
  return out;
}

// The initial tiles brought to the count the options ask for. Beyond N (unless `about`) the most
// crowded tiles go first, one of each close pair (dropping by crowding alone took both, and left
// holes: the cube's overlap was 0.8 % where it is 0.5 %). Then tiles are added at the largest
// holes, a round at a time: face centroids farthest from every tile, a cell apart; with `exact`
// until there are N tiles, otherwise only in holes a cell wide (a centroid farther than 0.85
// spacing from every tile; a regular lattice has none), never beyond N with `at_most`.
template <typename TriangleMesh, typename NamedParameters>
std::vector<internal::Surface_point>
Surface_mosaic<TriangleMesh, NamedParameters>::fit_count(std::vector<internal::Surface_point> out) {
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  const std::size_t count = layout_.tile_count;
  const double root = std::sqrt(layout_.aspect);
  const double step_u = layout_.spacing * root, step_v = layout_.spacing / root;
  internal::Point_search search;
  auto positions = [&] {
    std::vector<internal::Vec3> at;
    for (const auto& p : out)
      at.push_back(s.position(p));
    return at;
  };
  // With a size field, a lattice grown row by row keeps the row spacing of the size where the
  // rows started (grown from size 1.5 into size 2, rows 0.75 cell apart): tiles closer than 0.8
  // of a local cell to another go (one of each pair), and the holes below get tiles again. (With
  // exactly N tiles only the count decides.)
  const bool thin = !vertex_size_.empty() &&
                    options_.initialization == Mosaic_initialization::lattice &&
                    options_.count != Mosaic_count::exact;
  const bool over = options_.count != Mosaic_count::about && out.size() > count;
  if (thin || over) {
    const std::vector<internal::Vec3> at = positions();
    search.reset(at);
    std::vector<std::pair<double, std::uint32_t>> crowding;
    std::vector<std::uint32_t> partner(out.size(), internal::no_index);
    for (std::uint32_t i = 0; i < out.size(); ++i) {
      const internal::Vec3 x = tile_x_axis(out[i]), n = s.normal(out[i].face);
      const internal::Vec3 y = internal::cross(n, x);
      double nearest = std::numeric_limits<double>::infinity();
      search.nearest(at[i], 9, [&](std::size_t j, double) {
        if (j == i || internal::dot(s.normal(out[j].face), n) < 0.5)
          return;
        const internal::Vec3 d = at[j] - at[i];
        const double m = std::max(std::abs(internal::dot(d, x)) / step_u,
                                  std::abs(internal::dot(d, y)) / step_v) /
                         size_at(out[i]);
        if (m < nearest)
          nearest = m, partner[i] = std::uint32_t(j);
      });
      crowding.push_back({nearest, i});
    }
    std::stable_sort(crowding.begin(), crowding.end());
    std::vector<char> drop(out.size(), 0);
    std::size_t extra = thin ? out.size() : out.size() - count;
    for (const auto& c : crowding) {
      const std::uint32_t i = c.second;
      if (extra == 0 || (thin && !(c.first < 0.8)))
        break;
      if (partner[i] != internal::no_index && drop[partner[i]])
        continue;
      drop[i] = 1, --extra;
    }
    std::vector<internal::Surface_point> kept;
    for (std::uint32_t i = 0; i < out.size(); ++i)
      if (!drop[i])
        kept.push_back(out[i]);
    out = std::move(kept);
  }
  const bool exact = options_.count == Mosaic_count::exact;
  const std::size_t most =
      options_.count == Mosaic_count::about ? std::numeric_limits<std::size_t>::max() : count;
  while (out.size() < most) {
    search.reset(positions());
    const std::size_t before = out.size();
    for (const std::uint32_t f : largest_holes(search, exact ? 0 : 0.85, most - out.size()))
      out.push_back(internal::Surface_point{f, {{1.0 / 3, 1.0 / 3, 1.0 / 3}}});
    if (out.size() == before)
      break;
  }
  return out;
}

// Keeps the tiles i with keep[i]; the neighbour lists are renumbered (or, when there are none
// yet, built on their next use).
template <typename TriangleMesh, typename NamedParameters>
void Surface_mosaic<TriangleMesh, NamedParameters>::remove_tiles(const std::vector<char>& keep) {
  const std::size_t n = points_.size(), nk = options_.neighbors;
  // The neighbour lists stay, renumbered, with the left-out tiles taken out (the separation
  // leaves out a few tiles a round; querying every list again took 0.05 s a round at 40k tiles).
  // Each list then holds its k nearest less those left out, padded at the end; the next refresh
  // queries again the lists of tiles that moved, as it does for any list.
  const bool lists = neighbors_.size() == n * nk && built_pos_.size() == n;
  std::vector<std::uint32_t> index(n + virtual_pos_.size(), internal::no_index);
  std::size_t k = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (keep[i]) {
      index[i] = std::uint32_t(k);
      points_[k] = points_[i], pos_[k] = pos_[i], chart_[k] = chart_[i];
      if (!scale_.empty())
        scale_[k] = scale_[i];
      if (lists)
        built_pos_[k] = built_pos_[i];
      ++k;
    }
  for (std::size_t v = 0; v < virtual_pos_.size(); ++v) // virtual tiles follow the tiles
    index[n + v] = std::uint32_t(k + v);
  if (lists) {
    std::size_t row = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (!keep[i])
        continue;
      std::size_t m = 0;
      for (std::size_t e = 0; e < nk; ++e) {
        const std::uint32_t j = neighbors_[i * nk + e];
        if (j == internal::no_index)
          break;
        if (index[j] != internal::no_index)
          neighbors_[row * nk + m++] = index[j];
      }
      for (; m < nk; ++m)
        neighbors_[row * nk + m] = internal::no_index;
      ++row;
    }
    neighbors_.resize(k * nk), built_pos_.resize(k);
  }
  points_.resize(k), pos_.resize(k), chart_.resize(k);
  if (!scale_.empty())
    scale_.resize(k);
  if (lists)
    forget_tile_state();
  else
    forget_neighbors();
}

// After tiles were added or removed: the per-tile state of the optimization and the neighbour
// lists no longer match the tiles; they are rebuilt on their next use.
template <typename TriangleMesh, typename NamedParameters>
void Surface_mosaic<TriangleMesh, NamedParameters>::forget_neighbors() {
  forget_tile_state();
  built_pos_.clear(), neighbors_.clear();
  knn_.reset({});
}

// The optimization's per-tile state (steps, gains, nearest neighbours), rebuilt on its next use.
template <typename TriangleMesh, typename NamedParameters>
void Surface_mosaic<TriangleMesh, NamedParameters>::forget_tile_state() {
  last_move_.clear(), gain_.clear(), nearest_.clear(), nearest_index_.clear();
}

// The least gap between two tiles' rectangles (`min_tile_gap` × the grout width).
template <typename TriangleMesh, typename NamedParameters>
double Surface_mosaic<TriangleMesh, NamedParameters>::separation_gap() const {
  const double grout = layout_.spacing * std::sqrt(layout_.aspect) - layout_.tile_size[0];
  return std::max(0.0, options_.min_tile_gap * grout);
}

// Tile i's half side along `axis` with half the gap: a shrunk or trimmed tile keeps the whole
// gap.
template <typename TriangleMesh, typename NamedParameters>
double Surface_mosaic<TriangleMesh, NamedParameters>::half_side(std::size_t i, int axis,
                                                                double gap) const {
  return 0.5 * (layout_.tile_size[axis] * tile_scale(i, axis) + gap);
}

// Measures every active tile against its neighbours (see `Separation`); returns the pairs
// closer than the gap.
template <typename TriangleMesh, typename NamedParameters>
std::size_t Surface_mosaic<TriangleMesh, NamedParameters>::measure_crowding(Separation& sep) {
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  const std::size_t n = points_.size(), k = options_.neighbors;
  const double gap = separation_gap();
  const double ex = 0.5 * (layout_.tile_size[0] + gap), ey = 0.5 * (layout_.tile_size[1] + gap);
  const double reach = 2 * std::hypot(ex, ey), side = std::max(ex, ey);
  // Lists rebuilt only when tiles have moved far enough: the passes move them little.
  refresh_neighbors(false, false);
  if (sep.active.size() != n)
    sep.active.assign(n, 1);
  // Axes of the tiles the last pass moved (all at the first measure of a set of tiles).
  const bool all = sep.xs.size() != n || sep.move.size() != n;
  sep.xs.resize(n), sep.ys.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    if (all || sep.move[i] != internal::Vec3{{0, 0, 0}}) {
      sep.xs[i] = tile_x_axis(points_[i]);
      sep.ys[i] = internal::cross(s.normal(points_[i].face), sep.xs[i]);
    }
  sep.move.assign(n, internal::Vec3{{0, 0, 0}});
  sep.crowding.assign(n, 0.0);
  sep.overlap.assign(n, {{0, 0, 0, 0}});
  std::vector<std::uint32_t> pairs(n, 0);
  std::vector<double> depths(n, 0.0);
  internal::parallel_blocks(n, [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i)
      if (sep.active[i])
        measure_tile(i, gap, reach, side, sep, pairs[i], depths[i]);
  });
  std::size_t close = 0;
  sep.summed_overlap = 0;
  for (std::size_t i = 0; i < n; ++i)
    close += pairs[i], sep.summed_overlap += depths[i];
  sep.active.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    if (pairs[i] > 0) {
      sep.active[i] = 1;
      for (std::size_t m = 0; m < k; ++m) {
        const std::uint32_t j = neighbors_[i * k + m];
        if (j != internal::no_index && j < n)
          sep.active[j] = 1;
      }
    }
  return close / 2; // each pair is seen from both tiles (near enough: k-nearest lists)
}

// Measures tile i against its neighbours (one pass of `measure_crowding()`): adds to its entries
// of `sep`, counts its close pairs in `pairs` and sums their depths without the gap in `depth`.
template <typename TriangleMesh, typename NamedParameters>
void Surface_mosaic<TriangleMesh, NamedParameters>::measure_tile(std::size_t i, double gap,
                                                                 double reach, double side,
                                                                 Separation& sep,
                                                                 std::uint32_t& pairs,
                                                                 double& depth) const {
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  const std::size_t n = points_.size(), k = options_.neighbors;
  const std::uint32_t region = s.region(points_[i].face);
  const internal::Vec3& ni = s.normal(points_[i].face);
  const std::array<double, 2> hi{{half_side(i, 0, gap), half_side(i, 1, gap)}};
  for (std::size_t m = 0; m < k; ++m) {
    const std::uint32_t j = neighbors_[i * k + m];
    if (j == internal::no_index)
      break;
    // Tiles up to 120° apart: on a part thinner than a tile (horn and tail tips, hooves, ear
    // rims) tiles a quarter turn or more apart around it both cover its ridge. Skipping pairs
    // past 90° left that overlap unseen: 62 % of the bull's and 68 % of the cow's doubly
    // covered samples (quality report) lay under two such tiles.
    if (j >= n)
      continue;
    const internal::Vec3& nj = s.normal(points_[j].face);
    const double facing = internal::dot(nj, ni);
    if (s.region(points_[j].face) != region || facing <= -0.5)
      continue;
    const internal::Vec3 d = pos_[j] - pos_[i];
    const double dx = internal::dot(d, sep.xs[i]), dy = internal::dot(d, sep.ys[i]);
    const double pair_reach = reach * std::max(size_at(points_[i]), size_at(points_[j]));
    const double seen = std::sqrt(dx * dx + dy * dy);
    if (seen > pair_reach || std::abs(internal::dot(d, ni)) > pair_reach)
      continue;
    double ax = internal::dot(sep.xs[j], sep.xs[i]), ay = internal::dot(sep.xs[j], sep.ys[i]);
    const double al = std::sqrt(ax * ax + ay * ay); // j's x axis in i's plane
    if (!(al > 1e-9))
      continue;
    ax /= al, ay /= al;
    std::array<double, 2> hj{{half_side(j, 0, gap), half_side(j, 1, gap)}};
    if (facing <= 0) {
      // Past 90°, j's rectangle as i's plane sees it: each side foreshortened by its axis's
      // projection (at full size every such pair counted as crowded, and the bull lost 0.025 of
      // its coverage to tiles shrunk and left out).
      const internal::Vec3 yj = internal::cross(nj, sep.xs[j]);
      hj[0] *= al;
      hj[1] *= std::hypot(internal::dot(yj, sep.xs[i]), internal::dot(yj, sep.ys[i]));
    }
    const Box_overlap chord = box_overlap(hi, hj, ax, ay, dx, dy);
    // Along the surface the two are at least as far apart as the chord says.
    if (!(chord.depth > 0))
      continue;
    // How far apart the two are along the surface (in i's chart), in the direction the
    // plane of i sees j: where the surface curves, the chord projected onto i's plane is
    // shorter than the tiles' distance, and tiles one cell apart on a tube or in a groove
    // would count as overlapping.
    const Manhattan_chart& ci = atlas_->chart(chart_[i]);
    const std::uint32_t si = ci.slot(points_[i].face);
    const auto uv = chart_difference(i, j, ci, ci.uv_at(si, points_[i].bary), ci.frame[si]);
    const double along = std::sqrt(uv[0] * uv[0] + uv[1] * uv[1]);
    // Measured along the surface, each tile covers more than its side where the surface curves
    // (its footprint: the part of the surface its rectangle projects onto, what the quality
    // report counts): both tiles' half sides grow by that stretch.
    Box_overlap o = chord;
    if (seen > 0 && along > seen) {
      const double w = hi[0] * std::abs(dx) / seen + hi[1] * std::abs(dy) / seen;
      const double k = footprint_stretch(seen / along, along, w);
      o = box_overlap({{k * hi[0], k * hi[1]}}, {{k * hj[0], k * hj[1]}}, ax, ay, dx * along / seen,
                      dy * along / seen);
    }
    if (!(o.depth > 0))
      continue;
    ++pairs;
    sep.crowding[i] += o.depth / (2 * side * size_at(points_[i]));
    sep.move[i] = sep.move[i] + o.push[0] * sep.xs[i] + o.push[1] * sep.ys[i];
    if (o.depth > gap) {
      // The side of i that faces j along the separating axis (the push points away).
      const int axis = std::abs(o.axis[0]) >= std::abs(o.axis[1]) ? 0 : 1;
      const int facing = 2 * axis + (o.push[axis] > 0 ? 1 : 0);
      sep.overlap[i][facing] = std::max(sep.overlap[i][facing], o.depth - gap);
      depth += o.depth - gap;
    }
  }
}

// One round of passes; returns the pairs still closer than the gap. The passes stop early when
// one takes less than 2 % off the summed overlap: where rows are squeezed (fronts out of
// phase, thin parts) each tile is pushed from both sides and only the ends of a squeezed row
// move, so the passes would run to their cap (on a 10k-tile fandisk 270 passes, 5 s, for 0.05 %
// less overlap than 18 passes); the crowding rounds and the trimming deal with what is left.
template <typename TriangleMesh, typename NamedParameters>
std::size_t Surface_mosaic<TriangleMesh, NamedParameters>::spread_tiles(Separation& sep, bool all) {
  if (all)
    sep.active.assign(points_.size(), 1);
  std::size_t pass = 0, close = measure_crowding(sep);
  for (; pass < options_.separation_passes && close > 0; ++pass) {
    const double before = sep.summed_overlap;
    move_by(sep.move);
    close = measure_crowding(sep);
    if (sep.summed_overlap > 0.98 * before) {
      ++pass;
      break;
    }
  }
  stats_.separation_passes += pass;
  return close;
}

// Shrinks the most crowded tiles by their crowding (where a part of the surface is thinner than
// the rows need, as a mosaicist cuts smaller tesserae), or leaves out those that would fall
// below `min_tile_scale` of the size; never two close ones in one round (the other may fit once
// its neighbour has shrunk or gone). Returns how many tiles shrank or were left out.
template <typename TriangleMesh, typename NamedParameters>
std::size_t Surface_mosaic<TriangleMesh, NamedParameters>::shrink_crowded_tiles(Separation& sep) {
  const std::size_t n = points_.size(), k = options_.neighbors;
  const double near =
      1.2 * layout_.spacing * std::max(std::sqrt(layout_.aspect), 1 / std::sqrt(layout_.aspect));
  std::vector<char> keep(n, 1), blocked(n, 0), changed(n, 0);
  std::vector<std::uint32_t> order(n);
  for (std::uint32_t i = 0; i < n; ++i)
    order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return sep.crowding[a] > sep.crowding[b]; });
  std::size_t dropped = 0, shrunk = 0;
  for (const std::uint32_t i : order) {
    if (!(sep.crowding[i] > options_.max_tile_crowding))
      break;
    if (blocked[i])
      continue;
    const double factor = 1 - sep.crowding[i];
    if (std::min(scale_[i][0], scale_[i][1]) * factor >= options_.min_tile_scale) {
      if (scale_[i] == std::array<double, 2>{{1, 1}})
        ++stats_.shrunk_tiles;
      scale_[i][0] *= factor, scale_[i][1] *= factor, ++shrunk;
    } else {
      keep[i] = 0, ++dropped;
    }
    changed[i] = 1;
    for (std::size_t m = 0; m < k; ++m) {
      const std::uint32_t j = neighbors_[i * k + m];
      if (j != internal::no_index && j < n &&
          internal::norm(pos_[j] - pos_[i]) < near * size_at(points_[i]))
        blocked[j] = 1;
    }
  }
  // The next round measures only where this one changed something: the tiles shrunk or left
  // out, and every tile with one of them in its list or in theirs. Elsewhere the pairs are as
  // the last passes left them, stopped where a pass took less than 2 % off their overlap or
  // none was close (measuring every tile in each of the six rounds took 0.8 s of 1.6 at 40k
  // tiles).
  sep.active.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t m = 0; m < k; ++m) {
      const std::uint32_t j = neighbors_[i * k + m];
      if (j == internal::no_index)
        break;
      if (j < n && (changed[i] || changed[j]))
        sep.active[i] = sep.active[j] = 1;
    }
  stats_.left_out_crowded += dropped;
  if (dropped > 0) {
    std::size_t kept = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (keep[i])
        sep.active[kept++] = sep.active[i];
    sep.active.resize(kept);
    remove_tiles(keep);
  }
  return dropped + shrunk;
}

// Cuts back each side of a tile that overlaps a neighbour by half the overlap, keeping the
// opposite side where it is: the tile gets shorter along that axis and its centre moves away
// from the neighbour by a quarter of the overlap. A tile that would fall below `min_tile_scale`
// is left out.
template <typename TriangleMesh, typename NamedParameters>
std::size_t Surface_mosaic<TriangleMesh, NamedParameters>::trim_overlapping_tiles(Separation& sep) {
  const std::size_t n = points_.size();
  sep.active.assign(n, 1);
  const std::size_t close = measure_crowding(sep);
  std::vector<internal::Vec3> shift(n, internal::Vec3{{0, 0, 0}});
  std::vector<char> keep(n, 1);
  std::size_t dropped = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::array<double, 4>& o = sep.overlap[i];
    if (o == std::array<double, 4>{{0, 0, 0, 0}})
      continue;
    std::array<double, 2> scale = scale_[i];
    for (int axis = 0; axis < 2; ++axis)
      scale[axis] -=
          0.5 * (o[2 * axis] + o[2 * axis + 1]) / (layout_.tile_size[axis] * size_at(points_[i]));
    if (std::min(scale[0], scale[1]) < options_.min_tile_scale) {
      keep[i] = 0, ++dropped;
      continue;
    }
    ++stats_.trimmed_tiles; // (also a tile shrunk or filled in smaller before)
    scale_[i] = scale;
    // The side facing +x moved in by o[0] / 2, the one facing −x by o[1] / 2.
    shift[i] = (0.25 * (o[1] - o[0])) * sep.xs[i] + (0.25 * (o[3] - o[2])) * sep.ys[i];
  }
  move_by(shift);
  stats_.left_out_crowded += dropped;
  if (dropped > 0)
    remove_tiles(keep);
  return close;
}

// Two points a distance s apart along a surface that curves like a circle between them, whose
// chord projected onto the first one's tangent plane is q·s: the arc of that circle that projects
// onto a half side w of a tile in that plane, over w (r·asin(w/r) / w for the radius r with
// r·sin(s/r) = q·s; 1 on a plane, π/2·r/w once the tile reaches past a quarter circle).
template <typename TriangleMesh, typename NamedParameters>
double Surface_mosaic<TriangleMesh, NamedParameters>::footprint_stretch(double q, double s,
                                                                        double w) {
  if (!(q < 1) || !(w > 0))
    return 1;
  // x = s / r solves sin(x) = q·x on (0, π). Where the surface bends little between the two
  // (1 − q < 0.2, nearly every pair) the inverted series x² = 6u(1 + 0.3u), u = 1 − q, is exact
  // to O(u³); beyond, Newton from it. (The separation asks this of every close pair in every
  // pass: trigonometry here took a fifth of a 200k-triangle run.)
  const double pi = 3.14159265358979323846, u = 1 - q;
  double x = std::sqrt(6 * u * (1 + 0.3 * u));
  if (u >= 0.2)
    for (int it = 0; it < 6; ++it)
      x = std::clamp(x - (std::sin(x) - q * x) / (std::cos(x) - q), 1e-9, pi);
  const double rho = w * x / s; // w / r
  if (rho >= 1)
    return std::max(1.0, 0.5 * pi / rho);
  if (rho < 0.5) { // asin(ρ)/ρ by its series, to 1e-4
    const double r2 = rho * rho;
    return 1 + r2 * (1.0 / 6 + r2 * (3.0 / 40 + r2 * 5.0 / 112));
  }
  return std::asin(rho) / rho;
}

template <typename TriangleMesh, typename NamedParameters>
typename Surface_mosaic<TriangleMesh, NamedParameters>::Box_overlap
Surface_mosaic<TriangleMesh, NamedParameters>::box_overlap(const std::array<double, 2>& a,
                                                           const std::array<double, 2>& b,
                                                           double ax, double ay, double dx,
                                                           double dy) {
  const std::array<std::array<double, 2>, 4> axes{{{{1, 0}}, {{0, 1}}, {{ax, ay}}, {{-ay, ax}}}};
  Box_overlap o{std::numeric_limits<double>::infinity(), {{1, 0}}, {{0, 0}}};
  for (const auto& u : axes) {
    const double ri = a[0] * std::abs(u[0]) + a[1] * std::abs(u[1]);
    const double rj =
        b[0] * std::abs(u[0] * ax + u[1] * ay) + b[1] * std::abs(u[1] * ax - u[0] * ay);
    const double along = u[0] * dx + u[1] * dy;
    const double overlap = ri + rj - std::abs(along);
    if (!(overlap < o.depth))
      continue;
    o.depth = overlap;
    if (o.depth <= 0)
      break;
    const double h = along >= 0 ? -0.5 * overlap : 0.5 * overlap; // away from the other
    o.axis = u;
    o.push = {{h * u[0], h * u[1]}};
  }
  return o;
}

template <typename TriangleMesh, typename NamedParameters>
double Surface_mosaic<TriangleMesh, NamedParameters>::seconds(Clock::time_point a,
                                                              Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

template <typename TriangleMesh, typename NamedParameters>
void Surface_mosaic<TriangleMesh, NamedParameters>::fail(Mosaic_status s, std::string m) {
  status_ = s;
  message_ = std::move(m);
}

template <typename TriangleMesh, typename NamedParameters>
internal::Vec3
Surface_mosaic<TriangleMesh, NamedParameters>::tangent(const internal::Vec3& x,
                                                       const internal::Vec3& normal) {
  const internal::Vec3 t = x - internal::dot(x, normal) * normal;
  const double l = internal::norm(t);
  if (l > 1e-12)
    return (1 / l) * t;
  const internal::Vec3 a =
      std::abs(normal[0]) < 0.9 ? internal::Vec3{{1, 0, 0}} : internal::Vec3{{0, 1, 0}};
  const internal::Vec3 b = internal::cross(normal, a);
  return (1 / internal::norm(b)) * b;
}

// Rebuilds the k-nearest lists when some tile has moved far enough since its list was built to
// change them (an eighth of the spacing), or every 10 iterations. Only the lists that can have
// changed are queried again (`requery_neighbors()`), unless `force`.
template <typename TriangleMesh, typename NamedParameters>
void Surface_mosaic<TriangleMesh, NamedParameters>::refresh_neighbors(bool force, bool periodic) {
  if (!force && knn_.size() > 0 && moved_since_refresh_ < 0.25 * layout_.spacing &&
      (!periodic || iterations_since_refresh_ < 10)) {
    ++iterations_since_refresh_;
    return;
  }
  const std::size_t n = points_.size(), k = options_.neighbors;
  std::vector<internal::Vec3> all = pos_;
  all.insert(all.end(), virtual_pos_.begin(), virtual_pos_.end());
  knn_.reset(all);
  const bool whole = force || built_pos_.size() != n || neighbors_.size() != n * k;
  std::vector<std::uint32_t> query;
  if (whole) {
    neighbors_.assign(n * k, internal::no_index);
    built_pos_.resize(n);
    query.resize(n);
    for (std::uint32_t i = 0; i < n; ++i)
      query[i] = i;
  } else {
    query = movers();
  }
  requery_neighbors(query);
  if (!whole) {
    // A tile that moved can have left the lists it was in, and entered those of the tiles now
    // near it (the tiles in its own new list: nearness is about symmetric): those are queried
    // again too. Every other list holds tiles that moved less than the threshold.
    std::vector<char> mover(n, 0), again(n, 0);
    for (const std::uint32_t i : query)
      mover[i] = 1;
    for (const std::uint32_t i : query)
      for (std::size_t m = 0; m < k; ++m) {
        const std::uint32_t j = neighbors_[i * k + m];
        if (j < n && !mover[j])
          again[j] = 1;
      }
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t m = 0; m < k && !mover[i] && !again[i]; ++m) {
        const std::uint32_t j = neighbors_[i * k + m];
        if (j < n && mover[j])
          again[i] = 1;
      }
    std::vector<std::uint32_t> second;
    for (std::uint32_t i = 0; i < n; ++i)
      if (again[i])
        second.push_back(i);
    requery_neighbors(second);
  }
  // The threshold holds against each tile's position when its list was last built.
  double largest = 0;
  for (std::size_t i = 0; i < n; ++i)
    largest = std::max(largest, internal::norm(pos_[i] - built_pos_[i]) / size_at(points_[i]));
  moved_since_refresh_ = 2 * largest;
  iterations_since_refresh_ = 0;
}

// The tiles that moved more than a sixteenth of the spacing since their lists were built (half the
// refresh threshold: the lists of those below it stay).
template <typename TriangleMesh, typename NamedParameters>
std::vector<std::uint32_t> Surface_mosaic<TriangleMesh, NamedParameters>::movers() const {
  std::vector<std::uint32_t> out;
  for (std::uint32_t i = 0; i < points_.size(); ++i)
    if (internal::norm(pos_[i] - built_pos_[i]) / size_at(points_[i]) > 0.0625 * layout_.spacing)
      out.push_back(i);
  return out;
}

// Queries the k-nearest lists of `tiles` in the current tree, on every core.
template <typename TriangleMesh, typename NamedParameters>
void Surface_mosaic<TriangleMesh, NamedParameters>::requery_neighbors(
    const std::vector<std::uint32_t>& tiles) {
  const std::size_t k = options_.neighbors;
  internal::parallel_blocks(tiles.size(), [&](std::size_t first, std::size_t last) {
    for (std::size_t t = first; t < last; ++t) {
      const std::uint32_t i = tiles[t];
      std::size_t m = 0;
      knn_.nearest(pos_[i], k + 1, [&](std::size_t j, double) {
        if (j != i && m < k)
          neighbors_[i * k + m++] = std::uint32_t(j);
      });
      for (; m < k; ++m)
        neighbors_[i * k + m] = internal::no_index;
      built_pos_[i] = pos_[i];
    }
  });
}

// The size field at face f's centroid.
template <typename TriangleMesh, typename NamedParameters>
double Surface_mosaic<TriangleMesh, NamedParameters>::face_size(std::uint32_t f) const {
  return size_at(internal::Surface_point{f, {{1.0 / 3, 1.0 / 3, 1.0 / 3}}});
}

// The size field at p (1 without one).
template <typename TriangleMesh, typename NamedParameters>
double
Surface_mosaic<TriangleMesh, NamedParameters>::size_at(const internal::Surface_point& p) const {
  if (vertex_size_.empty())
    return 1;
  const auto& c = surface_->corners(p.face);
  return p.bary[0] * vertex_size_[c[0]] + p.bary[1] * vertex_size_[c[1]] +
         p.bary[2] * vertex_size_[c[2]];
}

// Tile i's side along `axis` over the layout's: the size field at its centre, times its
// shrinking and trimming.
template <typename TriangleMesh, typename NamedParameters>
double Surface_mosaic<TriangleMesh, NamedParameters>::tile_scale(std::size_t i, int axis) const {
  return size_at(points_[i]) * (i < scale_.size() ? scale_[i][axis] : 1.0);
}

// (du, dv) from tile j to tile i in tile i's chart, or in j's chart when i's does not hold j, or
// else in i's tangent frame.
template <typename TriangleMesh, typename NamedParameters>
std::array<double, 2> Surface_mosaic<TriangleMesh, NamedParameters>::chart_difference(
    std::uint32_t i, std::uint32_t j, const Manhattan_chart& ci, const std::array<double, 2>& uvi,
    const std::array<internal::Vec3, 2>& frame) const {
  const internal::Surface_point& pj = points_[j];
  const std::uint32_t sj = ci.slot(pj.face);
  if (sj != internal::no_index) {
    const auto uvj = ci.uv_at(sj, pj.bary);
    return {{uvi[0] - uvj[0], uvi[1] - uvj[1]}};
  }
  const Manhattan_chart& cj = atlas_->chart(chart_[j]);
  const std::uint32_t si = cj.slot(points_[i].face);
  if (si != internal::no_index) {
    const auto a = cj.uv_at(si, points_[i].bary), b = cj.uv_at(cj.slot(pj.face), pj.bary);
    return {{a[0] - b[0], a[1] - b[1]}};
  }
  const internal::Vec3 d = pos_[i] - pos_[j];
  return {{internal::dot(d, frame[0]), internal::dot(d, frame[1])}};
}

// A tile's x axis: the power average of its face corners' field at its centre, in the face's
// plane, started from the face's direction.
template <typename TriangleMesh, typename NamedParameters>
internal::Vec3
Surface_mosaic<TriangleMesh, NamedParameters>::tile_x_axis(const internal::Surface_point& p) const {
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  const internal::Vec3 normal = s.normal(p.face);
  const internal::Vec3 e1 = tangent(face_field_->direction(p.face), normal);
  const internal::Vec3 e2 = internal::cross(normal, e1);
  const auto& c = s.corners(p.face);
  double a = 0;
  internal::interpolated_field_angle(
      {{vertex_field_[c[0]], vertex_field_[c[1]], vertex_field_[c[2]]}}, p.bary, e1, e2, symmetry_,
      a);
  return std::cos(a) * e1 + std::sin(a) * e2;
}

// With the soft-box energy feature lines are walls (a mirror image hardly pushes a tile that sits
// on the line, the energy being flat near zero distance): a tile whose cell (the tile and half
// the grout around it) crosses the closest line of its region moves straight away from it until
// the cell touches the line, so the tile's edge stays half a grout width off it (Lai et al.
// §5.2).
template <typename TriangleMesh, typename NamedParameters>
void Surface_mosaic<TriangleMesh, NamedParameters>::keep_off_features(std::uint32_t i) {
  if (!features_)
    return;
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  const double root = std::sqrt(layout_.aspect);
  // A tile near two lines (a corner of a region) may be pushed from one towards the other: a few
  // passes.
  for (int pass = 0; pass < 4; ++pass) {
    internal::Surface_point& p = points_[i];
    const internal::Vec3 at = s.position(p);
    internal::Vec3 q;
    if (!features_->near(p.face) || !features_->closest(s.region(p.face), at, q))
      return;
    internal::Vec3 away = at - q;
    const double depth = internal::norm(away);
    if (!(depth > 1e-9 * layout_.spacing))
      away = s.centroid(p.face) - q; // on the line: into the face
    // In the tile's own axes (those `tiles()` writes), not its chart's: near a line the field
    // turns, and a few degrees between the two would let a corner of the tile over the line.
    const internal::Vec3 x = tile_x_axis(p);
    const std::array<internal::Vec3, 2> frame{{x, internal::cross(s.normal(p.face), x)}};
    const double nu = internal::dot(away, frame[0]), nv = internal::dot(away, frame[1]);
    const double l = std::sqrt(nu * nu + nv * nv);
    if (!(l > 0))
      return;
    // Half the cell's extent along the line's normal (cell sides s·√η along u, s/√η along v).
    const double half =
        0.5 * layout_.spacing * size_at(p) * (root * std::abs(nu) + std::abs(nv) / root) / l;
    if (depth >= half)
      return;
    p = s.walk(p, ((half - depth) / l) * (nu * frame[0] + nv * frame[1])).p;
    chart_[i] = atlas_->chart_index_of(p.face);
  }
}

// One iteration of eq. 3: every force from the current positions, then every move. Both loops
// run over the tiles in parallel (forces read the positions of the last iteration; projections
// touch one tile each); charts, which grow lazily, and the feature walls follow serially.
template <typename TriangleMesh, typename NamedParameters>
void Surface_mosaic<TriangleMesh, NamedParameters>::step() {
  refresh_neighbors(false);
  const std::size_t n = points_.size();
  const double cap = options_.max_step * layout_.spacing;
  std::vector<internal::Vec3> move(n);
  std::vector<double> energy(n, 0.0);
  if (last_move_.size() != n) {
    last_move_.assign(n, internal::Vec3{{0, 0, 0}});
    gain_.assign(n, 1.0);
  }
  nearest_.assign(n, std::numeric_limits<double>::infinity());
  nearest_index_.assign(n, 0);
  internal::parallel_blocks(n, [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i) {
      internal::Vec3 m = force(std::uint32_t(i), energy[i]);
      // A tile pushed back and forth between two neighbours (its move reverses) halves its own
      // step; one that keeps going regains it. Without this, crowded tiles oscillate for ever.
      if (internal::dot(m, last_move_[i]) < 0)
        gain_[i] *= 0.5;
      else
        gain_[i] = std::min(1.0, 1.25 * gain_[i]);
      m = gain_[i] * m;
      const double l = internal::norm(m), most = cap * size_at(points_[i]);
      if (l > most)
        m = (most / l) * m;
      move[i] = m;
    }
  });
  last_move_ = move;
  const double total = move_by(move);
  double sum = 0;
  for (double e : energy)
    sum += e;
  stats_.energy.push_back(sum);
  stats_.mean_displacement.push_back(n > 0 ? total / double(n) / layout_.spacing : 0);
}

// Eq. 3's force on tile i (times the step t), in its tangent plane; adds i's pair energies to
// `energy` and records its nearest neighbour in the Manhattan metric.
template <typename TriangleMesh, typename NamedParameters>
internal::Vec3 Surface_mosaic<TriangleMesh, NamedParameters>::force(std::uint32_t i,
                                                                    double& energy) {
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  const std::size_t n = points_.size();
  const bool paper = options_.energy == Mosaic_energy::gaussian_manhattan;
  const double sigma2 = layout_.sigma * layout_.sigma, two_sigma2 = 2 * sigma2,
               sigma4 = sigma2 * sigma2;
  const double root = std::sqrt(layout_.aspect);
  const internal::Surface_point& p = points_[i];
  const Manhattan_chart& chart = atlas_->chart(chart_[i]);
  const std::uint32_t slot = chart.slot(p.face);
  const auto uvi = chart.uv_at(slot, p.bary);
  const std::array<internal::Vec3, 2>& frame = chart.frame[slot];
  const std::uint32_t region = s.region(p.face);
  double fx = 0, fy = 0;
  internal::Vec3 f3{{0, 0, 0}};
  // One neighbour at (du, dv) from tile i in i's chart, the pair's mean size h (of the size
  // field; the energy is that of tiles of size 1 at (du, dv) / h): its energy and its push on i.
  const double hi = size_at(p);
  auto add = [&](double du, double dv, double h) {
    const double x = du / (root * h), y = dv * root / h;
    const double d = manhattan_distance(x, y);
    if (paper) {
      const double e = std::exp(-d * d / two_sigma2); // eq. 2
      fx += h * x * e;                                // eq. 3
      fy += h * y * e;
      energy += e;
    } else {
      const double x2 = x * x, y2 = y * y;
      const double e = std::exp(-2 * (x2 * x2 + y2 * y2) / sigma4);
      fx += h * x * x2 * e / sigma2; // −σ²/8 ∇e
      fy += h * y * y2 * e / sigma2;
      energy += e;
      // Cells (a tile with the grout around it, a spacing wide) that overlap push apart along
      // the axis of least overlap, each by half of it times `separation`: the soft box alone
      // lets crowded rows settle with the tiles overlapping by a few percent.
      const double ox = layout_.spacing - std::abs(x), oy = layout_.spacing - std::abs(y);
      if (options_.separation > 0 && ox > 0 && oy > 0) {
        if (ox < oy)
          fx += (x >= 0 ? 0.5 : -0.5) * h * options_.separation * ox;
        else
          fy += (y >= 0 ? 0.5 : -0.5) * h * options_.separation * oy;
      }
    }
    return d;
  };
  for (std::size_t m = 0; m < options_.neighbors; ++m) {
    const std::uint32_t j = neighbors_[i * options_.neighbors + m];
    if (j == internal::no_index)
      break;
    if (j >= n) { // a virtual tile at a singularity: Euclidean distance
      if (virtual_region_[j - n] != region)
        continue;
      const internal::Vec3 d = pos_[i] - virtual_pos_[j - n];
      const double r2 = internal::dot(d, d) / (hi * hi);
      const double e = paper ? std::exp(-r2 / two_sigma2) : std::exp(-2 * r2 * r2 / sigma4);
      f3 = f3 + (paper ? e : e * r2 / sigma2) * d;
      energy += e;
      continue;
    }
    // Tiles of another region, or facing away (the other side of a thin part), do not interact.
    if (s.region(points_[j].face) != region ||
        internal::dot(s.normal(points_[j].face), s.normal(p.face)) < -0.5)
      continue;
    const auto d = chart_difference(i, j, chart, uvi, frame);
    const double dist =
        add(d[0], d[1], vertex_size_.empty() ? 1 : 0.5 * (hi + size_at(points_[j])));
    if (dist < nearest_[i]) {
      nearest_[i] = dist;
      nearest_index_[i] = j;
    }
  }
  // Feature lines with the paper's energy: repulsion from the mirror image across the closest
  // line (Lai et al. §5.2). With the soft-box energy they are walls (`keep_off_features`).
  internal::Vec3 q;
  if (paper && features_ && features_->near(p.face) && features_->closest(region, pos_[i], q) &&
      internal::norm(pos_[i] - q) < reach_) {
    const internal::Vec3 d = 2.0 * (pos_[i] - q);
    add(internal::dot(d, frame[0]), internal::dot(d, frame[1]), hi);
  }
  const internal::Vec3 normal = s.normal(p.face);
  return options_.step * ((fx * root) * frame[0] + (fy / root) * frame[1] +
                          (f3 - internal::dot(f3, normal) * normal));
}

// Walks every tile by `move` along its region (`Surface_arrays::walk`: a closest-point
// projection of the moved point, as before, took a fifth of the run on 200k triangles and could
// land on the far side of a thin part), then off the
// feature lines; returns the summed displacement on the surface, each in units of its tile's
// size.
template <typename TriangleMesh, typename NamedParameters>
double
Surface_mosaic<TriangleMesh, NamedParameters>::move_by(const std::vector<internal::Vec3>& move) {
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  const std::size_t n = points_.size();
  const bool paper = options_.energy == Mosaic_energy::gaussian_manhattan;
  internal::parallel_blocks(n, [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i)
      if (move[i][0] != 0 || move[i][1] != 0 || move[i][2] != 0) // (the separation's idle tiles)
        points_[i] = s.walk(points_[i], move[i]).p;
  });
  double total = 0, largest = 0;
  const bool built = built_pos_.size() == n;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (move[i][0] == 0 && move[i][1] == 0 && move[i][2] == 0)
      continue; // not moved: its chart, walls and position stand
    chart_[i] = atlas_->chart_index_of(points_[i].face);
    if (!paper)
      keep_off_features(i);
    const internal::Vec3 next = s.position(points_[i]);
    // In units of the tile's size (with a size field, the stopping rule and the neighbour
    // lists' refresh hold for small and large tiles alike).
    const double d = internal::norm(next - pos_[i]) / size_at(points_[i]);
    total += d;
    pos_[i] = next;
    // How far the tile is from where the neighbour lists were built: no pair's distance has
    // changed by more than twice the largest of these (summing each pass's largest move, as
    // before, rebuilt the lists every second pass of the separation, where tiles jitter in
    // place: a fifth of its time).
    largest = std::max(largest, built ? internal::norm(next - built_pos_[i]) / size_at(points_[i])
                                      : std::numeric_limits<double>::infinity());
  }
  moved_since_refresh_ = std::max(moved_since_refresh_, 2 * largest);
  return total;
}

} // namespace tessera
