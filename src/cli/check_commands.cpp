// tessera check: validate a cutting made by Tessera or by another tool (a result directory, a mesh
// with a seam file, or an OBJ whose texture coordinates split it into charts), optionally exactly,
// and optionally as a refinement of an original surface. One line per problem, a JSON report,
// exit 0 when valid and 2 when not.
#include "choices.h"
#include "commands.h"
#include "output_dir.h"

#include <tessera/types.h>

#include <tessera/io/check_report.h>
#include <tessera/io/read_cutting.h>
#include <tessera/io/read_mesh.h>
#include <tessera/topology/method_names.h>
#include <tessera/topology/validate_charts.h>
#include <tessera/topology/validate_refinement.h>

#include <tessera/io/internal/bounded_readers.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <cmath>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>

namespace tessera::cli {
namespace {

// The cutting's files are read as they are: vertex ids must stay the file's.
template <typename M> M read_unchanged(const std::string& path) {
  Read_mesh_options options;
  options.repair = Mesh_repair::none;
  options.triangulate = false;
  M mesh;
  const Read_mesh_result r = read_mesh(path, mesh, options);
  if (!r)
    throw User_error(r.message +
                     " (check reads files unchanged, so that vertex ids keep their meaning)");
  return mesh;
}

// An OFF polygon mesh with every vertex as the file has it (duplicated points stay apart), read
// through the bounded OFF reader: result directories are user input like any mesh.
bool read_off_as_is(const std::string& path, Mesh& tm) {
  std::error_code error;
  const std::uintmax_t bytes = std::filesystem::file_size(path, error);
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  std::string why;
  if (error || !internal::read_off_bounded(path, bytes, points, polygons, why) ||
      !CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons))
    return false;
  for (const auto& p : points)
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      return false;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, tm);
  return CGAL::is_valid_polygon_mesh(tm);
}

// A surface with its coordinates read exactly from the file's text (decimals or p/q rationals).
Exact_mesh read_exact(const std::string& path) {
  Exact_mesh exact;
  const Cutting_read_result r = read_exact_polygon_mesh(path, exact);
  if (!r)
    throw User_error(r.message);
  return exact;
}

