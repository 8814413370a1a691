// The texture generators behind add_bump_lattice(), add_ridges() and add_screw_thread()
// (tessera/generators/textures.h): chart coordinates, the bump lattice, displacement along the
// normals and the grouping of raised vertices into texels. Included at the end of textures.h.
#pragma once

#include <tessera/generators/textures.h>

#include <CGAL/Polygon_mesh_processing/compute_normal.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <stdexcept>
#include <vector>

namespace tessera {

namespace internal {

// The chart coordinates (u, v) of `p` (see `Texture_chart`).
template <typename Point>
std::array<double, 2> chart_coordinates(Texture_chart chart, const Point& p) {
  const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
  if (chart == Texture_chart::plane_xy)
    return {{x, y}};
  return {{x, std::hypot(y, z) * std::atan2(z, y)}};
}

// The lattice centres (in the chart) of the bumps whose footprints lie inside the region, row by
// row.
inline std::vector<std::array<double, 2>> lattice_centres(const Bump_texture_options& options) {
  std::vector<std::array<double, 2>> centres;
  const double row = options.lattice == Texel_lattice::square
                         ? options.spacing
                         : options.spacing * std::sqrt(3.0) / 2;
  std::size_t r = 0;
  for (double v = options.min[1] + options.radius; v <= options.max[1] - options.radius + 1e-12;
       v += row, ++r) {
    const double shift =
        options.lattice == Texel_lattice::hexagonal && r % 2 == 1 ? 0.5 * options.spacing : 0;
    for (double u = options.min[0] + options.radius + shift;
         u <= options.max[0] - options.radius + 1e-12; u += options.spacing)
      centres.push_back({{u, v}});
  }
  return centres;
}

// Displaces every vertex of `tm` along its normal (taken before any vertex moves) by
// `height_of(point)`, and returns the displacements in the order of `vertices(tm)`.
template <typename MutableFaceGraph, typename HeightOf>
std::vector<double> displace_along_normals(MutableFaceGraph& tm, HeightOf&& height_of) {
  auto vpm = get(CGAL::vertex_point, tm);
  using Point = typename boost::property_traits<decltype(vpm)>::value_type;
  std::vector<typename boost::graph_traits<MutableFaceGraph>::vertex_descriptor> verts(
      vertices(tm).begin(), vertices(tm).end());
  std::vector<double> height(verts.size(), 0);
  std::vector<Point> moved(verts.size());
  for (std::size_t i = 0; i < verts.size(); ++i) {
    const Point p = get(vpm, verts[i]);
    moved[i] = p;
    height[i] = height_of(p);
    if (height[i] != 0)
      moved[i] = p + height[i] * CGAL::Polygon_mesh_processing::compute_vertex_normal(verts[i], tm);
  }
  for (std::size_t i = 0; i < verts.size(); ++i)
    put(vpm, verts[i], moved[i]);
  return height;
}

constexpr long no_texel = std::numeric_limits<long>::min();

// Groups the vertices by texel label (`no_texel`: none) into `truth.texels`, in the order the
// texels are first met; `start(texel, label, first_vertex)` sets a new texel's centre and radius.
template <typename Start>
void group_texels(const std::vector<long>& label, Texture_ground_truth& truth, Start&& start) {
  std::map<long, std::size_t> texel_of;
  for (std::size_t i = 0; i < label.size(); ++i) {
    if (label[i] == no_texel)
      continue;
    const auto [it, added] = texel_of.emplace(label[i], truth.texels.size());
    if (added) {
      truth.texels.emplace_back();
      start(truth.texels.back(), label[i], i);
    }
    truth.texels[it->second].vertices.push_back(i);
  }
}

inline double ridge_section(double d, double half_width, double height) {
  if (!(std::abs(d) < half_width))
    return 0;
  const double s = 1 - (d / half_width) * (d / half_width);
  return height * s * s;
}

} // namespace internal

template <typename MutableFaceGraph>
Texture_ground_truth add_bump_lattice(MutableFaceGraph& tm, const Bump_texture_options& options) {
  if (!(options.spacing > 0) || !(options.radius > 0) || options.radius > 0.5 * options.spacing)
    throw std::invalid_argument("add_bump_lattice: need 0 < radius <= spacing / 2");
  using Point = typename boost::property_traits<
      typename boost::property_map<MutableFaceGraph, CGAL::vertex_point_t>::type>::value_type;
  auto vpm = get(CGAL::vertex_point, tm);
  const std::vector<typename boost::graph_traits<MutableFaceGraph>::vertex_descriptor> verts(
      vertices(tm).begin(), vertices(tm).end());
  const std::vector<std::array<double, 2>> centres = internal::lattice_centres(options);
  Texture_ground_truth truth;
  truth.height.assign(verts.size(), 0);
  truth.texels.resize(centres.size());
  std::vector<Point> moved(verts.size());
  for (std::size_t i = 0; i < verts.size(); ++i) {
    const Point p = get(vpm, verts[i]);
    moved[i] = p;
    const auto uv = internal::chart_coordinates(options.chart, p);
    // The nearest centre is the only one whose footprint can hold the point (radius ≤ spacing/2).
    for (std::size_t c = 0; c < centres.size(); ++c) {
      const double d = std::hypot(uv[0] - centres[c][0], uv[1] - centres[c][1]);
      if (d >= options.radius)
        continue;
      const double s = 1 - (d / options.radius) * (d / options.radius);
      const double h =
          options.height * (options.profile == Bump_profile::cap     ? s * s
                            : options.profile == Bump_profile::rivet ? std::sqrt(s)
                                                                     : std::exp(-4.5 * (1 - s)));
      const auto n = CGAL::Polygon_mesh_processing::compute_vertex_normal(verts[i], tm);
      moved[i] = p + h * n;
      truth.height[i] = h;
      truth.texels[c].vertices.push_back(i);
      break;
    }
  }
  for (std::size_t c = 0; c < centres.size(); ++c) {
    truth.texels[c].radius = options.radius;
    const double u = centres[c][0], v = centres[c][1];
    if (options.chart == Texture_chart::plane_xy) {
      truth.texels[c].center = {{u, v, 0}};
    } else {
      // The cylinder's radius at the texel: that of its first vertex.
      double radius = 1;
      if (!truth.texels[c].vertices.empty()) {
        const Point& p = get(vpm, verts[truth.texels[c].vertices.front()]);
        radius = std::hypot(CGAL::to_double(p.y()), CGAL::to_double(p.z()));
      }
      const double theta = v / radius;
      truth.texels[c].center = {{u, radius * std::cos(theta), radius * std::sin(theta)}};
    }
  }
  for (std::size_t i = 0; i < verts.size(); ++i)
    put(vpm, verts[i], moved[i]);
  return truth;
}

template <typename MutableFaceGraph>
Texture_ground_truth add_ridges(MutableFaceGraph& tm, const Ridge_texture_options& options) {
  if (!(options.spacing > 0) || !(options.half_width > 0) ||
      options.half_width > 0.5 * options.spacing)
    throw std::invalid_argument("add_ridges: need 0 < half_width <= spacing / 2");
  const double cu = std::cos(options.angle), cv = std::sin(options.angle);
  Texture_ground_truth truth;
  std::vector<long> ridge_of;
  // Signed distance across the ridges from the region's centre, and the ridge it falls on.
  const double mu = 0.5 * (options.min[0] + options.max[0]),
               mv = 0.5 * (options.min[1] + options.max[1]);
  truth.height = internal::displace_along_normals(tm, [&](const auto& p) {
    const auto uv = internal::chart_coordinates(options.chart, p);
    long ridge = internal::no_texel;
    double h = 0;
    if (uv[0] >= options.min[0] && uv[0] <= options.max[0] && uv[1] >= options.min[1] &&
        uv[1] <= options.max[1]) {
      const double across = -(uv[0] - mu) * cv + (uv[1] - mv) * cu;
      const double k = std::round(across / options.spacing);
      h = internal::ridge_section(across - k * options.spacing, options.half_width, options.height);
      if (h > 0)
        ridge = long(k);
    }
    ridge_of.push_back(ridge);
    return h;
  });
  auto vpm = get(CGAL::vertex_point, tm);
  const std::vector<typename boost::graph_traits<MutableFaceGraph>::vertex_descriptor> verts(
      vertices(tm).begin(), vertices(tm).end());
  internal::group_texels(ridge_of, truth, [&](Texel& texel, long ridge, std::size_t first) {
    const double k = double(ridge) * options.spacing;
    const double u = mu - k * cv, v = mv + k * cu;
    if (options.chart == Texture_chart::plane_xy) {
      texel.center = {{u, v, 0}};
    } else { // on the cylinder through the ridge's first vertex (before it was raised)
      const auto& p = get(vpm, verts[first]);
      const double r =
          std::hypot(CGAL::to_double(p.y()), CGAL::to_double(p.z())) - truth.height[first];
      texel.center = {{u, r * std::cos(v / r), r * std::sin(v / r)}};
    }
    texel.radius = options.half_width;
  });
  return truth;
}

template <typename MutableFaceGraph>
Texture_ground_truth add_screw_thread(MutableFaceGraph& tm, const Screw_thread_options& options) {
  if (!(options.pitch > 0) || !(options.half_width > 0) ||
      options.half_width > 0.5 * options.pitch || !(options.radius > 0))
    throw std::invalid_argument("add_screw_thread: need 0 < half_width <= pitch / 2, radius > 0");
  const double two_pi = 2 * std::acos(-1.0);
  Texture_ground_truth truth;
  std::vector<long> turn_of;
  truth.height = internal::displace_along_normals(tm, [&](const auto& p) {
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
    long turn = internal::no_texel;
    double h = 0;
    // On the cylinder (not its caps) within the thread's length.
    if (x >= options.min_x && x <= options.max_x &&
        std::abs(std::hypot(y, z) - options.radius) <= 1e-6 * options.radius) {
      // The crest passes x = min_x + pitch·(k + θ/2π) at angle θ.
      const double phase = (x - options.min_x) / options.pitch - std::atan2(z, y) / two_pi;
      const double k = std::round(phase);
      h = internal::ridge_section((phase - k) * options.pitch, options.half_width, options.height);
      if (h > 0)
        turn = long(k);
    }
    turn_of.push_back(turn);
    return h;
  });
  internal::group_texels(turn_of, truth, [&](Texel& texel, long turn, std::size_t) {
    texel.center = {{options.min_x + options.pitch * double(turn), options.radius, 0}};
    texel.radius = options.half_width;
  });
  return truth;
}

} // namespace tessera
