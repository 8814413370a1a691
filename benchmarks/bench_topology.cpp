// Topology I figures: cut graphs on generated genus-10 surfaces (~50k, 200k, 1M faces) and on
// Loop-subdivided real meshes: compute time and cut length per method, the length of the plain
// tree-cotree cut graph, and CGAL's Curves_on_surface_topology minimal quadrangulation as the peer.
#include "harness.h"
#include "meshes.h"

#include <tessera/types.h>

#include <tessera/generators.h>
#include <tessera/io.h>
#include <tessera/topology.h>

#include <CGAL/Curves_on_surface_topology.h>

#include <set>

namespace {

using namespace tessera;

struct Named_mesh {
  std::string name;
  Mesh mesh;
};

/// Length of the tree-cotree cut graph: the union of the greedy system of loops at the basepoint
/// the cut methods use by default (the first vertex), each edge once.
double tree_cotree_cut_length(const Mesh& mesh) {
  auto cost = get(CGAL::dynamic_edge_property_t<double>(), mesh);
  compute_edge_costs(mesh, cost);
  const auto sys = greedy_system_of_loops(mesh, *vertices(mesh).begin(), cost);
  std::set<Mesh::Edge_index> edges_used;
  for (const auto& loop : sys.loops)
    for (auto h : loop)
      edges_used.insert(edge(h, mesh));
  double len = 0;
  for (auto e : edges_used)
    len += get(cost, e);
  return len;
}

void run_methods(bench::Report& report, const std::string& table, const Named_mesh& m,
                 bool with_peer) {
  bench::Row row{{"mesh", m.name},
                 {"faces", std::to_string(num_faces(m.mesh))},
                 {"genus", std::to_string(mesh_info(m.mesh, {false}).components.at(0).genus)}};
  for (Cut_method method : {Cut_method::greedy, Cut_method::intermediate, Cut_method::schema}) {
    Mesh copy = m.mesh;
    auto se = copy.add_property_map<Mesh::Edge_index, bool>("e:tessera_seam", false).first;
    auto sv = copy.add_property_map<Mesh::Vertex_index, bool>("v:tessera_seam", false).first;
    Cut_options o;
    o.method = method;
    Cut_result<Mesh> r;
    // One run: the schema refines the mesh it cuts.
    const double t = bench::time_best([&] { r = cut_to_disk(copy, se, sv, o); });
    const std::string name = to_string(method);
    row.push_back({name + " (s)", bench::fixed(t, 3)});
    row.push_back({name + " length", r ? bench::fixed(r.cut_length, 2) : "failed"});
  }
  row.push_back({"tree-cotree length", bench::fixed(tree_cotree_cut_length(m.mesh), 2)});
  if (with_peer) {
    double t_build = 0, t_quad = 0;
    t_build = bench::time_best([&] {
      CGAL::Surface_mesh_topology::Curves_on_surface_topology<Mesh> cst(m.mesh);
      t_quad = bench::time_best([&] { cst.compute_minimal_quadrangulation(false); });
    });
    row.push_back({"CGAL min. quadrangulation (s)", bench::fixed(t_quad, 3)});
    row.push_back({"CGAL incl. map copy (s)", bench::fixed(t_build, 3)});
  }
  report.add(table, row);
}

void topology_cuts(bench::Report& report, const bench::Config& config) {
  const std::string t1 = "Topology I: cut graphs on genus-10 surfaces";
  const std::vector<std::size_t> sizes =
      config.quick ? std::vector<std::size_t>{2} : std::vector<std::size_t>{7, 13, 29};
  for (std::size_t n : sizes)
    run_methods(report, t1, {"genus-10 plate", bench::genus_plate(10, n)}, true);
  report.note(
      t1, "Times are compute only (no I/O), best of one run. The peer is CGAL 5.5's "
          "`Curves_on_surface_topology::compute_minimal_quadrangulation` on the same mesh in "
          "the same run (the copy into its combinatorial map is timed separately). "
          "`tree-cotree length` is the union of the greedy system of loops at the same basepoint.");

  const std::string t2 = "Topology I: Loop-subdivided real meshes";
  struct Real {
    const char* file;
    int steps;
  };
  const std::vector<Real> reals =
      config.quick ? std::vector<Real>{{"eight.off", 0}}
                   : std::vector<Real>{{"eight.off", 3},    {"eight.off", 5},    {"knot1.off", 3},
                                       {"elephant.off", 2}, {"elephant.off", 3}, {"rotor.off", 4}};
  for (const Real& r : reals)
    run_methods(report, t2,
                {std::string(r.file) + " x" + std::to_string(r.steps),
                 bench::loop_subdivided(r.file, r.steps)},
                true);
}

/// Meshes of the sizes of the rows of Favreau et al.'s Table 1 (genus 1 to 4, 768 to ~53k
/// vertices).
void topology_paper_sizes(bench::Report& report, const bench::Config& config) {
  const std::string t = "Topology I: meshes of the sizes of the paper's Table 1";
  Mesh torus;
  make_torus(torus, 3.0, 1.0, 32, 24); // 768 vertices
  run_methods(report, t, {"torus 768 V", torus}, false);
  if (config.quick)
    return;
  run_methods(report, t, {"eight.off x2 (genus 2)", bench::loop_subdivided("eight.off", 2)}, false);
  run_methods(report, t, {"elephant.off (genus 3)", bench::loop_subdivided("elephant.off", 0)},
              false);
  run_methods(report, t, {"genus-4 plate ~53k V", bench::genus_plate(4, 14)}, false);
  report.note(
      t, "The paper reports 155-446 s for its cut graphs at about 50k vertices (Alg. 1, "
         "searching loops from every basepoint); the rows above are ours on meshes of the same "
         "genus and size, on this machine.");
}

/// The canonical schema (issue 12, item 5): the schema cut alone and brought into canonical form,
/// on the same surface in the same run: time, cut-and-paste moves, faces after refinement, cut
/// length. No peer computes a canonical schema on a given mesh (CGAL builds surfaces from words).
void topology_canonical(bench::Report& report, const bench::Config& config) {
  const std::string t = "Topology I: canonical polygonal schema";
  struct Case {
    std::string name;
    Mesh mesh;
  };
  std::vector<Case> cases;
  cases.push_back({"genus-10 plate", bench::genus_plate(10, config.quick ? 2 : 7)});
  if (!config.quick) {
    cases.push_back({"genus-10 plate", bench::genus_plate(10, 13)});
    cases.push_back({"genus-10 plate", bench::genus_plate(10, 29)});
    cases.push_back({"genus-5 plate", bench::genus_plate(5, 4)});
    cases.push_back({"genus-25 plate", bench::genus_plate(25, 4)});
    Mesh holed = bench::genus_plate(5, 4);
    punch_holes(holed, 3, 7);
    cases.push_back({"genus-5 plate, 3 holes", holed});
    holed = bench::genus_plate(5, 4);
    punch_holes(holed, 20, 7);
    cases.push_back({"genus-5 plate, 20 holes", holed});
  }
  for (const Case& c : cases) {
    bench::Row row{{"mesh", c.name}, {"faces", std::to_string(num_faces(c.mesh))}};
    for (const bool canonical : {false, true}) {
      Mesh copy = c.mesh;
      auto se = copy.add_property_map<Mesh::Edge_index, bool>("e:tessera_seam", false).first;
      auto sv = copy.add_property_map<Mesh::Vertex_index, bool>("v:tessera_seam", false).first;
      Cut_options o;
      o.method = Cut_method::schema;
      o.canonical = canonical;
      Cut_result<Mesh> r;
      // One run: the cut refines the mesh.
      const double seconds = bench::time_best([&] { r = cut_to_disk(copy, se, sv, o); });
      const std::string name = canonical ? "canonical" : "schema";
      row.push_back({name + " (s)", bench::fixed(seconds, 3)});
      row.push_back({name + " faces after", r ? std::to_string(num_faces(copy)) : "failed"});
      row.push_back({name + " length", r ? bench::fixed(r.cut_length, 1) : "failed"});
      if (canonical) {
        row.push_back({"moves", std::to_string(r.canonical_moves)});
        row.push_back({"valid", bool(validate_cut(copy, se, sv, r)) ? "yes" : "NO"});
      }
    }
    report.add(t, row);
  }
  report.note(t, "Compute only (no I/O), one run each, on copies of the same surface. `canonical` "
                 "includes the schema cut it starts from. `valid`: `validate_cut` of the "
                 "canonical result (disks, pairing, corners, and the word read again from the "
                 "sides). Each move cuts one shortest diagonal of the disk and glues one side "
                 "pair back; the mesh is refined where a diagonal runs beside earlier loops.");
}

TESSERA_BENCHMARK("topology", topology_cuts);
TESSERA_BENCHMARK("topology-canonical", topology_canonical);
TESSERA_BENCHMARK("topology-paper", topology_paper_sizes);

} // namespace
