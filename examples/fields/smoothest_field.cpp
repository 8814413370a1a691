// Reads a mesh (default: the fandisk), aligns a cross field with its sharp creases, and prints the
// solve and the singularities (whose indices sum to the Euler characteristic).
#include <tessera/fields.h>
#include <tessera/io.h>
#include <tessera/types.h>

#include <iostream>

int main(int argc, char** argv) {
  const std::string path = argc > 1 ? argv[1] : TESSERA_EXAMPLE_DATA_DIR "/fandisk.off";
  tessera::Mesh mesh;
  const tessera::Read_mesh_result read = tessera::read_mesh(path, mesh);
  if (!read) {
    std::cerr << read.message << "\n";
    return 1;
  }
  tessera::Feature_line_options features;
  features.creases = true;
  features.crease_angle_degrees = 40;
  const auto lines = tessera::feature_lines(mesh, features);
  const auto constraints =
      tessera::feature_alignment_constraints(mesh, lines, {tessera::Feature_alignment::parallel});

  auto field =
      mesh.add_property_map<tessera::Mesh::Vertex_index, tessera::Vector_3>("v:tessera_field")
          .first;
  tessera::Smoothest_field_options options;
  options.symmetry = 4;
  const tessera::Smoothest_field_result result =
      tessera::smoothest_field(mesh, constraints, field, options);
  if (!result) {
    std::cerr << result.message << "\n";
    return 1;
  }
  const auto singularities = tessera::field_singularities(mesh, field, options.symmetry);
  std::cout << path << ": " << lines.size() << " crease lines, " << result.hard_constraints
            << " aligned vertices, energy " << result.energy << " (" << result.solver << ")\n"
            << singularities.singularities.size() << " singularities, indices sum to "
            << double(singularities.face_index_sum) / options.symmetry << " = Euler characteristic "
            << singularities.euler_characteristic << "\n";
  return singularities.poincare_hopf_holds() ? 0 : 1;
}
