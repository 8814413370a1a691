// One reader for every command's input mesh (see mesh_input.h).
#include "mesh_input.h"

#include <tessera/io/read_mesh.h>

#include <iostream>

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
  if (!r) throw User_error(r.message);
  if (r.triangulated_faces > 0)
    std::cerr << "tessera: note: " << r.triangulated_faces
              << " polygonal faces were split into triangles\n";
  if (r.changes.any())
    std::cerr << "tessera: note: the input was repaired: " << r.changes.to_string()
              << " (vertex ids differ from the file's)\n";
  if (changes) *changes = r.changes;
  return mesh;
}

nlohmann::json mesh_changes_json(const Mesh_changes& changes) {
  return {{"merged_vertices", changes.merged_vertices},
          {"removed_vertices", changes.removed_vertices},
          {"split_faces", changes.split_faces},
          {"removed_faces", changes.removed_faces},
          {"reoriented_faces", changes.reoriented_faces},
          {"pinched_vertices", changes.pinched_vertices},
          {"non_manifold_edges", changes.non_manifold_edges}};
}

} // namespace tessera::cli
