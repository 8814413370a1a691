// tessera info | render | demo: mesh statistics, pictures, and the built-in demonstration.
#include "commands.h"
#include "mesh_input.h"
#include "output_dir.h"

#include <tessera/generators.h>
#include <tessera/io.h>
#include <tessera/io/info_report.h>
#include <tessera/render.h>
#include <tessera/types.h>
#include <tessera/validation.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace tessera::cli {
namespace {

void print_info(std::ostream& os, const std::string& name, const Mesh_info& info) {
  os << name << "\n"
     << "  vertices " << info.vertices << ", edges " << info.edges << ", faces " << info.faces
     << "\n"
     << "  connected components " << info.components.size() << ", boundary loops "
     << info.boundary_loops << ", Euler characteristic " << info.euler_characteristic << "\n"
     << "  manifold " << (info.is_valid_polygon_mesh ? "yes" : "no") << ", triangles only "
     << (info.is_triangle_mesh ? "yes" : "no") << ", closed " << (info.is_closed ? "yes" : "no")
     << ", self-intersecting "
     << (info.self_intersection_checked ? (info.self_intersects ? "yes" : "no") : "not checked")
     << "\n"
     << "  area " << info.area << "\n"
     << "  bbox [" << info.bbox_min[0] << ", " << info.bbox_min[1] << ", " << info.bbox_min[2]
     << "] - [" << info.bbox_max[0] << ", " << info.bbox_max[1] << ", " << info.bbox_max[2]
     << "]\n";
  for (std::size_t i = 0; i < info.components.size(); ++i) {
    const Component_info& c = info.components[i];
    os << "  component " << i << ": V " << c.vertices << ", E " << c.edges << ", F " << c.faces
       << ", boundaries " << c.boundary_loops << ", chi " << c.euler_characteristic << ", genus "
       << c.genus << ", area " << c.area << "\n";
  }
}

Render_result render_mesh_png(const Mesh& mesh, const std::string& path, const std::string& title) {
  Render_scene scene;
  add_mesh(scene, mesh);
  Render_options options;
  options.title = title;
  return render_png(scene, path, options);
}

struct Info_arguments {
  std::string mesh;
  Mesh_input_flags input;
  bool json = false, no_self_intersection = false;
};

int run_info(const Info_arguments& a) {
  Mesh_changes changes;
  const Mesh mesh = read_input_mesh(a.mesh, a.input, &changes);
  Mesh_info_options options;
  options.check_self_intersection = !a.no_self_intersection;
  const Mesh_info info = mesh_info(mesh, options);
  if (a.json)
    write_info_report(std::cout, {info, changes});
  else
    print_info(std::cout, a.mesh, info);
  return exit_ok;
}

struct Render_arguments {
  std::string mesh, out;
  Mesh_input_flags input;
};

int run_render(const Render_arguments& a) {
  if (file_extension(a.out) != ".png")
    throw User_error(a.out + ": output must end in .png");
  std::error_code ec;
  if (std::filesystem::exists(a.out, ec) && std::filesystem::equivalent(a.out, a.mesh, ec))
    throw User_error(a.out + " is the input file; refusing to overwrite it");
  const Mesh mesh = read_input_mesh(a.mesh, a.input);
  write_checked(a.out, [&](const std::string& tmp) { return render_mesh_png(mesh, tmp, a.mesh); });
  std::cout << "wrote " << a.out << "\n";
  return exit_ok;
}

struct Demo_arguments {
  std::string out = "tessera-demo";
  std::size_t genus = 2;
  bool force = false;
};

// The generated surface, its info and picture; returns its OFF file.
std::string write_demo_surface(const Output_directory& dir, std::size_t genus) {
  Mesh mesh;
  make_genus_surface(mesh, genus);
  const Mesh_info info = mesh_info(mesh);
  print_info(std::cout, "generated genus-" + std::to_string(genus) + " surface", info);
  const std::string off = dir.file("surface.off"), png = dir.file("surface.png");
  write_checked(off, [&](const std::string& tmp) { return write_mesh(tmp, mesh); });
  write_checked(png, [&](const std::string& tmp) {
    return render_mesh_png(mesh, tmp, "genus " + std::to_string(genus) + " surface");
  });
  write_checked_stream(dir.file("info.json"), [&](std::ostream& out) {
    return write_info_report(out, {info, Mesh_changes{}});
  });
  std::cout << "wrote " << off << ", " << png << ", " << dir.file("info.json") << "\n";
  return off;
}

// The demo: the surface, its schema cut and quadrangulation, a surface mosaic and a planar one,
// each through the command a user would run.
int run_demo(const Demo_arguments& a) {
  const Output_directory dir(a.out, a.force, {});
  const std::string off = write_demo_surface(dir, a.genus);
  Cut_arguments cut;
  cut.mesh = off;
  cut.out = dir.file("cut");
  cut.method = "schema";
  cut.view = true;
  if (const int rc = run_cut(cut); rc != exit_ok)
    return rc;
  Quad_arguments quads;
  quads.mesh = off;
  quads.out = dir.file("quads");
  quads.from = "schema";
  quads.view = true;
  if (const int rc = run_quadrangulate(quads); rc != exit_ok)
    return rc;
  // The surface-mosaics paper's genus-2 "eight" with 3000 tiles (its Fig. 9), shipped in the
  // repository; the generated surface when the binary runs away from its source tree.
  Mosaic_arguments mosaic;
  mosaic.mesh = std::filesystem::exists(TESSERA_DEMO_MOSAIC_MESH) ? TESSERA_DEMO_MOSAIC_MESH : off;
  mosaic.out = dir.file("mosaic");
  mosaic.tiles = 3000;
  mosaic.tiles_given = true;
  mosaic.teleport = true;
  mosaic.view = true;
  if (const int rc = run_mosaic(mosaic); rc != exit_ok)
    return rc;
  // A planar decorative mosaic (Hausner 2001) of a photograph shipped in the repository; skipped
  // when the binary runs away from its source tree.
  if (!std::filesystem::exists(TESSERA_DEMO_IMAGE))
    return exit_ok;
  Planar_mosaic_arguments planar;
  planar.image = TESSERA_DEMO_IMAGE;
  planar.out = dir.file("planar-mosaic");
  planar.tiles = 3000;
  planar.view = true;
  return run_planar_mosaic(planar);
}

} // namespace

