// Validation of cuttings from anywhere (validate_charts, validate_seams, validate_uv_layout) and of
// refinements (validate_refinement): Tessera's own cuts and quadrangulations pass, and deliberately
// broken ones fail for the reason they were broken: a missing seam edge, an extra seam splitting a
// chart, a T-junction, a folded texture face, a face inverted inside its original face, and a
// vertex off its face by less than a double can hold (seen only when read and tested exactly).
#include "corpus.h"

#include <tessera/generators/uv_layouts.h>
#include <tessera/io/read_cutting.h>
#include <tessera/io/read_result_directory.h>
#include <tessera/io/result_reports.h>
#include <tessera/topology.h>
#include <tessera/topology/validate_charts.h>
#include <tessera/topology/validate_refinement.h>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <numeric>
#include <sstream>

using namespace tessera;
using namespace tessera::test;

namespace {

bool has_problem(const Cutting_validation& v, Cutting_problem_kind kind) {
  for (const auto& p : v.problems)
    if (p.kind == kind)
      return true;
  return false;
}

std::string problems_of(const Cutting_validation& v) {
  std::string s;
  for (const auto& p : v.problems)
    s += p.message + "; ";
  return s;
}

struct Cut {
  Mesh mesh;
  Mesh::Property_map<Mesh::Edge_index, bool> seam_e;
  Mesh::Property_map<Mesh::Vertex_index, bool> seam_v;
  Cut_result<Mesh> result;
};

Cut cut_genus(std::size_t genus, Cut_method method) {
  Cut c;
  Genus_surface_options o;
  o.cell_resolution = 3;
  o.subdivision_steps = 1;
  make_genus_surface(c.mesh, genus, o);
  c.seam_e = c.mesh.add_property_map<Mesh::Edge_index, bool>("e:tessera_seam", false).first;
  c.seam_v = c.mesh.add_property_map<Mesh::Vertex_index, bool>("v:tessera_seam", false).first;
  Cut_options options;
  options.method = method;
  c.result = cut_to_disk(c.mesh, c.seam_e, c.seam_v, options);
  return c;
}

} // namespace

TEST_CASE("Tessera's schema cuts check out as schemas with 4g sides and non-contractible loops",
          "[check]") {
  for (std::size_t g : {1u, 2u, 3u}) {
    Cut c = cut_genus(g, Cut_method::schema);
    REQUIRE(c.result);
    Validate_charts_options o;
    o.expect = Expected_cutting::schema;
    o.check_loops_non_contractible = true;
    const Cutting_validation v = validate_seams(c.mesh, c.seam_e, o);
    INFO("genus " << g << ": " << problems_of(v));
    CHECK(v);
    REQUIRE(v.charts.size() == 1);
    CHECK(v.charts[0].is_disk());
    CHECK(v.charts[0].sides == 4 * g);
    CHECK(v.corner_vertices == 1);
    // Every label appears once plainly and once inverted: 2g pairs.
    std::istringstream word(v.charts[0].word);
    std::size_t plain = 0, inverse = 0;
    for (std::string s; word >> s;)
      (s.find("^-1") == std::string::npos ? plain : inverse) += 1;
    CHECK(plain == 2 * g);
    CHECK(inverse == 2 * g);
  }
}

TEST_CASE("Greedy cuts are disks but not schemas", "[check]") {
  Cut c = cut_genus(2, Cut_method::greedy);
  REQUIRE(c.result);
  CHECK(validate_seams(c.mesh, c.seam_e));
  Validate_charts_options o;
  o.expect = Expected_cutting::schema;
  const Cutting_validation v = validate_seams(c.mesh, c.seam_e, o);
  // A greedy cut graph branches at several vertices: not one basepoint.
  CHECK((!v && has_problem(v, Cutting_problem_kind::not_a_schema)) == (v.corner_vertices > 1));
}

TEST_CASE("A missing seam edge leaves a chart that is not a disk", "[check]") {
  Cut c = cut_genus(2, Cut_method::schema);
  REQUIRE(c.result);
  for (auto e : c.mesh.edges())
    if (c.seam_e[e]) {
      c.seam_e[e] = false;
      break;
    }
  const Cutting_validation v = validate_seams(c.mesh, c.seam_e);
  CHECK_FALSE(v);
  CHECK(has_problem(v, Cutting_problem_kind::not_a_disk));
}

