// Unsticking the greedy system of loops: the refined loops are simple, disjoint but at the
// basepoint, cut the surface into one 4g-gon whose corners are all the basepoint, keep their
// homotopy classes and lengths, and (with Epeck) every new point lies exactly on the original
// surface without folding it.
#include "corpus.h"

#include <tessera/topology/edge_cost.h>
#include <tessera/topology/system_of_loops.h>
#include <tessera/topology/unstick_loops.h>

#include <CGAL/Curves_on_surface_topology.h>
#include <CGAL/Path_on_surface.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

using namespace tessera;

namespace {

template <typename TM>
using Halfedge_path = std::vector<typename boost::graph_traits<TM>::halfedge_descriptor>;

template <typename TM> System_of_loops<TM> greedy_loops(TM& m, std::size_t basepoint = 0) {
  auto cost = m.template add_property_map<typename TM::Edge_index, double>("e:tessera_cost").first;
  compute_edge_costs(m, cost);
  return greedy_system_of_loops(m, *std::next(vertices(m).begin(), long(basepoint)), cost);
}

template <typename TM> double path_length(const TM& m, const Halfedge_path<TM>& path) {
  double len = 0;
  for (auto h : path)
    len += std::sqrt(
        CGAL::to_double(CGAL::squared_distance(m.point(source(h, m)), m.point(target(h, m)))));
  return len;
}

/// (a) and (b): closed simple halfedge paths at b, sharing no vertex but b and no edge.
template <typename TM>
void check_simple_and_disjoint(const TM& m, const std::vector<Halfedge_path<TM>>& loops,
                               typename TM::Vertex_index b) {
  std::map<typename TM::Vertex_index, std::size_t> owner;
  std::set<typename TM::Edge_index> used;
  for (std::size_t i = 0; i < loops.size(); ++i) {
    INFO("loop " << i);
    const auto& loop = loops[i];
    REQUIRE(loop.size() >= 3);
    CHECK(source(loop.front(), m) == b);
    CHECK(target(loop.back(), m) == b);
    for (std::size_t k = 0; k < loop.size(); ++k) {
      if (k > 0)
        CHECK(source(loop[k], m) == target(loop[k - 1], m));
      CHECK(used.insert(edge(loop[k], m)).second);
      const auto v = target(loop[k], m);
      if (v == b) {
        CHECK(k + 1 == loop.size()); // b only at the ends: the loop is simple
        continue;
      }
      CHECK(
          owner.emplace(v, i).second); // no other vertex is visited twice, by this loop or another
    }
  }
}

/// (c): cut along the loops, the surface opens to one disk (with its `holes`) bounded by a 4g-gon
/// whose corners all map to b: b appears exactly 4g times, all along one boundary cycle, and the
/// other cycles are the holes.
template <typename TM>
void check_opens_to_schema(TM& m, const std::vector<Halfedge_path<TM>>& loops,
                           typename TM::Vertex_index b, long genus, std::size_t holes = 0) {
  using GT = boost::graph_traits<TM>;
  auto sem =
      m.template add_property_map<typename TM::Edge_index, bool>("e:tessera_test_seam", false)
          .first;
  auto svm =
      m.template add_property_map<typename TM::Vertex_index, bool>("v:tessera_test_seam", false)
          .first;
  std::size_t cut_edges = 0;
  for (const auto& loop : loops)
    for (auto h : loop) {
      put(sem, edge(h, m), true);
      put(svm, source(h, m), true);
      ++cut_edges;
    }
  using Seam = CGAL::Seam_mesh<TM, decltype(sem), decltype(svm)>;
  Seam seam(m, sem, svm);
  TM opened;
  CGAL::copy_face_graph(seam, opened);
  m.remove_property_map(sem);
  m.remove_property_map(svm);

  const long chi = long(num_vertices(opened)) - long(num_edges(opened)) + long(num_faces(opened));
  CHECK(chi == 1 - long(holes));
  auto component =
      opened.template add_property_map<typename TM::Face_index, std::size_t>("f:tessera_component")
          .first;
  CHECK(CGAL::Polygon_mesh_processing::connected_components(opened, component) == 1);

  std::size_t cycles = 0, polygons = 0;
  std::set<typename GT::halfedge_descriptor> seen;
  for (auto h : halfedges(opened)) {
    if (!is_border(h, opened) || !seen.insert(h).second)
      continue;
    ++cycles;
    std::size_t corners_at_b = 0, sides = 0;
    for (auto c : CGAL::halfedges_around_face(h, opened)) {
      seen.insert(c);
      ++sides;
      if (opened.point(target(c, opened)) == m.point(b))
        ++corners_at_b;
    }
    if (corners_at_b == 0)
      continue;
    ++polygons;
    CHECK(long(corners_at_b) == 4 * genus);
    CHECK(sides == 2 * cut_edges); // every loop edge borders the polygon on both sides
  }
  CHECK(cycles == 1 + holes);
  CHECK(polygons == 1);
}

template <typename TM>
using Vertex_path = std::vector<typename boost::graph_traits<TM>::vertex_descriptor>;

/// The vertices of the loops before the refinement (which splits edges, so the halfedges of the
/// input loops end at new vertices afterwards).
template <typename TM>
std::vector<Vertex_path<TM>> loop_vertices(const TM& m, const System_of_loops<TM>& sys) {
  std::vector<Vertex_path<TM>> out;
  for (const auto& loop : sys.loops) {
    out.push_back({source(loop.front(), m)});
    for (auto h : loop)
      out.back().push_back(target(h, m));
  }
  return out;
}

/// The original loop, walked on the refined mesh along the pieces its edges were split into.
template <typename TM>
Halfedge_path<TM> original_on_refined(const TM& m, const Vertex_path<TM>& loop,
                                      const std::vector<Vertex_origin<TM>>& origins) {
  std::map<typename TM::Vertex_index, std::array<typename TM::Vertex_index, 3>> support;
  for (const auto& o : origins)
    support[o.vertex] = o.support;
  auto on_edge = [&](typename TM::Vertex_index w, typename TM::Vertex_index x,
                     typename TM::Vertex_index y) {
    const auto it = support.find(w);
    return it != support.end() && it->second[2] == TM::null_vertex() &&
           ((it->second[0] == x && it->second[1] == y) ||
            (it->second[0] == y && it->second[1] == x));
  };
  Halfedge_path<TM> path;
  for (std::size_t k = 0; k + 1 < loop.size(); ++k) {
    const auto x = loop[k], y = loop[k + 1];
    auto at = x, from = TM::null_vertex();
    while (at != y) {
      typename TM::Halfedge_index step;
      for (auto g : CGAL::halfedges_around_source(at, m))
        if (target(g, m) != from && (target(g, m) == y || on_edge(target(g, m), x, y)))
          step = g;
      REQUIRE(step != TM::null_halfedge());
      path.push_back(step);
      from = at;
      at = target(step, m);
    }
  }
  return path;
}

/// (d): every refined loop is homotopic, with b fixed, to its original (so is not contractible),
/// and runs close to it: its length differs from the original's by at most the outer offset
/// (a fraction of the edges it runs beside) times that length.
void check_homotopy_and_length(const Mesh& m, const System_of_loops<Mesh>& sys,
                               const std::vector<Vertex_path<Mesh>>& originals,
                               const Unstick_result<Mesh>& r, double outer_offset) {
  namespace SMT = CGAL::Surface_mesh_topology;
  SMT::Curves_on_surface_topology<Mesh> cst(m);
  for (std::size_t i = 0; i < r.loops.size(); ++i) {
    INFO("loop " << i);
    SMT::Path_on_surface<Mesh> refined(m), original(m);
    const Halfedge_path<Mesh> before = original_on_refined(m, originals[i], r.new_vertices);
    for (auto h : r.loops[i])
      refined.push_back(h);
    for (auto h : before)
      original.push_back(h);
    CHECK(refined.is_closed());
    CHECK_FALSE(cst.is_contractible(refined));
    CHECK(cst.are_base_point_homotopic(refined, original));
    const double length = path_length(m, before);
    CHECK(length == Approx(sys.lengths[i]).epsilon(1e-9));
    CHECK(std::abs(path_length(m, r.loops[i]) - length) <= outer_offset * length);
  }
}

void check_unsticking(Mesh m, long genus, const Unstick_options& options = {},
                      std::size_t basepoint = 0, std::size_t holes = 0) {
  const auto sys = greedy_loops(m, basepoint);
  REQUIRE(long(sys.loops.size()) == 2 * genus);
  const std::size_t vertices_before = num_vertices(m);
  const auto originals = loop_vertices(m, sys);
  const auto r = unstick_loops(m, sys, options);
  INFO(r.message);
  REQUIRE(r.status == Unstick_status::ok);
  REQUIRE(r.loops.size() == sys.loops.size());
  CHECK(num_vertices(m) == vertices_before + r.new_vertices.size());
  CHECK(CGAL::is_triangle_mesh(m));
  CHECK(CGAL::is_valid_polygon_mesh(m));
  check_simple_and_disjoint(m, r.loops, sys.basepoint);
  check_opens_to_schema(m, r.loops, sys.basepoint, genus, holes);
  check_homotopy_and_length(m, sys, originals, r, options.outer_offset);
}

Genus_surface_options coarse() {
  Genus_surface_options o;
  o.cell_resolution = 2;
  o.wall_resolution = 1;
  o.subdivision_steps = 1;
  return o;
}

} // namespace

