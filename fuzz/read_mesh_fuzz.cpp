// The one CGAL translation unit of the fuzz targets (see read_mesh_fuzz.h).
#include "read_mesh_fuzz.h"

#include <tessera/fields/color_regions.h>
#include <tessera/io/read_mesh.h>
#include <tessera/types.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>

namespace tessera::fuzz {

void read_mesh_bytes(const std::uint8_t* data, std::size_t size, const char* ext) {
  // One file per process, in memory where /dev/shm exists: read_mesh() takes a path, as users do.
  static const std::string path = [&] {
    const char* dir = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
    return std::string(dir) + "/tessera-fuzz-" + std::to_string(getpid()) + ext;
  }();
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  }
  Mesh mesh;
  const Read_mesh_result r = read_mesh(path, mesh);
  // A result is either a valid surface or a refusal with a message.
  if (r && !CGAL::is_valid_polygon_mesh(mesh))
    __builtin_trap();
  if (!r && r.message.empty())
    __builtin_trap();
  // The colours of a mesh read (tessera mosaic --colors mesh, tessera field --features color): read
  // or refused with a message.
  if (r && (std::string(ext) == ".off" || std::string(ext) == ".ply")) {
    auto colors = get(CGAL::dynamic_face_property_t<CGAL::IO::Color>(), mesh);
    const Color_regions_result c = read_face_colors(path, mesh, colors);
    if (!c && c.message.empty())
      __builtin_trap();
  }
}

} // namespace tessera::fuzz
