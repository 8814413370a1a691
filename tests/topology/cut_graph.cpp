// Cut graphs open every surface of the corpus into disks, with paired sides and corners at branch
// points; costs steer the cut; bad input is reported.
// The graph traits of every mesh type must be declared before CGAL::Seam_mesh is instantiated.
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>

#include "corpus.h"

#include <tessera/topology.h>
#include <tessera/io/result_reports.h>
#include <tessera/validation.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <sstream>

using namespace tessera;

namespace {

struct Cut_run {
  Cut_result<Mesh> result;
  Cut_validation validation;
};

Cut_run run_cut(Mesh& mesh, Cut_method method) {
  auto seam_e = mesh.add_property_map<Mesh::Edge_index, bool>("e:tessera_seam", false).first;
  auto seam_v = mesh.add_property_map<Mesh::Vertex_index, bool>("v:tessera_seam", false).first;
  Cut_options options;
  options.method = method;
  Cut_run run{cut_to_disk(mesh, seam_e, seam_v, options), {}};
  run.validation = validate_cut(mesh, seam_e, seam_v, run.result);
  return run;
}

} // namespace

TEST_CASE("greedy and intermediate cuts open the corpus into disks", "[topology][cut]") {
  auto corpus = test::generated_corpus(5, 2);
  for (auto& r : test::real_corpus())
    corpus.push_back(std::move(r));
  for (Cut_method method : {Cut_method::greedy, Cut_method::intermediate}) {
    for (auto& e : corpus) {
      INFO(e.name << " " << to_string(method));
      Mesh mesh = e.mesh;
      const Cut_run run = run_cut(mesh, method);
      INFO(run.result.message);
      INFO(test::joined(run.validation.problems));
      REQUIRE(run.result);
      CHECK(run.validation.opens_to_disks);
      CHECK(run.validation.sides_paired);
      CHECK(run.validation.corners_are_branch_points);
      REQUIRE(run.result.polygons.size() == 1);
      CHECK(run.result.polygons[0].genus == e.genus);
      CHECK(run.result.polygons[0].boundaries == e.boundaries);
      // Euler: a disk from genus g with b boundaries; the cut is non-empty unless already a disk.
      if (e.genus > 0 || e.boundaries != 1)
        CHECK(run.result.cut_length > 0);
    }
  }
}

TEST_CASE("the schema opens closed surfaces into a 4g-gon at the basepoint",
          "[topology][cut][schema]") {
  auto corpus = test::generated_corpus(4, 2);
  for (auto& r : test::real_corpus())
    corpus.push_back(std::move(r));
  for (auto& e : corpus) {
    INFO(e.name);
    Mesh mesh = e.mesh;
    const std::size_t faces_before = num_faces(mesh);
    auto seam_e = mesh.add_property_map<Mesh::Edge_index, bool>("e:tessera_seam", false).first;
    auto seam_v = mesh.add_property_map<Mesh::Vertex_index, bool>("v:tessera_seam", false).first;
    Cut_options options;
    options.method = Cut_method::schema;
    const auto result = cut_to_disk(mesh, seam_e, seam_v, options);
    INFO(result.message);
    REQUIRE(result);
    Validate_cut_options vo;
    vo.check_loops_non_contractible = e.genus > 0 && num_faces(mesh) < 20000;
    const Cut_validation v = validate_cut(mesh, seam_e, seam_v, result, vo);
    INFO(test::joined(v.problems));
    CHECK(bool(v));
    REQUIRE(result.polygons.size() == 1);
    const auto& poly = result.polygons[0];
    CHECK(poly.genus == e.genus);
    if (e.boundaries == 0 && e.genus > 0) {
      CHECK(poly.sides.size() == std::size_t(4 * e.genus));
      for (auto c : poly.corners)
        CHECK(c == poly.basepoint);
      CHECK(result.multipoints.size() == 1);
    }
    // The refinement only adds: the surface keeps its area and topology.
    CHECK(num_faces(mesh) >= faces_before);
    CHECK(mesh_info(mesh, {false}).components.at(0).genus == e.genus);
  }
}

