// The two representations of a texture's detail in texture-preserving resizing: an offset along
// the base's normal (Chen and Meng's conference version) and Laplacian coordinates rebuilt by a
// Poisson solve (their journal version). Ridges on a plate (or the mesh given) are stretched 2x
// along x both ways; prints their texels and how far apart the two results are, draws both.
#include <tessera/generators/textures.h>
#include <tessera/io.h>
#include <tessera/render.h>
#include <tessera/resizing.h>
#include <tessera/types.h>

#include <cmath>
#include <iostream>
#include <vector>

int main(int argc, char** argv) {
  using namespace tessera;
  Mesh input;
  if (argc > 1) {
    if (const Read_mesh_result read = read_mesh(argv[1], input); !read)
      return std::cerr << read.message << "\n", 1;
  } else { // 13 ridges across x on a 4 x 2 plate, every 0.25
    make_plate(input, 4.0, 2.0, 40);
    Ridge_texture_options ridges;
    ridges.min = {0.5, 0.5}, ridges.max = {3.5, 1.5}, ridges.angle = std::acos(-1.0) / 2;
    add_ridges(input, ridges);
  }
  std::vector<Mesh> results;
  std::vector<Mesh_state> states; // coloured by the detail height, blue -0.06 to red 0.06
  for (const Detail_representation detail :
       {Detail_representation::normal_displacement, Detail_representation::laplacian_coordinates}) {
    Mesh& mesh = results.emplace_back(input);
    auto texture = mesh.add_property_map<Mesh::Vertex_index, bool>("v:tessera_texture").first;
    auto base = mesh.add_property_map<Mesh::Vertex_index, Point_3>("v:tessera_base").first;
    auto height = mesh.add_property_map<Mesh::Vertex_index, double>("v:tessera_height").first;
    Texture_resize_options options;
    options.resize.scale = {2, 1, 1};
    options.resize.method = Resize_method::simple;
    options.texture.detail = detail;
    const Texture_resize_result r = resize_preserving_texture(mesh, texture, base, height, options);
    if (!r)
      return std::cerr << r.message << "\n", 1;
    Mesh_state& state = states.emplace_back();
    for (auto v : vertices(mesh)) {
      state.positions.push_back({mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()});
      state.vertex_colors.push_back(diverging_color(0.5 + height[v] / 0.12));
    }
    std::cout << internal::enum_name(detail_representation_names, detail) << ": texels "
              << r.stages.texels_before.texels.size() << " -> "
              << r.stages.texels_after.texels.size() << ", median aspect "
              << r.stages.texels_after.median_aspect << "\n";
  }
  // Both runs remesh and synthesize alike, so the results share their vertices: a third state,
  // the second coloured by its distance from the first (white 0, red 0.01 and beyond).
  if (num_vertices(results[0]) != num_vertices(results[1]))
    return std::cerr << "the two results differ in their vertices\n", 1;
  Mesh_state& distance = states.emplace_back(states[1]);
  double largest = 0;
  for (std::size_t i = 0; i < distance.positions.size(); ++i) {
    const auto &a = states[0].positions[i], &b = states[1].positions[i];
    const double d = std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
    distance.vertex_colors[i] = diverging_color(0.5 + 50 * d);
    largest = std::max(largest, d);
  }
  std::cout << "largest distance between the two results: " << largest << "\n";
  Render_scene scene;
  for (std::size_t k = 0; k < 3; ++k)
    append_mesh_state(scene, results[k == 0 ? 0 : 1], states[k], 1);
  Render_options view;
  view.title = "front to back: normal displacement, Laplacian coordinates (colour: detail height), "
               "their distance (white 0, red 0.01)";
  return render_png(scene, "detail-representations.png", view) ? 0 : 1;
}
