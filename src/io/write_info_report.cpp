// JSON writer of the info report (tessera/io/info_report.h): what `tessera info --json` prints, in
// the CLI and in a library user's code alike.
#include <tessera/io/info_report.h>

#include "report_json.h"

#include <nlohmann/json.hpp>

namespace tessera {

bool write_info_report(std::ostream& out, const Info_report& r) {
  const Mesh_info& info = r.info;
  nlohmann::json j;
  j["vertices"] = info.vertices;
  j["edges"] = info.edges;
  j["faces"] = info.faces;
  j["boundary_loops"] = info.boundary_loops;
  j["euler_characteristic"] = info.euler_characteristic;
  j["connected_components"] = info.components.size();
  j["manifold"] = info.is_valid_polygon_mesh;
  j["triangle_mesh"] = info.is_triangle_mesh;
  j["closed"] = info.is_closed;
  if (info.self_intersection_checked)
    j["self_intersects"] = info.self_intersects;
  j["area"] = info.area;
  j["bbox"] = {{"min", info.bbox_min}, {"max", info.bbox_max}};
  nlohmann::json components = nlohmann::json::array();
  for (const Component_info& c : info.components)
    components.push_back({{"vertices", c.vertices},
                          {"edges", c.edges},
                          {"faces", c.faces},
                          {"boundary_loops", c.boundary_loops},
                          {"euler_characteristic", c.euler_characteristic},
                          {"genus", c.genus},
                          {"area", c.area}});
  j["components"] = components;
  j["repairs"] = io_internal::repairs_json(r.repairs);
  return io_internal::dump(out, j, 2);
}

} // namespace tessera
