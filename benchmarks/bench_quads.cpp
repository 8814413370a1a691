// Topology II figures: Q-criterion quadrangulation on generated genus-10 surfaces (~50k, 200k, 1M
// faces) and Loop-subdivided real meshes: compute time per source cut method, quads, total cut length,
// and the worst tile's distortion after mapping every quad onto the unit square.
#include "harness.h"

#include <tessera/types.h>

#include <tessera/generators.h>
#include <tessera/io.h>
#include <tessera/topology.h>

namespace {

using namespace tessera;

void run_sources(bench::Report& report, const std::string& table, const std::string& name, const Mesh& input,
                 const std::vector<Cut_method>& methods = {Cut_method::schema, Cut_method::greedy,
                                                           Cut_method::intermediate}) {
  for (Cut_method method : methods) {
    Mesh mesh = input;
    auto tile = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:tile", 0).first;
    auto se = mesh.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;
    auto sv = mesh.add_property_map<Mesh::Vertex_index, bool>("v:seam", false).first;
    Quadrangulation_options o;
    o.cut.method = method;
    Quadrangulation_result<Mesh> r;
    const double t = bench::time_best([&] { r = quadrangulate(mesh, tile, se, sv, o); });
    const char* source = method == Cut_method::schema ? "schema" : method == Cut_method::greedy ? "greedy" : "intermediate";
    bench::Row row{{"mesh", name}, {"faces", std::to_string(num_faces(input))}, {"from", source}};
    if (!r) {
      row.push_back({"seconds", bench::fixed(t, 3)});
      row.push_back({"quads", "failed: " + r.message});
      for (const char* column : {"source corners", "refinements (mesh+local)", "source cut length",
                                 "total cut length", "param. (s)", "worst stretch",
                                 "worst angle dist.", "flipped"})
        row.push_back({column, "-"});
      report.add(table, row);
      continue;
    }
    double t_param = 0;
    Tile_parameterization_result p;
    auto uv = mesh.add_property_map<Mesh::Halfedge_index, CGAL::Point_2<Kernel>>("h:uv").first;
    t_param = bench::time_best([&] { p = parameterize_tiles(mesh, r.tiles, tile, se, sv, uv); });
    const bool valid = validate_quadrangulation(mesh, tile, se, sv, r).valid();
    const auto& worst = p.tiles.at(p.worst_tile);
    row.push_back({"seconds", bench::fixed(t, 3)});
    row.push_back({"quads", std::to_string(r.number_of_quads()) + (valid ? "" : " (INVALID)")});
    row.push_back({"source corners", std::to_string(r.polygon_corners.at(0))});
    row.push_back({"refinements (mesh+local)", std::to_string(r.refinements) + "+" + std::to_string(r.local_refinements)});
    row.push_back({"source cut length", bench::fixed(r.cut.cut_length, 2)});
    row.push_back({"total cut length", bench::fixed(r.cut_length, 2)});
    row.push_back({"param. (s)", bench::fixed(t_param, 2)});
    row.push_back({"worst stretch", bench::fixed(worst.stretch, 3)});
    row.push_back({"worst angle dist.", bench::fixed(worst.angle, 3)});
    row.push_back({"flipped", std::to_string(p.flipped)});
    report.add(table, row);
  }
}

void quadrangulations(bench::Report& report, const bench::Config& config) {
  const std::string t1 = "Topology II: quadrangulation of genus-10 surfaces";
  for (std::size_t n : config.quick ? std::vector<std::size_t>{2} : std::vector<std::size_t>{7, 13, 29}) {
    Genus_surface_options o;
    o.cell_resolution = n;
    o.wall_resolution = std::max<std::size_t>(1, n / 2);
    o.subdivision_steps = 1;
    Mesh m;
    make_genus_surface(m, 10, o);
    run_sources(report, t1, "genus-10 plate", m,
                n <= 13 ? std::vector<Cut_method>{Cut_method::schema, Cut_method::greedy,
                                                  Cut_method::intermediate}
                        : std::vector<Cut_method>{Cut_method::schema});
  }
  report.note(t1, "`seconds` is quadrangulate() (source cut, evening of corners, Alg. 5), best of one run; "
                  "the parameterization (mean-value interior, unit-square border per quad) is timed apart. "
                  "Target: ~1M faces, genus 10, from the schema: 19 quads in <= 2 s. Shortest cutting "
                  "paths run in one-triangle-wide strips beside earlier sides (and, from the schema, "
                  "between its parallel strands); each time one is stuck, chords across such strips are "
                  "split and Alg. 5 restarts on the refined mesh, which is what the time goes into.");
  const std::string t2 = "Topology II: quadrangulation of Loop-subdivided real meshes";
  struct Real {
    const char* file;
    int steps;
  };
  for (const Real& r : config.quick ? std::vector<Real>{{"eight.off", 0}}
                                    : std::vector<Real>{{"eight.off", 3}, {"elephant.off", 2}}) {
    Mesh m;
    read_mesh(std::string(TESSERA_BENCH_DATA_DIR) + "/" + r.file, m);
    CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(r.steps));
    run_sources(report, t2, std::string(r.file) + " x" + std::to_string(r.steps), m);
  }
}

TESSERA_BENCHMARK("quads", quadrangulations);

} // namespace