TEST_CASE("unsticking the loops of generated surfaces of genus 1 to 4", "[topology][unstick]") {
  for (std::size_t g = 1; g <= 4; ++g) {
    INFO("genus " << g);
    Mesh m;
    make_genus_surface(m, g, coarse());
    check_unsticking(m, long(g));
  }
}

TEST_CASE("unsticking on a torus of revolution and with a small offset", "[topology][unstick]") {
  Mesh torus;
  make_torus(torus, 3.0, 1.0, 12, 8);
  check_unsticking(torus, 1);
  Unstick_options tight;
  tight.outer_offset = 0.05;
  Mesh m;
  make_genus_surface(m, 3, coarse());
  check_unsticking(m, 3, tight);
}

TEST_CASE("unsticking on surfaces with holes, strands turning away from the border",
          "[topology][unstick]") {
  // Basepoints 7 and 14 give loops through border vertices where turning on the right of the path
  // would cross a hole (genus 1 and 2), so some strands must turn on the left.
  for (auto& e : test::generated_corpus(3, 3)) {
    if (e.boundaries == 0 || e.genus == 0)
      continue;
    for (std::size_t b : {0, 7, 14, 21}) {
      INFO(e.name << " basepoint " << b);
      check_unsticking(e.mesh, e.genus, {}, b, e.boundaries);
    }
  }
}