void register_mesh_commands(CLI::App& app, std::function<int()>& run) {
  auto info = std::make_shared<Info_arguments>();
  auto* cmd = app.add_subcommand("info", "Print counts, topology and geometry of a mesh");
  add_mesh_input(cmd, info->mesh, info->input);
  cmd->add_flag("--json", info->json, "Print JSON instead of text");
  cmd->add_flag("--no-self-intersection", info->no_self_intersection,
                "Skip the self-intersection test");
  cmd->callback([&run, info] { run = [info] { return run_info(*info); }; });

  auto render = std::make_shared<Render_arguments>();
  cmd = app.add_subcommand("render", "Draw a mesh into a PNG file");
  add_mesh_input(cmd, render->mesh, render->input);
  cmd->add_option("--out", render->out, "Output PNG file")->required();
  cmd->callback([&run, render] { run = [render] { return run_render(*render); }; });

  auto demo = std::make_shared<Demo_arguments>();
  cmd = app.add_subcommand(
      "demo", "Generate a genus-2 surface, cut it open by the polygonal schema, quadrangulate it, "
              "lay a surface mosaic on the 'eight' and a planar mosaic on a photograph, and write "
              "meshes and pictures");
  cmd->add_option("--out", demo->out, "Output directory")->capture_default_str();
  cmd->add_option("--genus", demo->genus, "Genus of the generated surface")->capture_default_str();
  cmd->add_flag("--force", demo->force, "Write into a non-empty directory Tessera did not create");
  cmd->callback([&run, demo] { run = [demo] { return run_demo(*demo); }; });
}

} // namespace tessera::cli
