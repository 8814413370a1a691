// Q-criterion quadrangulation (Alg. 4 and 5) over the corpus: every tile is a disk with exactly
// four corners, corners are where tile borders meet, m-gons give m/2 - 1 quads (2g - 1 from the
// schema), the tiles cover the surface, and every quad maps onto the unit square without flipped
// triangles. Polyhedron_3's graph traits come before any header that instantiates CGAL::Seam_mesh.
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>

#include "corpus.h"

#include <tessera/topology.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <catch2/catch.hpp>

#include <set>

using namespace tessera;
namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

struct Quad_run {
  Quadrangulation_result<Mesh> result;
  Quadrangulation_validation validation;
  Mesh::Property_map<Mesh::Face_index, std::size_t> tile;
  Mesh::Property_map<Mesh::Edge_index, bool> seam_e;
  Mesh::Property_map<Mesh::Vertex_index, bool> seam_v;
};

Quad_run run_quads(Mesh& mesh, Cut_method method, bool canonical = false) {
  Quad_run run;
  run.tile = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:tessera_tile", 0).first;
  run.seam_e = mesh.add_property_map<Mesh::Edge_index, bool>("e:tessera_seam", false).first;
  run.seam_v = mesh.add_property_map<Mesh::Vertex_index, bool>("v:tessera_seam", false).first;
  Quadrangulation_options options;
  options.cut.method = method;
  options.cut.canonical = canonical;
  run.result = quadrangulate(mesh, run.tile, run.seam_e, run.seam_v, options);
  if (run.result)
    run.validation = validate_quadrangulation(mesh, run.tile, run.seam_e, run.seam_v, run.result);
  return run;
}

/// Area of each component of the mesh opened along the seams, summed.
double opened_area(const Mesh& mesh, const Quad_run& run, std::size_t& components) {
  Mesh opened;
  open_along_seams(mesh, run.seam_e, run.seam_v, opened);
  auto cc = opened.add_property_map<Mesh::Face_index, std::size_t>("f:tessera_component").first;
  components = PMP::connected_components(opened, cc);
  std::vector<double> area(components, 0);
  for (auto f : faces(opened))
    area[cc[f]] += PMP::face_area(f, opened);
  double sum = 0;
  for (double a : area)
    sum += a;
  return sum;
}

void check_parameterization(const Mesh& mesh, const Quad_run& run) {
  Mesh& m = const_cast<Mesh&>(mesh);
  auto uv = m.add_property_map<Mesh::Halfedge_index, CGAL::Point_2<Kernel>>("h:tessera_uv").first;
  const Tile_parameterization_result p =
      parameterize_tiles(mesh, run.result.tiles, tile_maps(run.tile, run.seam_e, run.seam_v), uv);
  INFO(p.message);
  REQUIRE(p);
  CHECK(p.flipped == 0);
  const std::set<std::pair<double, double>> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (const auto& tile : run.result.tiles) {
    std::set<std::pair<double, double>> corners;
    for (const auto& side : tile.sides) {
      const auto q = uv[prev(side.front(), mesh)]; // the UV of the side's first vertex in its tile
      corners.emplace(q.x(), q.y());
    }
    CHECK(corners == square);
  }
  for (const auto& d : p.tiles) {
    CHECK(d.parameterized);
  }
  m.remove_property_map(uv);
}

/// A tile's corners as Alg. 5 searches them: sources at even positions, targets at odd ones, and
/// the Q-criterion on a (source, target) pair of indices into them (3 <= j - i <= m - 3).
struct Q_pairs {
  std::vector<Mesh::Halfedge_index> even, odd;
  std::size_t m;
  explicit Q_pairs(const std::vector<Mesh::Halfedge_index>& corners) : m(corners.size()) {
    for (std::size_t i = 0; i < m; ++i)
      (i % 2 == 0 ? even : odd).push_back(corners[i]);
  }
  bool operator()(std::size_t s, std::size_t t) const {
    const std::size_t d = (2 * t + 1 + m - 2 * s) % m;
    return d >= 3 && d <= m - 3;
  }
};

/// `mesh` cut to a disk by `method`, as a one-tile M-tiling.
M_tiling<Mesh> one_tile(Mesh& mesh, Cut_method method) {
  auto se = mesh.add_property_map<Mesh::Edge_index, bool>("e:tessera_quad_seam", false).first;
  auto sv = mesh.add_property_map<Mesh::Vertex_index, bool>("v:tessera_quad_seam", false).first;
  Cut_options options;
  options.method = method;
  REQUIRE(cut_to_disk(mesh, se, sv, options));
  M_tiling<Mesh> tiling(mesh);
  for (auto e : edges(mesh))
    if (se[e])
      REQUIRE(tiling.cut({halfedge(e, mesh)}) == Cut_path_status::ok);
  REQUIRE(tiling.number_of_tiles() == 1);
  return tiling;
}

} // namespace