TEST_CASE("An extra seam splitting the chart gives two disks, not a schema", "[check]") {
  Cut c = cut_genus(1, Cut_method::schema);
  REQUIRE(c.result);
  // A chord: an edge off the cut whose two ends are on it. Opening along it splits the disk in two.
  bool added = false;
  for (auto e : c.mesh.edges()) {
    const auto h = halfedge(e, c.mesh);
    if (!c.seam_e[e] && c.seam_v[source(h, c.mesh)] && c.seam_v[target(h, c.mesh)]) {
      c.seam_e[e] = added = true;
      break;
    }
  }
  REQUIRE(added);
  const Cutting_validation disks = validate_seams(c.mesh, c.seam_e);
  CHECK(disks);
  CHECK(disks.charts.size() == 2);
  Validate_charts_options o;
  o.expect = Expected_cutting::schema;
  const Cutting_validation schema = validate_seams(c.mesh, c.seam_e, o);
  CHECK_FALSE(schema);
  CHECK(has_problem(schema, Cutting_problem_kind::not_a_schema));
}

TEST_CASE("Quadrangulations check out as quads, and merging two quads leaves T-junctions",
          "[check]") {
  Mesh mesh;
  Genus_surface_options go;
  go.cell_resolution = 3;
  go.subdivision_steps = 1;
  make_genus_surface(mesh, 2, go);
  const Mesh original = mesh;
  auto tile = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:tessera_tile", 0).first;
  auto seam_e = mesh.add_property_map<Mesh::Edge_index, bool>("e:tessera_seam", false).first;
  auto seam_v = mesh.add_property_map<Mesh::Vertex_index, bool>("v:tessera_seam", false).first;
  Quadrangulation_options qo;
  qo.cut.method = Cut_method::greedy;
  const auto result = quadrangulate(mesh, tile, seam_e, seam_v, qo);
  REQUIRE(result);
  Validate_charts_options o;
  o.expect = Expected_cutting::quads;
  for (auto v : result.multipoints)
    o.marked_corners.push_back(std::size_t(v));
  const Cutting_validation quads = validate_seams(mesh, seam_e, o);
  INFO(problems_of(quads));
  CHECK(quads);
  CHECK(quads.charts.size() == result.number_of_quads());

  // The refined surface lies on the original and tiles it (to the default tolerance).
  const Refinement_validation refined = validate_refinement(original, mesh);
  INFO(refined.message);
  CHECK(refined);

  // Remove the seam between two quads, along a whole side: a side whose two ends are corners of
  // degree >= 4 leaves them as T-junctions of degree >= 3 for the merged tile.
  std::vector<std::size_t> cut_degree(num_vertices(mesh), 0);
  for (auto e : mesh.edges())
    if (seam_e[e]) {
      ++cut_degree[std::size_t(source(halfedge(e, mesh), mesh))];
      ++cut_degree[std::size_t(target(halfedge(e, mesh), mesh))];
    }
  bool merged = false;
  for (auto e : mesh.edges()) {
    const auto h = halfedge(e, mesh);
    if (!seam_e[e] || tile[face(h, mesh)] == tile[face(opposite(h, mesh), mesh)])
      continue;
    // Walk this side both ways to its corners.
    std::vector<Mesh::Edge_index> side{e};
    std::vector<std::size_t> ends;
    for (auto start : {h, opposite(h, mesh)}) {
      auto g = start;
      while (cut_degree[std::size_t(target(g, mesh))] == 2) {
        for (auto n : halfedges_around_source(target(g, mesh), mesh))
          if (seam_e[edge(n, mesh)] && edge(n, mesh) != edge(g, mesh)) {
            g = n;
            break;
          }
        side.push_back(edge(g, mesh));
      }
      ends.push_back(std::size_t(target(g, mesh)));
    }
    if (cut_degree[ends[0]] < 4 || cut_degree[ends[1]] < 4 || ends[0] == ends[1])
      continue;
    for (auto s : side)
      seam_e[s] = false;
    merged = true;
    break;
  }
  REQUIRE(merged);
  const Cutting_validation t = validate_seams(mesh, seam_e, o);
  CHECK_FALSE(t);
  REQUIRE(has_problem(t, Cutting_problem_kind::not_a_quad));
  bool named = false;
  for (const auto& p : t.problems)
    named = named || p.message.find("T-junction") != std::string::npos;
  INFO(problems_of(t));
  CHECK(named);
  CHECK(t.charts.size() == result.number_of_quads() - 1);
}