// Checks one input; prints its problems and figures to `out` (a null stream when several inputs
// are checked, which get one line each).
Check_report check_one(const Check_arguments& a, const std::string& input, std::ostream& out) {
  namespace fs = std::filesystem;
  std::optional<Expected_cutting> expect;
  if (!a.expect.empty())
    expect = parse_choice(expected_cutting_names, a.expect, "--expect");

  // The surface and its charts, whichever way they come.
  std::string form;
  Mesh mesh, charts;
  std::vector<Mesh::Vertex_index> chart_to_mesh;
  Validate_charts_options options;
  std::string surface_path = input;
  bool has_charts = true;
  std::optional<Cutting_validation> uv_check;
  if (fs::is_directory(input)) {
    form = "result directory";
    const fs::path dir(input);
    for (const char* name : {"result.json", "mesh.off", "opened.off"})
      if (!fs::exists(dir / name))
        throw User_error(input + ": not a Tessera result directory (no " + name + ")");
    nlohmann::json j;
    try {
      std::ifstream(dir / "result.json") >> j;
    } catch (const nlohmann::json::exception& e) {
      throw User_error((dir / "result.json").string() + ": malformed JSON (" + e.what() + ")");
    }
    surface_path = (dir / "mesh.off").string();
    mesh = read_unchanged<Mesh>(surface_path);
    // The opened mesh repeats the points of seam vertices, which read_mesh() would merge: read it
    // as CGAL's OFF reader gives it.
    const std::string opened = (dir / "opened.off").string();
    if (!read_off_as_is(opened, charts))
      throw User_error(opened + ": not a valid OFF polygon mesh");
    const auto o2m = j.find("opened_to_mesh_vertex");
    if (o2m == j.end() || !o2m->is_array())
      throw User_error(input + ": result.json has no opened_to_mesh_vertex");
    for (const auto& v : *o2m) {
      if (!v.is_number_unsigned() || v.get<std::size_t>() >= num_vertices(mesh))
        throw User_error(input +
                         ": opened_to_mesh_vertex holds an id that is not a vertex of mesh.off");
      chart_to_mesh.emplace_back(v.get<std::size_t>());
    }
    if (const auto mp = j.find("multipoints"); mp != j.end() && mp->is_array())
      for (const auto& v : *mp)
        if (v.is_number_unsigned())
          options.marked_corners.push_back(v.get<std::size_t>());
    if (!expect)
      expect = j.contains("quad_tiles") ? Expected_cutting::quads
               : parse_cut_method(j.value("method", std::string())) == Cut_method::schema
                   ? Expected_cutting::schema
                   : Expected_cutting::disks;
  } else if (!a.seams.empty()) {
    form = "seam file";
    mesh = read_unchanged<Mesh>(input);
    auto seam_e = mesh.add_property_map<Mesh::Edge_index, bool>("e:tessera_seam", false).first;
    auto seam_v = mesh.add_property_map<Mesh::Vertex_index, bool>("v:tessera_seam", false).first;
    const Cutting_read_result r = read_seam_file(a.seams, mesh, seam_e);
    if (!r)
      throw User_error(r.message);
    for (auto e : mesh.edges())
      if (seam_e[e])
        seam_v[source(halfedge(e, mesh), mesh)] = seam_v[target(halfedge(e, mesh), mesh)] = true;
    chart_to_mesh = open_along_seams(mesh, seam_e, seam_v, charts);
    mesh.remove_property_map(seam_e);
    mesh.remove_property_map(seam_v);
  } else if (file_extension(input) == ".obj" && a.original.empty()) {
    form = "texture coordinates";
    Uv_layout<Mesh> layout;
    const Cutting_read_result r = read_obj_with_uvs(input, layout);
    if (!r)
      throw User_error(r.message);
    mesh = std::move(layout.mesh);
    charts = std::move(layout.charts);
    chart_to_mesh = std::move(layout.chart_to_mesh);
    if (a.exact) {
      Uv_layout<Exact_mesh> exact;
      const Cutting_read_result re = read_obj_with_uvs(input, exact);
      if (!re)
        throw User_error(re.message);
      uv_check = validate_uv_layout(exact.charts, exact.uv, exact.pinched);
    } else {
      uv_check = validate_uv_layout(charts, layout.uv, layout.pinched);
    }
  } else if (!a.original.empty()) {
    form = "refinement";
    has_charts = false;
  } else {
    throw User_error(
        "nothing to check: give a Tessera result directory, a mesh with --seams FILE, an OBJ "
        "with texture coordinates, or --original ORIGINAL to check a refinement");
  }

  Check_report report;
  report.input = input;
  report.form = form;
  report.exact = a.exact;
  std::size_t shown = 0;
  auto say = [&](const std::string& check, const std::string& kind, const std::string& message) {
    if (shown++ < 50)
      out << "problem: " << check << ": " << kind << ": " << message << "\n";
  };

  if (has_charts) {
    options.expect = expect.value_or(Expected_cutting::disks);
    options.check_loops_non_contractible = a.exact && options.expect == Expected_cutting::schema;
    const Cutting_validation v = validate_charts(mesh, charts, chart_to_mesh, options);
    add_chart_check(report, v, options.expect);
    for (const auto& p : v.problems)
      say("charts", problem_kind_name(p.kind), p.message);
    out << form << ": " << v.charts.size() << " chart(s), " << v.seam_edges << " seam edges, "
        << v.corner_vertices << " corner vertices, expected " << report.charts->expect;
    if (v.charts.size() == 1)
      out << ", word " << v.charts.front().word;
    out << (v ? ": valid" : ": INVALID") << "\n";
  }
  if (uv_check) {
    add_problems(report, *uv_check, "texture");
    for (const auto& p : uv_check->problems)
      say("texture", problem_kind_name(p.kind), p.message);
    for (std::size_t i = 0; i < uv_check->notes.size() && i < 10; ++i)
      out << "note: texture: " << problem_kind_name(uv_check->notes[i].kind) << ": "
          << uv_check->notes[i].message << "\n";
    if (uv_check->notes.size() > 10)
      out << "note: " << uv_check->notes.size() - 10 << " more notes"
          << (a.report.empty() ? " (--report lists them all)" : " in the report") << "\n";
    out << "texture layout: " << uv_check->message << (a.exact ? " (exact)" : "") << "\n";
  }
  if (!a.original.empty()) {
    Validate_refinement_options ro;
    Refinement_validation r;
    if (a.exact) {
      ro.tolerance = 0;
      const Exact_mesh original = read_exact(a.original);
      // A result of `--kernel exact` keeps its exact coordinates beside mesh.off.
      const fs::path exact_surface = fs::path(surface_path).parent_path() / "mesh.exact.off";
      const bool in_result_dir = fs::is_directory(input) && fs::exists(exact_surface);
      r = validate_refinement(
          original, read_exact(in_result_dir ? exact_surface.string() : surface_path), ro);
      if (in_result_dir)
        out << "refinement: exact coordinates from " << exact_surface.string() << "\n";
      // A run in double precision rounded every coordinate that is not a double on reading: such
      // vertices are then, truly, off the original by up to half a unit in the last place.
      std::size_t not_doubles = 0;
      for (auto v : original.vertices())
        for (int d = 0; d < 3; ++d) {
          const Exact_kernel::FT& x = original.point(v)[d];
          not_doubles += x != Exact_kernel::FT(CGAL::to_double(CGAL::exact(x))) ? 1 : 0;
        }
      if (!r && not_doubles > 0)
        std::cerr
            << "tessera: note: " << not_doubles << " coordinates of " << a.original
            << " are not doubles; a run in double precision rounded them, so --exact finds its "
               "vertices off the original by rounding (an exact run keeps them)\n";
    } else {
      r = validate_refinement(read_unchanged<Mesh>(a.original), read_unchanged<Mesh>(surface_path),
                              ro);
    }
    if (r.status == Refinement_validation_status::not_triangles)
      throw User_error(r.message);
    add_refinement_check(report, r, a.original, ro.tolerance);
    for (const auto& p : r.problems)
      say("refinement", problem_kind_name(p.kind), p.message);
    out << "refinement of " << a.original << ": " << r.message << (r ? ": valid" : ": INVALID")
        << "\n";
  }
  return report;
}