TEST_CASE("Alg. 5 cuts the corpus into valid quads", "[topology][quad]") {
  auto corpus = test::generated_corpus(5, 2);
  for (auto& r : test::real_corpus()) {
    const std::set<std::string> wanted{
        "eight.off",   "knot1.off", "elephant.off", "pig.off", "mesh_with_border.off",
        "mushroom.off"};
    if (wanted.count(r.name))
      corpus.push_back(std::move(r));
  }
  for (Cut_method method : {Cut_method::greedy, Cut_method::intermediate}) {
    for (auto& e : corpus) {
      INFO(e.name << " " << to_string(method));
      Mesh mesh = e.mesh;
      const double area = PMP::area(mesh);
      const Quad_run run = run_quads(mesh, method);
      INFO(run.result.message);
      INFO(test::joined(run.validation.problems));
      REQUIRE(run.result);
      CHECK(run.validation.tiles_are_disks);
      CHECK(run.validation.four_corners);
      CHECK(run.validation.corners_where_borders_meet);
      CHECK(run.validation.tile_count);
      // Every source polygon has an even number of corners, at least 4.
      std::size_t expected = 0;
      for (std::size_t m : run.result.polygon_corners) {
        CHECK(m % 2 == 0);
        CHECK(m >= 4);
        expected += m / 2 - 1;
      }
      CHECK(run.result.number_of_quads() == expected);
      CHECK(run.result.cutting_paths == expected - run.result.polygon_corners.size());
      // The tiles cover the surface: the opened pieces' areas add up to the surface's.
      std::size_t components = 0;
      CHECK(opened_area(mesh, run, components) == Approx(area).epsilon(1e-9));
      CHECK(components == run.result.number_of_quads());
      if (method == Cut_method::greedy)
        check_parameterization(mesh, run);
    }
  }
}

TEST_CASE("the schema's 4g-gon gives 2g - 1 quads", "[topology][quad]") {
  auto corpus = test::generated_corpus(4, 0);
  corpus.push_back({"eight.off", test::load("eight.off"), 2, 0});
  corpus.push_back({"elephant.off", test::load("elephant.off"), 3, 0});
  for (auto& e : corpus) {
    if (e.genus == 0)
      continue;
    for (const bool canonical : {false, true}) {
      INFO(e.name << (canonical ? ", canonical schema" : ""));
      Mesh mesh = e.mesh;
      const Quad_run run = run_quads(mesh, Cut_method::schema, canonical);
      INFO(run.result.message);
      INFO(test::joined(run.validation.problems));
      REQUIRE(run.result);
      CHECK(run.result.cut.canonical == canonical);
      CHECK(bool(run.validation));
      CHECK(run.result.number_of_quads() == std::size_t(2 * e.genus - 1));
      CHECK(run.result.added_corners == 0);
      check_parameterization(mesh, run);
    }
  }
}

TEST_CASE("progress: one report per cutting path and per tile, counting up to the plan",
          "[topology][quad][progress]") {
  Mesh mesh = test::load("elephant.off"); // genus 3: a 12-gon, 4 cutting paths, 5 quads
  auto tile = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:tessera_tile", 0).first;
  auto se = mesh.add_property_map<Mesh::Edge_index, bool>("e:tessera_seam", false).first;
  auto sv = mesh.add_property_map<Mesh::Vertex_index, bool>("v:tessera_seam", false).first;
  std::vector<Progress> reports;
  Quadrangulation_options o;
  o.cut.method = Cut_method::schema;
  o.progress = [&](const Progress& p) { reports.push_back(p); };
  const auto r = quadrangulate(mesh, tile, se, sv, o);
  REQUIRE(r);
  REQUIRE(reports.size() == r.cutting_paths);
  CHECK(r.cutting_paths == 4);
  for (std::size_t i = 0; i < reports.size(); ++i) {
    CHECK(std::string(reports[i].stage) == "cutting paths");
    CHECK(reports[i].done == i + 1);
    CHECK(reports[i].total == 4);
  }
  reports.clear();
  auto uv =
      mesh.add_property_map<Mesh::Halfedge_index, CGAL::Point_2<Kernel>>("h:tessera_uv").first;
  Tile_parameterization_options po;
  po.progress = [&](const Progress& p) { reports.push_back(p); };
  REQUIRE(parameterize_tiles(mesh, r.tiles, tile_maps(tile, se, sv), uv, po));
  REQUIRE(reports.size() == r.tiles.size());
  CHECK(reports.back().done == r.tiles.size());
  CHECK(reports.back().total == r.tiles.size());
}

