// `Surface_mosaic`'s separation (tessera/mosaic/surface_mosaic.h), run after the optimization:
// overlapping tiles pushed apart by separating axes, the most crowded shrunk or left out, bare
// patches filled with tiles as large as the room there takes, what overlap is left trimmed, tiles
// grown back where room opened, and tiles moved off feature lines. Internal, included by
// surface_mosaic_impl.h.
#pragma once

#include <tessera/mosaic/surface_mosaic.h>

#include <tessera/internal/parallel.h>
#include <tessera/mosaic/internal/segment_box.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace tessera {

namespace internal {

// The half sides of a tile turned more than 90° from the plane of axes (x, y) (around a part
// thinner than a tile), as that plane sees them: each side foreshortened by its axis's projection.
// `along_x` is the length of the tile's x axis projected onto the plane, `tile_y` its y axis.
// Past 90° at full size every such pair counted as crowded, and the bull lost 0.025 of its
// coverage to tiles shrunk and left out. `measure_tile()` and `room_against()` share it, so that
// the separation and the filling and growth measure such pairs alike.
inline std::array<double, 2> foreshortened_half(std::array<double, 2> half, double along_x,
                                                const Vec3& tile_y, const Vec3& x, const Vec3& y) {
  half[0] *= along_x;
  half[1] *= std::hypot(dot(tile_y, x), dot(tile_y, y));
  return half;
}

// The length of a circular arc with chord `chord` whose tangents at its ends turn by the angle
// whose cosine is `facing`: how far apart two tiles are along a surface that bends evenly from
// one's plane to the other's. `measure_tile()` and `room_against()` take it as the distance along
// the surface that stretches the tiles' footprints. (Before, the distance between the two in a
// chart: a bump or groove between two tiles lengthens that without turning either tile's plane,
// which is what a footprint depends on. Armadillo and man kept 1.0-1.1 % of their area under two
// tiles; with the bend of the tiles' planes 0.5-0.9 %, and with the gap and crowding bounds
// relaxed on that margin every mesh of doc/mosaic.md covers more: see `min_tile_gap`.)
inline double bent_length(double chord, double facing) {
  const double turn = std::acos(std::clamp(facing, -1.0, 1.0));
  return turn > 1e-4 ? chord * 0.5 * turn / std::sin(0.5 * turn) : chord;
}

} // namespace internal

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
std::size_t Surface_mosaic<TriangleMesh, NamedParameters>::fill_bare_patches(bool off_lines) {
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
  const std::size_t budget = fill_budget();
  std::vector<Room_tile> laid;
  laid.reserve(order.size());
  for (const auto& o : order) {
    if (added == budget)
      break;
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
    if (off_lines && features_ && features_->near(p.face)) {
      if (!clear_of_lines_by_grout(p, {{options_.min_tile_scale, options_.min_tile_scale}}))
        continue;
      r = clear_scale(p, {{0, 0}}, {{1, 1}}, options_.min_tile_scale, r);
    }
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

// How many tiles `fill_bare_patches()` may add: up to N with `Mosaic_count::at_most`, up to
// `Surface_mosaic_options::most_over_count` past N with `about`. (Nothing after the filling adds a
// tile, so the count stays within it.)
template <typename TriangleMesh, typename NamedParameters>
std::size_t Surface_mosaic<TriangleMesh, NamedParameters>::fill_budget() const {
  const double most = options_.count == Mosaic_count::at_most
                          ? double(layout_.tile_count)
                          : std::floor((1 + options_.most_over_count) * double(layout_.tile_count));
  return most > double(points_.size()) ? std::size_t(most) - points_.size() : 0;
}

// Tiles shrunk or trimmed more than their neighbours now need (the room around them changed
// as tiles moved, were left out or filled in) grow back, up to the room there, one at a time so
// that two neighbours never grow into the same room. Returns how many grew.
template <typename TriangleMesh, typename NamedParameters>
std::size_t Surface_mosaic<TriangleMesh, NamedParameters>::grow_tiles(bool sides) {
  const std::size_t n = points_.size();
  if (scale_.size() != n)
    return 0;
  internal::Point_search search(pos_);
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
      double r = room_at(probe, search, tiles, i); // (at most 1)
      if (!(r > scale_[i][axis] + 1e-3))
        continue;
      r = clear_scale(points_[i], probe.base, probe.dir, scale_[i][axis], r);
      if (!(r > scale_[i][axis] + 1e-3))
        continue;
      scale_[i][axis] = r;
      changed = true;
    }
    // Then, with `sides`, each short side on its own, the opposite side staying: a tile cut or
    // trimmed between a line or a neighbour and a sliver of bare surface grows into the sliver
    // (the centre follows). Only after the clearance: before it, on every mesh, it added 0.001-
    // 0.003 to the organic meshes' coverage for a fifth more separation time (0.85 -> 1.04 s at
    // 40k tiles, paired runs).
    if (sides)
      for (int axis : {first, 1 - first})
        for (const double sign : {1.0, -1.0})
          changed = grow_side(i, axis, sign, search, tiles) || changed;
    if (!changed)
      continue;
    tiles[i] = room_tile(i);
    ++grown;
  }
  return grown;
}