// The inputs to check: each argument, or for a directory that is not a Tessera result directory,
// the OBJ files in it (sorted by name).
std::vector<std::string> expand_inputs(const std::vector<std::string>& arguments) {
  namespace fs = std::filesystem;
  std::vector<std::string> inputs;
  for (const std::string& a : arguments) {
    if (!fs::is_directory(a) || fs::exists(fs::path(a) / "result.json")) {
      inputs.push_back(a);
      continue;
    }
    std::vector<std::string> found;
    for (const auto& entry : fs::directory_iterator(a))
      if (entry.is_regular_file() && file_extension(entry.path().string()) == ".obj")
        found.push_back(entry.path().string());
    if (found.empty())
      throw User_error(a + ": neither a Tessera result directory (no result.json) nor a directory "
                           "of OBJ layouts");
    std::sort(found.begin(), found.end());
    inputs.insert(inputs.end(), found.begin(), found.end());
  }
  return inputs;
}

// One line for an input checked among several.
std::string summary_line(const Check_report& r) {
  std::string line = r.input + ": " + (r.valid ? "valid" : "INVALID");
  if (r.charts)
    line += ", " + std::to_string(r.charts->charts.size()) + " chart(s)";
  line += ", " + std::to_string(r.problems.size()) + " problem(s), " +
          std::to_string(r.notes.size()) + " note(s)";
  if (!r.problems.empty())
    line += ": " + r.problems.front().check + ": " + r.problems.front().kind + ": " +
            r.problems.front().message;
  return line;
}

} // namespace

int run_check(const Check_arguments& a) {
  namespace fs = std::filesystem;
  if (!a.report.empty() && fs::exists(a.report) && !a.force)
    throw User_error(a.report + " exists: pass --force to overwrite it");
  const std::vector<std::string> inputs = expand_inputs(a.inputs);
  if (inputs.size() == 1) {
    const Check_report report = check_one(a, inputs.front(), std::cout);
    if (!a.report.empty()) {
      write_checked_stream(a.report,
                           [&](std::ostream& out) { return write_check_report(out, report); });
      std::cout << "wrote " << a.report << "\n";
    }
    return report.valid ? exit_ok : exit_internal;
  }
  if (!a.seams.empty() || !a.original.empty())
    throw User_error("--seams and --original go with one input (" + std::to_string(inputs.size()) +
                     " given)");
  std::vector<Check_report> reports;
  std::size_t invalid = 0;
  std::ostream quiet(nullptr);
  for (const std::string& input : inputs) {
    try {
      reports.push_back(check_one(a, input, quiet));
    } catch (const User_error& e) {
      // An input that cannot be read is reported as invalid, and the others still checked.
      Check_report r;
      r.input = input;
      r.form = "unreadable";
      r.valid = false;
      r.problems.push_back({"input", "unreadable", e.what(), {}, {}, std::nullopt});
      reports.push_back(std::move(r));
    }
    invalid += reports.back().valid ? 0 : 1;
    std::cout << summary_line(reports.back()) << "\n";
  }
  std::cout << inputs.size() << " inputs: " << inputs.size() - invalid << " valid, " << invalid
            << " invalid\n";
  if (!a.report.empty()) {
    write_checked_stream(a.report,
                         [&](std::ostream& out) { return write_check_reports(out, reports); });
    std::cout << "wrote " << a.report << "\n";
  }
  return invalid == 0 ? exit_ok : exit_internal;
}

void register_check_commands(CLI::App& app, std::function<int()>& run) {
  auto args = std::make_shared<Check_arguments>();
  auto* cmd = app.add_subcommand(
      "check", "Validate a cutting (Tessera's or another tool's), optionally exactly");
  cmd->add_option("inputs", args->inputs,
                  "A Tessera result directory (cut or quadrangulate), a mesh with --seams, an OBJ "
                  "with texture coordinates, or a refined mesh with --original; several inputs, or "
                  "a directory of OBJ layouts, give one line each, a combined --report, and exit "
                  "code 2 if any is invalid")
      ->required();
  cmd->add_option("--seams", args->seams, "Seam file: one edge a line, two 0-based vertex ids");
  cmd->add_option(
      "--expect", args->expect,
      "disks, schema (one 4g-gon at one basepoint) or quads (four corners a chart); a result "
      "directory says which by default");
  cmd->add_option("--original", args->original,
                  "The surface before refinement: check the input lies on it and tiles it");
  cmd->add_flag(
      "--exact", args->exact,
      "Read coordinates as exact rationals (OFF/OBJ text, p/q allowed in OBJ) and test exactly; "
      "schema loops are also shown non-contractible");
  cmd->add_option("--report", args->report, "Write a JSON report to this file");
  cmd->add_flag("--force", args->force, "Overwrite an existing report");
  cmd->callback([&run, args] { run = [args] { return run_check(*args); }; });
}

} // namespace tessera::cli