TEST_CASE("the canonical schema reads a1 b1 a1^-1 b1^-1 ... on closed and bordered surfaces",
          "[topology][cut][schema][canonical]") {
  auto corpus = test::generated_corpus(4, 3);
  corpus.push_back({"eight.off", test::load("eight.off"), 2, 0});
  corpus.push_back({"elephant.off", test::load("elephant.off"), 3, 0});
  for (auto& e : corpus) {
    if (e.genus == 0)
      continue;
    INFO(e.name);
    Mesh mesh = e.mesh;
    auto seam_e = mesh.add_property_map<Mesh::Edge_index, bool>("e:tessera_seam", false).first;
    auto seam_v = mesh.add_property_map<Mesh::Vertex_index, bool>("v:tessera_seam", false).first;
    Cut_options options;
    options.method = Cut_method::schema;
    options.canonical = true;
    Cut_result<Mesh> result = cut_to_disk(mesh, seam_e, seam_v, options);
    INFO(result.message);
    REQUIRE(result);
    CHECK(result.canonical);
    REQUIRE(result.polygons.size() == 1);
    const auto& poly = result.polygons[0];
    INFO(poly.word);
    CHECK(poly.genus == e.genus);
    // Two moves per handle; on a bordered surface three more per commutator gathered.
    CHECK(result.canonical_moves <=
          std::size_t(2 * e.genus + (e.boundaries > 0 ? 3 * (e.genus - 1) : 0)));
    // The word from the first side: g commutators, then (bordered) one block c B c^-1 per hole.
    std::string expected;
    for (long k = 1; k <= e.genus; ++k) {
      const std::string a = "a" + std::to_string(k), b = "b" + std::to_string(k);
      expected += (k > 1 ? " " : "") + a + " " + b + " " + a + "^-1 " + b + "^-1";
    }
    if (e.boundaries == 0) {
      CHECK(poly.word == expected);
      for (auto c : poly.corners)
        CHECK(c == poly.basepoint);
    } else {
      CHECK(poly.word.rfind(expected, 0) == 0);
      CHECK(std::count(poly.word.begin(), poly.word.end(), 'B') == long(e.boundaries));
    }
    // Independently: the mesh opens into one disk, sides pair up, each loop is non-contractible
    // and the sides read canonically again.
    Validate_cut_options vo;
    vo.check_loops_non_contractible = num_faces(mesh) < 60000;
    const Cut_validation v = validate_cut(mesh, seam_e, seam_v, result, vo);
    INFO(test::joined(v.problems));
    CHECK(bool(v));
    CHECK(v.canonical_form);
    CHECK(mesh_info(mesh, {false}).components.at(0).genus == e.genus);
    // From the seams alone (as `tessera check` reads another tool's cut), the word starts where it
    // reads canonically, not at the corner that happens to have the smallest index.
    Validate_charts_options co;
    co.expect = Expected_cutting::schema;
    const Cutting_validation seams = validate_seams(mesh, seam_e, co);
    INFO(seams.message);
    REQUIRE(seams.charts.size() == 1);
    if (e.boundaries == 0)
      CHECK(seams.charts[0].word == expected);
    else
      CHECK(seams.charts[0].word.rfind(expected, 0) == 0);
    // The check can fail: the same polygon read from its second side is not canonical (but for a
    // closed torus, whose b a^-1 b^-1 a is a commutator again).
    if (e.genus == 1 && e.boundaries == 0)
      continue;
    std::rotate(result.polygons[0].sides.begin(), result.polygons[0].sides.begin() + 1,
                result.polygons[0].sides.end());
    std::rotate(result.polygons[0].corners.begin(), result.polygons[0].corners.begin() + 1,
                result.polygons[0].corners.end());
    const Cut_validation rotated = validate_cut(mesh, seam_e, seam_v, result);
    CHECK_FALSE(rotated.canonical_form);
    CHECK_FALSE(bool(rotated));
  }
}

