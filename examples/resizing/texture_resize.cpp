// Texture-preserving resizing: stretch a bumpy capsule 2x along its axis so that its bumps keep
// their shape and size and more of them fill the new room; print the texels before and after.
#include <tessera/io.h>
#include <tessera/resizing.h>
#include <tessera/types.h>

#include <iostream>

int main(int argc, char** argv) {
  const std::string file =
      argc > 1 ? argv[1] : TESSERA_EXAMPLE_DATA_DIR "/textured/bumpy-capsule.off";
  tessera::Mesh mesh;
  if (const tessera::Read_mesh_result read = tessera::read_mesh(file, mesh); !read) {
    std::cerr << read.message << "\n";
    return 1;
  }
  using V = tessera::Mesh::Vertex_index;
  auto texture = mesh.add_property_map<V, bool>("v:tessera_is_texture", false).first;
  auto base = mesh.add_property_map<V, tessera::Point_3>("v:tessera_base").first;
  auto height = mesh.add_property_map<V, double>("v:tessera_height", 0).first;

  tessera::Texture_resize_options options;
  options.resize.scale = {2, 1, 1}; // the base is resized non-homogeneously (the default)
  const tessera::Texture_resize_result result =
      tessera::resize_preserving_texture(mesh, texture, base, height, options);
  if (!result) {
    std::cerr << file << ": " << result.message << "\n";
    return 1;
  }
  const tessera::Texel_measure& before = result.stages.texels_before;
  const tessera::Texel_measure& after = result.stages.texels_after;
  std::cout << file << ": " << result.stages.texture_vertices_before << " texture vertices, "
            << before.texels.size() << " texels -> " << after.texels.size() << "; median aspect "
            << before.median_aspect << " -> " << after.median_aspect << ", median size "
            << before.median_size << " -> " << after.median_size << "; "
            << result.stages.total_seconds << " s\n";
  if (!tessera::write_mesh("texture-resized.off", mesh))
    return 1;
  std::cout << "wrote texture-resized.off (" << num_vertices(mesh) << " vertices)\n";
  return 0;
}
