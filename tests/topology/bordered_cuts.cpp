// Every cut method opens bordered surfaces of genus 1–5 into one disk per component: few and many
// holes (up to 100+), holes one edge apart, holes anywhere on the handles, polygonal input. Before
// the fix, greedy and intermediate cuts left a handle when a loop through border vertices cut off
// holes.
#include "corpus.h"

#include <tessera/topology.h>

#include <CGAL/boost/graph/Euler_operations.h>

#include <catch2/catch.hpp>

#include <random>

using namespace tessera;

namespace {

/// Removes `count` single faces, each sharing no vertex with an existing hole but with a vertex one
/// edge from one, so that the holes form a chain of neighbours. Returns the holes made.
std::size_t punch_adjacent_holes(Mesh& mesh, std::size_t count, unsigned seed) {
  std::mt19937 rng(seed);
  std::size_t made = 0;
  auto touches_border = [&](Mesh::Face_index f, bool one_ring) {
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      if (CGAL::is_border(v, mesh))
        return true;
      if (one_ring)
        for (auto w : CGAL::vertices_around_target(mesh.halfedge(v), mesh))
          if (CGAL::is_border(w, mesh))
            return true;
    }
    return false;
  };
  std::vector<Mesh::Face_index> order(mesh.faces().begin(), mesh.faces().end());
  std::shuffle(order.begin(), order.end(), rng);
  while (made < count) {
    bool removed = false;
    for (auto f : order) {
      if (mesh.is_removed(f) || touches_border(f, false))
        continue;
      if (made > 0 && !touches_border(f, true))
        continue; // next to an earlier hole
      CGAL::Euler::remove_face(mesh.halfedge(f), mesh);
      ++made;
      removed = true;
      break;
    }
    if (!removed)
      break;
  }
  mesh.collect_garbage();
  return made;
}

void check_every_method(const Mesh& input, long genus, std::size_t boundaries,
                        const std::string& name) {
  for (Cut_method method : {Cut_method::greedy, Cut_method::intermediate, Cut_method::schema}) {
    INFO(name << ", method " << to_string(method));
    Mesh mesh = input;
    auto seam_e = mesh.add_property_map<Mesh::Edge_index, bool>("e:tessera_seam", false).first;
    auto seam_v = mesh.add_property_map<Mesh::Vertex_index, bool>("v:tessera_seam", false).first;
    Cut_options options;
    options.method = method;
    const auto result = cut_to_disk(mesh, seam_e, seam_v, options);
    INFO(result.message);
    REQUIRE(result);
    const Cut_validation v = validate_cut(mesh, seam_e, seam_v, result);
    INFO(test::joined(v.problems));
    CHECK(bool(v));
    REQUIRE(result.polygons.size() == 1);
    CHECK(result.polygons[0].genus == genus);
    CHECK(result.polygons[0].boundaries == boundaries);
  }
}

} // namespace

TEST_CASE("every method opens genus 1-5 surfaces with 1, 3, 20 and 100+ holes into a disk",
          "[topology][cut][bordered]") {
  Genus_surface_options o;
  o.cell_resolution = 4;
  o.subdivision_steps = 1;
  for (std::size_t genus = 1; genus <= 5; ++genus) {
    for (std::size_t holes : {1, 3, 20, 120}) {
      // A finer lattice gives room for 100+ holes 4 edges apart on the smaller plates.
      o.cell_resolution = holes > 100 ? 7 : 4;
      Mesh mesh;
      make_genus_surface(mesh, genus, o);
      const std::size_t made = punch_holes(mesh, holes, unsigned(31 * genus + holes));
      CHECK(made >= std::min<std::size_t>(holes, 100));
      check_every_method(mesh, long(genus), made,
                         "genus " + std::to_string(genus) + ", " + std::to_string(made) + " holes");
    }
  }
}

TEST_CASE("holes one edge apart, chained across the surface and its handles",
          "[topology][cut][bordered]") {
  Genus_surface_options o;
  o.cell_resolution = 3;
  o.subdivision_steps = 1;
  for (std::size_t genus : {1, 2, 3}) {
    Mesh mesh;
    make_genus_surface(mesh, genus, o);
    const std::size_t made = punch_adjacent_holes(mesh, 25, unsigned(genus));
    CHECK(made == 25);
    check_every_method(mesh, long(genus), made,
                       "genus " + std::to_string(genus) + ", chained holes");
  }
}

TEST_CASE("polygonal input with holes is cut like its triangulation", "[topology][cut][bordered]") {
  // double-torus-example.off is quads (read_mesh triangulates and says so).
  Mesh mesh = test::load("double-torus-example.off");
  const std::size_t made = punch_holes(mesh, 3, 5);
  REQUIRE(made == 3);
  check_every_method(mesh, 2, 3, "double torus of quads, 3 holes");
}
