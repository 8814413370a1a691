// Rendering writes real pictures: the PNG exists, has the requested size, and shows the mesh's
// colours where the mesh is.
#include "corpus.h"

#include <tessera/render.h>

#include <catch2/catch.hpp>

#include <cairo.h>

using namespace tessera;

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
}
