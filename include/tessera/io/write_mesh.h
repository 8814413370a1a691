// Writing a FaceGraph to OFF, OBJ, PLY or STL through CGAL's IO at full double precision.
#pragma once

#include <tessera/io/read_mesh.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <string>

namespace tessera {

/// Writes `tm` to `path`, the format chosen by the extension. Returns false (and writes nothing
/// useful) on an unsupported extension or an I/O failure.
template <typename FaceGraph>
bool write_mesh(const std::string& path, const FaceGraph& tm) {
  if (!is_supported_mesh_extension(file_extension(path))) return false;
  return CGAL::IO::write_polygon_mesh(path, tm, CGAL::parameters::stream_precision(17));
}

} // namespace tessera
