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

// The maps `quadrangulate` fills and the UVs `parameterize_tiles` writes.
template <typename M> struct Quad_maps {
  typename M::template Property_map<typename M::Face_index, std::size_t> tile;
  typename M::template Property_map<typename M::Edge_index, bool> seam_e;
  typename M::template Property_map<typename M::Vertex_index, bool> seam_v;
  typename M::template Property_map<typename M::Halfedge_index, CGAL::Point_2<Kernel>> uv;

  explicit Quad_maps(M& mesh)
      : tile(
            mesh.template add_property_map<typename M::Face_index, std::size_t>("f:tessera_tile", 0)
                .first),
        seam_e(mesh.template add_property_map<typename M::Edge_index, bool>("e:tessera_seam", false)
                   .first),
        seam_v(
            mesh.template add_property_map<typename M::Vertex_index, bool>("v:tessera_seam", false)
                .first),
        uv(mesh.template add_property_map<typename M::Halfedge_index, CGAL::Point_2<Kernel>>(
                   "h:tessera_uv")
               .first) {}
  void remove_from(M& mesh) {
    mesh.remove_property_map(uv);
    mesh.remove_property_map(tile);
    mesh.remove_property_map(seam_e);
    mesh.remove_property_map(seam_v);
  }
};

// What the quadrangulation found: the quads, their check, their maps onto the unit square, the
// surface opened along their borders, and the report of it all.
template <typename M> struct Quad_run {
  Quadrangulation_result<M> result;
  Quadrangulation_validation validation;
  Tile_parameterization_result param;
  M opened;
  Quadrangulation_report report;
  std::size_t faces_before = 0;
  double seconds = 0;
};

template <typename M>
void quadrangulate_mesh(const Quad_arguments& a, const Quadrangulation_options& options,
                        const Tile_parameterization_options& po, M& mesh, Quad_maps<M>& maps,
                        Quad_run<M>& run) {
  Progress_printer printer;
  Quadrangulation_options qo = options;
  qo.progress = qo.cut.progress = printer.callback();
  Tile_parameterization_options tpo = po;
  tpo.progress = printer.callback();
  run.faces_before = num_faces(mesh);
  const auto t0 = std::chrono::steady_clock::now();
  run.result = quadrangulate(mesh, maps.tile, maps.seam_e, maps.seam_v, qo);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!run.result)
    throw User_error(a.mesh + ": " + run.result.message);
  run.validation = timed("validating the quads", [&] {
    return validate_quadrangulation(mesh, maps.tile, maps.seam_e, maps.seam_v, run.result);
  });
  run.param = parameterize_tiles(mesh, run.result.tiles,
                                 tile_maps(maps.tile, maps.seam_e, maps.seam_v), maps.uv, tpo);
  const auto opened_to_mesh = timed("opening along the tile borders", [&] {
    return open_along_seams(mesh, maps.seam_e, maps.seam_v, run.opened);
  });
  std::vector<std::size_t> tiles;
  for (auto f : faces(run.opened))
    tiles.push_back(maps.tile[typename M::Face_index(std::size_t(f))]);
  // Each quad's corners in boundary order, as vertices of mesh.off and of opened.off, from its
  // chart in the opened mesh.
  Validate_charts_options chart_options;
  chart_options.marked_corners = internal::index_list(run.result.multipoints);
  const Cutting_validation charts = timed("finding each quad's corners", [&] {
    return validate_charts(mesh, run.opened, opened_to_mesh, chart_options);
  });
  run.report =
      make_quadrangulation_report(mesh, run.result, options, run.faces_before, run.validation,
                                  run.param, charts, opened_to_mesh, tiles, run.seconds);
  run.report.kernel = to_string(std::is_same_v<M, Mesh> ? Coordinates::double_precision
                                                        : Coordinates::exact_rational);
}