TEST_CASE("Texture layouts: charts from vt indices, folds found", "[check][io]") {
  Uv_layout<Mesh> ok, folded;
  REQUIRE(read_obj_with_uvs(data_path("cuttings/torus.obj"), ok));
  REQUIRE(read_obj_with_uvs(data_path("cuttings/torus-folded.obj"), folded));
  Validate_charts_options o;
  o.expect = Expected_cutting::schema;
  const Cutting_validation v = validate_charts(ok.mesh, ok.charts, ok.chart_to_mesh, o);
  INFO(problems_of(v));
  CHECK(v);
  REQUIRE(v.charts.size() == 1);
  CHECK(v.charts[0].word == "a1 b1 a1^-1 b1^-1");
  CHECK(validate_uv_layout(ok.charts, ok.uv));
  const Cutting_validation f = validate_uv_layout(folded.charts, folded.uv);
  CHECK_FALSE(f);
  CHECK(has_problem(f, Cutting_problem_kind::inverted_uv_face));
  // Exact coordinates give the same verdicts.
  Uv_layout<Exact_mesh> exact;
  REQUIRE(read_obj_with_uvs(data_path("cuttings/torus-folded.obj"), exact));
  CHECK(validate_uv_layout(exact.charts, exact.uv).problems.size() == f.problems.size());
}

TEST_CASE("Cutting readers refuse what they cannot read, with the line", "[check][io]") {
  Mesh torus = load("cuttings/torus.off");
  auto seams = torus.add_property_map<Mesh::Edge_index, bool>("e:tessera_quad_seam", false).first;
  auto read = [&](const std::string& text) {
    std::istringstream in(text);
    return read_seams(in, torus, seams);
  };
  CHECK(read("# comment\n0 1\n\n1 2\n").count == 2);
  CHECK(read("0 1\n0 x\n").status == Cutting_read_status::parse_error);
  CHECK(read("0 1\n0 x\n").message.rfind("line 2", 0) == 0);
  CHECK(read("0 100000\n").status == Cutting_read_status::index_out_of_range);
  CHECK(read("0 1 2\n").status == Cutting_read_status::parse_error);
  CHECK(read("0 20\n").status == Cutting_read_status::not_an_edge);
  CHECK(read("-1 2\n").status == Cutting_read_status::parse_error);

  auto obj = [](const std::string& text) {
    std::istringstream in(text);
    Uv_layout<Mesh> layout;
    return read_obj_with_uvs(in, layout);
  };
  const std::string square = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";
  CHECK(obj(square + "f 1/1 2/2 3/3\nf -4/-4 -2/-2 -1/-1\n"));
  CHECK(obj(square + "f 1 2 3\n").status == Cutting_read_status::parse_error);
  CHECK(obj(square + "f 1/1 2/2 9/3\n").status == Cutting_read_status::index_out_of_range);
  CHECK(obj(square + "f 1/1 2/2 3/3\nf 1/1 2/2 4/4\n").status ==
        Cutting_read_status::not_a_surface);
  CHECK(obj(square).status == Cutting_read_status::no_faces);
  CHECK(obj("v 0 0 nan\n").status == Cutting_read_status::parse_error);

  // Exact readers: p/q and decimals read as written; a number that an exact type would expand into
  // millions of digits (minutes of work) is refused at once, with its line.
  auto exact_obj = [](const std::string& text) {
    std::istringstream in(text);
    Uv_layout<Exact_mesh> layout;
    return read_obj_with_uvs(in, layout);
  };
  CHECK(exact_obj("v 1/3 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n"));
  CHECK(exact_obj("v 1/00 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n").status ==
        Cutting_read_status::parse_error); // found by fuzz_read_cutting: GMP traps on p/0
  CHECK(exact_obj("v 1e3000000 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n")
            .status == Cutting_read_status::parse_error);
  const std::string huge = output_path("exact-huge-exponent.off");
  std::ofstream(huge) << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1e-3000000 0\n3 0 1 2\n";
  Exact_mesh exact;
  const Cutting_read_result r = read_exact_polygon_mesh(huge, exact);
  CHECK(r.status == Cutting_read_status::parse_error);
  CHECK(r.message.find("line 5") != std::string::npos);
  const std::string fine = output_path("exact-fine.off");
  std::ofstream(fine) << "OFF\n3 1 0\n0 0 0\n1 0 0\n-2/7 1.5e-300 +0.25\n3 0 1 2\n";
  REQUIRE(read_exact_polygon_mesh(fine, exact));
  CHECK(exact.point(Exact_mesh::Vertex_index(2)).x() == Exact_kernel::FT(-2) / 7);
  CHECK(exact.point(Exact_mesh::Vertex_index(2)).z() == Exact_kernel::FT(1) / 4);
  CHECK(exact.point(Exact_mesh::Vertex_index(2)).y() > 0);
}

