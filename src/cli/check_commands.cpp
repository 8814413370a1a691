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
#include <tessera/io/read_result_directory.h>
#include <tessera/topology/validate_charts.h>
#include <tessera/topology/validate_refinement.h>

#include <filesystem>
#include <iostream>
#include <optional>
#include <stdexcept>

namespace tessera::cli {
namespace {

// The cutting's files are read as they are: vertex ids must stay the file's.
const char* const kept_ids_note =
    " (check reads files unchanged, so that vertex ids keep their meaning)";

template <typename M> M read_unchanged(const std::string& path) {
  Read_mesh_options options;
  options.repair = Mesh_repair::none;
  options.triangulate = false;
  M mesh;
  const Read_mesh_result r = read_mesh(path, mesh, options);
  if (!r)
    throw User_error(r.message + kept_ids_note);
  return mesh;
}

// A surface with its coordinates read exactly from the file's text (decimals or p/q rationals).
Exact_mesh read_exact(const std::string& path) {
  Exact_mesh exact;
  const Cutting_read_result r = read_exact_polygon_mesh(path, exact);
  if (!r)
    throw User_error(r.message);
  return exact;
}

// One input as validate_charts() takes it, whichever way it comes, and what else to check.
struct Check_input {
  std::string form;
  Mesh mesh, charts;
  std::vector<Mesh::Vertex_index> chart_to_mesh;
  Validate_charts_options options;
  std::optional<Expected_cutting> expect;   ///< --expect, or what a result directory says
  std::string surface_path;                 ///< the refined surface, for --original
  std::optional<std::string> exact_surface; ///< a result directory's mesh.exact.off
  bool has_charts = true;
  std::optional<Cutting_validation> uv_check; ///< an OBJ's texture layout
};

void read_result_directory_input(const std::string& input, Check_input& in) {
  Result_directory_options options;
  options.expect = in.expect;
  Result_directory d = read_result_directory(input, options);
  // A "method" that is not a string stays what it was before the reader moved to the library: an
  // internal error (exit 2) that stops every input.
  if (d.status == Result_directory_status::bad_method)
    throw std::runtime_error(d.message);
  if (!d)
    throw User_error(d.message +
                     (d.status == Result_directory_status::bad_mesh ? kept_ids_note : ""));
  in.form = "result directory";
  in.surface_path = d.mesh_path;
  in.exact_surface = d.exact_mesh_path;
  in.mesh = std::move(d.mesh);
  in.charts = std::move(d.opened);
  in.chart_to_mesh = std::move(d.opened_to_mesh);
  in.options.marked_corners = std::move(d.multipoints);
  in.expect = d.expect;
}

void read_seam_input(const std::string& input, const std::string& seams, Check_input& in) {
  in.form = "seam file";
  in.mesh = read_unchanged<Mesh>(input);
  Mesh& mesh = in.mesh;
  auto seam_e = mesh.add_property_map<Mesh::Edge_index, bool>("e:tessera_seam", false).first;
  auto seam_v = mesh.add_property_map<Mesh::Vertex_index, bool>("v:tessera_seam", false).first;
  const Cutting_read_result r = read_seam_file(seams, mesh, seam_e);
  if (!r)
    throw User_error(r.message);
  for (auto e : mesh.edges())
    if (seam_e[e])
      seam_v[source(halfedge(e, mesh), mesh)] = seam_v[target(halfedge(e, mesh), mesh)] = true;
  in.chart_to_mesh = open_along_seams(mesh, seam_e, seam_v, in.charts);
  mesh.remove_property_map(seam_e);
  mesh.remove_property_map(seam_v);
}

void read_texture_input(const std::string& input, bool exact, Check_input& in) {
  in.form = "texture coordinates";
  Uv_layout<Mesh> layout;
  const Cutting_read_result r = read_obj_with_uvs(input, layout);
  if (!r)
    throw User_error(r.message);
  in.mesh = std::move(layout.mesh);
  in.charts = std::move(layout.charts);
  in.chart_to_mesh = std::move(layout.chart_to_mesh);
  if (!exact) {
    in.uv_check = validate_uv_layout(in.charts, layout.uv, layout.pinched);
    return;
  }
  Uv_layout<Exact_mesh> exact_layout;
  const Cutting_read_result re = read_obj_with_uvs(input, exact_layout);
  if (!re)
    throw User_error(re.message);
  in.uv_check = validate_uv_layout(exact_layout.charts, exact_layout.uv, exact_layout.pinched);
}

// The surface and its charts, whichever way they come.
Check_input read_check_input(const Check_arguments& a, const std::string& input) {
  Check_input in;
  if (!a.expect.empty())
    in.expect = parse_choice(expected_cutting_names, a.expect, "--expect");
  in.surface_path = input;
  if (std::filesystem::is_directory(input)) {
    read_result_directory_input(input, in);
  } else if (!a.seams.empty()) {
    read_seam_input(input, a.seams, in);
  } else if (file_extension(input) == ".obj" && a.original.empty()) {
    read_texture_input(input, a.exact, in);
  } else if (!a.original.empty()) {
    in.form = "refinement";
    in.has_charts = false;
  } else {
    throw User_error(
        "nothing to check: give a Tessera result directory, a mesh with --seams FILE, an OBJ "
        "with texture coordinates, or --original ORIGINAL to check a refinement");
  }
  return in;
}

// Prints the first 50 problems of all checks.
struct Problem_lines {
  std::ostream& out;
  std::size_t shown = 0;
  template <typename Problems> void operator()(const std::string& check, const Problems& problems) {
    for (const auto& p : problems)
      if (shown++ < 50)
        out << "problem: " << check << ": " << problem_kind_name(p.kind) << ": " << p.message
            << "\n";
  }
};

void check_charts(const Check_arguments& a, Check_input& in, Check_report& report,
                  Problem_lines& say, std::ostream& out) {
  in.options.expect = in.expect.value_or(Expected_cutting::disks);
  in.options.check_loops_non_contractible =
      a.exact && in.options.expect == Expected_cutting::schema;
  const Cutting_validation v = validate_charts(in.mesh, in.charts, in.chart_to_mesh, in.options);
  add_chart_check(report, v, in.options.expect);
  say("charts", v.problems);
  out << in.form << ": " << v.charts.size() << " chart(s), " << v.seam_edges << " seam edges, "
      << v.corner_vertices << " corner vertices, expected " << report.charts->expect;
  if (v.charts.size() == 1)
    out << ", word " << v.charts.front().word;
  out << (v ? ": valid" : ": INVALID") << "\n";
}

void check_texture(const Check_arguments& a, const Cutting_validation& uv, Check_report& report,
                   Problem_lines& say, std::ostream& out) {
  add_problems(report, uv, "texture");
  say("texture", uv.problems);
  for (std::size_t i = 0; i < uv.notes.size() && i < 10; ++i)
    out << "note: texture: " << problem_kind_name(uv.notes[i].kind) << ": " << uv.notes[i].message
        << "\n";
  if (uv.notes.size() > 10)
    out << "note: " << uv.notes.size() - 10 << " more notes"
        << (a.report.empty() ? " (--report lists them all)" : " in the report") << "\n";
  out << "texture layout: " << uv.message << (a.exact ? " (exact)" : "") << "\n";
}

// The coordinates of `tm` that are not doubles (a run in double precision rounded them).
std::size_t count_not_doubles(const Exact_mesh& tm) {
  std::size_t count = 0;
  for (auto v : tm.vertices())
    for (int d = 0; d < 3; ++d) {
      const Exact_kernel::FT& x = tm.point(v)[d];
      count += x != Exact_kernel::FT(CGAL::to_double(CGAL::exact(x))) ? 1 : 0;
    }
  return count;
}

// The refinement check with exact coordinates, from mesh.exact.off where a result directory has it.
Refinement_validation validate_refinement_exactly(const Check_arguments& a, const Check_input& in,
                                                  const Validate_refinement_options& ro,
                                                  std::ostream& out) {
  const Exact_mesh original = read_exact(a.original);
  const Refinement_validation r =
      validate_refinement(original, read_exact(in.exact_surface.value_or(in.surface_path)), ro);
  if (in.exact_surface)
    out << "refinement: exact coordinates from " << *in.exact_surface << "\n";
  // A run in double precision rounded every coordinate that is not a double on reading: such
  // vertices are then, truly, off the original by up to half a unit in the last place.
  if (const std::size_t not_doubles = r ? 0 : count_not_doubles(original); not_doubles > 0)
    std::cerr << "tessera: note: " << not_doubles << " coordinates of " << a.original
              << " are not doubles; a run in double precision rounded them, so --exact finds its "
                 "vertices off the original by rounding (an exact run keeps them)\n";
  return r;
}

void check_refinement(const Check_arguments& a, const Check_input& in, Check_report& report,
                      Problem_lines& say, std::ostream& out) {
  Validate_refinement_options ro;
  if (a.exact)
    ro.tolerance = 0;
  const Refinement_validation r =
      a.exact ? validate_refinement_exactly(a, in, ro, out)
              : validate_refinement(read_unchanged<Mesh>(a.original),
                                    read_unchanged<Mesh>(in.surface_path), ro);
  if (r.status == Refinement_validation_status::not_triangles)
    throw User_error(r.message);
  add_refinement_check(report, r, a.original, ro.tolerance);
  say("refinement", r.problems);
  out << "refinement of " << a.original << ": " << r.message << (r ? ": valid" : ": INVALID")
      << "\n";
}

// Checks one input; prints its problems and figures to `out` (a null stream when several inputs
// are checked, which get one line each).
Check_report check_one(const Check_arguments& a, const std::string& input, std::ostream& out) {
  Check_input in = read_check_input(a, input);
  Check_report report;
  report.input = input;
  report.form = in.form;
  report.exact = a.exact;
  Problem_lines say{out};
  if (in.has_charts)
    check_charts(a, in, report, say, out);
  if (in.uv_check)
    check_texture(a, *in.uv_check, report, say, out);
  if (!a.original.empty())
    check_refinement(a, in, report, say, out);
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

// An input among several that cannot be read: reported as invalid, and the others still checked.
Check_report unreadable_report(const std::string& input, const std::string& why) {
  Check_report r;
  r.input = input;
  r.form = "unreadable";
  r.valid = false;
  r.problems.push_back({"input", "unreadable", why, {}, {}, std::nullopt});
  return r;
}

// Several inputs: one line each, a count, and one report for all.
int check_several(const Check_arguments& a, const std::vector<std::string>& inputs) {
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
      reports.push_back(unreadable_report(input, e.what()));
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

} // namespace

int run_check(const Check_arguments& a) {
  namespace fs = std::filesystem;
  if (!a.report.empty() && fs::exists(a.report) && !a.force)
    throw User_error(a.report + " exists: pass --force to overwrite it");
  const std::vector<std::string> inputs = expand_inputs(a.inputs);
  if (inputs.size() != 1)
    return check_several(a, inputs);
  const Check_report report = check_one(a, inputs.front(), std::cout);
  if (!a.report.empty()) {
    write_checked_stream(a.report,
                         [&](std::ostream& out) { return write_check_report(out, report); });
    std::cout << "wrote " << a.report << "\n";
  }
  return report.valid ? exit_ok : exit_internal;
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