TEST_CASE("parameterize_tiles refuses two tiles joined by an edge off the seams",
          "[topology][quad]") {
  Mesh mesh = test::load("elephant.off");
  Quad_run run = run_quads(mesh, Cut_method::schema);
  REQUIRE(run.validation);
  // A seam edge between two different quads, taken off the seams: the two tiles now share the
  // copies of its ends in the seam mesh, so neither can be cut out on its own.
  Mesh::Edge_index joined;
  for (auto e : edges(mesh)) {
    const auto h = halfedge(e, mesh);
    if (run.seam_e[e] && run.tile[face(h, mesh)] != run.tile[face(opposite(h, mesh), mesh)]) {
      joined = e;
      break;
    }
  }
  REQUIRE(joined != Mesh::Edge_index());
  run.seam_e[joined] = false;
  auto uv =
      mesh.add_property_map<Mesh::Halfedge_index, CGAL::Point_2<Kernel>>("h:tessera_uv").first;
  const Tile_parameterization_result p =
      parameterize_tiles(mesh, run.result.tiles, tile_maps(run.tile, run.seam_e, run.seam_v), uv);
  CHECK_FALSE(p);
  CHECK(p.message.find("not on the seams") != std::string::npos);
  // The shared vertex itself is named (not only a first side found off the seams).
  std::size_t refused = 0, sharing = 0;
  for (const auto& d : p.tiles) {
    refused += d.parameterized ? 0 : 1;
    sharing += d.message.find("shares a vertex with tile") != std::string::npos ? 1 : 0;
  }
  CHECK(sharing >= 1);
  CHECK(refused >= 1);
  CHECK(refused < p.tiles.size());
}

TEST_CASE("Alg. 4 cuts one tile between two chosen corners", "[topology][quad]") {
  Mesh mesh = test::load("eight.off");
  M_tiling<Mesh> tiling = one_tile(mesh, Cut_method::greedy);
  auto tiles = tiling.tiles_without_faces();
  const auto corners = tile_corners(tiling, tiles[0]);
  const std::size_t m = corners.size();
  REQUIRE(m >= 6);
  auto cost = get(CGAL::dynamic_edge_property_t<double>(), mesh);
  compute_edge_costs(mesh, cost);
  // A corner whose wedge is a single face cannot be reached: take the first pair (i, i + 3) that
  // can.
  std::vector<Mesh::Halfedge_index> path;
  std::size_t a = 0;
  for (; a < m && path.empty(); ++a)
    path = shortest_cutting_path(tiling, corners[a], corners[(a + 3) % m], cost);
  REQUIRE(!path.empty());
  const auto from = corners[a - 1], to = corners[(a + 2) % m];
  CHECK(source(path.front(), mesh) == target(from, mesh));
  CHECK(target(path.back(), mesh) == target(to, mesh));
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    CHECK(!tiling.is_on_cut(target(path[i], mesh)));
  REQUIRE(cut_tile_between_corners(tiling, from, to, cost) == Cut_path_status::ok);
  tiles = tiling.tiles_without_faces();
  REQUIRE(tiles.size() == 2);
  std::multiset<std::size_t> counts;
  for (const auto& t : tiles) {
    CHECK(t.boundaries.size() == 1);
    CHECK(t.genus == 0);
    counts.insert(tile_corners(tiling, t).size());
  }
  CHECK(counts == std::multiset<std::size_t>{4, m - 2});
}

TEST_CASE("closed spheres and disks become one quad", "[topology][quad]") {
  Mesh sphere;
  make_sphere(sphere, 1.0, 2);
  Mesh disk = test::load("mesh_with_border.off");
  // The sphere's slit has 2 corners: splitting a seam side marks one vertex, a corner on both
  // copies (4). The disk's border has none: 4 marks.
  const std::pair<Mesh*, std::size_t> cases[] = {{&sphere, 1}, {&disk, 4}};
  for (const auto& [mesh, marks] : cases) {
    const Quad_run run = run_quads(*mesh, Cut_method::greedy);
    INFO(test::joined(run.validation.problems));
    REQUIRE(run.result);
    CHECK(bool(run.validation));
    CHECK(run.result.number_of_quads() == 1);
    CHECK(run.result.added_corners == marks);
    check_parameterization(*mesh, run);
  }
}

TEST_CASE("coarse meshes are refined until cutting paths exist", "[topology][quad]") {
  Mesh mesh;
  Genus_surface_options o;
  o.cell_resolution = 1;
  o.wall_resolution = 1;
  o.subdivision_steps = 0;
  make_genus_surface(mesh, 3, o);
  const std::size_t faces_before = num_faces(mesh);
  const double area = PMP::area(mesh);
  const Quad_run run = run_quads(mesh, Cut_method::greedy);
  INFO(test::joined(run.validation.problems));
  REQUIRE(run.result);
  CHECK(bool(run.validation));
  CHECK(run.result.refinements + run.result.local_refinements > 0); // local or whole-mesh
  CHECK(num_faces(mesh) > faces_before);
  std::size_t components = 0;
  CHECK(opened_area(mesh, run, components) == Approx(area).epsilon(1e-9));
}

