// JSON writers of the result reports (tessera/io/result_reports.h): the one place result.json of
// `cut` and `quadrangulate` is written from, in the CLI and in a library user's code alike.
#include <tessera/io/result_reports.h>

#include "report_json.h"

#include <nlohmann/json.hpp>

namespace tessera {
namespace {

// The keys `cut` and `quadrangulate` share, from the members both reports have.
template <typename Report> nlohmann::json shared_keys(const Report& r) {
  nlohmann::json j;
  j["method"] = r.method;
  j["cost"] = r.cost;
  j["kernel"] = r.kernel;
  j["seconds"] = r.seconds;
  j["cut_length"] = r.cut_length;
  j["cut_cost"] = r.cut_cost;
  j["genus"] = r.genus;
  j["boundaries"] = r.boundaries;
  j["multipoints"] = r.multipoints;
  j["opened_to_mesh_vertex"] = r.opened_to_mesh_vertex;
  j["valid"] = r.valid;
  j["validation_problems"] = r.validation_problems;
  if (r.exact_mesh)
    j["exact_mesh"] = *r.exact_mesh;
  return j;
}

} // namespace

bool write_cut_report(std::ostream& out, const Cut_report& r) {
  nlohmann::json j = shared_keys(r);
  j["added_vertices"] = r.added_vertices;
  j["canonical"] = r.canonical;
  j["canonical_moves"] = r.canonical_moves;
  nlohmann::json polygons = nlohmann::json::array();
  for (const Cut_report_polygon& p : r.polygons)
    polygons.push_back({{"genus", p.genus},
                        {"boundaries", p.boundaries},
                        {"sides", p.sides},
                        {"basepoint", p.basepoint},
                        {"corners", p.corners},
                        {"word", p.word}});
  j["polygons"] = polygons;
  // A one-polygon cut (a connected surface) repeats its corners and word at the top.
  j["polygon_corners"] = r.polygons.size() == 1 ? polygons[0]["corners"] : nlohmann::json(nullptr);
  j["word"] = r.polygons.size() == 1 ? polygons[0]["word"] : nlohmann::json(nullptr);
  return io_internal::dump(out, j);
}

bool write_quadrangulation_report(std::ostream& out, const Quadrangulation_report& r) {
  nlohmann::json j = shared_keys(r);
  j["source_cut_length"] = r.source_cut_length;
  j["source_canonical"] = r.source_canonical;
  j["faces_before"] = r.faces_before;
  j["faces_after"] = r.faces_after;
  j["refinements"] = r.refinements;
  j["local_refinements"] = r.local_refinements;
  j["added_corners"] = r.added_corners;
  j["cutting_paths"] = r.cutting_paths;
  j["quads"] = r.quads;
  j["source_polygon_corner_counts"] = r.source_polygon_corner_counts;
  j["tiles"] = r.tiles;
  nlohmann::json quads = nlohmann::json::array();
  for (const Quad_report& q : r.quad_tiles)
    quads.push_back({{"corners", q.corners},
                     {"opened_corners", q.opened_corners},
                     {"angle_distortion", q.angle_distortion},
                     {"area_distortion", q.area_distortion},
                     {"stretch", q.stretch},
                     {"flipped", q.flipped},
                     {"degenerate", q.degenerate}});
  j["quad_tiles"] = quads;
  j["worst_tile"] = r.worst_tile;
  j["flipped"] = r.flipped;
  return io_internal::dump(out, j);
}

} // namespace tessera
