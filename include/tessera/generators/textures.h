// Geometric textures with ground truth, for testing texture-preserving resizing (Chen and Meng
// 2010): a flat plate and an open tube to carry them; round bumps or rivets raised on a square or
// hexagonal lattice over a region of a plane or of a cylinder, each texel's centre, radius and
// vertices returned; parallel ridges over such a region; and a helical screw thread on a cylinder
// (the papers' canal).
#pragma once

#include <tessera/generators/surfaces.h>

#include <CGAL/Polygon_mesh_processing/compute_normal.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <stdexcept>
#include <vector>

namespace tessera {

/// A flat rectangle [0, width] × [0, height] in the plane z = 0 with `cells_x` and `cells_y` grid
/// cells per unit of length along x and y (anisotropic sampling, as scanners and CAD exports
/// produce), each cut into two triangles (normals +z, one boundary loop).
template <typename MutableFaceGraph>
void make_plate(MutableFaceGraph& tm, double width, double height, double cells_x, double cells_y) {
  const std::size_t nx = std::max<std::size_t>(1, std::size_t(std::lround(width * cells_x)));
  const std::size_t ny = std::max<std::size_t>(1, std::size_t(std::lround(height * cells_y)));
  std::vector<std::array<double, 3>> coords;
  std::vector<std::array<std::size_t, 3>> triangles;
  for (std::size_t j = 0; j <= ny; ++j)
    for (std::size_t i = 0; i <= nx; ++i)
      coords.push_back({{width * double(i) / double(nx), height * double(j) / double(ny), 0}});
  auto id = [&](std::size_t i, std::size_t j) { return j * (nx + 1) + i; };
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      triangles.push_back({{id(i, j), id(i + 1, j), id(i + 1, j + 1)}});
      triangles.push_back({{id(i, j), id(i + 1, j + 1), id(i, j + 1)}});
    }
  internal::soup_to_mesh(coords, triangles, tm);
}

/// The same plate with square cells, `cells_per_unit` per unit of length.
template <typename MutableFaceGraph>
void make_plate(MutableFaceGraph& tm, double width, double height, double cells_per_unit) {
  make_plate(tm, width, height, cells_per_unit, cells_per_unit);
}

/// An open tube: the cylinder of radius `radius` around the x axis for x in [−length/2, length/2],
/// `segments` edges around and rows about as far apart, each quad cut into two triangles (normals
/// outwards, two boundary loops).
template <typename MutableFaceGraph>
void make_tube(MutableFaceGraph& tm, double radius, double length, std::size_t segments) {
  if (segments < 3 || !(radius > 0) || !(length > 0))
    throw std::invalid_argument("make_tube: need 3 segments or more, a positive radius and length");
  const double pi = std::acos(-1.0);
  const std::size_t rows = std::max<std::size_t>(
      1, std::size_t(std::lround(length * double(segments) / (2 * pi * radius))));
  std::vector<std::array<double, 3>> coords;
  std::vector<std::array<std::size_t, 3>> triangles;
  for (std::size_t j = 0; j <= rows; ++j)
    for (std::size_t i = 0; i < segments; ++i) {
      const double theta = 2 * pi * double(i) / double(segments);
      coords.push_back({{-0.5 * length + length * double(j) / double(rows),
                         radius * std::cos(theta), radius * std::sin(theta)}});
    }
  auto id = [&](std::size_t j, std::size_t i) { return j * segments + i % segments; };
  for (std::size_t j = 0; j < rows; ++j)
    for (std::size_t i = 0; i < segments; ++i) {
      triangles.push_back({{id(j, i), id(j, i + 1), id(j + 1, i + 1)}});
      triangles.push_back({{id(j, i), id(j + 1, i + 1), id(j + 1, i)}});
    }
  internal::soup_to_mesh(coords, triangles, tm);
}

enum class Texel_lattice { square, hexagonal };

/// Where texels go: in the plane's (x, y), or on a cylinder around the x axis at (x, r·θ) with θ
/// the angle around the axis from +y towards +z and r the distance from the axis.
enum class Texture_chart { plane_xy, cylinder_x };

/// The cross-section of a bump: a smooth cap h·(1 − (d/r)²)², a rivet's round head
/// h·√(1 − (d/r)²), steep at its rim, or a Gaussian h·exp(−(d/σ)²/2) with σ = r/3, cut at r.
enum class Bump_profile { cap, rivet, gaussian };

struct Bump_texture_options {
  Texel_lattice lattice = Texel_lattice::square;
  Bump_profile profile = Bump_profile::cap;
  Texture_chart chart = Texture_chart::plane_xy;
  /// Distance between neighbouring texel centres, in the chart.
  double spacing = 0.25;
  /// Footprint radius and height of each bump (its shape: `profile`).
  double radius = 0.09;
  double height = 0.05;
  /// The textured region of the chart: u in [min[0], max[0]], v in [min[1], max[1]]; texels whose
  /// footprint would leave it are left out.
  std::array<double, 2> min{{0, 0}}, max{{1, 1}};
};