TEST_CASE("quadrangulate reports bad input", "[topology][quad]") {
  Mesh mesh = test::load("eight.off");
  auto tile = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:tessera_tile", 0).first;
  auto se = mesh.add_property_map<Mesh::Edge_index, bool>("e:tessera_quad_seam", false).first;
  auto sv = mesh.add_property_map<Mesh::Vertex_index, bool>("v:tessera_quad_seam", false).first;
  Quadrangulation_options o;
  o.cut.basepoint = std::size_t(num_vertices(mesh)) + 5;
  CHECK(quadrangulate(mesh, tile, se, sv, o).status == Quadrangulation_status::invalid_basepoint);

  // Not a triangle mesh: refused, the mesh untouched.
  Mesh cube;
  CGAL::make_hexahedron(Kernel::Point_3(0, 0, 0), Kernel::Point_3(1, 0, 0),
                        Kernel::Point_3(1, 1, 0), Kernel::Point_3(0, 1, 0),
                        Kernel::Point_3(0, 1, 1), Kernel::Point_3(0, 0, 1),
                        Kernel::Point_3(1, 0, 1), Kernel::Point_3(1, 1, 1), cube);
  auto ct = cube.add_property_map<Mesh::Face_index, std::size_t>("f:tessera_tile", 0).first;
  auto ce = cube.add_property_map<Mesh::Edge_index, bool>("e:tessera_quad_seam", false).first;
  auto cv = cube.add_property_map<Mesh::Vertex_index, bool>("v:tessera_quad_seam", false).first;
  const auto bad = quadrangulate(cube, ct, ce, cv);
  CHECK(bad.status == Quadrangulation_status::invalid_mesh);
  CHECK(!bad.message.empty());
  CHECK(num_faces(cube) == 6);

  // A coarse surface whose tiles need local refinement: it is enough, no whole-mesh subdivision is
  // needed (with none allowed, the run still succeeds).
  Mesh coarse;
  Genus_surface_options go;
  go.cell_resolution = 1;
  go.wall_resolution = 1;
  go.subdivision_steps = 0;
  make_genus_surface(coarse, 3, go);
  auto kt = coarse.add_property_map<Mesh::Face_index, std::size_t>("f:tessera_tile", 0).first;
  auto ke = coarse.add_property_map<Mesh::Edge_index, bool>("e:tessera_quad_seam", false).first;
  auto kv = coarse.add_property_map<Mesh::Vertex_index, bool>("v:tessera_quad_seam", false).first;
  Quadrangulation_options none;
  none.max_refinements = 0;
  const auto local = quadrangulate(coarse, kt, ke, kv, none);
  INFO(local.message);
  CHECK(local);
  CHECK(local.refinements == 0);
  CHECK(local.local_refinements > 0);
  CHECK(bool(validate_quadrangulation(coarse, kt, ke, kv, local)));
}

namespace {

// A second point map of `mesh` with every point scaled by 2 (exactly, in binary floating point).
Mesh::Property_map<Mesh::Vertex_index, Kernel::Point_3> add_doubled_points(Mesh& mesh) {
  auto scaled =
      mesh.add_property_map<Mesh::Vertex_index, Kernel::Point_3>("v:tessera_scaled").first;
  for (auto v : vertices(mesh))
    scaled[v] = CGAL::ORIGIN + 2 * (mesh.point(v) - CGAL::ORIGIN);
  return scaled;
}

// The largest squared distance between `scaled` and twice the points of `plain` (a run on the
// mesh's own points), vertex by vertex.
double doubling_error(const Mesh& plain,
                      const Mesh::Property_map<Mesh::Vertex_index, Kernel::Point_3>& scaled) {
  double largest = 0;
  for (auto v : vertices(plain))
    largest =
        std::max(largest, CGAL::to_double(CGAL::squared_distance(
                              scaled[v], CGAL::ORIGIN + 2 * (plain.point(v) - CGAL::ORIGIN))));
  return largest;
}

} // namespace

