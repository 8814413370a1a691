// tessera quadrangulate: cut a mesh into quads (Q-criterion, Favreau et al. 2009, Alg. 5), map
// every quad onto the unit square, and write the surface, the opened tiles, a JSON summary, an OBJ
// with per-tile UVs and a picture.
#include "choices.h"
#include "commands.h"
#include "mesh_input.h"
#include "output_dir.h"
#include "progress_printer.h"

// Surface_mesh's graph traits must be declared before CGAL::Seam_mesh is instantiated.
#include <tessera/types.h>

#include <tessera/io.h>
#include <tessera/io/result_reports.h>
#include <tessera/render.h>
#include <tessera/topology.h>

#include <chrono>
#include <fstream>
#include <iostream>
#include <type_traits>

namespace tessera::cli {
namespace {

template <typename M>
int quadrangulate_and_write(const Quad_arguments& a, const Quadrangulation_options& options,
                            const Tile_parameterization_options& po, M& mesh,
                            const Output_directory& dir);

} // namespace

int run_quadrangulate(const Quad_arguments& a) {
  Quadrangulation_options options;
  options.cut.method = parse_choice(cut_method_names, a.from, "method", " for --from");
  options.cut.cost.kind = parse_choice(edge_cost_kind_names, a.cost, "cost");
  if (a.curvature_weight < 0 || a.curvature_weight > 1)
    throw User_error("--curvature-weight must be in [0, 1]");
  options.cut.cost.curvature_weight = a.curvature_weight;
  if (a.basepoint >= 0)
    options.cut.basepoint = std::size_t(a.basepoint);
  if (a.canonical && options.cut.method != Cut_method::schema)
    throw User_error("--canonical needs --from schema");
  options.cut.canonical = a.canonical;
  Tile_parameterization_options po;
  po.quad_interior = parse_choice(quad_interior_names, a.interior, "--interior");

  const Coordinates coordinates = parse_choice(coordinates_names, a.kernel, "--kernel");

  const Output_directory dir(a.out, a.force, {a.mesh});
  Mesh mesh = read_input_mesh(a.mesh, a.input);
  if (a.basepoint >= long(num_vertices(mesh)))
    throw User_error("--basepoint " + std::to_string(a.basepoint) +
                     " is out of range (the mesh has " + std::to_string(num_vertices(mesh)) +
                     " vertices)");
  if (coordinates == Coordinates::exact_rational) {
    Exact_mesh exact = exact_input_mesh(mesh, a.mesh);
    return quadrangulate_and_write(a, options, po, exact, dir);
  }
  return quadrangulate_and_write(a, options, po, mesh, dir);
}

namespace {

// The quadrangulation of `mesh` (double or exact coordinates) and its outputs.
template <typename M>
int quadrangulate_and_write(const Quad_arguments& a, const Quadrangulation_options& options,
                            const Tile_parameterization_options& po, M& mesh,
                            const Output_directory& dir) {
  constexpr bool exact = !std::is_same_v<M, Mesh>;
  Progress_printer printer;
  Quadrangulation_options qo = options;
  qo.progress = printer.callback();
  Tile_parameterization_options tpo = po;
  tpo.progress = printer.callback();
  auto tile =
      mesh.template add_property_map<typename M::Face_index, std::size_t>("f:tessera_tile", 0)
          .first;
  auto seam_e =
      mesh.template add_property_map<typename M::Edge_index, bool>("e:tessera_seam", false).first;
  auto seam_v =
      mesh.template add_property_map<typename M::Vertex_index, bool>("v:tessera_seam", false).first;
  const std::size_t faces_before = num_faces(mesh);
  const auto t0 = std::chrono::steady_clock::now();
  const Quadrangulation_result<M> result = quadrangulate(mesh, tile, seam_e, seam_v, qo);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!result)
    throw User_error(a.mesh + ": " + result.message);
  const Quadrangulation_validation validation = timed("validating the quads", [&] {
    return validate_quadrangulation(mesh, tile, seam_e, seam_v, result);
  });

  auto uv = mesh.template add_property_map<typename M::Halfedge_index, CGAL::Point_2<Kernel>>(
                    "h:tessera_uv")
                .first;
  const Tile_parameterization_result param =
      parameterize_tiles(mesh, result.tiles, tile_maps(tile, seam_e, seam_v), uv, tpo);

  M opened;
  const auto opened_to_mesh = timed("opening along the tile borders",
                                    [&] { return open_along_seams(mesh, seam_e, seam_v, opened); });
  std::vector<std::size_t> tiles;
  for (auto f : faces(opened))
    tiles.push_back(tile[typename M::Face_index(std::size_t(f))]);
  // Each quad's corners in boundary order, as vertices of mesh.off and of opened.off, from its
  // chart in the opened mesh.
  Validate_charts_options chart_options;
  chart_options.marked_corners = internal::index_list(result.multipoints);
  const Cutting_validation charts = timed("finding each quad's corners", [&] {
    return validate_charts(mesh, opened, opened_to_mesh, chart_options);
  });
  Quadrangulation_report report =
      make_quadrangulation_report(mesh, result, options, faces_before, validation, param, charts,
                                  opened_to_mesh, tiles, seconds);
  report.kernel = to_string(exact ? Coordinates::exact_rational : Coordinates::double_precision);

