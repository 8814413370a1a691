// Checked mesh reading: every kind of bad input gives its own status and a message, never a crash.
#include "corpus.h"

#include <tessera/fields/color_regions.h>
#include <tessera/io.h>
#include <tessera/validation.h>

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <set>
#include <sstream>

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
  const Read_mesh_result r = read_mesh(data_path("bad/nan.off"), m);
  CHECK(!r);
  CHECK(r.message.find("nan.off") != std::string::npos);
  // A failed read leaves the mesh empty, whatever it held and wherever reading stopped: before
  // the file is opened, in the parser, and at the checks of what it holds.
  for (const char* file :
       {"bad/mesh.xyz", "bad/garbage.off", "bad/nan.off", "bad/non_manifold_edge.off"}) {
    REQUIRE(read_mesh(data_path("eight.off"), m));
    REQUIRE(num_faces(m) > 0);
    CHECK(!read_mesh(data_path(file), m));
    UNSCOPED_INFO(file);
    CHECK(num_vertices(m) == 0);
    CHECK(num_faces(m) == 0);
  }
}

TEST_CASE("inputs that crashed or exhausted CGAL's readers under fuzzing are refused", "[io]") {
  // Each was found by fuzz/ (doc/reliability.md); each allocated gigabytes or read out of bounds.
  Mesh m;
  for (const char* file :
       {"bad/off_huge_face.off", "bad/off_huge_header.off", "bad/off_header_overflow.off",
        "bad/off_header_overflow_halfedges.off", "bad/off_binary_header_overflow.off",
        "bad/off_negative_face.off", "bad/ply_property_first.ply", "bad/ply_huge_list.ply",
        "bad/ply_huge_list_bad_format_line.ply", "bad/ply_no_end_header.ply",
        "bad/ply_short_body.ply", "bad/ply_huge_element_count.ply",
        "bad/ply_unknown_count_type.ply"}) {
    const Read_mesh_result r = read_mesh(data_path(file), m);
    UNSCOPED_INFO(file << ": " << r.message);
    CHECK(r.status == Read_status::parse_error);
  }
  CHECK(read_mesh(data_path("bad/off_huge_face.off"), m).message.find("face 1 announces") !=
        std::string::npos);
  CHECK(read_mesh(data_path("bad/off_huge_header.off"), m).message.find("the header announces") !=
        std::string::npos);
  CHECK(read_mesh(data_path("bad/off_header_overflow.off"), m)
            .message.find("the header announces 4 vertices and 1227997983 faces") !=
        std::string::npos);
  // CGAL 5.5's header parser computes 2 * E and int((V + F + 10) * 2.1) from these (signed
  // overflow, out-of-range cast): the counts are checked before it runs.
  CHECK(read_mesh(data_path("bad/off_header_overflow_halfedges.off"), m)
            .message.find("and 1227997983 edges") != std::string::npos);
  CHECK(read_mesh(data_path("bad/off_binary_header_overflow.off"), m)
            .message.find("the header announces 3 vertices and 2000000000 faces") !=
        std::string::npos);
  CHECK(read_mesh(data_path("bad/ply_property_first.ply"), m).message.find("before any element") !=
        std::string::npos);
}