TEST_CASE("cut_to_disk reads a user's vertex_point_map", "[topology][cut]") {
  // The same surface, its points in a second map scaled by 2 (exactly, in binary floating point):
  // the schema cut is the same (costs double, ties stay ties), its length doubles, and the schema's
  // new vertices are written into the user's map, at twice the positions of the plain run's.
  Mesh mesh = test::load("eight.off");
  const auto scaled = add_doubled_points(mesh);
  Mesh plain = mesh;
  auto e1 = plain.add_property_map<Mesh::Edge_index, bool>("e:tessera_seam", false).first;
  auto v1 = plain.add_property_map<Mesh::Vertex_index, bool>("v:tessera_seam", false).first;
  auto e2 = mesh.add_property_map<Mesh::Edge_index, bool>("e:tessera_seam", false).first;
  auto v2 = mesh.add_property_map<Mesh::Vertex_index, bool>("v:tessera_seam", false).first;
  Cut_options co;
  co.method = Cut_method::schema;
  const auto base = cut_to_disk(plain, e1, v1, co);
  const auto user = cut_to_disk(mesh, e2, v2, co, CGAL::parameters::vertex_point_map(scaled));
  REQUIRE(base);
  REQUIRE(user);
  CHECK(base.added_vertices > 0);
  CHECK(user.added_vertices == base.added_vertices);
  CHECK(user.cut_length == 2 * base.cut_length);
  REQUIRE(num_vertices(mesh) == num_vertices(plain));
  CHECK(doubling_error(plain, scaled) == 0);
  for (auto e : edges(mesh))
    CHECK(e2[e] == e1[e]);
}

TEST_CASE("quadrangulate reads and writes a user's vertex_point_map", "[topology][quad]") {
  // As above, through Alg. 5's local refinements: the same quads, lengths doubled, every refined
  // vertex written into the user's map at twice the plain run's position.
  Mesh mesh = test::load("eight.off");
  const auto scaled = add_doubled_points(mesh);
  Mesh plain = mesh;
  auto run = [](Mesh& m, auto np) {
    auto t = m.add_property_map<Mesh::Face_index, std::size_t>("f:tessera_tile", 0).first;
    auto e = m.add_property_map<Mesh::Edge_index, bool>("e:tessera_quad_seam", false).first;
    auto v = m.add_property_map<Mesh::Vertex_index, bool>("v:tessera_quad_seam", false).first;
    Quadrangulation_options o;
    o.cut.method = Cut_method::schema;
    return quadrangulate(m, t, e, v, o, np);
  };
  const auto base = run(plain, CGAL::parameters::default_values());
  const auto user = run(mesh, CGAL::parameters::vertex_point_map(scaled));
  INFO(base.message << " / " << user.message);
  REQUIRE(base);
  REQUIRE(user);
  CHECK(base.local_refinements > 0);
  CHECK(user.number_of_quads() == 3);
  CHECK(base.number_of_quads() == 3);
  CHECK(user.cut_length == 2 * base.cut_length);
  REQUIRE(num_vertices(mesh) == num_vertices(plain));
  CHECK(doubling_error(plain, scaled) == 0);
}

TEST_CASE("the bounded A* search finds the same shortest Q-paths as a full Dijkstra",
          "[topology][quad]") {
  // One tile: eight.off opened by the schema (all corners at one vertex) and by the greedy cut.
  for (Cut_method method : {Cut_method::schema, Cut_method::greedy}) {
    Mesh mesh = test::load("eight.off");
    const M_tiling<Mesh> tiling = one_tile(mesh, method);
    const auto tiles = tiling.tiles_without_faces();
    const auto corners = tile_corners(tiling, tiles[0]);
    const std::size_t m = corners.size();
    REQUIRE(m >= 6);
    auto cost = get(CGAL::dynamic_edge_property_t<double>(), mesh);
    compute_edge_costs(mesh, cost);
    auto c = [&](auto e) { return get(cost, e); };
    const Q_pairs valid(corners);
    const auto &even = valid.even, &odd = valid.odd;
    // Brute force: one full single-source search per even corner, every valid target.
    double brute = std::numeric_limits<double>::infinity();
    for (std::size_t s = 0; s < even.size(); ++s)
      for (std::size_t t = 0; t < odd.size(); ++t) {
        if (!valid(s, t))
          continue;
        const auto path = shortest_cutting_path(tiling, even[s], odd[t], cost);
        double length = 0;
        for (auto h : path)
          length += get(cost, edge(h, mesh));
        if (!path.empty())
          brute = std::min(brute, length);
      }
    REQUIRE(brute < std::numeric_limits<double>::infinity());
    internal::Cutting_path_search<Mesh> search(tiling, 3, c);
    search.run(even, odd, valid, 1.0);
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t t = 0; t < odd.size(); ++t)
      best = std::min(
          best, search.best_arrival(odd[t], [&](std::size_t s) { return valid(s, t); }).length);
    CHECK(best == Approx(brute).epsilon(1e-12));
  }
}

