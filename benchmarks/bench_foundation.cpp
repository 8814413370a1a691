// Foundation figures: generating, checking and rendering genus-10 surfaces at the corpus sizes the
// topology benchmarks use (about 50k, 200k and 1M faces).
#include "harness.h"

#include <tessera/generators.h>
#include <tessera/render.h>
#include <tessera/types.h>
#include <tessera/validation.h>

namespace {

using namespace tessera;

void foundation(bench::Report& report, const bench::Config& config) {
  const std::vector<std::size_t> resolutions =
      config.quick ? std::vector<std::size_t>{2} : std::vector<std::size_t>{8, 16, 35};
  for (std::size_t n : resolutions) {
    Genus_surface_options o;
    o.cell_resolution = n;
    o.wall_resolution = std::max<std::size_t>(1, n / 2);
    o.subdivision_steps = 1;
    Mesh mesh;
    const double t_gen = bench::time_best([&] { make_genus_surface(mesh, 10, o); });
    Mesh_info info;
    const double t_info = bench::time_best([&] { info = mesh_info(mesh); });
    Render_scene scene;
    add_mesh(scene, mesh);
    Render_options ro;
    ro.width = 800;
    ro.height = 600;
    const double t_render =
        bench::time_best([&] { render_png(scene, "/tmp/tessera_bench_render.png", ro); });
    report.add("Foundation: genus-10 generated surfaces",
               {{"faces", std::to_string(info.faces)},
                {"genus", std::to_string(info.components.at(0).genus)},
                {"generate (s)", bench::fixed(t_gen, 3)},
                {"mesh_info incl. self-intersection (s)", bench::fixed(t_info, 3)},
                {"render 800x600 (s)", bench::fixed(t_render, 3)}});
  }
}

TESSERA_BENCHMARK("foundation", foundation);

} // namespace
