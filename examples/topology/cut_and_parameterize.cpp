// Cuts a closed surface (default: the genus-2 "eight") open into one disk with the greedy cut
// graph, flattens that disk with CGAL's LSCM parameterization through CGAL::Seam_mesh, and writes
// an OBJ with texture coordinates.
#include <tessera/types.h>

#include <tessera/io.h>
#include <tessera/topology.h>

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <iostream>

namespace SMP = CGAL::Surface_mesh_parameterization;
using Mesh = tessera::Mesh;
using Seam_mesh = CGAL::Seam_mesh<Mesh, Mesh::Property_map<Mesh::Edge_index, bool>,
                                  Mesh::Property_map<Mesh::Vertex_index, bool>>;

int main(int argc, char** argv) {
  const std::string path = argc > 1 ? argv[1] : TESSERA_EXAMPLE_DATA_DIR "/eight.off";
  const std::string out = argc > 2 ? argv[2] : "cut_and_parameterize.obj";
  Mesh mesh;
  if (auto r = tessera::read_mesh(path, mesh); !r) {
    std::cerr << r.message << "\n";
    return 1;
  }
  auto seam_edges = mesh.add_property_map<Mesh::Edge_index, bool>("e:tessera_seam", false).first;
  auto seam_vertices =
      mesh.add_property_map<Mesh::Vertex_index, bool>("v:tessera_seam", false).first;
  const auto cut = tessera::cut_to_disk(mesh, seam_edges, seam_vertices);
  if (!cut || cut.polygons.size() != 1) {
    std::cerr << "cut failed: " << cut.message << "\n";
    return 1;
  }
  std::size_t seams = 0;
  for (auto e : edges(mesh))
    seams += seam_edges[e] ? 1 : 0;

  Seam_mesh seam_mesh(mesh, seam_edges, seam_vertices);
  seam_mesh.set_seam_edges_number(seams);
  auto uv =
      mesh.add_property_map<Mesh::Halfedge_index, CGAL::Point_2<tessera::Kernel>>("h:tessera_uv")
          .first;
  const auto border = CGAL::Polygon_mesh_processing::longest_border(seam_mesh).first;
  const SMP::Error_code err =
      SMP::parameterize(seam_mesh, SMP::LSCM_parameterizer_3<Seam_mesh>(), border, uv);
  if (err != SMP::OK) {
    std::cerr << "parameterization failed: " << SMP::get_error_message(err) << "\n";
    return 1;
  }
  if (!tessera::write_obj_with_uvs(out, seam_mesh, uv))
    return 1;
  std::cout << "genus " << cut.polygons[0].genus << " surface opened along "
            << cut.polygons[0].sides.size() << " sides (" << seams
            << " seam edges), flattened by LSCM; wrote " << out << "\n";
  return 0;
}