namespace {

Uv_layout<Mesh> layout_of(const std::string& text) {
  std::istringstream in(text);
  Uv_layout<Mesh> layout;
  const Cutting_read_result r = read_obj_with_uvs(in, layout);
  INFO(r.message);
  REQUIRE(r);
  return layout;
}

} // namespace

TEST_CASE("Texture layouts of other tools: charts touching at a point, cube projections, quads, "
          "objects and shared vt",
          "[check][io]") {
  SECTION("two charts touching at one texture vertex are two disks, the point a note") {
    // Four triangles around vertex 5; A and C share its vt 9 but no edge, B and D have their own.
    const std::string obj = "v 1 0 0\nv 0 1 0\nv -1 0 0\nv 0 -1 0\nv 0 0 0\n"
                            "vt 1 0\nvt 0 1\nvt -1 0\nvt 0 -1\nvt 0 1\nvt -1 0\nvt 0 -1\nvt 1 0\n"
                            "vt 0 0\nvt 0 0\nvt 0 0\n"
                            "f 1/1 2/2 5/9\nf 2/5 3/6 5/10\nf 3/3 4/4 5/9\nf 4/7 1/8 5/11\n";
    const Uv_layout<Mesh> layout = layout_of(obj);
    REQUIRE(layout.pinched.size() == 1);
    CHECK(layout.pinched[0].vertex == 4);
    CHECK(layout.pinched[0].texture_coordinate == 8);
    CHECK(layout.pinched[0].chart_vertices.size() == 2);
    const Cutting_validation v = validate_charts(layout.mesh, layout.charts, layout.chart_to_mesh);
    INFO(problems_of(v));
    CHECK(v);
    REQUIRE(v.charts.size() == 4);
    for (const Chart_summary& c : v.charts)
      CHECK(c.is_disk());
    const Cutting_validation uv = validate_uv_layout(layout.charts, layout.uv, layout.pinched);
    CHECK(uv);
    REQUIRE(uv.notes.size() == 1);
    CHECK(uv.notes[0].kind == Cutting_problem_kind::pinched_texture_vertex);
    CHECK(uv.notes[0].message.find("charts 0, 2 touch") != std::string::npos);
  }
  SECTION("a cube projection of an organic mesh: the charts of an independent reading, with "
          "their Euler characteristics") {
    const Mesh m = load("elephant.off");
    std::vector<int> side;
    std::ostringstream obj;
    write_cube_projection_obj(obj, m, &side);
    const Uv_layout<Mesh> layout = layout_of(obj.str());
    // The independent reading, on the surface: faces joined across an edge when both take the
    // same side (then both ends have the same vt on both faces); a chart's Euler characteristic
    // counts each vertex once per run of the chart's faces around it (a fan).
    std::vector<std::size_t> parent(m.number_of_faces());
    std::iota(parent.begin(), parent.end(), std::size_t(0));
    std::function<std::size_t(std::size_t)> find = [&](std::size_t i) {
      return parent[i] == i ? i : parent[i] = find(parent[i]);
    };
    for (auto e : m.edges()) {
      const std::size_t f = std::size_t(m.face(m.halfedge(e))),
                        g = std::size_t(m.face(m.opposite(m.halfedge(e))));
      if (side[f] == side[g])
        parent[find(f)] = find(g);
    }
    std::map<std::size_t, long> euler; // by root: F − E + V
    for (auto f : m.faces())
      ++euler[find(std::size_t(f))];
    for (auto e : m.edges()) {
      const std::size_t f = std::size_t(m.face(m.halfedge(e))),
                        g = std::size_t(m.face(m.opposite(m.halfedge(e))));
      --euler[find(f)];
      if (find(g) != find(f))
        --euler[find(g)];
    }
    for (auto v : m.vertices()) {
      std::vector<std::size_t> around; // the charts of the faces around v, in cyclic order
      for (auto f : CGAL::faces_around_target(m.halfedge(v), m))
        around.push_back(find(std::size_t(f)));
      for (std::size_t i = 0; i < around.size(); ++i)
        if (around[i] != around[(i + around.size() - 1) % around.size()])
          ++euler[around[i]]; // a run starts here
      if (std::all_of(around.begin(), around.end(), [&](std::size_t c) { return c == around[0]; }))
        ++euler[around[0]];
    }
    const Cutting_validation v = validate_charts(layout.mesh, layout.charts, layout.chart_to_mesh);
    INFO(problems_of(v) << " pinched texture vertices: " << layout.pinched.size());
    REQUIRE(v.charts.size() == euler.size());
    std::size_t disks = 0;
    for (const auto& [root, chi] : euler) {
      CHECK(v.charts[v.chart_of_face[root]].euler_characteristic == chi);
      disks += chi == 1 ? 1 : 0;
    }
    std::size_t found = 0;
    for (const Chart_summary& c : v.charts)
      found += c.is_disk() ? 1 : 0;
    CHECK(found == disks);
    // Every seam of a layout read from one surface has its partner, closed loops between two
    // charts (no corner on them, so each side starts anywhere) included.
    CHECK_FALSE(has_problem(v, Cutting_problem_kind::unpaired_side));
    CHECK_FALSE(layout.pinched.empty()); // sides meet in staircases that touch at corners
    CHECK(validate_uv_layout(layout.charts, layout.uv, layout.pinched).notes.size() ==
          layout.pinched.size());
  }
  SECTION("quads with v/vt/vn corners in several objects, one chart a face, checked as quads") {
    std::string obj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                      "vn 0 0 1\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";
    const char* quads[] = {"1 4 3 2", "5 6 7 8", "1 2 6 5", "2 3 7 6", "3 4 8 7", "4 1 5 8"};
    int object = 0;
    for (const char* q : quads) {
      obj += "o part" + std::to_string(object++) + "\nusemtl m\nf";
      std::istringstream ids(q);
      int corner = 0;
      for (std::size_t id; ids >> id;)
        obj += " " + std::to_string(id) + "/" + std::to_string(++corner) + "/1";
      obj += "\n";
    }
    const Uv_layout<Mesh> layout = layout_of(obj);
    CHECK(layout.charts.number_of_vertices() == 24); // a vertex per quad corner: no quad shares an
                                                     // edge's two (v, vt) pairs with another
    // One vt serves four v, and a (v, vt) pair used by two quads that share no chart edge is a
    // point where two charts touch: 3 quads at each cube vertex take 3 corner numbers.
    std::map<std::pair<std::size_t, std::size_t>, int> uses;
    for (const char* q : quads) {
      std::istringstream ids(q);
      std::size_t corner = 0;
      for (std::size_t id; ids >> id;)
        ++uses[{id, corner++}];
    }
    std::size_t repeated = 0;
    for (const auto& [pair, n] : uses)
      repeated += n > 1 ? 1 : 0;
    CHECK(layout.pinched.size() == repeated);
    Validate_charts_options o;
    o.expect = Expected_cutting::quads;
    const Cutting_validation v =
        validate_charts(layout.mesh, layout.charts, layout.chart_to_mesh, o);
    INFO(problems_of(v));
    CHECK(v);
    CHECK(v.charts.size() == 6);
    for (const Chart_summary& c : v.charts)
      CHECK(c.sides == 4);
  }
}

