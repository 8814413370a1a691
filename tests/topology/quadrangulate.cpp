// Q-criterion quadrangulation (Alg. 4 and 5) over the corpus: every tile is a disk with exactly four
// corners, corners are where tile borders meet, m-gons give m/2 - 1 quads (2g - 1 from the schema),
// the tiles cover the surface, and every quad maps onto the unit square without flipped triangles.
#include "corpus.h"

#include <tessera/topology.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

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

Quad_run run_quads(Mesh& mesh, Cut_method method) {
  Quad_run run;
  run.tile = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:tessera_tile", 0).first;
  run.seam_e = mesh.add_property_map<Mesh::Edge_index, bool>("e:tessera_seam", false).first;
  run.seam_v = mesh.add_property_map<Mesh::Vertex_index, bool>("v:tessera_seam", false).first;
  Quadrangulation_options options;
  options.cut.method = method;
  run.result = quadrangulate(mesh, run.tile, run.seam_e, run.seam_v, options);
  if (run.result) run.validation = validate_quadrangulation(mesh, run.tile, run.seam_e, run.seam_v, run.result);
  return run;
}

/// Area of each component of the mesh opened along the seams, summed.
double opened_area(const Mesh& mesh, const Quad_run& run, std::size_t& components) {
  Mesh opened;
  open_along_seams(mesh, run.seam_e, run.seam_v, opened);
  auto cc = opened.add_property_map<Mesh::Face_index, std::size_t>("f:cc").first;
  components = PMP::connected_components(opened, cc);
  std::vector<double> area(components, 0);
  for (auto f : faces(opened)) area[cc[f]] += PMP::face_area(f, opened);
  double sum = 0;
  for (double a : area) sum += a;
  return sum;
}

void check_parameterization(const Mesh& mesh, const Quad_run& run) {
  Mesh& m = const_cast<Mesh&>(mesh);
  auto uv = m.add_property_map<Mesh::Halfedge_index, CGAL::Point_2<Kernel>>("h:tessera_uv").first;
  const Tile_parameterization_result p =
      parameterize_tiles(mesh, run.result.tiles, run.tile, run.seam_e, run.seam_v, uv);
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
    CHECK(d.angle >= 1);
    CHECK(d.area >= 1);
    CHECK(d.stretch >= 1 - 1e-9);
  }
  m.remove_property_map(uv);
}

} // namespace

TEST_CASE("Alg. 5 cuts the corpus into valid quads", "[topology][quad]") {
  auto corpus = test::generated_corpus(5, 2);
  for (auto& r : test::real_corpus()) {
    const std::set<std::string> wanted{"eight.off", "knot1.off", "elephant.off", "pig.off",
                                       "mesh_with_border.off", "mushroom.off"};
    if (wanted.count(r.name)) corpus.push_back(std::move(r));
  }
  for (Cut_method method : {Cut_method::greedy, Cut_method::intermediate}) {
    for (auto& e : corpus) {
      INFO(e.name << (method == Cut_method::greedy ? " greedy" : " intermediate"));
      Mesh mesh = e.mesh;
      const double area = PMP::area(mesh);
      const Quad_run run = run_quads(mesh, method);
      INFO(run.result.message);
      for (const auto& p : run.validation.problems) INFO(p);
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
      if (method == Cut_method::greedy) check_parameterization(mesh, run);
    }
  }
}

TEST_CASE("the schema's 4g-gon gives 2g - 1 quads", "[topology][quad]") {
  auto corpus = test::generated_corpus(4, 0);
  corpus.push_back({"eight.off", test::load("eight.off"), 2, 0});
  corpus.push_back({"elephant.off", test::load("elephant.off"), 3, 0});
  for (auto& e : corpus) {
    if (e.genus == 0) continue;
    INFO(e.name);
    Mesh mesh = e.mesh;
    const Quad_run run = run_quads(mesh, Cut_method::schema);
    for (const auto& p : run.validation.problems) INFO(p);
    REQUIRE(run.result);
    CHECK(run.validation.valid());
    CHECK(run.result.number_of_quads() == std::size_t(2 * e.genus - 1));
    CHECK(run.result.added_corners == 0);
    check_parameterization(mesh, run);
  }
}

TEST_CASE("Alg. 4 cuts one tile between two chosen corners", "[topology][quad]") {
  Mesh mesh = test::load("eight.off");
  auto se = mesh.add_property_map<Mesh::Edge_index, bool>("e:s", false).first;
  auto sv = mesh.add_property_map<Mesh::Vertex_index, bool>("v:s", false).first;
  const auto cut = cut_to_disk(mesh, se, sv);
  REQUIRE(cut);
  M_tiling<Mesh> tiling(mesh);
  for (auto e : edges(mesh))
    if (se[e]) REQUIRE(tiling.cut({halfedge(e, mesh)}) == Cut_path_status::ok);
  auto tiles = tiling.tiles(false);
  REQUIRE(tiles.size() == 1);
  const auto corners = tile_corners(tiling, tiles[0]);
  const std::size_t m = corners.size();
  REQUIRE(m >= 6);
  auto cost = get(CGAL::dynamic_edge_property_t<double>(), mesh);
  compute_edge_costs(mesh, cost);
  // A corner whose wedge is a single face cannot be reached: take the first pair (i, i + 3) that can.
  std::vector<Mesh::Halfedge_index> path;
  std::size_t a = 0;
  for (; a < m && path.empty(); ++a) path = shortest_cutting_path(tiling, corners[a], corners[(a + 3) % m], cost);
  REQUIRE(!path.empty());
  const auto from = corners[a - 1], to = corners[(a + 2) % m];
  CHECK(source(path.front(), mesh) == target(from, mesh));
  CHECK(target(path.back(), mesh) == target(to, mesh));
  for (std::size_t i = 0; i + 1 < path.size(); ++i) CHECK(!tiling.is_on_cut(target(path[i], mesh)));
  REQUIRE(cut_tile_between_corners(tiling, from, to, cost) == Cut_path_status::ok);
  tiles = tiling.tiles(false);
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
  for (Mesh* mesh : {&sphere, &disk}) {
    const Quad_run run = run_quads(*mesh, Cut_method::greedy);
    for (const auto& p : run.validation.problems) INFO(p);
    REQUIRE(run.result);
    CHECK(run.validation.valid());
    CHECK(run.result.number_of_quads() == 1);
    CHECK(run.result.added_corners > 0);
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
  for (const auto& p : run.validation.problems) INFO(p);
  REQUIRE(run.result);
  CHECK(run.validation.valid());
  CHECK(run.result.refinements + run.result.wedge_refinements > 0); // local or whole-mesh
  CHECK(num_faces(mesh) > faces_before);
  std::size_t components = 0;
  CHECK(opened_area(mesh, run, components) == Approx(area).epsilon(1e-9));
}

TEST_CASE("quadrangulate reports bad input", "[topology][quad]") {
  Mesh mesh = test::load("eight.off");
  auto tile = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:tessera_tile", 0).first;
  auto se = mesh.add_property_map<Mesh::Edge_index, bool>("e:s", false).first;
  auto sv = mesh.add_property_map<Mesh::Vertex_index, bool>("v:s", false).first;
  Quadrangulation_options o;
  o.cut.basepoint = long(num_vertices(mesh)) + 5;
  CHECK(quadrangulate(mesh, tile, se, sv, o).status == Quadrangulation_status::invalid_basepoint);
}
