// A point where charts of a texture layout touch: one (vertex, texture coordinate) pair of an OBJ
// whose faces form several fans sharing no edge. `read_obj_with_uvs` finds them and splits them in
// the chart mesh; `validate_uv_layout` reports them.
#pragma once

#include <cstddef>
#include <vector>

namespace tessera {

/// A texture vertex (the file's `v` and `vt` pair) whose faces form several fans that share no
/// edge: two charts, or one chart with itself, touching at one point of the texture layout. Each
/// fan is a vertex of its own in the chart mesh.
struct Pinched_texture_vertex {
  std::size_t vertex = 0;             ///< the `v` (0-based)
  std::size_t texture_coordinate = 0; ///< the `vt` (0-based)
  /// The chart-mesh vertices of its fans (indices in vertex order).
  std::vector<std::size_t> chart_vertices;
};

} // namespace tessera