TEST_CASE("Refinements: an inverted face and a vertex off its face by 1e-17", "[check]") {
  // One triangle, refined by a centre vertex c and a second centre d in the face (c, B, C).
  auto refine = [](Exact_kernel::FT dx, Exact_kernel::FT dz, Exact_mesh& original) {
    using P = Exact_kernel::Point_3;
    original.clear();
    const auto A = original.add_vertex(P(0, 0, 1)), B = original.add_vertex(P(4, 0, 1)),
               C = original.add_vertex(P(0, 4, 1));
    original.add_face(A, B, C);
    Exact_mesh r;
    const auto a = r.add_vertex(P(0, 0, 1)), b = r.add_vertex(P(4, 0, 1)),
               cc = r.add_vertex(P(0, 4, 1)), c = r.add_vertex(P(1, 1, 1)),
               d = r.add_vertex(P(Exact_kernel::FT(5) / 3 + dx, Exact_kernel::FT(5) / 3, 1 + dz));
    r.add_face(a, b, c);
    r.add_face(cc, a, c);
    r.add_face(c, b, d);
    r.add_face(b, cc, d);
    r.add_face(cc, c, d);
    return r;
  };
  Exact_mesh original;
  Validate_refinement_options exact;
  exact.tolerance = 0;
  {
    const Exact_mesh r = refine(0, 0, original);
    const Refinement_validation v = validate_refinement(original, r, exact);
    INFO(v.message);
    CHECK(v);
    CHECK(v.on_original_vertices == 3);
    CHECK(v.inside_original_faces == 2);
  }
  {
    // d moved past the edge c-C, still inside the original triangle: a face turns over.
    const Exact_mesh r = refine(Exact_kernel::FT(-3) / 2, 0, original);
    const Refinement_validation v = validate_refinement(original, r, exact);
    CHECK_FALSE(v);
    CHECK(v.problem_counts[std::size_t(Refinement_problem_kind::inverted_face)] >= 1);
    CHECK(v.problem_counts[std::size_t(Refinement_problem_kind::coverage)] == 0);
  }
  {
    // d lifted by 1e-17: invisible to a tolerance, and to doubles (1 + 1e-17 rounds to 1).
    const Exact_mesh r =
        refine(0, Exact_kernel::FT(1) / Exact_kernel::FT(100000000000000000.0), original);
    CHECK(validate_refinement(original, r));
    const Refinement_validation v = validate_refinement(original, r, exact);
    CHECK_FALSE(v);
    CHECK(v.problem_counts[std::size_t(Refinement_problem_kind::off_surface)] == 1);
    REQUIRE_FALSE(v.problems.empty());
    CHECK(v.problems.front().vertices == std::vector<std::size_t>{4});
  }
  // The same through the exact text reader: "1.00000000000000001" is read as it is written.
  std::vector<Exact_kernel::Point_3> points;
  REQUIRE(read_exact_coordinates(data_path("cuttings/square-refined-off-by-1e-17.off"), points));
  REQUIRE(points.size() == 5);
  CHECK(points[4].z() != 1);
  CHECK(CGAL::to_double(points[4].z()) == 1.0);
}

