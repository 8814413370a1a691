// Tile colours taken from the model (Lai, Hu, Martin, "Surface Mosaics" §1.1: a mosaic renders the
// model's colours): each tile takes the mean colour of its footprint, sampled on a grid over its
// rectangle and read on the surface at the closest point to each sample (CGAL's
// `Polygon_mesh_processing::locate_with_AABB_tree`), from a texture image through per-vertex
// texture coordinates, from per-vertex colours, or from per-face colours. The colour under the
// tile's centre alone would make a tile astride two colours take one of them.
#pragma once

#include <tessera/io/image.h>
#include <tessera/mosaic/internal/surface_locator.h>
#include <tessera/mosaic/tile.h>
#include <tessera/render/scene.h>

#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

namespace tessera {

struct Tile_color_options {
  /// Each tile's rectangle is sampled at the centres of a k × k grid of cells.
  int samples_per_side = 6;
};

/// Gives every tile the mean of `color_at(point)` over a `samples_per_side`² grid on its rectangle
/// (the flat tile in 3D: centre, x axis, normal and size). `color_at` takes an
/// `std::array<double, 3>` and returns `std::optional<Color>`; samples it gives nothing for are
/// left out, and a tile with no sample keeps its colour. Returns how many tiles took a colour.
template <typename Tile, typename ColorAt>
std::size_t average_tile_colors(std::vector<Tile>& tiles, ColorAt&& color_at,
                                const Tile_color_options& options = {}) {
  const int k = std::max(1, options.samples_per_side);
  std::size_t colored = 0;
  for (Tile& t : tiles) {
    const auto& c = t.center;
    const auto& x = t.x_axis;
    const auto& n = t.normal;
    const std::array<double, 3> y{
        {n[1] * x[2] - n[2] * x[1], n[2] * x[0] - n[0] * x[2], n[0] * x[1] - n[1] * x[0]}};
    double r = 0, g = 0, b = 0;
    int count = 0;
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < k; ++j) {
        const double s = ((i + 0.5) / k - 0.5) * t.size[0], u = ((j + 0.5) / k - 0.5) * t.size[1];
        const std::array<double, 3> p{
            {c[0] + s * x[0] + u * y[0], c[1] + s * x[1] + u * y[1], c[2] + s * x[2] + u * y[2]}};
        if (const std::optional<Color> col = color_at(p)) {
          r += col->r, g += col->g, b += col->b;
          ++count;
        }
      }
    if (count == 0)
      continue;
    t.color = Color{r / count, g / count, b / count};
    ++colored;
  }
  return colored;
}

/// The colour of a texture image on a triangle mesh with texture coordinates per vertex (a vertex
/// property map of `std::array<double, 2>`, u to the right, v up, wrapping outside [0, 1]),
/// sampled bilinearly at the closest point of the mesh to a query. The mesh, map and image must
/// outlive it.
template <typename TriangleMesh, typename VertexUvMap> class Texture_colors {
public:
  Texture_colors(const TriangleMesh& tm, VertexUvMap uv, const Rgb_image& image)
      : locator_(tm), uv_(uv), image_(image) {}
  std::optional<Color> operator()(const std::array<double, 3>& p) const {
    if (image_.empty())
      return std::nullopt;
    const auto at = locator_.locate(p);
    if (!at)
      return std::nullopt;
    double u = 0, t = 0;
    for (int i = 0; i < 3; ++i) {
      const auto c = get(uv_, at->corner[i]);
      u += at->weight[i] * double(c[0]);
      t += at->weight[i] * double(c[1]);
    }
    if (!std::isfinite(u) || !std::isfinite(t))
      return std::nullopt;
    // Pixel centres at (x + 0.5, y + 0.5) / size; rows run down, v up.
    const double fx = (u - std::floor(u)) * image_.width - 0.5,
                 fy = (1 - (t - std::floor(t))) * image_.height - 0.5;
    const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
    const double ax = fx - x0, ay = fy - y0;
    auto pixel = [&](int x, int y) {
      x = ((x % image_.width) + image_.width) % image_.width;
      y = std::clamp(y, 0, image_.height - 1);
      return image_.at(x, y);
    };
    std::array<double, 3> sum{{0, 0, 0}};
    for (int dy = 0; dy < 2; ++dy)
      for (int dx = 0; dx < 2; ++dx) {
        const double weight = (dx ? ax : 1 - ax) * (dy ? ay : 1 - ay);
        const auto c = pixel(x0 + dx, y0 + dy);
        for (int i = 0; i < 3; ++i)
          sum[i] += weight * c[i];
      }
    return Color{sum[0] / 255, sum[1] / 255, sum[2] / 255};
  }

private:
  internal::Surface_locator<TriangleMesh> locator_;
  VertexUvMap uv_;
  const Rgb_image& image_;
};

/// Per-vertex colours (a vertex property map of `Color`) interpolated at the closest point of the
/// mesh to a query. The mesh and map must outlive it.
template <typename TriangleMesh, typename VertexColorMap> class Vertex_colors {
public:
  Vertex_colors(const TriangleMesh& tm, VertexColorMap colors) : locator_(tm), colors_(colors) {}
  std::optional<Color> operator()(const std::array<double, 3>& p) const {
    const auto at = locator_.locate(p);
    if (!at)
      return std::nullopt;
    Color c{0, 0, 0};
    for (int i = 0; i < 3; ++i) {
      const Color ci = get(colors_, at->corner[i]);
      c.r += at->weight[i] * ci.r, c.g += at->weight[i] * ci.g, c.b += at->weight[i] * ci.b;
    }
    return c;
  }

private:
  internal::Surface_locator<TriangleMesh> locator_;
  VertexColorMap colors_;
};

/// Per-face colours (a face property map of `Color`) at the closest point of the mesh to a query.
template <typename TriangleMesh, typename FaceColorMap> class Face_colors {
public:
  Face_colors(const TriangleMesh& tm, FaceColorMap colors) : locator_(tm), colors_(colors) {}
  std::optional<Color> operator()(const std::array<double, 3>& p) const {
    const auto at = locator_.locate(p);
    if (!at)
      return std::nullopt;
    return Color(get(colors_, at->face));
  }

private:
  internal::Surface_locator<TriangleMesh> locator_;
  FaceColorMap colors_;
};

} // namespace tessera
