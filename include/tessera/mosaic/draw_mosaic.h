// Pictures and meshes of a mosaic: the tiles as coloured flat polygons lifted a little off the
// surface, over the mesh drawn in the grout's colour, for `render_png()` or any mesh viewer.
#pragma once

#include <tessera/mosaic/tile.h>
#include <tessera/render/mesh_scene.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace tessera {

struct Mosaic_drawing_options {
  Color grout{0.28, 0.27, 0.25};
  /// Tiles float this far (× the shorter tile side) above the surface, so that the surface does not
  /// show through where it bulges between a tile's corners.
  double lift = 0.08;
  /// Each tile's brightness varies by up to this fraction (a fixed pseudo-random amount per tile),
  /// as real tesserae do: without it, tiles of one colour with thin grout read as one surface.
  double shade_variation = 0.12;
};

/// The tile's outline in 3D, counter-clockwise about its normal, lifted by `lift` along the normal:
/// its four corners, or the clipped outline of `cut_tiles()`.
template <typename FaceDescriptor>
std::vector<std::array<double, 3>> tile_polygon(const Mosaic_tile<FaceDescriptor>& t,
                                                double lift = 0) {
  const auto& n = t.normal;
  const auto& x = t.x_axis;
  const std::array<double, 3> y{
      {n[1] * x[2] - n[2] * x[1], n[2] * x[0] - n[0] * x[2], n[0] * x[1] - n[1] * x[0]}};
  std::vector<std::array<double, 2>> outline = t.outline;
  if (outline.empty()) {
    const double a = t.size[0] / 2, b = t.size[1] / 2;
    outline = {{{-a, -b}}, {{a, -b}}, {{a, b}}, {{-a, b}}};
  }
  std::vector<std::array<double, 3>> out;
  for (const auto& p : outline)
    out.push_back({{t.center[0] + p[0] * x[0] + p[1] * y[0] + lift * n[0],
                    t.center[1] + p[0] * x[1] + p[1] * y[1] + lift * n[1],
                    t.center[2] + p[0] * x[2] + p[1] * y[2] + lift * n[2]}});
  return out;
}

/// Appends the mesh in the grout colour and every tile as a fan of triangles in its colour. The
/// tiles count as a tile's length nearer to the eye in the depth test (`triangle_depth_bias`): a
/// tile then hides the grout under it, also where the surface bulges between its corners, but not
/// a part of the surface that passes in front of it.
template <typename FaceGraph, typename FaceDescriptor>
void add_mosaic(Render_scene& scene, const FaceGraph& tm,
                const std::vector<Mosaic_tile<FaceDescriptor>>& tiles,
                const Mosaic_drawing_options& options = {}) {
  add_mesh(scene, tm, options.grout);
  scene.triangle_depth_bias.resize(scene.triangles.size(), 0.0);
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const auto& t = tiles[i];
    const auto polygon = tile_polygon(t, options.lift * std::min(t.size[0], t.size[1]));
    // A hash of the index in [-1, 1] (Knuth's multiplicative hash).
    const double h = double((std::uint32_t(i) * 2654435761u) >> 8) / double(1u << 24) * 2 - 1;
    const double k = 1 + options.shade_variation * h;
    const Color c{std::min(1.0, t.color.r * k), std::min(1.0, t.color.g * k),
                  std::min(1.0, t.color.b * k)};
    const std::size_t first = scene.positions.size();
    scene.positions.insert(scene.positions.end(), polygon.begin(), polygon.end());
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
      scene.triangles.push_back({{first, first + k, first + k + 1}});
      scene.triangle_colors.push_back(c);
      scene.triangle_depth_bias.push_back(std::max(t.size[0], t.size[1]));
    }
  }
}

} // namespace tessera
