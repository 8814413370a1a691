// Whether a segment meets a tile's rectangle, in the tile's own frame: what the quality report
// counts as a tile crossing a feature line and what the mosaic's last pass clears.
#pragma once

#include <algorithm>
#include <array>

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

} // namespace tessera::internal
