// JSON writers of the field reports (tessera/io/field_reports.h): singularities.json and
// feature_lines.json of `tessera field`, in the CLI and in a library user's code alike.
#include <tessera/io/field_reports.h>

#include "report_json.h"

#include <nlohmann/json.hpp>

namespace tessera {

bool write_singularities_report(std::ostream& out, const Singularities_report& r) {
  nlohmann::json j;
  j["symmetry"] = r.symmetry;
  j["euler_characteristic"] = r.euler_characteristic;
  j["face_index_sum"] = r.face_index_sum;
  j["boundary_index_sum"] = r.boundary_index_sum;
  j["poincare_hopf_holds"] = r.poincare_hopf_holds;
  j["singularities"] = nlohmann::json::array();
  for (const Singularity_report& s : r.singularities)
    j["singularities"].push_back({{"face", s.face}, {"index", s.index}, {"position", s.position}});
  j["boundary_loops"] = nlohmann::json::array();
  for (const Boundary_index_report& b : r.boundary_loops)
    j["boundary_loops"].push_back({{"halfedge", b.halfedge}, {"index", b.index}});
  return io_internal::dump(out, j, 2);
}

bool write_feature_lines_report(std::ostream& out, const Feature_lines_report& r) {
  nlohmann::json j = nlohmann::json::array();
  for (const Feature_line_report& l : r.lines)
    j.push_back({{"line", l.line},
                 {"kind", l.kind},
                 {"closed", l.closed},
                 {"alignment", l.alignment},
                 {"vertices", l.vertices}});
  return io_internal::dump(out, j);
}

} // namespace tessera
