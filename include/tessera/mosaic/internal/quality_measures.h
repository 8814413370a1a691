// The small measures mosaic_quality() takes (tessera/mosaic/quality_report.h): a percentile of a
// list, whether a point lies inside a tile's outline, and a vector carried from one tangent plane
// to another by the least rotation (how course drift compares neighbouring tiles' axes).
#pragma once

#include <tessera/mosaic/internal/surface_arrays.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace tessera::internal {

inline double percentile(std::vector<double> v, double q) {
  if (v.empty())
    return 0;
  const std::size_t k = std::min(v.size() - 1, std::size_t(q * double(v.size() - 1) + 0.5));
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
  return v[k];
}

// Whether point (x, y) lies inside the convex polygon `outline` (counter-clockwise).
inline bool inside_outline(const std::vector<std::array<double, 2>>& outline, double x, double y) {
  for (std::size_t k = 0; k < outline.size(); ++k) {
    const auto& a = outline[k];
    const auto& b = outline[(k + 1) % outline.size()];
    if ((b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0]) < 0)
      return false;
  }
  return true;
}

/// x turned by the least rotation that takes unit vector `from` to unit vector `to` (Rodrigues,
/// with v = from × to and c = from · to: x + v × x + v × (v × x) / (1 + c)); `from` and `to` must
/// not be opposite.
inline Vec3 turned(const Vec3& x, const Vec3& from, const Vec3& to) {
  const Vec3 v = cross(from, to);
  const double c = dot(from, to);
  return x + cross(v, x) + (1 / (1 + c)) * cross(v, cross(v, x));
}

} // namespace tessera::internal
