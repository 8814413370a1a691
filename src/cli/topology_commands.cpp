// tessera cut: open a mesh into disks along a cut graph and write the cut surface, the opened mesh,
// a JSON summary and a picture.
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
#include <map>
#include <type_traits>

namespace tessera::cli {
namespace {

template <typename M>
int cut_and_write(const Cut_arguments& a, const Cut_options& options, M& mesh,
                  const Output_directory& dir);

} // namespace

int run_cut(const Cut_arguments& a) {
  Cut_options options;
  options.method = parse_choice(cut_method_names, a.method, "method");
  options.cost.kind = parse_choice(edge_cost_kind_names, a.cost, "cost");
  if (a.curvature_weight < 0 || a.curvature_weight > 1)
    throw User_error("--curvature-weight must be in [0, 1]");
  options.cost.curvature_weight = a.curvature_weight;
  if (a.basepoint >= 0)
    options.basepoint = std::size_t(a.basepoint);
  if (a.canonical && options.method != Cut_method::schema)
    throw User_error("--canonical needs --method schema");
  options.canonical = a.canonical;

  const Coordinates coordinates = parse_choice(coordinates_names, a.kernel, "--kernel");

  const Output_directory dir(a.out, a.force, {a.mesh});
  Mesh mesh = read_input_mesh(a.mesh, a.input);
  if (a.basepoint >= long(num_vertices(mesh)))
    throw User_error("--basepoint " + std::to_string(a.basepoint) +
                     " is out of range (the mesh has " + std::to_string(num_vertices(mesh)) +
                     " vertices)");
  if (coordinates == Coordinates::exact_rational) {
    Exact_mesh exact = exact_input_mesh(mesh, a.mesh);
    return cut_and_write(a, options, exact, dir);
  }
  return cut_and_write(a, options, mesh, dir);
}

namespace {

// mesh.off (and mesh.exact.off), opened.off, result.json and cut.png, each whole or not at all.
// Returns the files written.
template <typename M>
std::vector<std::string> write_cut_files(const Output_directory& dir, const Cut_options& options,
                                         const M& mesh, const M& opened,
                                         const Cut_result<M>& result, Cut_report& report) {
  std::vector<std::string> written{dir.file("mesh.off"), dir.file("opened.off")};
  write_checked(written[0], [&](const std::string& tmp) { return write_mesh(tmp, mesh); });
  if constexpr (!std::is_same_v<M, Mesh>) {
    report.exact_mesh = "mesh.exact.off";
    written.push_back(dir.file("mesh.exact.off"));
    write_checked(written.back(),
                  [&](const std::string& tmp) { return write_exact_off(tmp, mesh); });
  }
  write_checked(written[1], [&](const std::string& tmp) { return write_mesh(tmp, opened); });
  written.insert(written.end(), {dir.file("result.json"), dir.file("cut.png")});
  write_checked_stream(dir.file("result.json"),
                       [&](std::ostream& out) { return write_cut_report(out, report); });
  Render_scene scene;
  add_mesh(scene, mesh);
  add_cut(scene, mesh, result);
  Render_options ro;
  ro.title = std::string(result.canonical ? "canonical " : "") + to_string(options.method) +
             " cut, length " + std::to_string(result.cut_length);
  write_checked(dir.file("cut.png"),
                [&](const std::string& tmp) { return render_png(scene, tmp, ro); });
  return written;
}

// The cut on `mesh` (double or exact coordinates) and its outputs.
template <typename M>
int cut_and_write(const Cut_arguments& a, const Cut_options& options, M& mesh,
                  const Output_directory& dir) {
  constexpr bool exact = !std::is_same_v<M, Mesh>;
  auto seam_e =
      mesh.template add_property_map<typename M::Edge_index, bool>("e:tessera_seam", false).first;
  auto seam_v =
      mesh.template add_property_map<typename M::Vertex_index, bool>("v:tessera_seam", false).first;
  const auto t0 = std::chrono::steady_clock::now();
  Progress_printer printer;
  Cut_options with_progress = options;
  with_progress.progress = printer.callback();
  const Cut_result<M> result = cut_to_disk(mesh, seam_e, seam_v, with_progress);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!result)
    throw User_error(a.mesh + ": " + result.message);

  M opened;
  const auto opened_to_mesh = open_along_seams(mesh, seam_e, seam_v, opened);
  const Cut_validation validation = validate_cut(mesh, seam_e, seam_v, result);
  // The polygons as charts of the opened mesh: their corners in opened.off and their side words.
  Validate_charts_options chart_options;
  chart_options.marked_corners = internal::index_list(result.multipoints);
  const Cutting_validation charts = validate_charts(mesh, opened, opened_to_mesh, chart_options);

  Cut_report report =
      make_cut_report(mesh, result, options, validation, charts, opened, opened_to_mesh, seconds);
  report.kernel = to_string(exact ? Coordinates::exact_rational : Coordinates::double_precision);
  mesh.remove_property_map(seam_e);
  mesh.remove_property_map(seam_v);
  const std::vector<std::string> written =
      write_cut_files(dir, options, mesh, opened, result, report);

  std::cout << to_string(options.method) << " cut of " << a.mesh << ": genus " << report.genus
            << ", " << report.boundaries << " boundaries, " << result.polygons.size()
            << " polygon(s)";
  for (const auto& p : result.polygons)
    std::cout << " [" << p.sides.size() << " sides]";
  if (result.canonical)
    std::cout << ", canonical (" << result.canonical_moves << " cut-and-paste moves)";
  if (result.polygons.size() == 1 && options.method == Cut_method::schema)
    std::cout << ", word " << report.polygons.front().word;
  std::cout << ", cut length " << result.cut_length << ", " << result.multipoints.size()
            << " multipoints, " << seconds << " s" << (bool(validation) ? ", valid" : ", INVALID")
            << "\n";
  print_written(with_view(written, dir, a.view, a.mesh));
  return bool(validation) ? exit_ok : exit_internal;
}

} // namespace

void register_topology_commands(CLI::App& app, std::function<int()>& run) {
  auto args = std::make_shared<Cut_arguments>();
  auto* cmd = app.add_subcommand("cut", "Open a mesh into disks along a cut graph");
  add_mesh_input(cmd, args->mesh, args->input);
  cmd->add_option("--out", args->out, "Output directory")->required();
  cmd->add_option("--method", args->method, internal::enum_name_list(cut_method_names))
      ->capture_default_str();
  cmd->add_option("--cost", args->cost, internal::enum_name_list(edge_cost_kind_names))
      ->capture_default_str();
  cmd->add_option("--curvature-weight", args->curvature_weight, "c in [0, 1] of the curvature cost")
      ->capture_default_str();
  cmd->add_option("--basepoint", args->basepoint, "Basepoint vertex index");
  cmd->add_option("--kernel", args->kernel,
                  "double, or exact: run on exact rational coordinates (CGAL::Epeck) and also "
                  "write mesh.exact.off")
      ->capture_default_str();
  cmd->add_flag("--canonical", args->canonical,
                "With --method schema: the canonical schema a1 b1 a1^-1 b1^-1 ... (cut-and-paste)");
  cmd->add_flag("--force", args->force, "Write into a non-empty directory Tessera did not create");
  add_view_flag(cmd, args->view);
  cmd->callback([&run, args] { run = [args] { return run_cut(*args); }; });
}

} // namespace tessera::cli
