// What `tessera check --report` writes, for library users: a plain report struct filled from the
// validations of a cutting (`validate_charts`, `validate_uv_layout`) and of a refinement
// (`validate_refinement`) by `add_chart_check`, `add_problems` and `add_refinement_check`, and its
// JSON writer compiled into Tessera::core (nlohmann-json stays private). The keys and their
// meanings are doc/formats.md's; the CLI writes through these and nothing else.
#pragma once

#include <tessera/internal/enum_names.h>
#include <tessera/topology/validate_charts.h>
#include <tessera/topology/validate_refinement.h>

#include <cstddef>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace tessera {

/// The names of the problem kinds in the report.
inline constexpr internal::Enum_names<Cutting_problem_kind, 10> cutting_problem_kind_names{{
    {Cutting_problem_kind::mismatch, "mismatch"},
    {Cutting_problem_kind::not_a_disk, "not_a_disk"},
    {Cutting_problem_kind::unpaired_side, "unpaired_side"},
    {Cutting_problem_kind::dangling_seam, "dangling_seam"},
    {Cutting_problem_kind::not_a_schema, "not_a_schema"},
    {Cutting_problem_kind::not_a_quad, "not_a_quad"},
    {Cutting_problem_kind::contractible_loop, "contractible_loop"},
    {Cutting_problem_kind::degenerate_uv_face, "degenerate_uv_face"},
    {Cutting_problem_kind::inverted_uv_face, "inverted_uv_face"},
    {Cutting_problem_kind::pinched_texture_vertex, "pinched_texture_vertex"},
}};

/// The name of a problem kind in the report ("not_a_disk", "inverted_uv_face", …).
inline const char* problem_kind_name(Cutting_problem_kind k) {
  return internal::enum_name(cutting_problem_kind_names, k);
}

/// The names of the refinement problem kinds in the report.
inline constexpr internal::Enum_names<Refinement_problem_kind, refinement_problem_kinds>
    refinement_problem_kind_names{{
        {Refinement_problem_kind::off_surface, "off_surface"},
        {Refinement_problem_kind::straddles_faces, "straddles_faces"},
        {Refinement_problem_kind::degenerate_face, "degenerate_face"},
        {Refinement_problem_kind::inverted_face, "inverted_face"},
        {Refinement_problem_kind::coverage, "coverage"},
    }};

/// The name of a refinement problem kind in the report ("off_surface", "coverage", …).
inline const char* problem_kind_name(Refinement_problem_kind k) {
  return internal::enum_name(refinement_problem_kind_names, k);
}

/// What the charts are expected to form, as `tessera check --expect` and the report name it.
inline constexpr internal::Enum_names<Expected_cutting, 3> expected_cutting_names{
    {{Expected_cutting::disks, "disks"},
     {Expected_cutting::schema, "schema"},
     {Expected_cutting::quads, "quads"}}};

/// One problem found by one of the checks.
struct Check_problem_report {
  std::string check; ///< "charts", "texture" or "refinement"
  std::string kind, message;
  std::vector<std::size_t> vertices, faces;
  std::optional<std::vector<std::size_t>> original_faces; ///< refinement problems only
};

/// The charts of a cutting and what was expected of them.
struct Check_charts_report {
  std::string expect; ///< "disks", "schema" or "quads"
  std::vector<Chart_summary> charts;
  std::size_t seam_edges = 0, corner_vertices = 0;
};

/// The refinement check's figures.
struct Check_refinement_report {
  std::string original;
  std::size_t on_original_vertices = 0, on_original_edges = 0, inside_original_faces = 0;
  double tolerance = 0;
};

/// The report of `tessera check`.
struct Check_report {
  std::string input, form;
  bool exact = false;
  std::optional<Check_charts_report> charts; ///< when the input has charts
  std::optional<Check_refinement_report> refinement;
  bool valid = true;
  std::vector<Check_problem_report> problems;
  /// Facts that leave the input valid (charts touching at a point), in the problems' form.
  std::vector<Check_problem_report> notes;
};

/// Writes `report` as JSON (one key a line); false when the stream failed.
bool write_check_report(std::ostream& out, const Check_report& report);

/// Writes the reports of several inputs as one JSON object (schema `check-reports`): how many were
/// checked and found invalid, and each report as `write_check_report` writes it; false when the
/// stream failed.
bool write_check_reports(std::ostream& out, const std::vector<Check_report>& reports);

/// Adds the problems and notes of `v` under the name `check` to `report` and its verdict to
/// `report.valid`.
inline void add_problems(Check_report& report, const Cutting_validation& v,
                         const std::string& check) {
  for (const Cutting_problem& p : v.problems)
    report.problems.push_back(
        {check, problem_kind_name(p.kind), p.message, p.vertices, p.faces, std::nullopt});
  for (const Cutting_problem& p : v.notes)
    report.notes.push_back(
        {check, problem_kind_name(p.kind), p.message, p.vertices, p.faces, std::nullopt});
  report.valid = report.valid && bool(v);
}

/// Adds the charts `v` of `validate_charts(…)` under `expect` and their problems ("charts").
inline void add_chart_check(Check_report& report, const Cutting_validation& v,
                            Expected_cutting expect) {
  report.charts = Check_charts_report{internal::enum_name(expected_cutting_names, expect), v.charts,
                                      v.seam_edges, v.corner_vertices};
  add_problems(report, v, "charts");
}

/// Adds the refinement check `r` of the surface against `original` (a path, as given) with
/// `tolerance`, and its problems ("refinement").
inline void add_refinement_check(Check_report& report, const Refinement_validation& r,
                                 const std::string& original, double tolerance) {
  report.refinement = Check_refinement_report{original, r.on_original_vertices, r.on_original_edges,
                                              r.inside_original_faces, tolerance};
  for (const Refinement_problem& p : r.problems)
    report.problems.push_back({"refinement", problem_kind_name(p.kind), p.message, p.vertices,
                               p.faces, p.original_faces});
  report.valid = report.valid && bool(r);
}

} // namespace tessera
