// Geometric textures with ground truth, for testing texture-preserving resizing (Chen and Meng
// 2010): a flat plate to carry them, and round bumps raised on a square or hexagonal lattice over a
// region of a plane or of a cylinder, each texel's centre, radius and vertices returned.
#pragma once

#include <tessera/generators/surfaces.h>

#include <CGAL/Polygon_mesh_processing/compute_normal.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace tessera {

/// A flat rectangle [0, width] × [0, height] in the plane z = 0, `cells_per_unit` grid cells per
/// unit of length, each cut into two triangles (normals +z, one boundary loop).
template <typename MutableFaceGraph>
void make_plate(MutableFaceGraph& tm, double width, double height, double cells_per_unit) {
  const std::size_t nx = std::max<std::size_t>(1, std::size_t(std::lround(width * cells_per_unit)));
  const std::size_t ny =
      std::max<std::size_t>(1, std::size_t(std::lround(height * cells_per_unit)));
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

enum class Texel_lattice { square, hexagonal };

/// Where texels go: in the plane's (x, y), or on a cylinder around the x axis at (x, r·θ) with θ
/// the angle around the axis from +y towards +z and r the distance from the axis.
enum class Texture_chart { plane_xy, cylinder_x };

struct Bump_texture_options {
  Texel_lattice lattice = Texel_lattice::square;
  Texture_chart chart = Texture_chart::plane_xy;
  /// Distance between neighbouring texel centres, in the chart.
  double spacing = 0.25;
  /// Footprint radius and height of each bump (a smooth cap, height·(1 − (d/radius)²)²).
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
      const double h = options.height * s * s;
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

} // namespace tessera