TEST_CASE("the greedy cut of a torus of revolution holds the meridian", "[topology][cut]") {
  const double pi = std::acos(-1.0), r = 1.0;
  Mesh torus;
  make_torus(torus, 3.0, r, 90, 45);
  const Cut_run run = run_cut(torus, Cut_method::greedy);
  REQUIRE(run.result);
  REQUIRE(bool(run.validation));
  // The meridian is the shortest loop of the system; its edges must all be seams.
  auto cost = get(CGAL::dynamic_edge_property_t<double>(), torus);
  compute_edge_costs(torus, cost);
  const auto sys = greedy_system_of_loops(torus, *vertices(torus).begin(), cost);
  REQUIRE(sys.lengths.at(0) == Approx(2 * pi * r).epsilon(3e-3));
  auto seams = torus.property_map<Mesh::Edge_index, bool>("e:tessera_seam").first;
  for (auto h : internal::cyclically_reduced(sys.loops[0], torus))
    CHECK(seams[edge(h, torus)]);
  // A 4-gon with one corner where the join meets the meridian... or the schema-like square.
  CHECK(run.result.cut_length >= 2 * pi * r);
}

TEST_CASE("a user cost that makes a region expensive keeps the cut out of it", "[topology][cut]") {
  Mesh mesh;
  Genus_surface_options o;
  o.cell_resolution = 4;
  make_genus_surface(mesh, 2, o);
  // The plate spans [0, 5] x [0, 3] with holes in cells (1, 1) and (3, 1); the bar between the
  // holes is the cell (2, 1). Make it costly: a cut graph can go around it.
  auto cost = mesh.add_property_map<Mesh::Edge_index, double>("e:tessera_cost", 0.0).first;
  compute_edge_costs(mesh, cost);
  auto in_bar = [&](Mesh::Edge_index e) {
    const auto h = halfedge(e, mesh);
    const Point_3 m = CGAL::midpoint(mesh.point(source(h, mesh)), mesh.point(target(h, mesh)));
    return m.x() > 2.0 && m.x() < 3.0 && m.y() > 1.0 && m.y() < 2.0;
  };
  for (auto e : edges(mesh))
    if (in_bar(e))
      cost[e] *= 100.0;
  auto se = mesh.add_property_map<Mesh::Edge_index, bool>("e:tessera_seam", false).first;
  auto sv = mesh.add_property_map<Mesh::Vertex_index, bool>("v:tessera_seam", false).first;
  for (Cut_method method : {Cut_method::greedy, Cut_method::intermediate}) {
    Cut_options options;
    options.method = method;
    options.basepoint = 0;
    const auto result = cut_to_disk(mesh, cost, se, sv, options);
    REQUIRE(result);
    CHECK(bool(validate_cut(mesh, se, sv, result)));
    std::size_t seams_in_bar = 0;
    for (auto e : edges(mesh))
      seams_in_bar += (se[e] && in_bar(e)) ? 1 : 0;
    CHECK(seams_in_bar == 0);
  }
}

TEST_CASE("the curvature-weighted cost makes crease edges cheaper", "[topology][cut]") {
  Mesh cube = test::load("cube-meshed.off");
  auto euclid = get(CGAL::dynamic_edge_property_t<double>(), cube);
  auto curved = get(CGAL::dynamic_edge_property_t<double>(), cube);
  compute_edge_costs(cube, euclid);
  Edge_cost_options o;
  o.kind = Edge_cost_kind::curvature;
  o.curvature_weight = 1.0;
  compute_edge_costs(cube, curved, o);
  std::size_t creases = 0;
  for (auto e : edges(cube)) {
    const double alpha = dihedral_deviation(e, cube);
    CHECK(get(curved, e) == Approx(get(euclid, e) * (1 - alpha / std::acos(-1.0))));
    if (alpha > 1.5) {
      ++creases;
      CHECK(get(curved, e) < 0.55 * get(euclid, e));
    }
  }
  // Brute force: the edges with both ends on one edge line of the cube (two coordinates at the
  // bounding box's extremes, the same two), 16 per cube edge in cube-meshed.off.
  const auto box = CGAL::Polygon_mesh_processing::bbox(cube);
  auto extremes = [&](const Point_3& p) {
    int mask = 0;
    for (int i = 0; i < 3; ++i)
      if (std::abs(p[i] - box.min(i)) < 1e-9 || std::abs(p[i] - box.max(i)) < 1e-9)
        mask |= 1 << i;
    return mask;
  };
  std::size_t on_cube_edges = 0;
  for (auto e : edges(cube)) {
    const int a = extremes(cube.point(source(halfedge(e, cube), cube)));
    const int b = extremes(cube.point(target(halfedge(e, cube), cube)));
    const int common = a & b;
    if (common == 3 || common == 5 || common == 6 || common == 7)
      ++on_cube_edges;
  }
  CHECK(on_cube_edges == 192);
  CHECK(creases == on_cube_edges);
}