TEST_CASE("an M-tiling follows local refinements of its mesh", "[topology][quad]") {
  Mesh mesh = test::load("eight.off");
  M_tiling<Mesh> tiling = one_tile(mesh, Cut_method::schema);
  const auto before = tiling.tiles_without_faces();
  REQUIRE(before.size() == 1);
  const auto corners = tile_corners(tiling, before[0]);
  const std::size_t cycles = tiling.number_of_boundary_cycles();
  std::vector<Mesh::Vertex_index> added;
  const std::size_t chords =
      internal::split_tile_chords(mesh, tiling, corners, added, get(CGAL::vertex_point, mesh));
  REQUIRE(chords > 0); // the schema's parallel strands leave chords
  CHECK(added.size() == chords);
  tiling.absorb_refinement();
  for (auto v : added)
    CHECK(!tiling.is_on_cut(v));
  // The same seams on a fresh tiling describe the same tile.
  M_tiling<Mesh> fresh(mesh);
  for (auto e : edges(mesh))
    if (tiling.is_seam(e))
      fresh.cut({halfedge(e, mesh)});
  for (auto v : tiling.marked_vertices())
    fresh.mark_multipoint(v);
  const auto a = tiling.tiles(), b = fresh.tiles();
  REQUIRE(a.size() == 1);
  REQUIRE(b.size() == 1);
  CHECK(a[0].faces.size() == num_faces(mesh));
  CHECK(a[0].euler_characteristic == b[0].euler_characteristic);
  CHECK(a[0].sides.size() == b[0].sides.size());
  CHECK(tile_corners(tiling, a[0]) == corners);
  CHECK(tiling.number_of_boundary_cycles() == cycles);
  // No chord is left in the tile.
  std::vector<Mesh::Vertex_index> none;
  CHECK(internal::split_tile_chords(mesh, tiling, corners, none, get(CGAL::vertex_point, mesh)) ==
        0);
}

TEST_CASE("quadrangulate runs on Polyhedron_3 and with exact constructions",
          "[topology][quad][polyhedron][exact]") {
  using Polyhedron = CGAL::Polyhedron_3<Kernel, CGAL::Polyhedron_items_with_id_3>;
  Mesh reference = test::load("eight.off");
  const Quad_run ref = run_quads(reference, Cut_method::schema);
  REQUIRE(ref.result);
  REQUIRE(ref.result.local_refinements > 0); // the refinement path is exercised

  Polyhedron poly;
  REQUIRE(read_mesh(test::data_path("eight.off"), poly));
  CGAL::set_halfedgeds_items_id(poly);
  auto tile = get(CGAL::dynamic_face_property_t<std::size_t>(), poly);
  auto seam_e = get(CGAL::dynamic_edge_property_t<bool>(), poly);
  auto seam_v = get(CGAL::dynamic_vertex_property_t<bool>(), poly);
  Quadrangulation_options options;
  options.cut.method = Cut_method::schema;
  const auto pr = quadrangulate(poly, tile, seam_e, seam_v, options);
  INFO(pr.message);
  REQUIRE(pr);
  CGAL::set_halfedgeds_items_id(poly);
  const auto pv = validate_quadrangulation(poly, tile, seam_e, seam_v, pr);
  INFO(test::joined(pv.problems));
  CHECK(bool(pv));
  CHECK(pr.number_of_quads() == 3);
  CHECK(num_faces(poly) == num_faces(reference));
  CHECK(pr.cut_length == Approx(ref.result.cut_length).epsilon(1e-12));

  Exact_mesh exact;
  REQUIRE(read_mesh(test::data_path("eight.off"), exact));
  auto etile =
      exact.add_property_map<Exact_mesh::Face_index, std::size_t>("f:tessera_tile", 0).first;
  auto ee =
      exact.add_property_map<Exact_mesh::Edge_index, bool>("e:tessera_quad_seam", false).first;
  auto ev =
      exact.add_property_map<Exact_mesh::Vertex_index, bool>("v:tessera_quad_seam", false).first;
  const auto er = quadrangulate(exact, etile, ee, ev, options);
  REQUIRE(er);
  const auto xv = validate_quadrangulation(exact, etile, ee, ev, er);
  INFO(test::joined(xv.problems));
  CHECK(bool(xv));
  CHECK(er.number_of_quads() == 3);
  // The source cut is the same; after refinement, exact midpoints and Epick's rounded ones give
  // costs that differ in the last bits, so later paths may break ties differently.
  CHECK(er.cut.cut_length == Approx(ref.result.cut.cut_length).epsilon(1e-12));
  CHECK(er.cut_length == Approx(ref.result.cut_length).epsilon(1e-3));
  // Midpoints and centroids are exact constructions: no refinement made a flat (collinear)
  // triangle.
  std::size_t off_plane = 0;
  for (auto f : faces(exact)) {
    const auto h = halfedge(f, exact);
    const auto& p = exact.point(source(h, exact));
    const auto& q = exact.point(target(h, exact));
    const auto& r = exact.point(target(next(h, exact), exact));
    off_plane += CGAL::collinear(p, q, r) ? 1 : 0;
  }
  CHECK(off_plane == 0); // no degenerate (flat) triangle was made
}

