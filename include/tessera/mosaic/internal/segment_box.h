// Whether a segment meets a tile (its rectangle, within a slab about its plane): what the quality
// report counts as a tile crossing a feature line and what the mosaic's last pass clears.
#pragma once

#include <tessera/fields/internal/vertex_frames.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace tessera::internal {

// Whether the segment a-b (2D, in a tile's frame) meets the box |x| <= hx, |y| <= hy
// (Liang–Barsky).
inline bool segment_meets_box(std::array<double, 2> a, std::array<double, 2> b, double hx,
                              double hy) {
  double t0 = 0, t1 = 1;
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double p[4] = {-dx, dx, -dy, dy}, q[4] = {a[0] + hx, hx - a[0], a[1] + hy, hy - a[1]};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0)
        return false;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
    if (t0 > t1)
      return false;
  }
  return true;
}

/// The tile's reach across its plane: a feature line's point under (or over) a tile's rectangle
/// counts only within this distance of the tile's plane, so a wall's other side does not.
inline double tile_half_thickness(const std::array<double, 2>& size) {
  return 0.5 * std::min(size[0], size[1]);
}

/// Half-side of the cube about a tile's centre that holds every point where a segment can cross
/// the tile (its rectangle and the slab about its plane): the box to ask a segment tree with.
inline double tile_reach(const std::array<double, 2>& size) {
  const double hx = 0.5 * size[0], hy = 0.5 * size[1], t = tile_half_thickness(size);
  return std::sqrt(hx * hx + hy * hy + t * t);
}

/// Clips the segment a-b (3D, relative to a tile's centre) to the slab within `half_thickness` of
/// the tile's plane (normal n) and gives the clipped part in the tile's frame (x, y) as a2-b2;
/// false when no part of the segment is that near the plane.
inline bool segment_near_tile_plane(const Vec3& a, const Vec3& b, const Vec3& x, const Vec3& y,
                                    const Vec3& n, double half_thickness, std::array<double, 2>& a2,
                                    std::array<double, 2>& b2) {
  const double da = dot(a, n), db = dot(b, n);
  double t0 = 0, t1 = 1;
  if (da != db) {
    double u0 = (-half_thickness - da) / (db - da), u1 = (half_thickness - da) / (db - da);
    if (u0 > u1)
      std::swap(u0, u1);
    t0 = std::max(t0, u0), t1 = std::min(t1, u1);
    if (t0 > t1)
      return false;
  } else if (std::abs(da) > half_thickness) {
    return false;
  }
  const Vec3 p = a + t0 * (b - a), q = a + t1 * (b - a);
  a2 = {{dot(p, x), dot(p, y)}};
  b2 = {{dot(q, x), dot(q, y)}};
  return true;
}

/// Whether the segment a-b (3D, relative to the centre of a tile of `size` with frame x, y, n)
/// crosses the tile: its part within the tile's half thickness of the plane meets the rectangle.
/// a2-b2 get that part in the tile's frame. The quality report counts these crossings and the
/// mosaic's last pass clears them, by this one test.
inline bool segment_crosses_tile(const Vec3& a, const Vec3& b, const Vec3& x, const Vec3& y,
                                 const Vec3& n, const std::array<double, 2>& size,
                                 std::array<double, 2>& a2, std::array<double, 2>& b2) {
  return segment_near_tile_plane(a, b, x, y, n, tile_half_thickness(size), a2, b2) &&
         segment_meets_box(a2, b2, 0.5 * size[0], 0.5 * size[1]);
}

/// The extent [lo, hi] along `axis` (0: x, 1: y) of the part of the segment a-b (in a tile's
/// frame) that lies within `band` of the tile's centre across that axis; false when no part does.
inline bool segment_extent_in_band(const std::array<double, 2>& a, const std::array<double, 2>& b,
                                   int axis, double band, double& lo, double& hi) {
  const int other = 1 - axis;
  double t0 = 0, t1 = 1;
  const double d = b[other] - a[other];
  if (d == 0) {
    if (std::abs(a[other]) > band)
      return false;
  } else {
    double u0 = (-band - a[other]) / d, u1 = (band - a[other]) / d;
    if (u0 > u1)
      std::swap(u0, u1);
    t0 = std::max(t0, u0), t1 = std::min(t1, u1);
    if (t0 > t1)
      return false;
  }
  const double c0 = a[axis] + t0 * (b[axis] - a[axis]), c1 = a[axis] + t1 * (b[axis] - a[axis]);
  lo = std::min(c0, c1), hi = std::max(c0, c1);
  return true;
}

} // namespace tessera::internal
