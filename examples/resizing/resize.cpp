// Non-homogeneous resizing: stretch a model 2x along x so its straight parts take the stretch and
// its curved parts keep their proportions; print the stretch the free parts took and the local
// stretch on the most vulnerable vertices, beside simple scaling's.
#include <tessera/io.h>
#include <tessera/io/resize_reports.h>
#include <tessera/resizing.h>
#include <tessera/types.h>

#include <algorithm>
#include <iostream>

int main(int argc, char** argv) {
  const std::string file = argc > 1 ? argv[1] : TESSERA_EXAMPLE_DATA_DIR "/elephant.off";
  tessera::Mesh mesh;
  if (const tessera::Read_mesh_result read = tessera::read_mesh(file, mesh); !read) {
    std::cerr << read.message << "\n";
    return 1;
  }
  const tessera::Mesh input = mesh;

  auto vulnerability = mesh.add_property_map<tessera::Mesh::Vertex_index, std::array<double, 3>>(
                               "v:tessera_vulnerability")
                           .first;
  tessera::Resize_options options;
  options.scale = {2, 1, 1};
  const tessera::Resize_result result = tessera::resize(mesh, vulnerability, options);
  if (!result) {
    std::cerr << result.message << "\n";
    return 1;
  }
  tessera::Mesh simple = input;
  options.method = tessera::Resize_method::simple;
  tessera::resize(simple, options);

  // Stretch on the most vulnerable vertices (resisted the stretch along x by 0.9 or more).
  const tessera::Stretch_by_vulnerability ours = tessera::stretch_by_vulnerability(
      mesh, input.points(), mesh.points(), vulnerability, {{2, 1, 1}}, 0.9);
  const tessera::Stretch_by_vulnerability theirs = tessera::stretch_by_vulnerability(
      mesh, input.points(), simple.points(), vulnerability, {{2, 1, 1}}, 0.9);
  const tessera::Stretch_stats a = tessera::make_stretch_stats(ours.vulnerable),
                               b = tessera::make_stretch_stats(theirs.vulnerable);
  std::cout << file << ": length " << result.extent_after[0] << " (target "
            << result.target_extent[0] << "), free parts stretched " << result.free_stretch[0]
            << "x, " << result.tetrahedra << " tetrahedra\n"
            << "mean stretch ratio on the " << a.vertices << " most vulnerable vertices: " << a.mean
            << " (simple scaling " << b.mean << ")\n";
  return 0;
}
