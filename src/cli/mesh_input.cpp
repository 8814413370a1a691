// One reader for every command's input mesh (see mesh_input.h).
#include "mesh_input.h"

#include <tessera/io/read_cutting.h>
#include <tessera/io/read_mesh.h>

#include <CGAL/boost/graph/iterator.h>

#include <cmath>
#include <iostream>
#include <vector>

namespace tessera::cli {

void add_mesh_input(CLI::App* cmd, std::string& path, Mesh_input_flags& flags) {
  cmd->add_option("mesh", path, "Input mesh (.off, .obj, .ply, .stl)")->required();
  auto* strict = cmd->add_flag("--strict", flags.strict,
                               "Refuse input that needs any change (repair or triangulation)");
  cmd->add_flag("--repair", flags.repair, "Also split edges shared by more than two faces")
      ->excludes(strict);
}

Mesh read_input_mesh(const std::string& path, const Mesh_input_flags& flags,
                     Mesh_changes* changes) {
  Read_mesh_options options;
  options.repair = flags.strict   ? Mesh_repair::none
                   : flags.repair ? Mesh_repair::all
                                  : Mesh_repair::safe;
  options.triangulate = !flags.strict;
  Mesh mesh;
  const Read_mesh_result r = read_mesh(path, mesh, options);
  if (!r)
    throw User_error(r.message);
  if (r.triangulated_faces > 0)
    std::cerr << "tessera: note: " << r.triangulated_faces
              << " polygonal faces were split into triangles\n";
  if (r.changes.any())
    std::cerr << "tessera: note: the input was repaired: " << r.changes.to_string()
              << " (vertex ids differ from the file's)\n";
  if (changes)
    *changes = r.changes;
  return mesh;
}

Exact_mesh exact_input_mesh(const Mesh& mesh, const std::string& path) {
  // Vertices and faces in `mesh`'s order (CGAL::copy_face_graph does not keep the vertex order),
  // at first with the exact values of the doubles.
  Exact_mesh exact;
  for (auto v : mesh.vertices()) {
    const Point_3& p = mesh.point(v);
    exact.add_vertex(Exact_kernel::Point_3(p.x(), p.y(), p.z()));
  }
  for (auto f : mesh.faces()) {
    std::vector<Exact_mesh::Vertex_index> corners;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      corners.emplace_back(std::size_t(v));
    exact.add_face(corners);
  }
  const std::string ext = file_extension(path);
  std::string why;
  if (ext == ".off" || ext == ".obj") {
    std::vector<Exact_kernel::Point_3> points;
    const Cutting_read_result r = read_exact_coordinates(path, points);
    // Same vertices in the same order: CGAL's OFF scanner may round a decimal to a neighbouring
    // double rather than the nearest one, hence a tolerance, not equality.
    bool same = r && points.size() == num_vertices(mesh);
    for (std::size_t i = 0; same && i < points.size(); ++i)
      for (int d = 0; same && d < 3; ++d) {
        const double x = CGAL::to_double(points[i][d]), y = mesh.point(Mesh::Vertex_index(i))[d];
        same = std::abs(x - y) <= 1e-12 * (1 + std::abs(y));
      }
    if (same) {
      for (std::size_t i = 0; i < points.size(); ++i)
        exact.point(Exact_mesh::Vertex_index(i)) = points[i];
      return exact;
    }
    why = r ? "reading changed its vertices" : r.message;
  } else {
    why = "only OFF and OBJ text are read exactly";
  }
  std::cerr << "tessera: note: exact coordinates of " << path << " are not available (" << why
            << "); the exact kernel starts from the exact values of its doubles\n";
  return exact;
}

} // namespace tessera::cli
