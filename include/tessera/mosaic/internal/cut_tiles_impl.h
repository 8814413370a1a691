// Body of `cut_tiles()` (cut_tiles.h): each tile is clipped by each neighbour it overlaps, along
// the separating axis of least penetration, in the tile's own plane.
#pragma once

#include <tessera/mosaic/internal/point_search.h>
#include <tessera/mosaic/internal/tile_frames.h>
#include <tessera/mosaic/tile.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace tessera::internal {

using Polygon_2d = std::vector<std::array<double, 2>>;

inline double polygon_area(const Polygon_2d& p) {
  double a = 0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const auto& u = p[k];
    const auto& v = p[(k + 1) % p.size()];
    a += u[0] * v[1] - u[1] * v[0];
  }
  return a / 2;
}

/// Keeps the part of convex polygon `p` where n·x <= c.
inline Polygon_2d clip_half_plane(const Polygon_2d& p, std::array<double, 2> n, double c) {
  Polygon_2d out;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const auto& a = p[k];
    const auto& b = p[(k + 1) % p.size()];
    const double da = n[0] * a[0] + n[1] * a[1] - c, db = n[0] * b[0] + n[1] * b[1] - c;
    if (da <= 0)
      out.push_back(a);
    if ((da < 0 && db > 0) || (da > 0 && db < 0)) {
      const double t = da / (da - db);
      out.push_back({{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])}});
    }
  }
  return out;
}

/// Clips `poly` (tile i's outline in its frame; `rectangle` its whole rectangle) where tile j
/// overlaps it: along the separating axis of least penetration among both tiles' edge normals,
/// through the middle of the overlap and half a grout width towards i. Nothing when an axis
/// separates the two.
template <typename FaceDescriptor>
void clip_by_neighbour(Polygon_2d& poly, const Polygon_2d& rectangle,
                       const std::vector<Mosaic_tile<FaceDescriptor>>& tiles, const Tile_frames& f,
                       std::size_t i, std::size_t j, double grout_width) {
  // j's corners in i's frame.
  const Vec3 d = f.centres[j] - f.centres[i];
  const std::array<double, 2> c{{dot(d, f.xs[i]), dot(d, f.ys[i])}};
  const std::array<double, 2> jx{{dot(f.xs[j], f.xs[i]), dot(f.xs[j], f.ys[i])}};
  const std::array<double, 2> jy{{dot(f.ys[j], f.xs[i]), dot(f.ys[j], f.ys[i])}};
  const double ja = tiles[j].size[0] / 2, jb = tiles[j].size[1] / 2;
  Polygon_2d other;
  for (const auto& s : {std::array<double, 2>{{-1, -1}}, {{1, -1}}, {{1, 1}}, {{-1, 1}}})
    other.push_back({{c[0] + s[0] * ja * jx[0] + s[1] * jb * jy[0],
                      c[1] + s[0] * ja * jx[1] + s[1] * jb * jy[1]}});
  double best = std::numeric_limits<double>::infinity(), cut = 0;
  std::array<double, 2> axis{{1, 0}};
  // i and j each cut themselves, each in its own frame: both must pick the same axis, so near-ties
  // go to the lower-numbered tile's edge directions.
  const std::array<std::array<double, 2>, 4> normals{{{{1, 0}}, {{0, 1}}, jx, jy}};
  for (std::size_t a = 0; a < 4; ++a) {
    const auto& n = normals[a];
    const bool own = a < 2;
    const double bias = (own == (i < j)) ? 1.0 : 1.0 + 1e-6;
    const double l = std::hypot(n[0], n[1]);
    if (!(l > 0))
      continue;
    const std::array<double, 2> u{{n[0] / l, n[1] / l}};
    double lo_i = std::numeric_limits<double>::infinity(), hi_i = -lo_i, lo_j = lo_i, hi_j = -lo_i;
    for (const auto& p : rectangle)
      lo_i = std::min(lo_i, u[0] * p[0] + u[1] * p[1]),
      hi_i = std::max(hi_i, u[0] * p[0] + u[1] * p[1]);
    for (const auto& p : other)
      lo_j = std::min(lo_j, u[0] * p[0] + u[1] * p[1]),
      hi_j = std::max(hi_j, u[0] * p[0] + u[1] * p[1]);
    const double centre_i = (lo_i + hi_i) / 2, centre_j = (lo_j + hi_j) / 2;
    const bool j_ahead = centre_j >= centre_i;
    const double overlap = j_ahead ? hi_i - lo_j : hi_j - lo_i;
    if (overlap <= 0)
      return; // separated along this axis: no overlap at all
    if (overlap * bias < best) {
      best = overlap * bias;
      axis = j_ahead ? u : std::array<double, 2>{{-u[0], -u[1]}};
      // The cut runs through the middle of the overlap, half a grout width towards i.
      cut = (j_ahead ? (hi_i + lo_j) / 2 : -(hi_j + lo_i) / 2) - grout_width / 2;
    }
  }
  poly = clip_half_plane(poly, axis, cut);
}

template <typename FaceDescriptor>
void cut_tiles_impl(std::vector<Mosaic_tile<FaceDescriptor>>& tiles, double grout_width,
                    std::size_t neighbors, Cut_tiles_result& result) {
  const Tile_frames f = tile_frames(tiles);
  const Point_search search(f.centres);
  double total_area = 0;
  std::vector<Polygon_2d> outlines(tiles.size());
  std::vector<char> removed(tiles.size(), 0);
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const double a = tiles[i].size[0] / 2, b = tiles[i].size[1] / 2;
    const Polygon_2d rectangle{{{-a, -b}}, {{a, -b}}, {{a, b}}, {{-a, b}}};
    Polygon_2d poly = tiles[i].outline.empty() ? rectangle : tiles[i].outline;
    const double before = polygon_area(poly);
    total_area += before;
    search.nearest(f.centres[i], neighbors + 1, [&](std::size_t j, double) {
      if (j != i && !(dot(f.ns[i], f.ns[j]) < 0.5) && !poly.empty())
        clip_by_neighbour(poly, rectangle, tiles, f, i, j, grout_width);
    });
    const double after = poly.size() >= 3 ? polygon_area(poly) : 0;
    if (after < before * (1 - 1e-12)) {
      ++result.tiles_cut;
      result.area_removed += before - after;
      outlines[i] = poly.size() >= 3 ? poly : Polygon_2d{};
      removed[i] = poly.size() < 3;
    }
  }
  std::size_t kept = 0;
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    if (removed[i])
      continue;
    if (!outlines[i].empty())
      tiles[i].outline = outlines[i];
    tiles[kept++] = tiles[i];
  }
  result.tiles_removed = tiles.size() - kept;
  tiles.resize(kept);
  if (total_area > 0)
    result.fraction_removed = result.area_removed / total_area;
}

} // namespace tessera::internal
