// Reads a mesh with Tessera's checked reader, prints its genus and draws it.
#include <tessera/io.h>
#include <tessera/render.h>
#include <tessera/validation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <iostream>

int main(int argc, char** argv) {
  using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;
  if (argc < 3)
    return 2;
  Mesh mesh;
  const auto read = tessera::read_mesh(argv[1], mesh);
  if (!read) {
    std::cerr << read.message << "\n";
    return 1;
  }
  const auto info = tessera::mesh_info(mesh);
  std::cout << "genus " << info.components.at(0).genus << "\n";
  tessera::Render_scene scene;
  tessera::add_mesh(scene, mesh);
  return tessera::render_png(scene, argv[2]) ? 0 : 1;
}