// The largest s in [lo, hi] for which a tile at p with scales base + s · dir crosses no feature
// line of its region: `hi` where none does, else by bisection to a hundredth of a side, taking
// `lo` as clear. (`grow_tiles()` and `fill_bare_patches()` ask it: the room they measure is
// between tiles, and a tile grown or laid beside a crease reached over it.)
template <typename TriangleMesh, typename NamedParameters>
double Surface_mosaic<TriangleMesh, NamedParameters>::clear_scale(const internal::Surface_point& p,
                                                                  const std::array<double, 2>& base,
                                                                  const std::array<double, 2>& dir,
                                                                  double lo, double hi) const {
  if (!features_ || !features_->near(p.face))
    return hi;
  const auto clear = [&](double t) {
    return clear_of_lines_by_grout(p, {{base[0] + t * dir[0], base[1] + t * dir[1]}});
  };
  if (clear(hi))
    return hi;
  while (hi - lo > 0.01)
    (clear(0.5 * (lo + hi)) ? lo : hi) = 0.5 * (lo + hi);
  return lo;
}

// Whether the tile at p with `scales` keeps half a grout from every feature line of its region,
// as the clearance leaves tiles (`needed_moves()` tests the rectangle itself: a tile grown or laid
// up to a line would touch it).
template <typename TriangleMesh, typename NamedParameters>
bool Surface_mosaic<TriangleMesh, NamedParameters>::clear_of_lines_by_grout(
    const internal::Surface_point& p, const std::array<double, 2>& scales) const {
  if (!features_ || !features_->near(p.face))
    return true;
  const Extent ext = extent_at(p, scales);
  const double h = size_at(p);
  return clear_of_lines(
      needed_moves(p, {{scales[0] + 2 * ext.margin / (layout_.tile_size[0] * h),
                        scales[1] + 2 * ext.margin / (layout_.tile_size[1] * h)}}));
}

// Grows tile i's side facing `sign` × its `axis` as far as the room there takes (at most to the
// full size), the opposite side kept where it is: the largest scale whose tile, its centre moved
// by half the growth, keeps the gap to the tiles around and crosses no feature line (bisection to
// a hundredth of a side). Updates the tile and its entry in `tiles`; returns whether it grew.
template <typename TriangleMesh, typename NamedParameters>
bool Surface_mosaic<TriangleMesh, NamedParameters>::grow_side(std::size_t i, int axis, double sign,
                                                              const internal::Point_search& search,
                                                              std::vector<Room_tile>& tiles) {
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  const double from = scale_[i][axis];
  if (!(from < 1))
    return false;
  const internal::Surface_point p = points_[i];
  const internal::Vec3 x = tile_x_axis(p);
  const internal::Vec3 direction = axis == 0 ? x : internal::cross(s.normal(p.face), x);
  const double side = layout_.tile_size[axis] * size_at(p);
  // The tile at scale t along the axis: its point and whether it fits there.
  const auto at = [&](double t) {
    return s.walk(p, (sign * 0.5 * (t - from) * side) * direction).p;
  };
  const auto fits = [&](double t, internal::Surface_point& q) {
    q = at(t);
    Room_probe probe = room_probe(q);
    probe.base = scale_[i];
    probe.base[axis] = 0;
    probe.dir = {{0, 0}};
    probe.dir[axis] = 1;
    std::array<double, 2> scales = scale_[i];
    scales[axis] = t;
    return room_at(probe, search, tiles, std::uint32_t(i)) >= t - 1e-9 &&
           (!features_ || clear_of_lines_by_grout(q, scales));
  };
  internal::Surface_point q{}, best{};
  double lo = from, hi = 1;
  if (fits(hi, q)) {
    lo = hi, best = q;
  } else {
    if (!fits(from + 0.01, q))
      return false;
    lo = from + 0.01, best = q;
    while (hi - lo > 0.01) {
      const double mid = 0.5 * (lo + hi);
      if (fits(mid, q))
        lo = mid, best = q;
      else
        hi = mid;
    }
  }
  scale_[i][axis] = lo;
  points_[i] = best;
  pos_[i] = s.position(best);
  chart_[i] = atlas_->chart_index_of(best.face);
  tiles[i] = room_tile(i);
  return true;
}

