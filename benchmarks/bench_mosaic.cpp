// Surface-mosaic figures: end-to-end time per stage (field, setup and charts, initialization,
// optimization, quality report) at issue 13's sizes (50k triangles / 10k tiles, 200k / 40k) on
// Loop-subdivided fandisk, and the quality report on the paper's kinds of models (the "eight" with
// 3000 tiles, a creased cube, the knot, the CAD part with its creases) against issue 13's targets.
#include "harness.h"

#include <tessera/fields.h>
#include <tessera/io.h>
#include <tessera/mosaic.h>
#include <tessera/types.h>

#include <CGAL/subdivision_method_3.h>

#include <chrono>
#include <string>

namespace {

using namespace tessera;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

Mesh load(const std::string& file, int loop_steps) {
  Mesh m;
  const Read_mesh_result r = read_mesh(bench::data_dir() + "/" + file, m);
  if (!r)
    throw std::runtime_error(r.message);
  if (loop_steps > 0)
    CGAL::Subdivision_method_3::Loop_subdivision(
        m, CGAL::parameters::number_of_iterations(loop_steps));
  return m;
}

struct Run {
  double smoothing = 0, field = 0, setup = 0, init = 0, optimize = 0, separate = 0, report = 0,
         total = 0;
  std::size_t tiles = 0, iterations = 0;
  bool converged = false;
  Mosaic_quality quality;
};

Run run(Mesh& mesh, std::size_t tiles, const Feature_line_options& fo, bool teleport,
        Mosaic_count count = Mosaic_count::about,
        Mosaic_initialization start = Mosaic_initialization::automatic) {
  Run out;
  const auto t0 = Clock::now();
  auto lines = feature_lines(mesh, fo);
  Surface_mosaic_options o;
  o.tiles.tile_count = tiles;
  // As `tessera mosaic` does: faces with edges over four tile spacings remeshed for the field.
  const Mosaic_layout layout = surface_layout(mesh, o.tiles).value_or(Mosaic_layout{});
  refine_coarse_mesh(mesh, coarse_mesh_options(layout), lines);
  auto field = mesh.add_property_map<Mesh::Vertex_index, Vector_3>("v:tessera_field").first;
  // As it does by default: the field solved on the surface smoothed at the tiles' scale, turned
  // along parts fewer than 10 tiles around (and curved bands, where creases are lines) and held
  // elsewhere.
  auto points = mesh.add_property_map<Mesh::Vertex_index, Point_3>("v:tessera_tile_scale").first;
  const auto t_smooth = Clock::now();
  tile_scale_points(mesh, layout.spacing, lines, points);
  out.smoothing = since(t_smooth);
  const auto np = CGAL::parameters::vertex_point_map(points);
  smoothest_field_with_thin_parts(mesh,
                                  feature_alignment_constraints(mesh, lines,
                                                                {Feature_alignment::parallel},
                                                                feature_alignment_options(layout)),
                                  field, thin_part_options(layout, lines), {}, np);
  out.field = since(t0);
  if (teleport)
    o.teleport_every = 10;
  o.count = count;
  o.initialization = start;
  Surface_mosaic<Mesh> mosaic(mesh, field, lines, o);
  mosaic.run();
  const auto result = mosaic.result();
  out.setup = result.stats.seconds_setup;
  out.init = result.stats.seconds_initialization;
  out.optimize = result.stats.seconds_optimization;
  out.separate = result.stats.seconds_separation;
  out.iterations = result.stats.iterations;
  out.converged = result.stats.converged;
  out.tiles = result.tiles.size();
  const auto t1 = Clock::now();
  out.quality = mosaic_quality(mesh, result.tiles, field, lines);
  out.report = since(t1);
  out.total = since(t0);
  return out;
}

// The speed case on its own (`tessera_bench --filter mosaic_speed`), so a change to the
// optimization can be timed without the quality runs.
void mosaic_speed(bench::Report& report, const bench::Config& config) {
  const std::string speed =
      "Surface mosaics: time per stage (s), fandisk Loop-subdivided, smoothest 4-field";
  struct Size {
    int loop;
    std::size_t tiles;
  };
  const std::vector<Size> sizes = config.quick
                                      ? std::vector<Size>{{0, 1000}}
                                      : std::vector<Size>{{1, 10000}, {2, 40000}, {2, 3000}};
  for (const Size& s : sizes) {
    Mesh mesh = load("fandisk.off", s.loop);
    Feature_line_options none;
    none.boundary = false;
    const Run r = run(mesh, s.tiles, none, false);
    report.add(speed, {{"triangles", std::to_string(num_faces(mesh))},
                       {"tiles", std::to_string(r.tiles)},
                       {"field", bench::fixed(r.field, 3)},
                       {"of which smoothing", bench::fixed(r.smoothing, 3)},
                       {"setup + charts", bench::fixed(r.setup, 3)},
                       {"initialization", bench::fixed(r.init, 3)},
                       {"optimization", bench::fixed(r.optimize, 3)},
                       {"separation", bench::fixed(r.separate, 3)},
                       {"iterations", std::to_string(r.iterations) + (r.converged ? "" : " (cap)")},
                       {"report", bench::fixed(r.report, 3)},
                       {"end to end", bench::fixed(r.total, 3)},
                       {"coverage", bench::fixed(r.quality.coverage, 3)},
                       {"overlap", bench::fixed(r.quality.overlap, 3)},
                       {"course drift median (°)", bench::fixed(r.quality.course_drift_median, 1)},
                       {"widest bare patch (tiles)", bench::fixed(r.quality.largest_gap, 2)}});
  }
  report.note(
      speed,
      "Targets: 50k triangles / 10k tiles ≤ 2 s and 200k / 40k ≤ 6 s end to end on this "
      "2-core machine (issue 35; issue 13 asked 3 s for the first), with the defaults "
      "(automatic start: the position field; count about N). "
      "The paper: 2–10 minutes for 50k triangles and about 10k tiles on a Pentium 4. "
      "End to end = field (after remeshing faces with edges over four spacings, none "
      "here; the field solved on the surface smoothed at the tiles' scale, whose one "
      "conjugate-gradient step is the next column, then turned along thin parts by conjugate "
      "gradients from that field) + mosaic + quality report; the optimization (forces, "
      "projection, neighbour lists), the position field's sweeps, the chart fits and the "
      "report's samples run on both cores, the field's factorization on one. The benchmark "
      "allocates as `tessera` does: jemalloc on transparent huge pages. The last row is a fine "
      "mesh under few tiles (some 900 unknowns per chart fit instead of 60).");
}

void mosaic(bench::Report& report, const bench::Config& config) {
  const std::string quality =
      "Surface mosaics: quality on the paper's kinds of models (grout 0.1, teleportation on)";
  struct Model {
    const char* file;
    std::size_t tiles;
    bool creases;
  };
  const std::vector<Model> models =
      config.quick
          ? std::vector<Model>{{"cube-meshed.off", 300, true}}
          : std::vector<Model>{{"eight.off", 3000, false},    {"cube-meshed.off", 1500, true},
                               {"knot1.off", 4000, false},    {"fandisk.off", 3000, true},
                               {"elephant.off", 3000, false}, {"mushroom.off", 3000, false}};
  struct Variant {
    const char* name;
    Mosaic_initialization start;
    Mosaic_count count;
  };
  for (const Model& m : models)
    for (const Variant& v :
         {Variant{"position field, about N (default)", Mosaic_initialization::position_field,
                  Mosaic_count::about},
          Variant{"lattice, about N", Mosaic_initialization::lattice, Mosaic_count::about},
          Variant{"random start (Lai et al.), N", Mosaic_initialization::error_diffusion,
                  Mosaic_count::exact},
          Variant{"lattice, N", Mosaic_initialization::lattice, Mosaic_count::exact},
          Variant{"lattice, at most N", Mosaic_initialization::lattice, Mosaic_count::at_most}}) {
      Mesh mesh = load(m.file, 0);
      Feature_line_options fo;
      fo.creases = m.creases;
      fo.crease_angle_degrees = 60;
      const Run r = run(mesh, m.tiles, fo, true, v.count, v.start);
      report.add(quality,
                 {{"model", m.file},
                  {"start, count", v.name},
                  {"tiles", std::to_string(r.tiles)},
                  {"iterations", std::to_string(r.iterations)},
                  {"coverage", bench::fixed(r.quality.coverage, 3)},
                  {"overlap", bench::fixed(r.quality.overlap, 4)},
                  {"orientation error median / p95 (°)",
                   bench::fixed(r.quality.orientation_error_median, 2) + " / " +
                       bench::fixed(r.quality.orientation_error_p95, 2)},
                  {"row alignment median / p95 (°)",
                   bench::fixed(r.quality.row_alignment_median, 1) + " / " +
                       bench::fixed(r.quality.row_alignment_p95, 1)},
                  {"course drift median / p95 (°)",
                   bench::fixed(r.quality.course_drift_median, 1) + " / " +
                       bench::fixed(r.quality.course_drift_p95, 1)},
                  {"widest bare patch (tiles)", bench::fixed(r.quality.largest_gap, 2)},
                  {"tiles crossing features", std::to_string(r.quality.tiles_crossing_features)},
                  {"end to end (s)", bench::fixed(r.total, 2)}});
    }
  report.note(
      quality,
      "Targets (issue 35): tile count within 10 % of N, coverage ≥ 0.85 (0.90 is the bound at "
      "grout "
      "0.1), overlap ≤ 0.01 of the area, median course drift between neighbours ≤ 3°, no bare "
      "patch wider than two tiles, no tile crossing a feature line. Coverage and overlap are "
      "fractions of 40 area-uniform samples per tile. Start: a tile at each point of a "
      "field-aligned lattice (`--start position-field`, the default), rows grown from a seed "
      "(`--start lattice`) or Lai et al.'s error diffusion (`--start error-diffusion`); "
      "count: about N (the lattice decides; holes a cell wide get a tile, crowded tiles are left "
      "out), exactly N, or at most N (`--count at-most`).");
}

TESSERA_BENCHMARK("mosaic_speed", mosaic_speed);
TESSERA_BENCHMARK("mosaic", mosaic);

} // namespace
