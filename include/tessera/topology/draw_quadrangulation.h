// Pictures of quadrangulations: the surface with every tile in its own colour, the tile borders as
// dark polylines and the corners as dots.
#pragma once

#include <tessera/render/mesh_scene.h>
#include <tessera/topology/draw_cut.h>
#include <tessera/topology/quadrangulate.h>

namespace tessera {

/// Adds `tm` coloured by `tile_of_face` (a readable face map of tile ids) and the sides and corners
/// of `result` to `scene`.
template <typename TriangleMesh, typename FaceTileMap>
void add_quadrangulation(Render_scene& scene, const TriangleMesh& tm, FaceTileMap tile_of_face,
                         const Quadrangulation_result<TriangleMesh>& result,
                         double line_width = 3.5) {
  add_mesh(scene, tm, [&](auto f) { return distinct_color(get(tile_of_face, f)); });
  for (const auto& tile : result.tiles)
    for (const auto& side : tile.sides)
      add_halfedge_path(scene, tm, side, Color{0.1, 0.1, 0.1}, line_width);
  add_multipoints(scene, tm, result.multipoints, 4);
}

} // namespace tessera
