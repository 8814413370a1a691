// Reads a mesh (default: the genus-2 "eight") and prints its topology, component by component.
#include <tessera/io.h>
#include <tessera/types.h>
#include <tessera/validation.h>

#include <iostream>

int main(int argc, char** argv) {
  const std::string path = argc > 1 ? argv[1] : TESSERA_EXAMPLE_DATA_DIR "/eight.off";
  tessera::Mesh mesh;
  const tessera::Read_mesh_result read = tessera::read_mesh(path, mesh);
  if (!read) {
    std::cerr << read.message << "\n";
    return 1;
  }
  const tessera::Mesh_info info = tessera::mesh_info(mesh);
  std::cout << path << ": " << info.vertices << " vertices, " << info.faces << " faces, chi "
            << info.euler_characteristic << "\n";
  for (const auto& c : info.components)
    std::cout << "  component: genus " << c.genus << ", " << c.boundary_loops
              << " boundary loops, area " << c.area << "\n";
  return info.self_intersects ? 1 : 0;
}
