// Checked mesh reading: every kind of bad input gives its own status and a message, never a crash.
#include "corpus.h"

#include <tessera/io.h>
#include <tessera/validation.h>

#include <catch2/catch.hpp>

#include <cstdio>
#include <fstream>

using namespace tessera;
using tessera::test::data_path;
using tessera::test::output_path;

TEST_CASE("read_mesh rejects each kind of bad input with its own status", "[io]") {
  Mesh m;
  CHECK(read_mesh(data_path("bad/does_not_exist.off"), m).status == Read_status::file_not_found);
  CHECK(read_mesh(data_path("bad/empty.off"), m).status == Read_status::empty_file);
  CHECK(read_mesh(data_path("bad/garbage.off"), m).status == Read_status::parse_error);
  CHECK(read_mesh(data_path("bad/nan.off"), m).status == Read_status::non_finite_coordinates);
  CHECK(read_mesh(data_path("bad/mesh.xyz"), m).status == Read_status::unsupported_extension);
  CHECK(read_mesh(data_path("bad/non_manifold_edge.off"), m).status == Read_status::non_manifold);
  CHECK(read_mesh(data_path("bad/pinched_vertex.off"), m).status == Read_status::non_manifold);
  const Read_mesh_result r = read_mesh(data_path("bad/nan.off"), m);
  CHECK(!r);
  CHECK(r.message.find("nan.off") != std::string::npos);
}

TEST_CASE("polygonal input is triangulated and reported", "[io]") {
  Mesh m;
  const Read_mesh_result r = read_mesh(data_path("double-torus-example.off"), m);
  REQUIRE(r);
  CHECK(r.triangulated_faces == 220);
  CHECK(CGAL::is_triangle_mesh(m));
  CHECK(mesh_info(m).components.at(0).genus == 2);

  Read_mesh_options strict;
  strict.triangulate = false;
  CHECK(read_mesh(data_path("double-torus-example.off"), m, strict).status ==
        Read_status::invalid_face);
}

TEST_CASE("a mesh survives a write and read in every format", "[io]") {
  Mesh sphere;
  make_sphere(sphere, 1.0, 2);
  for (const std::string ext : {".off", ".obj", ".ply", ".stl"}) {
    const std::string path = output_path("roundtrip" + ext);
    REQUIRE(write_mesh(path, sphere));
    Mesh back;
    const Read_mesh_result r = read_mesh(path, back);
    INFO(ext << ": " << r.message);
    REQUIRE(r);
    CHECK(num_vertices(back) == num_vertices(sphere));
    CHECK(num_faces(back) == num_faces(sphere));
    // STL stores single-precision floats; the other formats are written with 17 digits.
    const double tolerance = ext == ".stl" ? 1e-6 : 1e-12;
    CHECK(mesh_info(back).area == Approx(mesh_info(sphere).area).epsilon(tolerance));
  }
  CHECK_FALSE(write_mesh(output_path("roundtrip.xyz"), sphere));
}

TEST_CASE("an OFF file with a face listed twice in opposite orientation is non-manifold", "[io]") {
  const std::string path = output_path("double_face.off");
  std::ofstream(path) << "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 2 1\n3 0 1 3\n";
  Mesh m;
  CHECK(read_mesh(path, m).status == Read_status::non_manifold);
}