TEST_CASE("every parameterization error code has its own message", "[topology][parameterization]") {
  namespace SMP = CGAL::Surface_mesh_parameterization;
  std::set<std::string> messages;
  for (int code = SMP::OK; code <= SMP::ERROR_WRONG_PARAMETER; ++code) {
    const std::string m = internal::parameterization_error_message(SMP::Error_code(code));
    UNSCOPED_INFO("code " << code << ": " << m);
    CHECK(!m.empty());
    messages.insert(m);
  }
  CHECK(messages.size() == std::size_t(SMP::ERROR_WRONG_PARAMETER) + 1);
  CHECK(internal::parameterization_error_message(SMP::ERROR_NO_1_TO_1_MAPPING).find("one-to-one") !=
        std::string::npos);
  CHECK(internal::parameterization_error_message(SMP::ERROR_NO_TOPOLOGICAL_BALL).find("ball") !=
        std::string::npos);
}

// [heavy]: 20 quadrangulations with their checks and parameterizations.
TEST_CASE("polygonal refinement: valid quads on the input surface, finished as triangles",
          "[topology][quad][heavy]") {
  auto corpus = test::generated_corpus(4, 3);
  corpus.push_back({"eight.off", test::load("eight.off"), 2, 0});
  for (auto& e : corpus) {
    if (e.genus == 0)
      continue;
    for (Cut_method method : {Cut_method::schema, Cut_method::greedy}) {
      INFO(e.name << " " << to_string(method));
      Mesh mesh = e.mesh;
      const Quad_run run = run_quads(mesh, method);
      INFO(run.result.message);
      INFO(test::joined(run.validation.problems));
      REQUIRE(run.result);
      CHECK(bool(run.validation));
      CHECK(CGAL::is_triangle_mesh(mesh));
      // No removed element is left behind (indices stay dense for index-based maps).
      CHECK(mesh.number_of_removed_vertices() + mesh.number_of_removed_edges() +
                mesh.number_of_removed_faces() ==
            0);
      if (method == Cut_method::schema && e.boundaries == 0)
        CHECK(run.result.number_of_quads() == std::size_t(2 * e.genus - 1));
      // Every new vertex lies on the input surface and no face is degenerate or flipped.
      const Refinement_validation on_surface = validate_refinement(e.mesh, mesh);
      INFO(on_surface.message);
      CHECK(bool(on_surface));
      check_parameterization(mesh, run);
    }
  }
}

// [heavy]: 2.5 s optimized, 160 s at -O0 with the sanitizers.
TEST_CASE("polygonal refinement keeps 99 paths apart on a genus-50 plate",
          "[topology][quad][heavy]") {
  // 7,312 faces: the paths of Alg. 5 pass one after another between one vertex and the previous
  // path. Splitting the gap at its midpoint each time made points coincide in double precision
  // (flipped faces, INVALID refinement); spread along their edges they stay apart.
  Genus_surface_options options;
  options.cell_resolution = 1;
  options.wall_resolution = 1;
  options.subdivision_steps = 1;
  Mesh input;
  make_genus_surface(input, 50, options);
  REQUIRE(num_faces(input) == 7312);
  Mesh mesh = input;
  const Quad_run run = run_quads(mesh, Cut_method::schema);
  INFO(run.result.message);
  INFO(test::joined(run.validation.problems));
  REQUIRE(run.result);
  CHECK(bool(run.validation));
  CHECK(run.result.number_of_quads() == 99);
  const Refinement_validation on_surface = validate_refinement(input, mesh);
  INFO(on_surface.message);
  CHECK(bool(on_surface));
  // Triangulating every split at once made 4.1M faces of it; the schema cut alone makes 99k.
  CHECK(num_faces(mesh) < 500000);
}

TEST_CASE("points added on one edge stay evenly spaced in their order", "[topology][quad]") {
  // Two triangles; the edge (a, b) is split 60 times, each time between a and the point nearest
  // to it, without triangulating: midpoints alone would be 2^-60 of the edge from a.
  Mesh mesh;
  const auto a = mesh.add_vertex({0, 0, 0}), b = mesh.add_vertex({1, 0, 0});
  const auto c = mesh.add_vertex({0.5, 1, 0}), d = mesh.add_vertex({0.5, -1, 0});
  mesh.add_face(a, b, c);
  mesh.add_face(b, a, d);
  const auto vpm = get(CGAL::vertex_point, mesh);
  internal::Edge_point_spacing<Mesh, decltype(vpm)> spacing;
  Mesh::Vertex_index nearest = b;
  for (int i = 0; i < 60; ++i) {
    const auto h = halfedge(a, nearest, mesh).first;
    const auto m = internal::split_edge_at_midpoint(mesh, h, vpm, false);
    spacing.record(mesh, {m});
    spacing.respace(vpm);
    nearest = m;
  }
  CHECK(num_faces(mesh) == 2);
  // Walk from a to b along the split edge: 61 equal steps.
  std::vector<Mesh::Vertex_index> chain{a};
  for (Mesh::Vertex_index v = a, from = a; v != b;) {
    Mesh::Vertex_index next_v = v;
    for (auto h : CGAL::halfedges_around_target(v, mesh))
      if (source(h, mesh) != from && source(h, mesh) != c && source(h, mesh) != d)
        next_v = source(h, mesh);
    REQUIRE(next_v != v);
    from = v;
    v = next_v;
    chain.push_back(v);
  }
  REQUIRE(chain.size() == 62);
  for (std::size_t i = 0; i < chain.size(); ++i) {
    CHECK(vpm[chain[i]].x() == Approx(double(i) / 61).margin(1e-15));
    CHECK(vpm[chain[i]].y() == 0);
  }
}

