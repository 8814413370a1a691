// Tests of tessera/view: the page's content for a hand-made scene, and scenes read from result
// directories written by hand (the pages in Chromium are tests/view/check_view.py's, run by ctest).
#include <tessera/view.h>

#include "paths.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

namespace {

namespace fs = std::filesystem;

std::string fresh_directory(const std::string& name) {
  const std::string dir = tessera::test::output_path(name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write_file(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}

// A unit square of two triangles, cut nowhere: a disk whose only polygon is the square itself.
const char* const square_off = "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n";

} // namespace

TEST_CASE("view_html inlines three.js, the geometry as base64 and the sources", "[view]") {
  tessera::View_scene scene;
  scene.title = "a <title>";
  scene.kind = "cut";
  scene.sources = {"dir/mesh.off"};
  tessera::View_mesh_layer mesh;
  mesh.name = "surface";
  mesh.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  mesh.triangles = {0, 1, 2};
  scene.meshes.push_back(mesh);
  const std::string page = tessera::view_html(scene);
  CHECK(page.find("<script type=\"importmap\">") != std::string::npos);
  CHECK(page.find("data:text/javascript;base64,") != std::string::npos);
  // Three float32 points: 36 bytes, 48 base64 characters; (1, 0, 0) starts at byte 12.
  CHECK(page.find("\"positions\":\"AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA\"") !=
        std::string::npos);
  CHECK(page.find("\"triangles\":\"AAAAAAEAAAACAAAA\"") != std::string::npos);
  CHECK(page.find("a &lt;title&gt;") != std::string::npos);
  CHECK(page.find("dir/mesh.off") != std::string::npos);
  CHECK(page.find("Tessera " + tessera::tessera_version()) != std::string::npos);
  CHECK(page.find("id=\"tessera-summary\"") != std::string::npos);
  CHECK(page.find("http://") == std::string::npos);
  CHECK(page.find("https://") == std::string::npos);
}

TEST_CASE("read_view_scene reads a cut directory: surface, seams, corners", "[view]") {
  const std::string dir = fresh_directory("view_cut");
  write_file(dir + "/mesh.off", square_off);
  // Opened along the diagonal 0-2: the second triangle gets its own copies 4 (of 0) and 5 (of 2).
  write_file(dir + "/opened.off",
             "OFF\n6 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 0\n1 1 0\n3 0 1 2\n3 4 5 3\n");
  write_file(
      dir + "/result.json",
      R"({"method": "greedy", "opened_to_mesh_vertex": [0, 1, 2, 3, 0, 2], "multipoints": [0, 2]})");
  const tessera::View_scene_result r = tessera::read_view_scene(dir);
  REQUIRE(r);
  CHECK(r.scene.kind == "cut");
  REQUIRE(r.scene.meshes.size() == 1);
  CHECK(r.scene.meshes[0].triangles.size() == 6);
  CHECK(r.scene.meshes[0].positions.size() == 12);
  REQUIRE(r.scene.segments.size() == 1);
  CHECK(r.scene.segments[0].name == "seams");
  CHECK(r.scene.segments[0].segments.size() == 6); // the diagonal, once
  REQUIRE(r.scene.points.size() == 1);
  CHECK(r.scene.points[0].positions.size() == 6);
  CHECK(r.scene.points[0].labels[1] == "vertex 2");
}

TEST_CASE("read_view_scene reads a mosaic's tiles with their colours", "[view]") {
  const std::string dir = fresh_directory("view_mosaic");
  write_file(dir + "/tiles.ply", "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\n"
                                 "property float y\nproperty float z\nelement face 2\n"
                                 "property list uchar int vertex_indices\nproperty uchar red\n"
                                 "property uchar green\nproperty uchar blue\nend_header\n"
                                 "0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 2 0\n4 0 1 2 3 10 20 30\n"
                                 "3 1 4 2 40 50 60\n");
  write_file(dir + "/tiles.json", R"({"tiles": [{"face": 3, "region": 1, "size": [1, 1]},
                                                {"face": 4, "region": 0, "size": [1, 1]}]})");
  write_file(dir + "/report.json", R"({"mesh": "no/such/mesh.off"})");
  const tessera::View_scene_result r = tessera::read_view_scene(dir);
  REQUIRE(r);
  CHECK(r.scene.kind == "mosaic");
  REQUIRE(r.scene.meshes.size() == 1); // the input mesh does not open from here: tiles only
  const tessera::View_mesh_layer& tiles = r.scene.meshes[0];
  CHECK(tiles.element_kind == "tile");
  CHECK(tiles.triangles.size() == 9); // a quad fanned into two triangles, and a triangle
  CHECK(tiles.element_ids == std::vector<std::uint32_t>{0, 0, 1});
  CHECK(tiles.triangle_colours == std::vector<std::uint8_t>{10, 20, 30, 10, 20, 30, 40, 50, 60});
  REQUIRE(tiles.element_figures.size() == 2);
  CHECK(tiles.element_figures[1].find("face 4, region 0") == 0);
}

