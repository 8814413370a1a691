// JSON writer of the check report (tessera/io/check_report.h): what `tessera check --report`
// writes, in the CLI and in a library user's code alike.
#include <tessera/io/check_report.h>

#include "report_json.h"

#include <nlohmann/json.hpp>

namespace tessera {

bool write_check_report(std::ostream& out, const Check_report& r) {
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
  nlohmann::json problems = nlohmann::json::array();
  for (const Check_problem_report& p : r.problems) {
    nlohmann::json q{{"check", p.check},
                     {"kind", p.kind},
                     {"message", p.message},
                     {"vertices", p.vertices},
                     {"faces", p.faces}};
    if (p.original_faces)
      q["original_faces"] = *p.original_faces;
    problems.push_back(q);
  }
  j["problems"] = problems;
  return io_internal::dump(out, j);
}

} // namespace tessera
