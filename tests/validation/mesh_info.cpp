// Invariants of the corpus: generated surfaces have the genus, boundary count and area they were
// built with; the real meshes have the genus and boundaries published with them.
#include "corpus.h"

#include <tessera/validation.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace tessera;

TEST_CASE("generated surfaces have the requested genus and boundaries",
          "[validation][generators]") {
  for (const auto& e : test::generated_corpus(5, 3)) {
    INFO(e.name);
    const Mesh_info info = mesh_info(e.mesh, {false});
    REQUIRE(info.components.size() == 1);
    CHECK(info.is_valid_polygon_mesh);
    CHECK(info.is_triangle_mesh);
    CHECK(info.components[0].genus == e.genus);
    CHECK(info.boundary_loops == e.boundaries);
    CHECK(info.euler_characteristic == 2 - 2 * e.genus - long(e.boundaries));
  }
}

TEST_CASE("the genus surface face count formula matches the generator", "[generators]") {
  for (std::size_t g : {0u, 1u, 3u}) {
    Genus_surface_options o;
    o.cell_resolution = 2;
    o.wall_resolution = 3;
    o.subdivision_steps = 1;
    Mesh m;
    make_genus_surface(m, g, o);
    CHECK(num_faces(m) == genus_surface_face_count(g, o));
  }
}

TEST_CASE("real meshes have their published genus and boundaries", "[validation]") {
  for (const auto& e : test::real_corpus()) {
    INFO(e.name);
    const Mesh_info info = mesh_info(e.mesh, {false});
    REQUIRE(info.components.size() == 1);
    CHECK(info.components[0].genus == e.genus);
    CHECK(info.boundary_loops == e.boundaries);
  }
}

TEST_CASE("torus and sphere areas converge to the analytic values", "[validation][generators]") {
  const double pi = std::acos(-1.0);
  Mesh torus;
  make_torus(torus, 3.0, 1.0, 200, 100);
  const Mesh_info t = mesh_info(torus, {false});
  CHECK(t.components.at(0).genus == 1);
  CHECK(t.area == Approx(4 * pi * pi * 3.0 * 1.0).epsilon(2e-3));

  Mesh sphere;
  make_sphere(sphere, 2.0, 5);
  const Mesh_info s = mesh_info(sphere, {false});
  CHECK(s.components.at(0).genus == 0);
  CHECK(num_faces(sphere) == 20u * 1024u);
  CHECK(s.area == Approx(4 * pi * 4.0).epsilon(2e-3));
  CHECK(s.bbox_max[0] == Approx(2.0).epsilon(1e-9));
}

TEST_CASE("several components and self-intersection are reported", "[validation]") {
  Mesh a, b;
  make_sphere(a, 1.0, 1);
  make_torus(b, 3.0, 1.0, 24, 12);
  a.join(b);
  Mesh_info info = mesh_info(a);
  REQUIRE(info.components.size() == 2);
  CHECK(info.components[0].genus + info.components[1].genus == 1);
  CHECK_FALSE(info.self_intersects);

  Mesh c, d;
  make_sphere(c, 1.0, 1);
  make_sphere(d, 1.0, 1);
  for (auto v : vertices(d))
    d.point(v) = d.point(v) + Vector_3(0.5, 0, 0);
  c.join(d);
  info = mesh_info(c);
  CHECK(info.self_intersection_checked);
  CHECK(info.self_intersects);
}
