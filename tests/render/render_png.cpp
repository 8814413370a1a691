// Rendering writes real pictures: the PNG exists, has the requested size, and shows the mesh's
// colours where the mesh is; nearer faces hide farther ones per pixel (also where faces cross),
// lines show only where no face is in front of them, and small faces tile their area without gaps.
#include "corpus.h"

#include <tessera/render.h>

#include <catch2/catch.hpp>

#include <cairo.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

using namespace tessera;

namespace {

// The pixels of a PNG as RGB triples, row by row.
struct Picture {
  int width = 0, height = 0;
  std::vector<std::array<int, 3>> rgb;
  std::array<int, 3> at(int x, int y) const { return rgb[std::size_t(y) * width + x]; }
};

Picture read_picture(const std::string& path) {
  Picture p;
  cairo_surface_t* img = cairo_image_surface_create_from_png(path.c_str());
  REQUIRE(cairo_surface_status(img) == CAIRO_STATUS_SUCCESS);
  p.width = cairo_image_surface_get_width(img);
  p.height = cairo_image_surface_get_height(img);
  const unsigned char* data = cairo_image_surface_get_data(img);
  const int stride = cairo_image_surface_get_stride(img);
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) { // ARGB32 little-endian: B, G, R, A
      const unsigned char* q = data + y * stride + 4 * x;
      p.rgb.push_back({{q[2], q[1], q[0]}});
    }
  cairo_surface_destroy(img);
  return p;
}

bool reddish(const std::array<int, 3>& c) {
  return c[0] > 60 && c[1] < 10 && c[2] < 10;
}
bool bluish(const std::array<int, 3>& c) {
  return c[2] > 60 && c[0] < 10 && c[1] < 10;
}
bool greenish(const std::array<int, 3>& c) {
  return c[1] > 60 && c[0] < 10 && c[2] < 10;
}

// A square seen from +z: screen x is world x and screen y is world y, upwards.
Render_options looking_down(int size) {
  Render_options o;
  o.width = o.height = size;
  o.eye_direction = {{0, 0, 1}};
  o.up = {{0, 1, 0}};
  o.edges = Edge_drawing::never;
  return o;
}

// Appends the quadrilateral a, b, c, d as two triangles of one colour.
void add_quad(Render_scene& scene, const std::array<std::array<double, 3>, 4>& corners,
              const Color& colour) {
  const std::size_t first = scene.positions.size();
  for (const auto& p : corners)
    scene.positions.push_back(p);
  scene.triangles.push_back({{first, first + 1, first + 2}});
  scene.triangles.push_back({{first, first + 2, first + 3}});
  scene.triangle_colors.push_back(colour);
  scene.triangle_colors.push_back(colour);
}

} // namespace

TEST_CASE("a rendered mesh covers the middle of the picture in its colour", "[render]") {
  Mesh sphere;
  make_sphere(sphere, 1.0, 3);
  Render_scene scene;
  add_mesh(scene, sphere, Color{1.0, 0.0, 0.0});
  Render_options options;
  options.width = 200;
  options.height = 100;
  const std::string path = test::output_path("sphere.png");
  REQUIRE(render_png(scene, path, options));

  cairo_surface_t* img = cairo_image_surface_create_from_png(path.c_str());
  REQUIRE(cairo_surface_status(img) == CAIRO_STATUS_SUCCESS);
  CHECK(cairo_image_surface_get_width(img) == 200);
  CHECK(cairo_image_surface_get_height(img) == 100);
  const unsigned char* data = cairo_image_surface_get_data(img);
  const int stride = cairo_image_surface_get_stride(img);
  auto pixel = [&](int x, int y) { // ARGB32 little-endian: B, G, R, A
    const unsigned char* p = data + y * stride + 4 * x;
    return std::array<int, 3>{{p[2], p[1], p[0]}};
  };
  const auto centre = pixel(100, 50);
  CHECK(centre[0] > 60);
  CHECK(centre[1] < 10);
  CHECK(centre[2] < 10);
  const auto corner = pixel(2, 2);
  CHECK(corner == std::array<int, 3>{{255, 255, 255}});
  cairo_surface_destroy(img);
}

TEST_CASE("render_png reports bad scenes and unwritable paths", "[render]") {
  Render_scene empty;
  CHECK(render_png(empty, test::output_path("x.png")).status == Render_status::empty_scene);
  Render_scene bad;
  bad.positions = {{{0, 0, 0}}};
  bad.triangles = {{{0, 1, 2}}};
  CHECK(render_png(bad, test::output_path("x.png")).status == Render_status::invalid_scene);
  Mesh sphere;
  make_sphere(sphere, 1.0, 1);
  Render_scene ok;
  add_mesh(ok, sphere);
  CHECK(render_png(ok, "/nonexistent-dir/x.png").status == Render_status::write_failed);
  // Finite coordinates so large that the view's arithmetic overflows (1e308: the projections are
  // NaN) or squeezes the rest into a point (1e300): a picture, and no integer conversion of a
  // NaN or out-of-range value (the sanitizer build's UBSan checks those).
  for (const double big : {1e300, 1e308}) {
    Render_scene huge = ok;
    const std::size_t n = huge.positions.size();
    huge.positions.push_back({{big, -big, big}});
    huge.positions.push_back({{-big, big, big}});
    huge.triangles.push_back({{0, n, n + 1}});
    huge.triangle_colors.push_back(Color{});
    Render_polyline line;
    line.points = {{{0, 0, 0}}, {{big, big, -big}}};
    huge.polylines.push_back(line);
    huge.points.push_back(Render_point{{{-big, -big, -big}}});
    CHECK(render_png(huge, test::output_path("huge.png")));
  }
}

