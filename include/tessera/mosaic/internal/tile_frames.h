// The tiles' frames as vectors: each tile's centre, normal and in-plane axes (y = normal × x).
// Shared by `cut_tiles()` and `mosaic_quality()`, which measure tiles in their own planes.
#pragma once

#include <tessera/fields/internal/vertex_frames.h>
#include <tessera/mosaic/tile.h>

#include <vector>

namespace tessera::internal {

/// The tiles' frames: centres, normals and in-plane axes.
struct Tile_frames {
  std::vector<Vec3> centres, xs, ys, ns;
};

template <typename FaceDescriptor>
Tile_frames tile_frames(const std::vector<Mosaic_tile<FaceDescriptor>>& tiles) {
  Tile_frames f;
  for (const auto& t : tiles) {
    f.centres.push_back({{t.center[0], t.center[1], t.center[2]}});
    f.ns.push_back({{t.normal[0], t.normal[1], t.normal[2]}});
    f.xs.push_back({{t.x_axis[0], t.x_axis[1], t.x_axis[2]}});
    f.ys.push_back(cross(f.ns.back(), f.xs.back()));
  }
  return f;
}

} // namespace tessera::internal
