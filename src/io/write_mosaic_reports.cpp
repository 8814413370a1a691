// JSON writers of the mosaic reports (tessera/io/mosaic_reports.h): report.json and tiles.json of
// `tessera mosaic` and `tessera planar-mosaic`, in the CLI and in a library user's code alike.
#include <tessera/io/mosaic_reports.h>

#include "report_json.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace tessera {

bool write_mosaic_report(std::ostream& out, const Mosaic_report& r) {
  const Mosaic_report_options& o = r.options;
  const Mosaic_layout& l = r.layout;
  const Surface_mosaic_stats& s = r.stats;
  const Mosaic_quality& q = r.quality;
  nlohmann::json j;
  j["mesh"] = r.mesh;
  j["repairs"] = io_internal::repairs_json(r.repairs);
  j["options"] = {{"energy", o.energy},     {"start", o.start},
                  {"count", o.count},       {"seed", o.seed},
                  {"teleport", o.teleport}, {"max_iterations", o.max_iterations},
                  {"colors", o.colors}};
  j["field"] = {{"symmetry", r.field.symmetry},
                {"hard_constraints", r.field.hard_constraints},
                {"soft_constraints", r.field.soft_constraints},
                {"feature_lines", r.field.feature_lines},
                {"color_regions", r.field.color_regions},
                {"energy", r.field.energy}};
  if (const auto& t = r.field.thin_parts)
    j["field"]["thin_parts"] = {{"guided_vertices", t->guided_vertices},
                                {"curved_band_vertices", t->curved_band_vertices},
                                {"guided_area_fraction", t->guided_area_fraction},
                                {"fewest_tiles_around", std::isfinite(t->fewest_tiles_around)
                                                            ? nlohmann::json(t->fewest_tiles_around)
                                                            : nlohmann::json(nullptr)},
                                {"median_guided_tiles_around", t->median_guided_tiles_around}};
  if (const auto& m = r.field.refined_mesh)
    j["field"]["refined_mesh"] = {{"vertices_before", m->vertices_before},
                                  {"vertices_added", m->vertices_added},
                                  {"longest_edge_before", m->longest_edge_before},
                                  {"max_edge_length", m->max_edge_length}};
  if (const auto& c = r.field.creases)
    j["field"]["creases"] = {{"lines", c->lines},
                             {"length_spacings", c->length_spacings},
                             {"long_share", c->long_share},
                             {"features", c->features}};
  j["layout"] = {{"tile_count", l.tile_count}, {"tile_size", l.tile_size}, {"aspect", l.aspect},
                 {"grout", l.grout},           {"sigma", l.sigma},         {"spacing", l.spacing}};
  j["stats"] = {{"iterations", s.iterations},
                {"converged", s.converged},
                {"energy", s.energy},
                {"mean_displacement", s.mean_displacement},
                {"net_displacement", s.net_displacement},
                {"charts", s.charts},
                {"failed_charts", s.failed_charts},
                {"regions", s.regions},
                {"virtual_tiles", s.virtual_tiles},
                {"teleported", s.teleported},
                {"moved_off_features", s.moved_off_features},
                {"cut_at_features", s.cut_at_features},
                {"removed_at_features", s.removed_at_features},
                {"separation_passes", s.separation_passes},
                {"left_out_crowded", s.left_out_crowded},
                {"close_pairs", s.close_pairs},
                {"shrunk_tiles", s.shrunk_tiles},
                {"trimmed_tiles", s.trimmed_tiles},
                {"filled_patches", s.filled_patches},
                {"grown_tiles", s.grown_tiles},
                {"lattice_levels", s.lattice_levels},
                {"lattice_points", s.lattice_points},
                {"seconds",
                 {{"field", r.seconds_field},
                  {"setup", s.seconds_setup},
                  {"initialization", s.seconds_initialization},
                  {"optimization", s.seconds_optimization},
                  {"separation", s.seconds_separation}}}};
  j["quality"] = {{"tiles", q.tiles},
                  {"samples", q.samples},
                  {"area", q.area},
                  {"coverage", q.coverage},
                  {"overlap", q.overlap},
                  {"orientation_error_median", q.orientation_error_median},
                  {"orientation_error_p95", q.orientation_error_p95},
                  {"orientation_error_max", q.orientation_error_max},
                  {"row_alignment_median", q.row_alignment_median},
                  {"row_alignment_p95", q.row_alignment_p95},
                  {"course_drift_median", q.course_drift_median},
                  {"course_drift_p95", q.course_drift_p95},
                  {"largest_gap", q.largest_gap},
                  {"largest_gap_center", q.largest_gap_center},
                  {"gap_mean", q.gap_mean},
                  {"gap_min", q.gap_min},
                  {"gap_ideal", q.gap_ideal},
                  {"tiles_crossing_features", q.tiles_crossing_features}};
  if (r.cut_tiles)
    j["cut_tiles"] = {{"grout_width", r.cut_tiles->grout_width},
                      {"tiles_cut", r.cut_tiles->cut.tiles_cut},
                      {"tiles_removed", r.cut_tiles->cut.tiles_removed},
                      {"area_removed", r.cut_tiles->cut.area_removed},
                      {"fraction_removed", r.cut_tiles->cut.fraction_removed}};
  return io_internal::dump(out, j);
}

