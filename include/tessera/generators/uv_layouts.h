// Texture layouts as other tools write them, for testing `tessera check` on inputs with known
// answers: Blender's "Cube Projection", whose charts touch at points wherever two faces of one
// cube side meet only at a corner.
#pragma once

#include <ostream>

namespace tessera {

/// Writes `tm` to `out` as an OBJ (`v`, `vt`, `f v/vt` lines) with a cube projection: each face
/// takes the side of the cube its normal points to most (0..5: +x, −x, +y, −y, +z, −z), and its
/// corners the projection of their points onto that side, oriented as the face. One `vt` per
/// (vertex, side), so two faces share a chart edge exactly when they share an edge and a side.
/// Writes each face's side to `side_of_face` (face order) when given. Returns `out`.
template <typename TriangleMesh>
std::ostream& write_cube_projection_obj(std::ostream& out, const TriangleMesh& tm,
                                        std::vector<int>* side_of_face = nullptr);

} // namespace tessera

#include <tessera/generators/internal/uv_layouts_impl.h>