// quads.obj (UVs per tile), mesh.off (and mesh.exact.off), opened.off, result.json and quads.png;
// each file whole or not at all, a failed write naming the file and the reason. The maps are
// removed from `mesh` before it is written. Returns the files written.
template <typename M>
std::vector<std::string> write_quad_files(const Output_directory& dir, const std::string& title,
                                          M& mesh, Quad_maps<M>& maps, Quad_run<M>& run) {
  auto write = [&](const char* what, const std::string& path, auto writer) {
    timed(what, [&] { write_checked(path, writer); });
  };
  std::vector<std::string> written{dir.file("mesh.off"), dir.file("opened.off")};
  // Each tile's copy of a vertex gets its own UV: write the mesh opened along the tile borders.
  using Seam_mesh = CGAL::Seam_mesh<M, decltype(maps.seam_e), decltype(maps.seam_v)>;
  const Seam_mesh sm(mesh, maps.seam_e, maps.seam_v);
  write("writing quads.obj", dir.file("quads.obj"), [&](const std::string& tmp) {
    return write_obj_with_uvs(tmp, sm,
                              internal::Seam_vertex_uv_map<Seam_mesh, decltype(maps.uv)>{maps.uv});
  });
  Render_scene scene;
  add_quadrangulation(scene, mesh, maps.tile, run.result);
  maps.remove_from(mesh);
  write("writing mesh.off", written[0],
        [&](const std::string& tmp) { return write_mesh(tmp, mesh); });
  if constexpr (!std::is_same_v<M, Mesh>) {
    run.report.exact_mesh = "mesh.exact.off";
    written.push_back(dir.file("mesh.exact.off"));
    write("writing mesh.exact.off", written.back(),
          [&](const std::string& tmp) { return write_exact_off(tmp, mesh); });
  }
  write("writing opened.off", written[1],
        [&](const std::string& tmp) { return write_mesh(tmp, run.opened); });
  written.insert(written.end(),
                 {dir.file("result.json"), dir.file("quads.obj"), dir.file("quads.png")});
  write_checked_stream(dir.file("result.json"), [&](std::ostream& out) {
    return write_quadrangulation_report(out, run.report);
  });
  Render_options ro;
  ro.title = title;
  write("drawing quads.png", dir.file("quads.png"),
        [&](const std::string& tmp) { return render_png(scene, tmp, ro); });
  return written;
}

// The quadrangulation of `mesh` (double or exact coordinates) and its outputs.
template <typename M>
int quadrangulate_and_write(const Quad_arguments& a, const Quadrangulation_options& options,
                            const Tile_parameterization_options& po, M& mesh,
                            const Output_directory& dir) {
  Quad_maps<M> maps(mesh);
  Quad_run<M> run;
  quadrangulate_mesh(a, options, po, mesh, maps, run);
  const std::string source = (a.canonical ? "canonical " : "") + a.from;
  const std::vector<std::string> written = write_quad_files(
      dir, std::to_string(run.result.number_of_quads()) + " quads from the " + source + " cut",
      mesh, maps, run);
  const Quadrangulation_result<M>& result = run.result;
  const Tile_distortion& worst = run.param.tiles.at(run.param.worst_tile);
  std::cout << result.number_of_quads() << " quads from the " << source << " cut of " << a.mesh
            << " (genus " << run.report.genus << ", " << run.report.boundaries
            << " boundaries): " << result.cutting_paths << " cutting paths, "
            << result.added_corners << " added corners, " << result.refinements << "+"
            << result.local_refinements << " refinements (mesh+local), faces " << run.faces_before
            << " -> " << num_faces(mesh) << ", cut length " << result.cut_length << ", "
            << run.seconds << " s" << (bool(run.validation) ? ", valid" : ", INVALID")
            << "\nworst tile " << run.param.worst_tile << ": stretch " << worst.stretch
            << ", angle distortion " << worst.angle << ", area distortion " << worst.area << "; "
            << run.param.flipped << " flipped triangles\n";
  print_written(with_view(written, dir, a.view, a.mesh));
  return bool(run.validation) && run.param ? exit_ok : exit_internal;
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
  add_view_flag(cmd, args->view);
  cmd->callback([&run, args] { run = [args] { return run_quadrangulate(*args); }; });
}

} // namespace tessera::cli
