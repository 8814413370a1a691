// Geometric textures with ground truth, for testing texture-preserving resizing (Chen and Meng
// 2010): a flat plate and an open tube to carry them; round bumps or rivets raised on a square or
// hexagonal lattice over a region of a plane or of a cylinder, each texel's centre, radius and
// vertices returned; parallel ridges over such a region; and a helical screw thread on a cylinder
// (the papers' canal).
#pragma once

#include <tessera/generators/surfaces.h>

#include <array>
#include <cmath>
#include <cstddef>
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
Texture_ground_truth add_bump_lattice(MutableFaceGraph& tm, const Bump_texture_options& options);

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

/// Raises parallel ridges over a region of `tm` along the vertex normals. Each ridge is one texel
/// (its centre the middle of its line in the region, its radius the half width).
template <typename MutableFaceGraph>
Texture_ground_truth add_ridges(MutableFaceGraph& tm, const Ridge_texture_options& options);

/// Cuts a helical screw thread (a raised crest) into the cylinder part of `tm` around the x axis,
/// along the vertex normals. Each turn is one texel (its centre where the crest crosses +y, its
/// radius the half width).
template <typename MutableFaceGraph>
Texture_ground_truth add_screw_thread(MutableFaceGraph& tm, const Screw_thread_options& options);

} // namespace tessera

#include <tessera/generators/internal/textures_impl.h>