TEST_CASE("unsticking the loops of real meshes", "[topology][unstick]") {
  check_unsticking(test::load("eight.off"), 2);
  check_unsticking(test::load("knot1.off"), 1);
}

TEST_CASE("unsticking with exact constructions keeps new points on the original surface",
          "[topology][unstick]") {
  using K = Exact_kernel;
  Exact_mesh m;
  make_genus_surface(m, 2, coarse());
  const Exact_mesh original = m;
  const auto sys = greedy_loops(m);
  REQUIRE(sys.loops.size() == 4);
  const auto r = unstick_loops(m, sys);
  REQUIRE(r.status == Unstick_status::ok);
  check_simple_and_disjoint(m, r.loops, sys.basepoint);
  check_opens_to_schema(m, r.loops, sys.basepoint, 2);

  std::map<Exact_mesh::Vertex_index, std::set<Exact_mesh::Vertex_index>> support;
  for (const auto& o : r.new_vertices) {
    const K::Point_3& p = m.point(o.vertex);
    const K::Point_3 &a = original.point(o.support[0]), &b = original.point(o.support[1]);
    if (o.support[2] == Exact_mesh::null_vertex()) {
      CHECK(CGAL::collinear(a, b, p));
      CHECK(K::Segment_3(a, b).has_on(p));
      CHECK((p != a && p != b));
      support[o.vertex] = {o.support[0], o.support[1]};
    } else {
      const K::Point_3& c = original.point(o.support[2]);
      CHECK(CGAL::coplanar(a, b, c, p));
      CHECK(K::Triangle_3(a, b, c).has_on(p));
      support[o.vertex] = {o.support[0], o.support[1], o.support[2]};
    }
  }
  for (auto v : vertices(original))
    support[v] = {v};

  // Every face of the refined mesh lies in one original face, is not degenerate, and is oriented
  // like it (their normals are parallel since the corners are coplanar with it).
  std::size_t checked = 0;
  for (auto f : faces(m)) {
    std::set<Exact_mesh::Vertex_index> on;
    std::vector<K::Point_3> corners;
    for (auto v : CGAL::vertices_around_face(halfedge(f, m), m)) {
      on.insert(support[v].begin(), support[v].end());
      corners.push_back(m.point(v));
    }
    REQUIRE(corners.size() == 3);
    const K::Vector_3 n = CGAL::cross_product(corners[1] - corners[0], corners[2] - corners[0]);
    CHECK_FALSE(CGAL::collinear(corners[0], corners[1], corners[2]));
    Exact_mesh::Face_index host;
    for (auto g : CGAL::faces_around_target(halfedge(*on.begin(), original), original)) {
      if (g == Exact_mesh::null_face())
        continue;
      std::set<Exact_mesh::Vertex_index> around;
      for (auto v : CGAL::vertices_around_face(halfedge(g, original), original))
        around.insert(v);
      if (std::includes(around.begin(), around.end(), on.begin(), on.end()))
        host = g;
    }
    REQUIRE(host != Exact_mesh::null_face());
    std::vector<K::Point_3> h;
    for (auto v : CGAL::vertices_around_face(halfedge(host, original), original))
      h.push_back(original.point(v));
    CHECK(CGAL::is_positive(n * CGAL::cross_product(h[1] - h[0], h[2] - h[0])));
    ++checked;
  }
  CHECK(checked == num_faces(m));
}