// Every tile as `room_at()` measures room against it.
template <typename TriangleMesh, typename NamedParameters>
std::vector<typename Surface_mosaic<TriangleMesh, NamedParameters>::Room_tile>
Surface_mosaic<TriangleMesh, NamedParameters>::room_tiles() const {
  std::vector<Room_tile> tiles(points_.size());
  for (std::size_t i = 0; i < points_.size(); ++i)
    tiles[i] = room_tile(i);
  return tiles;
}

// Tile i as `room_at()` measures room against it: where it stands, its axes and its half sides
// less half the gap.
template <typename TriangleMesh, typename NamedParameters>
typename Surface_mosaic<TriangleMesh, NamedParameters>::Room_tile
Surface_mosaic<TriangleMesh, NamedParameters>::room_tile(std::size_t i) const {
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  const double gap = separation_gap();
  const internal::Vec3 x = tile_x_axis(points_[i]), normal = s.normal(points_[i].face);
  return {points_[i],
          pos_[i],
          x,
          internal::cross(normal, x),
          normal,
          {{half_side(i, 0, gap), half_side(i, 1, gap)}},
          s.region(points_[i].face)};
}

// Whether q, a point of face f, lies under tile t (inside its rectangle less half the gap, near
// its plane, on its side of the surface and in its region).
template <typename TriangleMesh, typename NamedParameters>
bool Surface_mosaic<TriangleMesh, NamedParameters>::under(const Room_tile& t,
                                                          const internal::Vec3& q, std::uint32_t f,
                                                          double gap) const {
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  const double facing = internal::dot(t.normal, s.normal(f));
  const internal::Vec3 d = q - t.centre;
  if (facing <= 0 ||
      !share_room(t.region, s.region(f), facing, std::abs(internal::dot(d, t.normal))))
    return false;
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
  const double facing = internal::dot(t.normal, s.normal(f));
  const internal::Vec3 d = q - t.centre;
  if (facing <= 0 ||
      !share_room(t.region, s.region(f), facing, std::abs(internal::dot(d, t.normal))))
    return false;
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

// What `room_against()` needs of a tile about to be laid at p: its point, frame, size and region.
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
// along the axis that separates them best, their distance taken along the surface (the bend of
// their planes: `bent_length()`) and their footprints stretched where it curves, as
// `measure_tile()` does; a tile turned more than 90° from p (around a part thinner than a tile)
// foreshortened as `measure_tile()` sees it.
// Infinite for a tile the probe shares no room with (`share_room()`: more than 135° away, the
// other side of the surface, or in another region not overlapping it), or one that an axis the
// growth does not move along already separates.
template <typename TriangleMesh, typename NamedParameters>
double Surface_mosaic<TriangleMesh, NamedParameters>::room_against(const Room_probe& p,
                                                                   const Room_tile& t,
                                                                   double gap) const {
  const double far = std::numeric_limits<double>::infinity();
  const double facing = internal::dot(t.normal, p.normal);
  const internal::Vec3 d = t.centre - p.q;
  if (!share_room(p.region, t.region, facing, std::abs(internal::dot(d, p.normal))))
    return far;
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
  const std::array<double, 2> half =
      facing <= 0 ? internal::foreshortened_half(t.half, al, t.y, p.x, p.y) : t.half;
  double k = 1;
  const double seen = std::sqrt(dx * dx + dy * dy);
  const double along = internal::bent_length(internal::norm(d), facing);
  if (seen > 0 && along > seen) {
    const double w = 0.5 * p.h *
                     (layout_.tile_size[0] * std::abs(dx) + layout_.tile_size[1] * std::abs(dy)) /
                     seen;
    k = footprint_stretch(seen / along, along, w);
    dx *= along / seen, dy *= along / seen;
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
  // Room is measured as the filling measures it, against the tiles as they stand (a moved tile's
  // entry follows it; the search keeps the centres it was built on, within a move of them).
  const internal::Point_search search(pos_);
  std::vector<Room_tile> tiles = room_tiles();
  std::vector<char> keep(points_.size(), 1);
  std::size_t changed = 0, nudged = 0;
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const internal::Surface_point p = points_[i];
    const std::array<double, 2> shrink =
        i < scale_.size() ? scale_[i] : std::array<double, 2>{{1.0, 1.0}};
    const std::array<double, 4> need = needed_moves(p, shrink);
    const double radius = extent_at(p, shrink).radius;
    if (clear_of_lines(need))
      continue;
    ++changed;
    std::array<int, 4> order{{0, 1, 2, 3}};
    std::sort(order.begin(), order.end(), [&](int a, int b) { return need[a] < need[b]; });
    const internal::Vec3 x = tile_x_axis(p);
    const internal::Vec3 y = internal::cross(s.normal(p.face), x);
    // A move that clears the lines is taken where the tile fits there at its size. Moved as far
    // as the lines asked (up to twice its reach) regardless, tiles landed on their neighbours:
    // on oblong, two whole tiles 0.08 apart (a side is 2.8), and much of its 1 % overlap under
    // such pairs. Else the tile is cut to the lines (its other sides stay, so no new overlap); else
    // the clearing move with the most room (a tile of at least `min_tile_scale` fits there) is
    // taken and the trimming below cuts the overlap it makes; else the tile is left out.
    bool fits = false, has_nudge = false;
    double best_room = options_.min_tile_scale;
    internal::Surface_point nudge{};
    for (const int k : order) {
      if (!(need[k] > 0) || need[k] > 2 * radius)
        continue;
      const internal::Vec3 axis = (k < 2 ? x : y);
      const internal::Surface_point q = s.walk(p, ((k % 2 == 0 ? 1.0 : -1.0) * need[k]) * axis).p;
      if (!clear_of_lines(needed_moves(q, shrink)))
        continue;
      Room_probe probe = room_probe(q);
      probe.dir = shrink;
      const double room = room_at(probe, search, tiles, std::uint32_t(i));
      if (room >= 1 - 1e-9) {
        fits = true;
        nudge = q;
        break;
      }
      if (room > best_room)
        has_nudge = true, nudge = q, best_room = room;
    }
    const bool cut = !fits && cut_at_features(i);
    if (fits || (!cut && has_nudge)) {
      points_[i] = nudge;
      pos_[i] = s.position(nudge);
      chart_[i] = atlas_->chart_index_of(nudge.face);
      ++stats_.moved_off_features;
      nudged += !fits;
    } else if (cut) {
      ++stats_.cut_at_features;
    } else {
      keep[i] = 0, ++stats_.removed_at_features;
      continue;
    }
    tiles[i] = room_tile(i);
  }
  if (stats_.removed_at_features > 0)
    remove_tiles(keep);
  // The overlap the nudges made, trimmed as the separation trims (trimming only pulls sides in,
  // so no tile reaches over a line again).
  if (nudged > 0 && options_.count != Mosaic_count::exact && options_.separation_passes > 0) {
    scale_.resize(points_.size(), {{1.0, 1.0}});
    refresh_neighbors(true);
    Separation sep;
    stats_.close_pairs = trim_overlapping_tiles(sep);
    // The trimming's moves keep centres off the lines, which can push a corner of a tile in a
    // band narrower than a cell over the line across (couplingdown: 1-3 tiles): cut to it, or
    // left out.
    std::vector<char> kept(points_.size(), 1);
    std::size_t dropped = 0;
    for (std::size_t i = 0; i < points_.size(); ++i) {
      if (clear_of_lines(needed_moves(points_[i], scale_[i])))
        continue;
      if (cut_at_features(i))
        ++stats_.cut_at_features;
      else
        kept[i] = 0, ++dropped;
    }
    stats_.removed_at_features += dropped;
    if (dropped > 0)
      remove_tiles(kept);
  }
  // Tiles trimmed, cut or beside those left out grow into the room this left, and bare patches
  // get tiles (neither over a line); the tiles laid there grow into the slivers beside them.
  if (changed > 0 && options_.count != Mosaic_count::exact && options_.separation_passes > 0) {
    scale_.resize(points_.size(), {{1.0, 1.0}});
    stats_.grown_tiles += grow_tiles(true);
    if (fill_bare_patches(true) > 0)
      stats_.grown_tiles += grow_tiles(true);
  }
  return changed;
}

// Cuts tile i to the feature lines it crosses, as a mosaicist cuts a tessera to an edge: along one
// axis, each side that a line crosses is pulled in to half a grout from it (the other sides stay
// where they are, so no new overlap with the tiles beside it), then along the other axis if a
// line at a corner still crosses; of the two orders (x first, y first) the one leaving the larger
// tile; at least `min_tile_scale` of the size must be left along each. Returns false (the tile
// unchanged) when no such cut clears it. (On couplingdown at 3000 tiles, 130 tiles that no move
// cleared, 4 % of them, were left out before: rows along its creases end a fraction of a tile from
// the line, and bands between two creases are narrower than a tile.)
template <typename TriangleMesh, typename NamedParameters>
bool Surface_mosaic<TriangleMesh, NamedParameters>::cut_at_features(std::size_t i) {
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  const auto clears = [&](const internal::Surface_point& q, const std::array<double, 2>& scales) {
    return clear_of_lines(needed_moves(q, scales));
  };
  // The tile at p with `scales` cut along `axis` to the lines crossing it; false when a line
  // crosses its middle along that axis or too little would be left.
  const auto cut = [&](internal::Surface_point& p, std::array<double, 2>& scales, int axis) {
    const Extent ext = extent_at(p, scales);
    const internal::Vec3 at = s.position(p), n = s.normal(p.face), x = tile_x_axis(p);
    const internal::Vec3 y = internal::cross(n, x);
    const double half = axis == 0 ? ext.hx : ext.hy, band = axis == 0 ? ext.hy : ext.hx;
    double low = -half, high = half; // the tile's extent along the axis after the cut
    bool through = false;
    features_->segments_near(
        s.region(p.face), at, ext.radius, [&](const internal::Vec3& a3, const internal::Vec3& b3) {
          std::array<double, 2> a, b;
          if (!internal::segment_crosses_tile(a3 - at, b3 - at, x, y, n, ext.size, a, b))
            return;
          // The part of the segment within the tile's band across the axis (and half a grout
          // beyond it, as `needed_moves()` measures).
          double lo = 0, hi = 0;
          if (!internal::segment_extent_in_band(a, b, axis, band + ext.margin, lo, hi))
            return;
          if (hi < 0)
            low = std::max(low, hi + ext.margin);
          else if (lo > 0)
            high = std::min(high, lo - ext.margin);
          else
            through = true;
        });
    const double side = 2 * half / scales[axis]; // the side at scale 1
    if (through || !(high - low >= options_.min_tile_scale * side))
      return false;
    if (low == -half && high == half)
      return true; // nothing crosses along this axis
    const internal::Vec3& direction = axis == 0 ? x : y;
    p = s.walk(p, (0.5 * (low + high)) * direction).p;
    scales[axis] = (high - low) / side;
    return true;
  };
  const internal::Surface_point start = points_[i];
  const std::array<double, 2> shrink =
      i < scale_.size() ? scale_[i] : std::array<double, 2>{{1.0, 1.0}};
  bool found = false;
  double best_area = 0;
  internal::Surface_point best_point{};
  std::array<double, 2> best_scales{};
  for (const int first : {0, 1}) {
    internal::Surface_point p = start;
    std::array<double, 2> scales = shrink;
    if (!cut(p, scales, first))
      continue;
    if (!clears(p, scales) && !(cut(p, scales, 1 - first) && clears(p, scales)))
      continue;
    if (!found || scales[0] * scales[1] > best_area) {
      found = true;
      best_area = scales[0] * scales[1];
      best_point = p;
      best_scales = scales;
    }
  }
  if (!found)
    return false;
  if (scale_.size() < points_.size())
    scale_.resize(points_.size(), {{1.0, 1.0}});
  points_[i] = best_point;
  pos_[i] = s.position(best_point);
  chart_[i] = atlas_->chart_index_of(best_point.face);
  scale_[i] = best_scales;
  return true;
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
          const double half = axis == 0 ? hx : hy, band = (axis == 0 ? hy : hx) + margin;
          double lo = 0, hi = 0;
          if (!internal::segment_extent_in_band(a, b, axis, band, lo, hi))
            continue;
          need[2 * axis] = std::max(need[2 * axis], hi + half + margin);         // along +axis
          need[2 * axis + 1] = std::max(need[2 * axis + 1], half + margin - lo); // along −axis
        }
      });
  return need;
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