  const std::string mesh_off = dir.file("mesh.off"), opened_off = dir.file("opened.off"),
                    obj = dir.file("quads.obj");
  // Each tile's copy of a vertex gets its own UV: write the mesh opened along the tile borders.
  using Seam_mesh = CGAL::Seam_mesh<M, decltype(seam_e), decltype(seam_v)>;
  const Seam_mesh sm(mesh, seam_e, seam_v);
  // Each file whole or not at all; a failed write names the file and the reason.
  auto write = [&](const char* what, const std::string& path, auto writer) {
    timed(what, [&] { write_checked(path, writer); });
  };
  write("writing quads.obj", obj, [&](const std::string& tmp) {
    return write_obj_with_uvs(tmp, sm, internal::Seam_vertex_uv_map<Seam_mesh, decltype(uv)>{uv});
  });
  Render_scene scene;
  add_quadrangulation(scene, mesh, tile, result);
  mesh.remove_property_map(uv);
  mesh.remove_property_map(tile);
  mesh.remove_property_map(seam_e);
  mesh.remove_property_map(seam_v);
  write("writing mesh.off", mesh_off,
        [&](const std::string& tmp) { return write_mesh(tmp, mesh); });
  const std::string exact_off = dir.file("mesh.exact.off");
  if (exact) {
    report.exact_mesh = "mesh.exact.off";
    write("writing mesh.exact.off", exact_off,
          [&](const std::string& tmp) { return write_exact_off(tmp, mesh); });
  }
  write("writing opened.off", opened_off,
        [&](const std::string& tmp) { return write_mesh(tmp, opened); });
  write_checked_stream(dir.file("result.json"), [&](std::ostream& out) {
    return write_quadrangulation_report(out, report);
  });
  Render_options ro;
  const std::string source = (a.canonical ? "canonical " : "") + a.from;
  ro.title = std::to_string(result.number_of_quads()) + " quads from the " + source + " cut";
  write("drawing quads.png", dir.file("quads.png"),
        [&](const std::string& tmp) { return render_png(scene, tmp, ro); });

  const Tile_distortion& worst = param.tiles.at(param.worst_tile);
  std::cout << result.number_of_quads() << " quads from the " << source << " cut of " << a.mesh
            << " (genus " << report.genus << ", " << report.boundaries
            << " boundaries): " << result.cutting_paths << " cutting paths, "
            << result.added_corners << " added corners, " << result.refinements << "+"
            << result.local_refinements << " refinements (mesh+local), faces " << faces_before
            << " -> " << num_faces(mesh) << ", cut length " << result.cut_length << ", " << seconds
            << " s" << (bool(validation) ? ", valid" : ", INVALID") << "\nworst tile "
            << param.worst_tile << ": stretch " << worst.stretch << ", angle distortion "
            << worst.angle << ", area distortion " << worst.area << "; " << param.flipped
            << " flipped triangles\n"
            << "wrote " << mesh_off << ", " << opened_off << ", "
            << (exact ? exact_off + ", " : std::string()) << dir.file("result.json") << ", " << obj
            << ", " << dir.file("quads.png") << "\n";
  return bool(validation) && param ? exit_ok : exit_internal;
}

} // namespace

void register_quad_commands(CLI::App& app, std::function<int()>& run) {
  auto args = std::make_shared<Quad_arguments>();
  auto* cmd = app.add_subcommand("quadrangulate",
                                 "Cut a mesh into quads and map each onto the unit square");
  add_mesh_input(cmd, args->mesh, args->input);
  cmd->add_option("--out", args->out, "Output directory")->required();
  cmd->add_option("--from", args->from,
                  "Source cut graph: " + internal::enum_name_list(cut_method_names))
      ->capture_default_str();
  cmd->add_option("--cost", args->cost, internal::enum_name_list(edge_cost_kind_names))
      ->capture_default_str();
  cmd->add_option("--curvature-weight", args->curvature_weight, "c in [0, 1] of the curvature cost")
      ->capture_default_str();
  cmd->add_option("--basepoint", args->basepoint, "Basepoint vertex index");
  cmd->add_option("--interior", args->interior,
                  "Quad interior map: " + internal::enum_name_list(quad_interior_names))
      ->capture_default_str();
  cmd->add_option("--kernel", args->kernel,
                  "double, or exact: refine on exact rational coordinates (CGAL::Epeck) and also "
                  "write mesh.exact.off")
      ->capture_default_str();
  cmd->add_flag("--canonical", args->canonical,
                "With --from schema: start from the canonical schema a1 b1 a1^-1 b1^-1 ...");
  cmd->add_flag("--force", args->force, "Write into a non-empty directory Tessera did not create");
  cmd->callback([&run, args] { run = [args] { return run_quadrangulate(*args); }; });
}

} // namespace tessera::cli