TEST_CASE("Exact runs: rationals round-trip and an Epeck quadrangulation lies exactly on its input",
          "[check][io][exact]") {
  // A genus-2 surface whose coordinates are thirds, not doubles: read exactly from text.
  Mesh generated;
  Genus_surface_options o;
  o.cell_resolution = 3;
  o.subdivision_steps = 1;
  make_genus_surface(generated, 2, o);
  Exact_mesh original;
  for (auto v : generated.vertices()) {
    const Point_3& p = generated.point(v);
    original.add_vertex(Exact_kernel::Point_3(
        Exact_kernel::FT(p.x()) / 3, Exact_kernel::FT(p.y()) / 3, Exact_kernel::FT(p.z()) / 3));
  }
  for (auto f : generated.faces()) {
    std::vector<Exact_mesh::Vertex_index> corners;
    for (auto v : vertices_around_face(generated.halfedge(f), generated))
      corners.emplace_back(std::size_t(v));
    original.add_face(corners);
  }
  const std::string path = output_path("exact-thirds.off");
  REQUIRE(write_exact_off(path, original));
  Exact_mesh read;
  REQUIRE(read_exact_polygon_mesh(path, read));
  REQUIRE(num_vertices(read) == num_vertices(original));
  REQUIRE(num_faces(read) == num_faces(original));
  bool same = true;
  for (auto v : original.vertices())
    same = same && read.point(v) == original.point(v);
  CHECK(same);
  // A double's exact value survives too (its 17-digit decimal would not).
  {
    Mesh one;
    const auto a = one.add_vertex(Point_3(0.1, 0.2, 0.3)), b = one.add_vertex(Point_3(1, 0, 0)),
               c = one.add_vertex(Point_3(0, 1, 0));
    one.add_face(a, b, c);
    const std::string p1 = output_path("exact-doubles.off");
    REQUIRE(write_exact_off(p1, one));
    Exact_mesh back;
    REQUIRE(read_exact_polygon_mesh(p1, back));
    CHECK(back.point(Exact_mesh::Vertex_index(0)).x() == Exact_kernel::FT(0.1));
    CHECK(back.point(Exact_mesh::Vertex_index(0)).x() != Exact_kernel::FT(1) / 10);
  }

  // The schema quadrangulation on exact coordinates: every refinement vertex exactly on the input.
  Exact_mesh mesh = read;
  auto tile = mesh.add_property_map<Exact_mesh::Face_index, std::size_t>("f:tessera_tile", 0).first;
  auto seam_e = mesh.add_property_map<Exact_mesh::Edge_index, bool>("e:tessera_seam", false).first;
  auto seam_v =
      mesh.add_property_map<Exact_mesh::Vertex_index, bool>("v:tessera_seam", false).first;
  Quadrangulation_options qo;
  qo.cut.method = Cut_method::schema;
  const auto q = quadrangulate(mesh, tile, seam_e, seam_v, qo);
  REQUIRE(q);
  CHECK(q.number_of_quads() >= 3);
  CHECK(num_faces(mesh) > num_faces(original)); // the schema's unsticking refined it
  CHECK(bool(validate_quadrangulation(mesh, tile, seam_e, seam_v, q)));
  Validate_refinement_options exact;
  exact.tolerance = 0;
  const Refinement_validation r = validate_refinement(original, mesh, exact);
  INFO(r.message);
  CHECK(r);
  CHECK(r.inside_original_faces + r.on_original_edges > 0);
  // Parameterized through a copy in doubles: every quad on the unit square, none folded.
  auto uv = mesh.add_property_map<Exact_mesh::Halfedge_index, CGAL::Point_2<Kernel>>("h:tessera_uv")
                .first;
  const Tile_parameterization_result p =
      parameterize_tiles(mesh, q.tiles, tile_maps(tile, seam_e, seam_v), uv);
  INFO(p.message);
  REQUIRE(p);
  CHECK(p.flipped == 0);
  for (const auto& quad : q.tiles) {
    // The corners of each quad sit on the unit square's corners.
    const auto h = quad.sides.front().front();
    const auto& c = uv[mesh.prev(h)]; // target(prev(h)) = source(h) = the quad's first corner
    CHECK(((c.x() == 0 || c.x() == 1) && (c.y() == 0 || c.y() == 1)));
  }
}

