// to_double_array() and unit_normal(): points and face normals in double, for the edge costs of
// tessera/topology/edge_cost.h and the cutting-path searches.
#pragma once

#include <CGAL/number_utils.h>

#include <array>
#include <cmath>

namespace tessera::internal {

/// Coordinates in double: costs are a numeric stage, computed the same way whatever the kernel, so
/// that Epick and Epeck meshes with the same input coordinates get bitwise equal costs.
template <typename Point> std::array<double, 3> to_double_array(const Point& p) {
  return {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
}

/// The unit normal of triangle abc (zero when it has no area).
inline std::array<double, 3> unit_normal(const std::array<double, 3>& a,
                                         const std::array<double, 3>& b,
                                         const std::array<double, 3>& c) {
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  std::array<double, 3> n{
      {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]}};
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (len > 0)
    for (double& x : n)
      x /= len;
  return n;
}

} // namespace tessera::internal
