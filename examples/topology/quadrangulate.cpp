// Cuts a surface (default: the genus-2 "eight") into quads along shortest Q-criterion cutting
// paths, maps every quad onto the unit square, and prints the quads and their worst distortion.
#include <tessera/types.h>

#include <tessera/io.h>
#include <tessera/topology.h>

#include <iostream>

using Mesh = tessera::Mesh;

int main(int argc, char** argv) {
  const std::string path = argc > 1 ? argv[1] : TESSERA_EXAMPLE_DATA_DIR "/eight.off";
  Mesh mesh;
  if (auto r = tessera::read_mesh(path, mesh); !r) {
    std::cerr << r.message << "\n";
    return 1;
  }
  auto tile = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:tessera_tile", 0).first;
  auto seam_edges = mesh.add_property_map<Mesh::Edge_index, bool>("e:tessera_seam", false).first;
  auto seam_vertices =
      mesh.add_property_map<Mesh::Vertex_index, bool>("v:tessera_seam", false).first;
  const auto quads = tessera::quadrangulate(mesh, tile, seam_edges, seam_vertices);
  if (!quads) {
    std::cerr << "quadrangulation failed: " << quads.message << "\n";
    return 1;
  }
  auto uv =
      mesh.add_property_map<Mesh::Halfedge_index, CGAL::Point_2<tessera::Kernel>>("h:tessera_uv")
          .first;
  const auto param = tessera::parameterize_tiles(
      mesh, quads.tiles, tessera::tile_maps(tile, seam_edges, seam_vertices), uv);
  if (!param) {
    std::cerr << "parameterization failed: " << param.message << "\n";
    return 1;
  }
  const auto& worst = param.tiles[param.worst_tile];
  std::cout << quads.number_of_quads() << " quads (" << quads.cutting_paths
            << " cutting paths, total cut length " << quads.cut_length << "); worst tile "
            << param.worst_tile << ": stretch " << worst.stretch << ", angle distortion "
            << worst.angle << ", " << param.flipped << " flipped triangles\n";
  return param.flipped == 0 ? 0 : 1;
}