TEST_CASE("read_view_scene reads a planar mosaic: a flat scene of tiles in their shapes",
          "[view]") {
  const std::string dir = fresh_directory("view_planar");
  // A 4 x 2 tile at (10, 20) turned by 90 degrees, and a 2 x 2 one; the image does not open.
  write_file(dir + "/tiles.json", R"({"units": "pixels; angle in radians", "tiles": [
    {"center": [10, 20], "angle": 1.5707963267948966, "width": 4, "height": 2,
     "color": [10, 20, 30], "region": 0},
    {"center": [3, 3], "angle": 0, "width": 2, "height": 2, "color": [40, 50, 60], "region": 1}]})");
  const std::string report = R"({"image": {"path": "no/such/image.png", "width": 40,
    "height": 30}, "options": {"shape": "SHAPE"}})";
  write_file(dir + "/report.json", std::string(report).replace(report.find("SHAPE"), 5, "rect"));
  tessera::View_scene_result r = tessera::read_view_scene(dir);
  REQUIRE(r);
  CHECK(r.scene.kind == "planar-mosaic");
  CHECK(r.scene.flat);
  REQUIRE(r.scene.meshes.size() == 1); // no image, no field.png: the tiles only
  const tessera::View_mesh_layer& tiles = r.scene.meshes[0];
  CHECK(tiles.element_kind == "tile");
  CHECK_FALSE(tiles.lit);
  CHECK_FALSE(tiles.hover_vertex);
  CHECK(tiles.triangles.size() == 12);
  CHECK(tiles.element_ids == std::vector<std::uint32_t>{0, 0, 1, 1});
  CHECK(tiles.triangle_colours ==
        std::vector<std::uint8_t>{10, 20, 30, 10, 20, 30, 40, 50, 60, 40, 50, 60});
  // Turned by 90 degrees, the width runs down the image: corner (-2, -1) of the tile's frame is
  // the pixel point (11, 18), drawn with y up.
  REQUIRE(tiles.positions.size() == 24);
  CHECK(tiles.positions[0] == Approx(11));
  CHECK(tiles.positions[1] == Approx(-18));
  REQUIRE(tiles.element_figures.size() == 2);
  CHECK(tiles.element_figures[0].find("colour 10, 20, 30, size 4 x 2 px, angle 90°, centre (10, "
                                      "20) px, region 0") == 0);

  write_file(dir + "/report.json", std::string(report).replace(report.find("SHAPE"), 5, "ellipse"));
  r = tessera::read_view_scene(dir);
  REQUIRE(r);
  CHECK(r.scene.meshes[0].triangles.size() == 2 * 24 * 3); // a fan of 24 triangles a tile

  write_file(dir + "/tiles.json", R"({"units": "pixels", "tiles": [{"center": [1, 2]}]})");
  r = tessera::read_view_scene(dir);
  CHECK(r.status == tessera::View_status::bad_file);
  CHECK(r.message.find("tiles.json") != std::string::npos);
}

TEST_CASE("read_view_scene reads a check report: the surface and its problems", "[view]") {
  const std::string dir = fresh_directory("view_check");
  write_file(dir + "/square.off", square_off);
  const std::string report = dir + "/report.json";
  write_file(report, R"({"form": "seam file", "input": ")" + dir + R"(/square.off", "problems": [
    {"check": "charts", "kind": "not_a_disk", "message": "m", "vertices": [2], "faces": [1]}],
    "notes": []})");
  const tessera::View_scene_result r = tessera::read_view_scene(report);
  REQUIRE(r);
  CHECK(r.scene.kind == "check");
  REQUIRE(r.scene.meshes.size() == 1);
  CHECK(r.scene.meshes[0].name == "charts");
  CHECK(r.scene.meshes[0].triangles.size() == 6);
  REQUIRE(r.scene.points.size() == 2);
  const tessera::View_point_layer& problems = r.scene.points[0];
  CHECK(problems.name == "problems");
  CHECK(problems.labels == std::vector<std::string>{"not_a_disk: vertex 2", "not_a_disk: face 1"});
  REQUIRE(problems.positions.size() == 6);
  CHECK(problems.positions[0] == 1.0f);             // vertex 2 is (1, 1, 0)
  CHECK(problems.positions[4] == Approx(2.0f / 3)); // face 1's centroid is (1/3, 2/3, 0)
  CHECK(r.scene.points[1].positions.empty());

  write_file(report, R"({"form": "seam file", "input": ")" + dir + R"(/square.off", "problems": [
    {"check": "charts", "kind": "not_a_disk", "message": "m", "vertices": [9], "faces": []}]})");
  const tessera::View_scene_result bad = tessera::read_view_scene(report);
  CHECK(bad.status == tessera::View_status::bad_file);
  CHECK(bad.message.find("vertex 9") != std::string::npos);
}

TEST_CASE("read_view_scene refuses a missing, an unknown and a broken result", "[view]") {
  CHECK(tessera::read_view_scene(tessera::test::output_path("view_no_such_dir")).status ==
        tessera::View_status::not_found);
  const std::string empty = fresh_directory("view_empty");
  CHECK(tessera::read_view_scene(empty).status == tessera::View_status::unknown_result_kind);
  const std::string broken = fresh_directory("view_broken");
  write_file(broken + "/mesh.off", square_off);
  write_file(broken + "/opened.off", square_off);
  write_file(broken + "/result.json", "{not json");
  const tessera::View_scene_result r = tessera::read_view_scene(broken);
  CHECK(r.status == tessera::View_status::bad_file);
  CHECK(r.message.find("result.json") != std::string::npos);
  CHECK(r.scene.meshes.empty());
}

TEST_CASE("write_view_html reports a page it cannot write", "[view]") {
  const tessera::View_result r =
      tessera::write_view_html({}, tessera::test::output_path("view_no_such_dir/view.html"));
  CHECK(r.status == tessera::View_status::cannot_write);
  CHECK(r.message.find("cannot write") == 0);
}