namespace {

// A result directory as `tessera cut` writes it (mesh.off, opened.off, result.json), by the
// library's writers; `c`'s seam maps are removed, as the command removes them before writing.
std::vector<Mesh::Vertex_index> write_cut_directory(const std::string& dir, Cut& c,
                                                    Cut_method method, Mesh& opened) {
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto opened_to_mesh = open_along_seams(c.mesh, c.seam_e, c.seam_v, opened);
  const Cut_validation validation = validate_cut(c.mesh, c.seam_e, c.seam_v, c.result);
  Validate_charts_options chart_options;
  chart_options.marked_corners = internal::index_list(c.result.multipoints);
  const Cutting_validation charts = validate_charts(c.mesh, opened, opened_to_mesh, chart_options);
  Cut_options options;
  options.method = method;
  const Cut_report report =
      make_cut_report(c.mesh, c.result, options, validation, charts, opened, opened_to_mesh);
  c.mesh.remove_property_map(c.seam_e);
  c.mesh.remove_property_map(c.seam_v);
  REQUIRE(write_mesh(dir + "/mesh.off", c.mesh));
  REQUIRE(write_mesh(dir + "/opened.off", opened));
  std::ofstream json(dir + "/result.json");
  REQUIRE(write_cut_report(json, report));
  return opened_to_mesh;
}

std::string points_differ(const Mesh& a, const Mesh& b) {
  if (num_vertices(a) != num_vertices(b) || num_faces(a) != num_faces(b))
    return "counts differ";
  for (auto v : a.vertices())
    if (a.point(v) != b.point(v))
      return "vertex " + std::to_string(std::size_t(v)) + " moved";
  return "";
}

} // namespace

TEST_CASE("A result directory written by the library reads back as the same cutting",
          "[check][io]") {
  for (const Cut_method method : {Cut_method::schema, Cut_method::greedy}) {
    Cut c = cut_genus(2, method);
    REQUIRE(c.result);
    const std::string dir = output_path(std::string("result-dir-") + to_string(method));
    Mesh opened;
    const auto opened_to_mesh = write_cut_directory(dir, c, method, opened);

    const Result_directory d = read_result_directory(dir);
    INFO(to_string(method) << ": " << d.message);
    REQUIRE(d);
    CHECK(d.message.empty());
    CHECK(d.mesh_path == (std::filesystem::path(dir) / "mesh.off").string());
    CHECK_FALSE(d.exact_mesh_path);
    CHECK(points_differ(d.mesh, c.mesh).empty());
    CHECK(points_differ(d.opened, opened).empty());
    CHECK(d.opened_to_mesh == opened_to_mesh);
    CHECK(d.multipoints == internal::index_list(c.result.multipoints));
    CHECK(d.expect ==
          (method == Cut_method::schema ? Expected_cutting::schema : Expected_cutting::disks));
    // The charts read back are those of the cut: the same polygon, word and corners.
    Validate_charts_options o;
    o.expect = d.expect;
    o.marked_corners = d.multipoints;
    const Cutting_validation v = validate_charts(d.mesh, d.opened, d.opened_to_mesh, o);
    const Cutting_validation cut = validate_charts(c.mesh, opened, opened_to_mesh, o);
    CHECK(v);
    REQUIRE(v.charts.size() == 1);
    REQUIRE(cut.charts.size() == 1);
    CHECK(v.charts.front().word == cut.charts.front().word);
    CHECK(v.charts.front().sides == c.result.polygons.front().sides.size());
    CHECK(v.charts.front().chart_corners == cut.charts.front().chart_corners);
    CHECK(v.seam_edges == cut.seam_edges);
    CHECK(v.corner_vertices == cut.corner_vertices);

    // --expect wins over what result.json says; mesh.exact.off is found beside mesh.off.
    REQUIRE(write_exact_off(dir + "/mesh.exact.off", c.mesh));
    Result_directory_options quads;
    quads.expect = Expected_cutting::quads;
    const Result_directory q = read_result_directory(dir, quads);
    CHECK(q.expect == Expected_cutting::quads);
    CHECK(q.exact_mesh_path == (std::filesystem::path(dir) / "mesh.exact.off").string());
  }
}