TEST_CASE("an ASCII COFF with colours on some lines only is read with its geometry", "[io]") {
  // Found by fuzz_read_off: CGAL 5.5 takes the first coloured line's layout for every later line
  // and read the colour of "1 0 0" (and of the uncoloured face) past the line's numbers. Under the
  // sanitizer build this case fails with a heap-buffer-overflow if the colours are looked up.
  const std::string path = output_path("ragged-colours.off");
  {
    std::ofstream out(path);
    out << "COFF\n4 4 0\n0 0 0 255 0 0\n1 0 0\n0 1 0 0.5 0.5 0.5 1\n0 0 1 7\n"
           "3 0 2 1 255 0 0\n3 0 1 3\n3 1 2 3 0 0 255\n3 0 3 2\n";
  }
  Mesh m;
  const Read_mesh_result r = read_mesh(path, m);
  INFO(r.message);
  REQUIRE(r);
  CHECK(m.number_of_vertices() == 4);
  CHECK(m.number_of_faces() == 4);
  CHECK(mesh_info(m).components.at(0).genus == 0);
  CHECK(m.point(Mesh::Vertex_index(2)) == Point_3(0, 1, 0));
  CHECK(m.point(Mesh::Vertex_index(3)) == Point_3(0, 0, 1));
  // The colour reader refuses the file's colours (not every line has one) without reading past.
  auto color = m.add_property_map<Mesh::Face_index, CGAL::IO::Color>("f:tessera_color").first;
  CHECK(read_face_colors(path, m, color).status == Color_regions_status::no_colors);
  // Every face coloured: integers, fractions, an index into the OFF colour map.
  {
    std::ofstream out(path);
    out << "COFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1 255 0 0\n3 0 1 3 1 0.5 0\n"
           "3 1 2 3 6\n3 0 3 2 0 0 255 255 # a comment\n";
  }
  Mesh c;
  REQUIRE(read_mesh(path, c));
  auto fc = c.add_property_map<Mesh::Face_index, CGAL::IO::Color>("f:tessera_color").first;
  const Color_regions_result r2 = read_face_colors(path, c, fc);
  INFO(r2.message);
  REQUIRE(r2);
  CHECK(r2.face_colors);
  CHECK(r2.regions == 4);
  std::set<std::array<int, 3>> seen;
  for (auto f : faces(c))
    seen.insert({{fc[f].red(), fc[f].green(), fc[f].blue()}});
  CHECK(seen == std::set<std::array<int, 3>>{
                    {{255, 0, 0}}, {{255, 127, 0}}, {{178, 38, 25}}, {{0, 0, 255}}});
  // An index past the colour map (CGAL 5.5 reads past its 149 entries) is no colour.
  {
    std::ofstream out(path);
    out << "COFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1 1000\n3 0 1 3 1\n"
           "3 1 2 3 2\n3 0 3 2 3\n";
  }
  CHECK(read_face_colors(path, c, fc).status == Color_regions_status::no_colors);
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

TEST_CASE("coordinates are written as the shortest text that reads back to the same double",
          "[io]") {
  std::ostringstream text;
  internal::write_shortest_doubles(text);
  text << 0.1 << ' ' << 1.0 / 3 << ' ' << -0.0 << ' ' << 1e-310 << ' ' << 123456789.0;
  CHECK(text.str() == "0.1 0.3333333333333333 -0 1e-310 123456789");
  // Other requests are formatted as the standard facet does.
  std::ostringstream fixed;
  internal::write_shortest_doubles(fixed);
  fixed << std::fixed << std::setprecision(3) << 0.1 << ' ' << std::defaultfloat
        << std::setprecision(17) << std::setw(6) << 0.5;
  CHECK(fixed.str() == "0.100    0.5");

  // Every coordinate of a sphere moved off round values comes back bit for bit, from OFF and OBJ.
  Mesh sphere;
  make_sphere(sphere, 1.0, 2);
  std::size_t i = 0;
  for (auto v : vertices(sphere)) {
    const Point_3 p = sphere.point(v);
    const double s = 1 + std::ldexp(double(++i % 97), -40) / 3;
    sphere.point(v) = Point_3(p.x() * s, p.y() / s, p.z() * s * s);
  }
  std::multiset<std::array<double, 3>> written;
  for (auto v : vertices(sphere))
    written.insert({sphere.point(v).x(), sphere.point(v).y(), sphere.point(v).z()});
  for (const std::string ext : {".off", ".obj"}) {
    const std::string path = output_path("shortest" + ext);
    REQUIRE(write_mesh(path, sphere));
    Mesh back;
    REQUIRE(read_mesh(path, back));
    std::multiset<std::array<double, 3>> read;
    for (auto v : vertices(back))
      read.insert({back.point(v).x(), back.point(v).y(), back.point(v).z()});
    CHECK(read == written);
  }
}

namespace {

// The faces of `m` as a soup with the file's vertex ids, for writing deliberately broken files.
struct Soup {
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t>> faces;
  explicit Soup(const Mesh& m) {
    for (auto v : m.vertices())
      points.push_back(m.point(v));
    for (auto f : m.faces()) {
      faces.emplace_back();
      for (auto v : CGAL::vertices_around_face(m.halfedge(f), m))
        faces.back().push_back(v.idx());
    }
  }
  std::string write_off(const std::string& name) const {
    const std::string path = output_path(name);
    std::ofstream out(path);
    out.precision(17);
    out << "OFF\n" << points.size() << " " << faces.size() << " 0\n";
    for (const auto& p : points)
      out << p << "\n";
    for (const auto& f : faces) {
      out << f.size();
      for (std::size_t v : f)
        out << " " << v;
      out << "\n";
    }
    return path;
  }
};

Mesh_info read_info(const std::string& path, Read_mesh_result& r,
                    Mesh_repair repair = Mesh_repair::safe) {
  Mesh m;
  Read_mesh_options options;
  options.repair = repair;
  r = read_mesh(path, m, options);
  UNSCOPED_INFO(r.message);
  return mesh_info(m);
}

} // namespace

TEST_CASE("a face listed twice, in either orientation, is dropped, and --strict refuses it",
          "[io]") {
  const std::string path = output_path("double_face.off");
  std::ofstream(path) << "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 2 1\n3 0 1 3\n";
  Read_mesh_result r;
  const Mesh_info info = read_info(path, r);
  REQUIRE(r);
  CHECK(r.changes.removed_faces == 1);
  CHECK(info.faces == 2);
  read_info(path, r, Mesh_repair::none);
  CHECK(r.status == Read_status::needs_repair);
}

TEST_CASE("a pinched vertex is split by default and named with --strict", "[io]") {
  Read_mesh_result r;
  const Mesh_info info = read_info(data_path("bad/pinched_vertex.off"), r);
  REQUIRE(r);
  CHECK(r.changes.pinched_vertices == 1);
  CHECK(info.vertices == 6); // the two fans no longer share a vertex
  CHECK(info.components.size() == 2);
  read_info(data_path("bad/pinched_vertex.off"), r, Mesh_repair::none);
  CHECK(r.status == Read_status::needs_repair);
  CHECK(r.message.find("pinched at vertex") != std::string::npos);
}

TEST_CASE("an edge of three faces is refused with its place, and split on request", "[io]") {
  Read_mesh_result r;
  read_info(data_path("bad/non_manifold_edge.off"), r);
  CHECK(r.status == Read_status::non_manifold);
  CHECK(r.message.find("1 edge is shared by more than two faces") != std::string::npos);
  CHECK(r.message.find("vertex 1 at (1 0 0)") != std::string::npos);
  const Mesh_info info = read_info(data_path("bad/non_manifold_edge.off"), r, Mesh_repair::all);
  REQUIRE(r);
  CHECK(r.changes.non_manifold_edges == 1);
  CHECK(info.is_valid_polygon_mesh);
  CHECK(info.faces == 3);
}

TEST_CASE("two face lines joined into one are split back, in bounded time", "[io]") {
  Mesh sphere;
  make_sphere(sphere, 1.0, 1);
  Soup soup(sphere);
  // A fuzzer's one-token edit: face 10 and a face sharing a vertex with it on one line, a hexagon
  // through that vertex twice.
  auto& joined = soup.faces[10];
  std::size_t other = 11;
  auto shares = [&](std::size_t f) {
    return std::find_first_of(soup.faces[f].begin(), soup.faces[f].end(), joined.begin(),
                              joined.end()) != soup.faces[f].end();
  };
  while (!shares(other))
    ++other;
  const auto next = soup.faces[other];
  const std::size_t shared =
      *std::find_first_of(next.begin(), next.end(), joined.begin(), joined.end());
  std::rotate(joined.begin(), std::find(joined.begin(), joined.end(), shared), joined.end());
  std::vector<std::size_t> tail(next);
  std::rotate(tail.begin(), std::find(tail.begin(), tail.end(), shared), tail.end());
  joined.insert(joined.end(), tail.begin(), tail.end());
  soup.faces.erase(soup.faces.begin() + long(other));
  Read_mesh_result r;
  const Mesh_info info = read_info(soup.write_off("joined_faces.off"), r);
  REQUIRE(r);
  CHECK(r.changes.split_faces == 1);
  CHECK(r.triangulated_faces == 0);
  CHECK(info.faces == num_faces(sphere));
  CHECK(info.components.at(0).genus == 0);
  CHECK(info.is_closed);
}

TEST_CASE("inconsistent orientation, duplicated points, unused vertices are repaired and counted",
          "[io]") {
  Mesh sphere;
  make_sphere(sphere, 1.0, 1);
  const double area = mesh_info(sphere).area;
  Soup soup(sphere);
  for (std::size_t f = 5; f < 25; f += 2)
    std::reverse(soup.faces[f].begin(), soup.faces[f].end());
  Read_mesh_result r;
  Mesh_info info = read_info(soup.write_off("flipped.off"), r);
  REQUIRE(r);
  CHECK(r.changes.reoriented_faces == 10);
  CHECK(info.is_closed);

  // Every face with its own three points (a soup as STL stores it) and one point no face uses.
  Soup split(sphere);
  split.points.clear();
  for (auto& f : split.faces)
    for (auto& v : f) {
      split.points.push_back(sphere.point(Mesh::Vertex_index(std::uint32_t(v))));
      v = split.points.size() - 1;
    }
  split.points.emplace_back(5, 5, 5);
  info = read_info(split.write_off("split_points.off"), r);
  REQUIRE(r);
  CHECK(r.changes.merged_vertices == 3 * num_faces(sphere) - num_vertices(sphere));
  CHECK(r.changes.removed_vertices == 1);
  CHECK(info.vertices == num_vertices(sphere));
  CHECK(info.is_closed);
  CHECK(info.area == Approx(area).epsilon(1e-12));

  // A clean file is read as it is, with its vertex ids.
  read_info(Soup(sphere).write_off("clean.off"), r);
  CHECK(!r.changes.any());
}