// Whether tiles in regions a and b, their normals `facing` (cosine) apart and one
// `plane_distance` from the other's plane, take room from each other: within a region unless
// they face away (past 135°, the other side of a part thinner than a tile); across regions only
// where the surface runs into itself, as the quality report sees it, tiles of different connected
// components on one sheet (within 45° and half a tile of each other's plane: patches that overlap
// at their seams, sheets that cross). Regions of one component meet at feature lines, whose walls
// keep their tiles apart already. (ALSTOM_TEST4, six patches overlapping at their seams: overlap
// 2.00 % -> 0.00 %, doc/mosaic.md.)
template <typename TriangleMesh, typename NamedParameters>
bool Surface_mosaic<TriangleMesh, NamedParameters>::share_room(std::uint32_t region_a,
                                                               std::uint32_t region_b,
                                                               double facing,
                                                               double plane_distance) const {
  if (region_a == region_b)
    return facing > -std::sqrt(0.5);
  return facing >= std::sqrt(0.5) && surface_->apart(region_a, region_b) &&
         plane_distance <= 0.5 * std::min(layout_.tile_size[0], layout_.tile_size[1]);
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
    // Tiles up to 135° apart: on a part thinner than a tile (horn and tail tips, hooves, ear
    // rims) tiles a quarter turn or more apart around it both cover its ridge. Skipping pairs
    // past 90° left that overlap unseen: 62 % of the bull's and 68 % of the cow's doubly
    // covered samples (quality report) lay under two such tiles. Past 120° (the report's limit
    // between a tile and a sample, so two tiles up to 240° apart can cover one rim) lay 24 % of
    // the armadillo's (seed 2: its overlap 1.02 % -> 0.82 % at 135°); past 135° tiles across
    // a part thinner than a tile pushed each other off it (a bare patch of 2.9 tiles on the bull).
    if (j >= n)
      continue;
    const internal::Vec3& nj = s.normal(points_[j].face);
    const double facing = internal::dot(nj, ni);
    const internal::Vec3 d = pos_[j] - pos_[i];
    if (!share_room(region, s.region(points_[j].face), facing, std::abs(internal::dot(d, ni))))
      continue;
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
    if (facing <= 0) // past 90°: j's rectangle as i's plane sees it
      hj = internal::foreshortened_half(hj, al, internal::cross(nj, sep.xs[j]), sep.xs[i],
                                        sep.ys[i]);
    const Box_overlap chord = box_overlap(hi, hj, ax, ay, dx, dy);
    // Along the surface the two are at least as far apart as the chord says.
    if (!(chord.depth > 0))
      continue;
    // How far apart the two are along the surface, in the direction the plane of i sees j:
    // where the surface curves, the chord projected onto i's plane is shorter than that, and
    // tiles one cell apart on a tube or in a groove would count as overlapping.
    const double along = internal::bent_length(internal::norm(d), facing);
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

} // namespace tessera
