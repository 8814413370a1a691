// Overlap-free mosaics: where two tiles overlap, a mosaicist cuts them. Each overlapping pair is
// cut along the separating axis of least penetration (a tile edge direction of one of them), each
// tile losing half the overlap plus half a grout width, in the tile's own plane (Sutherland–Hodgman
// clipping of its outline by a half-plane). Lai et al. do not guarantee overlap-free layouts; this
// is the post-process that does.
#pragma once

#include <tessera/mosaic/tile.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace tessera {

enum class Cut_tiles_status {
  ok,
  /// The grout width is negative or not finite, or `neighbors` is 0.
  invalid_options
};

struct Cut_tiles_result {
  Cut_tiles_status status = Cut_tiles_status::ok;
  std::string message;
  /// Tiles that lost a part.
  std::size_t tiles_cut = 0;
  /// Area cut away, summed over the tiles (mesh units²), and as a fraction of the tiles' area.
  double area_removed = 0;
  double fraction_removed = 0;
  /// Tiles cut away entirely (another tile covered them): removed from the vector.
  std::size_t tiles_removed = 0;
  explicit operator bool() const { return status == Cut_tiles_status::ok; }
};

} // namespace tessera

#include <tessera/mosaic/internal/cut_tiles_impl.h>

namespace tessera {

/// Clips every tile against the tiles it overlaps (nearest `neighbors` centres with normals less
/// than 60° apart), keeping `grout_width` between the cut edges; writes each cut tile's `outline`
/// and removes tiles nothing is left of. On failure the tiles are left as they were.
template <typename FaceDescriptor>
Cut_tiles_result cut_tiles(std::vector<Mosaic_tile<FaceDescriptor>>& tiles, double grout_width,
                           std::size_t neighbors = 12) {
  Cut_tiles_result result;
  if (!(grout_width >= 0) || !std::isfinite(grout_width) || neighbors == 0) {
    result.status = Cut_tiles_status::invalid_options;
    result.message = "cut_tiles: the grout width must be finite and not negative, and at least "
                     "one neighbour must be searched";
    return result;
  }
  internal::cut_tiles_impl(tiles, grout_width, neighbors, result);
  return result;
}

} // namespace tessera