/// One texel: its centre on the surface before displacement, its footprint radius, and the indices
/// (in the order of `vertices(tm)`) of the vertices it raised.
struct Texel {
  std::array<double, 3> center{{0, 0, 0}};
  double radius = 0;
  std::vector<std::size_t> vertices;
};

struct Texture_ground_truth {
  std::vector<Texel> texels;
  /// Per vertex (in the order of `vertices(tm)`): its displacement along the normal (0 off texels).
  std::vector<double> height;
};

/// Raises round bumps on a lattice over a region of `tm` along the vertex normals (CGAL's
/// `compute_vertex_normal`, taken before any vertex moves). The mesh should be fine enough for a
/// texel to cover several vertices (spacing of a few edge lengths).
template <typename MutableFaceGraph>
Texture_ground_truth add_bump_lattice(MutableFaceGraph& tm, const Bump_texture_options& options) {
  if (!(options.spacing > 0) || !(options.radius > 0) || options.radius > 0.5 * options.spacing)
    throw std::invalid_argument("add_bump_lattice: need 0 < radius <= spacing / 2");
  using Point = typename boost::property_traits<
      typename boost::property_map<MutableFaceGraph, CGAL::vertex_point_t>::type>::value_type;
  auto vpm = get(CGAL::vertex_point, tm);
  const std::vector<typename boost::graph_traits<MutableFaceGraph>::vertex_descriptor> verts(
      vertices(tm).begin(), vertices(tm).end());
  auto chart = [&](const Point& p) -> std::array<double, 2> {
    if (options.chart == Texture_chart::plane_xy)
      return {{CGAL::to_double(p.x()), CGAL::to_double(p.y())}};
    const double y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
    return {{CGAL::to_double(p.x()), std::hypot(y, z) * std::atan2(z, y)}};
  };
  // Lattice centres inside the region.
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
  Texture_ground_truth truth;
  truth.height.assign(verts.size(), 0);
  truth.texels.resize(centres.size());
  std::vector<Point> moved(verts.size());
  for (std::size_t i = 0; i < verts.size(); ++i) {
    const Point p = get(vpm, verts[i]);
    moved[i] = p;
    const auto uv = chart(p);
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

/// Parallel ridges over a region of a chart (plane or cylinder, as for bumps).
struct Ridge_texture_options {
  Texture_chart chart = Texture_chart::plane_xy;
  /// Direction of the ridges in the chart, radians from the u axis (0: ridges along u).
  double angle = 0;
  /// Distance between neighbouring ridges, and each ridge's half width and height (cross-section
  /// height·(1 − (d/half_width)²)², d the distance to the ridge's line).
  double spacing = 0.25;
  double half_width = 0.08;
  double height = 0.04;
  /// The textured region of the chart (u in [min[0], max[0]], v in [min[1], max[1]]).
  std::array<double, 2> min{{0, 0}}, max{{1, 1}};
};

/// A helical screw thread on the cylinder of radius `radius` around the x axis: one ridge whose
/// crest advances `pitch` along the axis per turn (right-handed: θ grows from +y towards +z as x
/// grows), over x in [min_x, max_x].
struct Screw_thread_options {
  double radius = 1;
  double pitch = 0.4;
  /// Half width of the crest's footprint along the axis, and its height (cross-section as for
  /// ridges).
  double half_width = 0.12;
  double height = 0.06;
  double min_x = -1, max_x = 1;
};

namespace internal {

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

/// Raises parallel ridges over a region of `tm` along the vertex normals. Each ridge is one texel
/// (its centre the middle of its line in the region, its radius the half width).
template <typename MutableFaceGraph>
Texture_ground_truth add_ridges(MutableFaceGraph& tm, const Ridge_texture_options& options) {
  if (!(options.spacing > 0) || !(options.half_width > 0) ||
      options.half_width > 0.5 * options.spacing)
    throw std::invalid_argument("add_ridges: need 0 < half_width <= spacing / 2");
  const double cu = std::cos(options.angle), cv = std::sin(options.angle);
  Texture_ground_truth truth;
  std::vector<long> ridge_of;
  auto chart = [&](const auto& p) -> std::array<double, 2> {
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
    if (options.chart == Texture_chart::plane_xy)
      return {{x, y}};
    return {{x, std::hypot(y, z) * std::atan2(z, y)}};
  };
  // Signed distance across the ridges from the region's centre, and the ridge it falls on.
  const double mu = 0.5 * (options.min[0] + options.max[0]),
               mv = 0.5 * (options.min[1] + options.max[1]);
  truth.height = internal::displace_along_normals(tm, [&](const auto& p) {
    const auto uv = chart(p);
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

/// Cuts a helical screw thread (a raised crest) into the cylinder part of `tm` around the x axis,
/// along the vertex normals. Each turn is one texel (its centre where the crest crosses +y, its
/// radius the half width).
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