TEST_CASE("several components are cut one by one", "[topology][cut]") {
  Mesh a, b;
  make_torus(a, 3.0, 1.0, 30, 15);
  Genus_surface_options o;
  o.cell_resolution = 2;
  make_genus_surface(b, 2, o);
  for (auto v : vertices(b))
    b.point(v) = b.point(v) + Vector_3(10, 0, 0);
  a.join(b);
  const Cut_run run = run_cut(a, Cut_method::greedy);
  REQUIRE(run.result);
  CHECK(bool(run.validation));
  REQUIRE(run.result.polygons.size() == 2);
  CHECK(run.result.polygons[0].genus + run.result.polygons[1].genus == 3);
}

TEST_CASE("bad input to cut_to_disk is reported, not crashed on", "[topology][cut]") {
  Mesh torus;
  make_torus(torus, 3.0, 1.0, 20, 10);
  auto se = torus.add_property_map<Mesh::Edge_index, bool>("e:tessera_seam", false).first;
  auto sv = torus.add_property_map<Mesh::Vertex_index, bool>("v:tessera_seam", false).first;
  Cut_options options;
  options.basepoint = 100000;
  CHECK(cut_to_disk(torus, se, sv, options).status == Cut_status::invalid_basepoint);

  Mesh quads;
  CGAL::make_hexahedron(Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(1, 1, 0), Point_3(0, 1, 0),
                        Point_3(0, 1, 1), Point_3(0, 0, 1), Point_3(1, 0, 1), Point_3(1, 1, 1),
                        quads);
  auto qe = quads.add_property_map<Mesh::Edge_index, bool>("e:tessera_seam", false).first;
  auto qv = quads.add_property_map<Mesh::Vertex_index, bool>("v:tessera_seam", false).first;
  CHECK(cut_to_disk(quads, qe, qv).status == Cut_status::invalid_mesh);
}

TEST_CASE("an exact-constructions mesh gives the same cut combinatorics",
          "[topology][cut][exact]") {
  for (const char* file : {"eight.off", "elephant.off"}) {
    INFO(file);
    Mesh inexact = test::load(file);
    Exact_mesh exact;
    REQUIRE(read_mesh(test::data_path(file), exact));
    auto ie = inexact.add_property_map<Mesh::Edge_index, bool>("e:tessera_seam", false).first;
    auto iv = inexact.add_property_map<Mesh::Vertex_index, bool>("v:tessera_seam", false).first;
    auto ee = exact.add_property_map<Exact_mesh::Edge_index, bool>("e:tessera_seam", false).first;
    auto ev = exact.add_property_map<Exact_mesh::Vertex_index, bool>("v:tessera_seam", false).first;
    for (Cut_method method : {Cut_method::greedy, Cut_method::intermediate, Cut_method::schema}) {
      Cut_options options;
      options.method = method;
      const auto ri = cut_to_disk(inexact, ie, iv, options);
      const auto re = cut_to_disk(exact, ee, ev, options);
      REQUIRE(ri);
      REQUIRE(re);
      CHECK(bool(validate_cut(exact, ee, ev, re)));
      REQUIRE(ri.polygons.size() == re.polygons.size());
      CHECK(ri.polygons[0].sides.size() == re.polygons[0].sides.size());
      CHECK(ri.multipoints.size() == re.multipoints.size());
      std::size_t differing = 0;
      for (auto e : edges(inexact))
        differing += ie[e] != ee[Exact_mesh::Edge_index(std::size_t(e))];
      CHECK(differing == 0);
      CHECK(ri.cut_length == Approx(re.cut_length).epsilon(1e-12));
    }
  }
}