TEST_CASE("unsticking has the same combinatorics with Epick and Epeck", "[topology][unstick]") {
  Genus_surface_options lattice = coarse();
  lattice.subdivision_steps = 0; // the points are the same doubles in both kernels
  for (std::size_t g : {1, 3}) {
    INFO("genus " << g);
    Mesh a;
    Exact_mesh e;
    make_genus_surface(a, g, lattice);
    make_genus_surface(e, g, lattice);
    const auto sa = greedy_loops(a);
    const auto se = greedy_loops(e);
    const auto ra = unstick_loops(a, sa);
    const auto re = unstick_loops(e, se);
    INFO(ra.message);
    REQUIRE(ra.status == Unstick_status::ok);
    REQUIRE(re.status == Unstick_status::ok);
    CHECK(ra.new_vertices.size() == re.new_vertices.size());
    CHECK(ra.new_faces == re.new_faces);
    REQUIRE(ra.loops.size() == re.loops.size());
    for (std::size_t i = 0; i < ra.loops.size(); ++i)
      CHECK(ra.loops[i].size() == re.loops[i].size());
  }
}

TEST_CASE("unsticking rejects bad systems of loops without touching the mesh",
          "[topology][unstick]") {
  SECTION("a genus-0 surface has no loops: nothing to do") {
    Mesh sphere;
    make_sphere(sphere, 1.0, 1);
    const auto sys = greedy_loops(sphere);
    const auto r = unstick_loops(sphere, sys);
    CHECK(r);
    CHECK(r.message.empty());
    CHECK(r.loops.empty());
    CHECK(r.new_vertices.empty());
    CHECK(r.new_faces == 0);
  }
  Mesh torus;
  make_torus(torus, 3.0, 1.0, 10, 6);
  const std::size_t n = num_vertices(torus);
  const auto sys = greedy_loops(torus);
  REQUIRE(sys.loops.size() == 2);
  SECTION("a loop not closed at the basepoint") {
    auto bad = sys;
    bad.loops[1].pop_back();
    const auto r = unstick_loops(torus, bad);
    CHECK(!r);
    CHECK(r.status == Unstick_status::invalid_input);
    CHECK(r.message.find("not closed") != std::string::npos);
  }
  SECTION("generators that do not match the loops") {
    auto bad = sys;
    bad.generators.pop_back();
    CHECK(unstick_loops(torus, bad).status == Unstick_status::invalid_input);
    bad = sys;
    std::swap(bad.generators[0], bad.generators[1]);
    CHECK(unstick_loops(torus, bad).status == Unstick_status::invalid_input);
  }
  SECTION("an offset outside (0, 1/2)") {
    Unstick_options o;
    for (const double offset : {0.5, 0.0, std::numeric_limits<double>::quiet_NaN()}) {
      o.outer_offset = offset;
      const auto r = unstick_loops(torus, sys, o);
      INFO("outer_offset " << offset << ": " << r.message);
      CHECK(!r);
      CHECK(r.status == Unstick_status::invalid_input);
      CHECK(r.message == "outer_offset must lie in (0, 1/2)");
      CHECK(r.new_vertices.empty());
    }
  }
  SECTION("a mesh that is not triangulated") {
    Mesh quads = torus;
    CGAL::Euler::join_face(halfedge(*edges(quads).begin(), quads), quads);
    const auto r = unstick_loops(quads, sys);
    CHECK(!r);
    CHECK(r.status == Unstick_status::invalid_input);
    CHECK(r.message == "the mesh is not triangulated");
  }
  SECTION("loops that reach a vertex by different paths (they may cross)") {
    // Vertex (i, j) of the torus grid is i * 6 + j. Loop A goes around the tube along i = 0, loop B
    // starts along i = 1 and joins i = 0 at (0, 2), which A reaches from (0, 1).
    auto v = [](std::size_t i, std::size_t j) {
      return Mesh::Vertex_index(Mesh::size_type((i % 10) * 6 + j % 6));
    };
    auto path = [&](std::vector<Mesh::Vertex_index> vs) {
      std::vector<Mesh::Halfedge_index> p;
      for (std::size_t k = 0; k + 1 < vs.size(); ++k) {
        const auto h = halfedge(vs[k], vs[k + 1], torus);
        REQUIRE(h.second);
        p.push_back(h.first);
      }
      return p;
    };
    System_of_loops<Mesh> crossing;
    crossing.basepoint = v(0, 0);
    crossing.loops.push_back(path({v(0, 0), v(0, 1), v(0, 2), v(0, 3), v(0, 4), v(0, 5), v(0, 0)}));
    crossing.generators.push_back(edge(crossing.loops[0][3], torus));
    crossing.loops.push_back(
        path({v(0, 0), v(1, 0), v(1, 1), v(1, 2), v(0, 2), v(0, 3), v(0, 4), v(0, 5), v(0, 0)}));
    crossing.generators.push_back(edge(crossing.loops[1][1], torus));
    const auto r = unstick_loops(torus, crossing);
    CHECK(r.status == Unstick_status::invalid_input);
    CHECK(r.message.find("tree paths") != std::string::npos);
  }
  CHECK(num_vertices(torus) == n);
}