namespace {

// One tile a line: readable, and a tenth of the size of an indented dump.
template <typename Tile, typename Json>
void write_tile_lines(std::ostream& out, const std::vector<Tile>& tiles, Json tile_json) {
  for (std::size_t i = 0; i < tiles.size(); ++i)
    out << "  " << tile_json(tiles[i]).dump() << (i + 1 < tiles.size() ? ",\n" : "\n");
  out << "]}\n";
}

} // namespace

bool write_mosaic_tiles_report(std::ostream& out, const Mosaic_tiles_report& r) {
  out << "{\"tiles\": [\n";
  write_tile_lines(out, r.tiles, [](const Mosaic_tile_report& t) {
    nlohmann::json j{{"center", t.center}, {"normal", t.normal}, {"x_axis", t.x_axis},
                     {"size", t.size},     {"face", t.face},     {"region", t.region},
                     {"color", t.color}};
    if (!t.outline.empty())
      j["outline"] = t.outline;
    return j;
  });
  return bool(out);
}

bool write_planar_mosaic_report(std::ostream& out, const Planar_mosaic_report& r) {
  const Planar_mosaic_report_options& o = r.options;
  const Planar_mosaic_quality& q = r.quality;
  const Planar_mosaic_stats& s = r.stats;
  nlohmann::json j;
  j["image"] = {{"path", r.image_path}, {"width", r.image_width}, {"height", r.image_height}};
  j["edges"] = {{"source", r.edge_source}, {"curves", r.edge_curves}, {"pixels", r.edge_pixels}};
  j["tiles"] = r.tiles;
  j["tile_side"] = r.tile_side;
  j["options"] = {{"tiles", o.tiles},
                  {"delta", o.delta},
                  {"aspect", o.aspect},
                  {"shape", o.shape},
                  {"colors", o.colors},
                  {"fit", o.fit},
                  {"iterations", o.iterations},
                  {"barrier_iterations", o.barrier_iterations},
                  {"seed", o.seed}};
  j["quality"] = {{"coverage", q.coverage},
                  {"overlap", q.overlap},
                  {"straddling_tiles", q.straddling_tiles},
                  {"orientation_error_median_degrees", q.orientation_error_median},
                  {"orientation_error_p95_degrees", q.orientation_error_p95},
                  {"color_error_delta_e", q.color_error}};
  j["fitting"] = {{"tiles_shrunk", s.tiles_shrunk},
                  {"tiles_dropped", s.tiles_dropped},
                  {"area_removed", s.area_removed}};
  j["energy"] = s.energy;
  j["grown_windows"] = s.grown_windows;
  j["seconds"] = {{"field", s.seconds_field},
                  {"initialization", s.seconds_initialization},
                  {"iterations", s.seconds_iterations},
                  {"tiles", s.seconds_tiles},
                  {"fitting", s.seconds_fitting},
                  {"report", q.seconds},
                  {"total", r.seconds_total}};
  return io_internal::dump(out, j);
}

bool write_planar_mosaic_tiles_report(std::ostream& out, const Planar_mosaic_tiles_report& r) {
  out << "{\"units\": \"pixels; angle in radians, of the width side, from the x axis towards the "
         "y axis (down)\",\n \"tiles\": [\n";
  write_tile_lines(out, r.tiles, [](const Planar_tile& t) {
    return nlohmann::json{{"center", {t.x, t.y}}, {"angle", t.angle}, {"width", t.width},
                          {"height", t.height},   {"color", t.color}, {"region", t.region}};
  });
  return bool(out);
}

} // namespace tessera