TEST_CASE("cut_to_disk runs on another FaceGraph model: Polyhedron_3",
          "[topology][cut][polyhedron]") {
  using Polyhedron = CGAL::Polyhedron_3<Kernel, CGAL::Polyhedron_items_with_id_3>;
  Polyhedron poly;
  REQUIRE(read_mesh(test::data_path("eight.off"), poly));
  CGAL::set_halfedgeds_items_id(poly);
  for (Cut_method method : {Cut_method::greedy, Cut_method::schema}) {
    auto seam_e = get(CGAL::dynamic_edge_property_t<bool>(), poly);
    auto seam_v = get(CGAL::dynamic_vertex_property_t<bool>(), poly);
    Cut_options options;
    options.method = method;
    const auto result = cut_to_disk(poly, seam_e, seam_v, options);
    INFO(result.message);
    REQUIRE(result);
    CGAL::set_halfedgeds_items_id(poly);
    const auto v = validate_cut(poly, seam_e, seam_v, result);
    INFO(test::joined(v.problems));
    CHECK(bool(v));
    REQUIRE(result.polygons.size() == 1);
    if (method == Cut_method::schema)
      CHECK(result.polygons[0].sides.size() == 8);
  }
}

TEST_CASE("the cut report gives each polygon's corners in opened.off and its side word",
          "[topology][cut][io]") {
  // What `tessera cut` writes to result.json, built and written by the library
  // (tessera/io/result_reports.h).
  Mesh mesh;
  REQUIRE(read_mesh(test::data_path("eight.off"), mesh));
  auto seam_e = mesh.add_property_map<Mesh::Edge_index, bool>("e:tessera_seam", false).first;
  auto seam_v = mesh.add_property_map<Mesh::Vertex_index, bool>("v:tessera_seam", false).first;
  Cut_options options;
  options.method = Cut_method::schema;
  const auto result = cut_to_disk(mesh, seam_e, seam_v, options);
  REQUIRE(result);
  Mesh opened;
  const auto o2m = open_along_seams(mesh, seam_e, seam_v, opened);
  Validate_charts_options co;
  for (auto v : result.multipoints)
    co.marked_corners.push_back(std::size_t(v));
  const Cutting_validation charts = validate_charts(mesh, opened, o2m, co);
  const Cut_report report = make_cut_report(
      mesh, result, options, validate_cut(mesh, seam_e, seam_v, result), charts, opened, o2m);
  CHECK(report.valid);
  CHECK(report.genus == 2);
  REQUIRE(report.polygons.size() == 1);
  const Cut_report_polygon& p = report.polygons[0];
  // The schema: 4g corners, each a copy of the basepoint in opened.off, and 4g letters, each
  // side once with its partner reversed.
  REQUIRE(p.corners.size() == 8);
  for (std::size_t c : p.corners) {
    REQUIRE(c < report.opened_to_mesh_vertex.size());
    CHECK(report.opened_to_mesh_vertex[c] == p.basepoint);
  }
  std::istringstream letters(p.word);
  std::vector<std::string> word{std::istream_iterator<std::string>(letters), {}};
  REQUIRE(word.size() == 8);
  for (const std::string& w : word) {
    const bool inverse = w.size() > 3 && w.compare(w.size() - 3, 3, "^-1") == 0;
    const std::string partner = inverse ? w.substr(0, w.size() - 3) : w + "^-1";
    CHECK(std::count(word.begin(), word.end(), partner) == 1);
  }
  std::ostringstream json;
  REQUIRE(write_cut_report(json, report));
  CHECK(json.str().find("\"word\": \"" + p.word + "\"") != std::string::npos);
  CHECK(json.str().find("\"valid\": true") != std::string::npos);
}
