// tessera::read_result_directory (see tessera/io/read_result_directory.h).
#include <tessera/io/read_result_directory.h>

#include <tessera/io/internal/bounded_readers.h>
#include <tessera/io/read_mesh.h>
#include <tessera/topology/method_names.h>

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace tessera {
namespace {

namespace fs = std::filesystem;

Result_directory failed(Result_directory& d, Result_directory_status status, std::string message) {
  d.status = status;
  d.message = std::move(message);
  return std::move(d);
}

// An OFF polygon mesh with every vertex as the file has it (duplicated points stay apart), read
// through the bounded OFF reader: result directories are user input like any mesh.
bool read_off_as_is(const std::string& path, Mesh& tm) {
  std::error_code error;
  const std::uintmax_t bytes = fs::file_size(path, error);
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

// opened_to_mesh_vertex into `d.opened_to_mesh`; false when it is missing or names a vertex that
// mesh.off lacks (`why` says which).
bool read_vertex_map(const nlohmann::json& j, const std::string& dir, Result_directory& d,
                     std::string& why) {
  const auto o2m = j.find("opened_to_mesh_vertex");
  if (o2m == j.end() || !o2m->is_array()) {
    why = dir + ": result.json has no opened_to_mesh_vertex";
    return false;
  }
  for (const auto& v : *o2m) {
    if (!v.is_number_unsigned() || v.get<std::size_t>() >= num_vertices(d.mesh)) {
      why = dir + ": opened_to_mesh_vertex holds an id that is not a vertex of mesh.off";
      return false;
    }
    d.opened_to_mesh.emplace_back(v.get<std::size_t>());
  }
  return true;
}

// What result.json says the charts form: quads for a quadrangulation, schema for a schema cut.
// Throws nlohmann::json::type_error when "method" is there but not a string.
Expected_cutting expected_cutting_of(const nlohmann::json& j) {
  if (j.contains("quad_tiles"))
    return Expected_cutting::quads;
  return parse_cut_method(j.value("method", std::string())) == Cut_method::schema
             ? Expected_cutting::schema
             : Expected_cutting::disks;
}

} // namespace

Result_directory read_result_directory(const std::string& dir,
                                       const Result_directory_options& options) {
  Result_directory d;
  const fs::path path(dir);
  for (const char* name : {"result.json", "mesh.off", "opened.off"})
    if (!fs::exists(path / name))
      return failed(d, Result_directory_status::not_a_result_directory,
                    dir + ": not a Tessera result directory (no " + name + ")");
  nlohmann::json j;
  try {
    std::ifstream(path / "result.json") >> j;
  } catch (const nlohmann::json::exception& e) {
    return failed(d, Result_directory_status::malformed_json,
                  (path / "result.json").string() + ": malformed JSON (" + e.what() + ")");
  }
  d.mesh_path = (path / "mesh.off").string();
  Read_mesh_options unchanged; // vertex ids must stay the file's
  unchanged.repair = Mesh_repair::none;
  unchanged.triangulate = false;
  if (const Read_mesh_result r = read_mesh(d.mesh_path, d.mesh, unchanged); !r)
    return failed(d, Result_directory_status::bad_mesh, r.message);
  // The opened mesh repeats the points of seam vertices, which read_mesh() would merge: read it as
  // the OFF file gives it.
  const std::string opened = (path / "opened.off").string();
  if (!read_off_as_is(opened, d.opened))
    return failed(d, Result_directory_status::bad_opened_mesh,
                  opened + ": not a valid OFF polygon mesh");
  std::string why;
  if (!read_vertex_map(j, dir, d, why))
    return failed(d, Result_directory_status::bad_vertex_map, why);
  if (const auto mp = j.find("multipoints"); mp != j.end() && mp->is_array())
    for (const auto& v : *mp)
      if (v.is_number_unsigned())
        d.multipoints.push_back(v.get<std::size_t>());
  if (options.expect) {
    d.expect = *options.expect;
  } else {
    try {
      d.expect = expected_cutting_of(j);
    } catch (const nlohmann::json::exception& e) {
      return failed(d, Result_directory_status::bad_method, e.what());
    }
  }
  const fs::path exact = fs::path(d.mesh_path).parent_path() / "mesh.exact.off";
  if (fs::exists(exact))
    d.exact_mesh_path = exact.string();
  return d;
}

} // namespace tessera
