// Shared body of the mesh-reader fuzz targets: the bytes become a file with the target's extension,
// which read_mesh() must read or refuse with a message, never crash, hang or exhaust memory; the
// colours of an OFF or PLY file that reads are then read too (read_face_colors()).
#pragma once

#include <cstddef>
#include <cstdint>

namespace tessera::fuzz {

/// Reads `data` as a mesh file with extension `ext` (".off", ".obj", ".ply" or ".stl").
void read_mesh_bytes(const std::uint8_t* data, std::size_t size, const char* ext);

} // namespace tessera::fuzz