TEST_CASE("render_png hides farther faces per pixel, also where two faces cross", "[render]") {
  // Two squares crossing along x = 0: the red one rises towards +x (z = x), the blue one towards -x
  // (z = -x). Seen from +z, blue is in front on the left and red on the right. Their centroids are
  // at the same depth, so no order of whole triangles can draw both halves right.
  for (const bool red_first : {true, false}) {
    Render_scene scene;
    const std::array<std::array<double, 3>, 4> red{
        {{{-1, -1, -1}}, {{1, -1, 1}}, {{1, 1, 1}}, {{-1, 1, -1}}}};
    const std::array<std::array<double, 3>, 4> blue{
        {{{-1, -1, 1}}, {{1, -1, -1}}, {{1, 1, -1}}, {{-1, 1, 1}}}};
    add_quad(scene, red_first ? red : blue, red_first ? Color{1, 0, 0} : Color{0, 0, 1});
    add_quad(scene, red_first ? blue : red, red_first ? Color{0, 0, 1} : Color{1, 0, 0});
    const std::string path = test::output_path("crossing.png");
    REQUIRE(render_png(scene, path, looking_down(200)));
    const Picture p = read_picture(path);
    REQUIRE(p.width == 200);
    for (int y : {40, 100, 160}) {
      CHECK(bluish(p.at(30, y)));
      CHECK(bluish(p.at(80, y)));
      CHECK(reddish(p.at(120, y)));
      CHECK(reddish(p.at(170, y)));
    }
  }
}

TEST_CASE("render_png draws lines where no face is in front of them", "[render]") {
  // A grey square at z = 0; a blue line in front of it, a green line on it, a red line behind it.
  Render_scene scene;
  add_quad(scene, {{{{-1, -1, 0}}, {{1, -1, 0}}, {{1, 1, 0}}, {{-1, 1, 0}}}}, Color{0.5, 0.5, 0.5});
  auto line = [&](double y, double z, const Color& colour) {
    Render_polyline l;
    l.points = {{{-0.8, y, z}}, {{0.8, y, z}}};
    l.color = colour;
    l.width = 4;
    scene.polylines.push_back(l);
  };
  line(0.5, 0.5, Color{0, 0, 1});
  line(0.0, 0.0, Color{0, 1, 0});
  line(-0.5, -0.5, Color{1, 0, 0});
  const std::string path = test::output_path("lines.png");
  REQUIRE(render_png(scene, path, looking_down(200)));
  const Picture p = read_picture(path);
  // World y = 0.5, 0 and -0.5 fall on rows 56, 100 and 144 (the square fills 88% of the picture).
  for (int x : {40, 100, 160}) {
    CHECK(bluish(p.at(x, 56)));
    CHECK(greenish(p.at(x, 100)));
    const auto hidden = p.at(x, 144);
    CHECK(hidden[0] == hidden[1]); // the grey square, not the red line
    CHECK(hidden[1] == hidden[2]);
  }
}

TEST_CASE("render_png lets a lifted face win over the coplanar face under it", "[render]") {
  // A mosaic tile lies on its grout: with triangle_depth_bias it is drawn over it in either order.
  for (const bool tile_first : {true, false}) {
    Render_scene scene;
    const std::array<std::array<double, 3>, 4> grout{
        {{{-1, -1, 0}}, {{1, -1, 0}}, {{1, 1, 0}}, {{-1, 1, 0}}}};
    const std::array<std::array<double, 3>, 4> tile{
        {{{-0.5, -0.5, 0}}, {{0.5, -0.5, 0}}, {{0.5, 0.5, 0}}, {{-0.5, 0.5, 0}}}};
    add_quad(scene, tile_first ? tile : grout, tile_first ? Color{1, 0, 0} : Color{0, 0, 1});
    add_quad(scene, tile_first ? grout : tile, tile_first ? Color{0, 0, 1} : Color{1, 0, 0});
    scene.triangle_depth_bias =
        tile_first ? std::vector<double>{0.01, 0.01, 0, 0} : std::vector<double>{0, 0, 0.01, 0.01};
    const std::string path = test::output_path("lifted.png");
    REQUIRE(render_png(scene, path, looking_down(100)));
    const Picture p = read_picture(path);
    CHECK(reddish(p.at(50, 50)));
    CHECK(bluish(p.at(10, 50)));
  }
}

TEST_CASE("render_png covers a surface of many small faces without gaps", "[render]") {
  // 2 x 160 x 160 triangles of about a pixel each (at the supersampled size: 1.1 pixels across)
  // over a red square: every pixel inside it is red, none shows the white background.
  Render_scene scene;
  const int n = 160;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      scene.positions.push_back({{-1 + 2.0 * i / n, -1 + 2.0 * j / n, 0.05 * std::sin(i + j)}});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::size_t a = std::size_t(j) * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      scene.triangles.push_back({{a, b, d}});
      scene.triangles.push_back({{a, d, c}});
    }
  scene.triangle_colors.assign(scene.triangles.size(), Color{1, 0, 0});
  const std::string path = test::output_path("small_faces.png");
  REQUIRE(render_png(scene, path, looking_down(100)));
  const Picture p = read_picture(path);
  std::size_t red = 0;
  for (int y = 8; y < 92; ++y)
    for (int x = 8; x < 92; ++x)
      red += reddish(p.at(x, y)) ? 1 : 0;
  CHECK(red == std::size_t(84 * 84));
}
