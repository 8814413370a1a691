// The tiles of a surface mosaic and their sizes: a tile is a flat l_x × l_y rectangle centred on
// the surface, oriented by the direction field, with grout around it (Lai, Hu, Martin, "Surface
// Mosaics", The Visual Computer 22, 2006, §3). Shared by every stage of the mosaic module.
#pragma once

#include <tessera/render/scene.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace tessera {

/// One tile of a mosaic, in the mesh's coordinates. `x_axis` is the unit direction of the side of
/// length `size[0]` (the field's direction at the tile), `normal` the unit normal of the tile's
/// plane; the tile's corners are center ± size[0]/2 · x_axis ± size[1]/2 · (normal × x_axis).
template <typename FaceDescriptor> struct Mosaic_tile {
  std::array<double, 3> center{{0, 0, 0}};
  std::array<double, 3> normal{{0, 0, 1}};
  std::array<double, 3> x_axis{{1, 0, 0}};
  std::array<double, 2> size{{0, 0}};
  /// The face the centre lies in, and the centre's barycentric coordinates in it (in the order of
  /// `vertices_around_face(halfedge(face, tm), tm)`).
  FaceDescriptor face{};
  std::array<double, 3> barycentric{{1.0 / 3, 1.0 / 3, 1.0 / 3}};
  /// Region: the connected part of the surface between feature lines the tile belongs to.
  std::size_t region = 0;
  Color color{0.8, 0.8, 0.8};
  /// The tile's outline in its plane when `cut_tiles()` clipped it (counter-clockwise about
  /// `normal`, in (x_axis, normal × x_axis) coordinates about `center`); empty for a whole
  /// rectangle.
  std::vector<std::array<double, 2>> outline;
};

/// How big the tiles are: set either `tile_size` (l_x, l_y; l_y = 0 for square tiles) or
/// `tile_count` N with `aspect` η = l_x / l_y, and the grout fraction g. With a count,
/// N = (1 − g)·A / (l_x·l_y) (Lai et al. §3.2), A the surface area.
struct Mosaic_tile_size {
  std::array<double, 2> tile_size{{0, 0}};
  std::size_t tile_count = 0;
  double aspect = 1;
  /// Fraction of the surface left to grout between tiles (0.1 is a mosaicist's usual choice).
  double grout = 0.1;
};

/// Symmetry of the field such tiles follow: 4 (a cross field) for square tiles, 2 (a line field)
/// for rectangles, whose long side must follow one direction of the field.
inline int mosaic_field_symmetry(const Mosaic_tile_size& t) {
  const bool rectangles =
      t.tile_size[0] > 0 ? t.tile_size[1] > 0 && t.tile_size[1] != t.tile_size[0] : t.aspect != 1;
  return rectangles ? 2 : 4;
}

/// The layout that follows from `Mosaic_tile_size` on a surface of area `area`.
struct Mosaic_layout {
  /// Tile sides (l_x, l_y) along the field's x and y directions.
  std::array<double, 2> tile_size{{0, 0}};
  /// Number of tiles to place.
  std::size_t tile_count = 0;
  /// Aspect η = l_x / l_y.
  double aspect = 1;
  double grout = 0.1;
  /// Width of the repulsion kernel, σ = 0.9 √(A / N) (Lai et al. §4.1).
  double sigma = 0;
  /// Side of the square that one tile and its grout cover in the aspect-normalized metric,
  /// √(A / N): the spacing of the ideal grid.
  double spacing = 0;
};

/// Works out tile sizes, count and σ, or says why it cannot (returns the reason, `layout`
/// untouched).
inline std::optional<std::string> mosaic_layout(const Mosaic_tile_size& in, double area,
                                                Mosaic_layout& layout) {
  if (!(area > 0) || !std::isfinite(area))
    return std::string("the surface has no area");
  if (!(in.grout >= 0 && in.grout < 1))
    return std::string("the grout fraction must be in [0, 1)");
  Mosaic_layout out;
  out.grout = in.grout;
  const bool by_size = in.tile_size[0] > 0;
  if (by_size == (in.tile_count > 0))
    return std::string("give either a tile size or a tile count (exactly one of them)");
  if (by_size) {
    const double lx = in.tile_size[0], ly = in.tile_size[1] > 0 ? in.tile_size[1] : in.tile_size[0];
    if (!std::isfinite(lx) || !std::isfinite(ly))
      return std::string("the tile size must be finite");
    out.tile_size = {{lx, ly}};
    out.aspect = lx / ly;
    const double n = (1 - in.grout) * area / (lx * ly);
    if (n < 1)
      return std::string("the tiles are larger than the surface");
    if (n > 5e7)
      return std::string("the tiles are too small: more than 50 million would be needed");
    out.tile_count = std::size_t(std::llround(n));
  } else {
    if (!(in.aspect > 0) || !std::isfinite(in.aspect))
      return std::string("the aspect must be positive");
    out.tile_count = in.tile_count;
    out.aspect = in.aspect;
    const double ly = std::sqrt((1 - in.grout) * area / (double(in.tile_count) * in.aspect));
    out.tile_size = {{in.aspect * ly, ly}};
  }
  out.spacing = std::sqrt(area / double(out.tile_count));
  out.sigma = 0.9 * out.spacing;
  layout = out;
  return std::nullopt;
}

/// The grout between two neighbouring tiles of the ideal grid: the spacing less the side of a
/// square of one tile's area. What `cut_tiles()` should keep between the tiles it cuts, so that
/// they are set as far apart as the others.
inline double grid_grout_width(const Mosaic_layout& layout) {
  return layout.spacing - std::sqrt(layout.tile_size[0] * layout.tile_size[1]);
}

} // namespace tessera
