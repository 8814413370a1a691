// JSON writer of the check report (tessera/io/check_report.h): what `tessera check --report`
// writes, in the CLI and in a library user's code alike.
#include <tessera/io/check_report.h>

#include "report_json.h"

#include <nlohmann/json.hpp>

namespace tessera {

namespace {

nlohmann::json check_report_json(const Check_report& r) {
  nlohmann::json j;
  j["input"] = r.input;
  j["form"] = r.form;
  j["exact"] = r.exact;
  if (r.charts) {
    j["expect"] = r.charts->expect;
    nlohmann::json charts = nlohmann::json::array();
    for (const Chart_summary& c : r.charts->charts)
      charts.push_back({{"faces", c.faces},
                        {"euler_characteristic", c.euler_characteristic},
                        {"boundary_loops", c.boundary_loops},
                        {"corners", c.corners},
                        {"opened_corners", c.chart_corners},
                        {"sides", c.sides},
                        {"word", c.word}});
    j["charts"] = charts;
    j["seam_edges"] = r.charts->seam_edges;
    j["corner_vertices"] = r.charts->corner_vertices;
  }
  if (r.refinement)
    j["refinement"] = {{"original", r.refinement->original},
                       {"on_original_vertices", r.refinement->on_original_vertices},
                       {"on_original_edges", r.refinement->on_original_edges},
                       {"inside_original_faces", r.refinement->inside_original_faces},
                       {"tolerance", r.refinement->tolerance}};
  j["valid"] = r.valid;
  auto listed = [](const std::vector<Check_problem_report>& list) {
    nlohmann::json out = nlohmann::json::array();
    for (const Check_problem_report& p : list) {
      nlohmann::json q{{"check", p.check},
                       {"kind", p.kind},
                       {"message", p.message},
                       {"vertices", p.vertices},
                       {"faces", p.faces}};
      if (p.original_faces)
        q["original_faces"] = *p.original_faces;
      out.push_back(q);
    }
    return out;
  };
  j["problems"] = listed(r.problems);
  j["notes"] = listed(r.notes);
  return j;
}

} // namespace

bool write_check_report(std::ostream& out, const Check_report& r) {
  return io_internal::dump(out, check_report_json(r));
}

bool write_check_reports(std::ostream& out, const std::vector<Check_report>& reports) {
  nlohmann::json j;
  std::size_t invalid = 0;
  nlohmann::json list = nlohmann::json::array();
  for (const Check_report& r : reports) {
    invalid += r.valid ? 0 : 1;
    list.push_back(check_report_json(r));
  }
  j["inputs"] = reports.size();
  j["invalid"] = invalid;
  j["valid"] = invalid == 0;
  j["reports"] = list;
  return io_internal::dump(out, j);
}

} // namespace tessera