TEST_CASE("A result directory with a file missing or malformed gives its status and message",
          "[check][io]") {
  Cut c = cut_genus(1, Cut_method::schema);
  REQUIRE(c.result);
  const std::string dir = output_path("result-dir-broken");
  Mesh opened;
  write_cut_directory(dir, c, Cut_method::schema, opened);
  const std::string json = dir + "/result.json";
  std::ifstream in(json);
  const std::string good((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto with_json = [&](const std::string& text) {
    std::ofstream(json) << text;
    return read_result_directory(dir);
  };
  // result.json with one key set to `value` (JSON text), everything else as written.
  auto replaced = [&](const std::string& key, const std::string& value) {
    nlohmann::json j = nlohmann::json::parse(good);
    j[key] = nlohmann::json::parse(value);
    return j.dump(1);
  };

  Result_directory d = with_json("{\"a\": ");
  CHECK(d.status == Result_directory_status::malformed_json);
  CHECK(d.message.rfind(json + ": malformed JSON ([json.exception.parse_error", 0) == 0);

  d = with_json("{}");
  CHECK(d.status == Result_directory_status::bad_vertex_map);
  CHECK(d.message == dir + ": result.json has no opened_to_mesh_vertex");

  d = with_json(replaced("opened_to_mesh_vertex", "[0, 1, 100000]"));
  CHECK(d.status == Result_directory_status::bad_vertex_map);
  CHECK(d.message == dir + ": opened_to_mesh_vertex holds an id that is not a vertex of mesh.off");
  d = with_json(replaced("opened_to_mesh_vertex", "[0, -1]"));
  CHECK(d.status == Result_directory_status::bad_vertex_map);

  // "method" decides the expected cutting only when none is asked for.
  d = with_json(replaced("method", "5"));
  CHECK(d.status == Result_directory_status::bad_method);
  CHECK(d.message.find("type must be string") != std::string::npos);
  Result_directory_options disks;
  disks.expect = Expected_cutting::disks;
  CHECK(read_result_directory(dir, disks));
  CHECK(with_json(replaced("method", "\"greedy\"")).expect == Expected_cutting::disks);
  CHECK(with_json(replaced("method", "\"nonsense\"")).expect == Expected_cutting::disks);
  CHECK(with_json(replaced("method", "\"schema\"")).expect == Expected_cutting::schema);
  CHECK(with_json(replaced("quad_tiles", "[]")).expect == Expected_cutting::quads);
  // Multipoints that are not vertex ids are skipped.
  CHECK(with_json(replaced("multipoints", "[3, \"a\", -1, 2.5, 7]")).multipoints ==
        std::vector<std::size_t>{3, 7});
  std::ofstream(json) << good;
  REQUIRE(read_result_directory(dir));

  std::ofstream(dir + "/opened.off") << "OFF 3 1 0\n0 0 0\n1 0 0\nnan 1 0\n3 0 1 2\n";
  d = read_result_directory(dir);
  CHECK(d.status == Result_directory_status::bad_opened_mesh);
  CHECK(d.message == dir + "/opened.off: not a valid OFF polygon mesh");

  std::ofstream(dir + "/mesh.off") << "garbage\n";
  d = read_result_directory(dir);
  CHECK(d.status == Result_directory_status::bad_mesh);
  CHECK(d.message.rfind(dir + "/mesh.off: ", 0) == 0);

  for (const char* name : {"opened.off", "mesh.off", "result.json"}) {
    std::filesystem::remove(dir + "/" + name);
    d = read_result_directory(dir);
    CHECK(d.status == Result_directory_status::not_a_result_directory);
    CHECK(d.message == dir + ": not a Tessera result directory (no " + name + ")");
  }
}