TEST_CASE("a search across faces finds paths no longer than across their triangulation",
          "[topology][quad]") {
  // The eight opened by the schema, its chords split without triangulating: strips between
  // parallel strands become quads and pentagons, which paths cross along diagonals.
  Mesh mesh = test::load("eight.off");
  M_tiling<Mesh> tiling = one_tile(mesh, Cut_method::schema);
  const auto corners = tile_corners(tiling, tiling.tiles_without_faces()[0]);
  const std::size_t m = corners.size();
  const auto vpm = get(CGAL::vertex_point, mesh);
  std::vector<Mesh::Vertex_index> added;
  REQUIRE(internal::split_tile_chords(mesh, tiling, corners, added, vpm, false) > 0);
  tiling.absorb_refinement();
  REQUIRE(!CGAL::is_triangle_mesh(mesh));
  auto cost = get(CGAL::dynamic_edge_property_t<double>(), mesh);
  compute_edge_costs(mesh, cost);
  const Q_pairs valid(corners);
  const auto &even = valid.even, &odd = valid.odd;
  const auto best_of = [&](auto& search) {
    search.run(even, odd, valid, 1.0);
    std::pair<typename std::decay_t<decltype(search)>::Candidate, std::size_t> best;
    for (std::size_t t = 0; t < odd.size(); ++t) {
      const auto c = search.best_arrival(odd[t], [&](std::size_t s) { return valid(s, t); });
      if (c.length < best.first.length)
        best = {c, t};
    }
    return best;
  };
  internal::Cutting_path_search<Mesh, decltype(vpm)> across(
      tiling, 3, [&](auto e) { return get(cost, e); }, vpm, true);
  const auto [best, best_target] = best_of(across);
  REQUIRE(best.found());
  // The same tiling triangulated: every triangle edge is an edge or a diagonal of a face, so the
  // search across faces can only be shorter.
  Mesh triangulated = mesh;
  CGAL::Polygon_mesh_processing::triangulate_faces(triangulated);
  {
    M_tiling<Mesh> t2(triangulated);
    for (auto e : edges(mesh))
      if (tiling.is_seam(e)) {
        const auto h = halfedge(e, mesh);
        t2.cut({halfedge(source(h, mesh), target(h, mesh), triangulated).first});
      }
    for (auto v : tiling.marked_vertices())
      t2.mark_multipoint(v);
    auto cost2 = get(CGAL::dynamic_edge_property_t<double>(), triangulated);
    compute_edge_costs(triangulated, cost2);
    const auto c2 = tile_corners(t2, t2.tiles_without_faces()[0]);
    REQUIRE(c2 == corners);
    internal::Cutting_path_search<Mesh> along(t2, 3, [&](auto e) { return get(cost2, e); });
    const auto [tri, t] = best_of(along);
    REQUIRE(tri.found());
    CHECK(best.length <= tri.length * (1 + 1e-12));
  }
  // Inserted into the mesh, the path is a valid cut of the tile, as long as the search said.
  std::vector<Mesh::Vertex_index> touched;
  const auto path = internal::insert_path(mesh, tiling, across.path_vertices(best),
                                          even[best.source], odd[best_target], touched);
  REQUIRE(!path.empty());
  tiling.absorb_refinement();
  double length = 0;
  for (auto h : path)
    length += std::sqrt(CGAL::squared_distance(vpm[source(h, mesh)], vpm[target(h, mesh)]));
  CHECK(length == Approx(best.length).epsilon(1e-12));
  CHECK(tiling.check_path(path) == Cut_path_status::ok);
  REQUIRE(tiling.cut(path) == Cut_path_status::ok);
  const auto tiles = tiling.tiles_without_faces();
  REQUIRE(tiles.size() == 2);
  std::size_t corner_sum = 0;
  for (const auto& tile : tiles) {
    CHECK(tile.genus == 0);
    CHECK(tile.boundaries.size() == 1);
    corner_sum += tile_corners(tiling, tile).size();
  }
  CHECK(corner_sum == m + 2);
}
