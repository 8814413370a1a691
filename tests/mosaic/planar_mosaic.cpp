// Planar decorative mosaics: the Voronoi labelling against brute force, regular grids under a
// constant field, edge avoidance, region sizes, the energy, determinism, bad images, and the
// field picture.
#include "paths.h"

#include <tessera/io/image.h>
#include <tessera/mosaic/draw_planar_mosaic.h>
#include <tessera/mosaic/planar_field.h>
#include <tessera/mosaic/planar_mosaic.h>
#include <tessera/mosaic/planar_quality.h>
#include <tessera/mosaic/planar_voronoi.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>

using namespace tessera;

namespace {

std::vector<Planar_site> random_sites(int w, int h, std::size_t n, unsigned seed, bool vary) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> ux(0, w - 1), uy(0, h - 1), angle(-M_PI, M_PI),
      scale(0.7, 1.4);
  std::vector<Planar_site> sites;
  for (std::size_t i = 0; i < n; ++i)
    sites.push_back({ux(rng), uy(rng), vary ? angle(rng) : 0.3, vary ? scale(rng) : 1.0});
  return sites;
}

// Nearest site by brute force, and the gap to the second nearest.
std::pair<int, double> brute_nearest(const std::vector<Planar_site>& sites, double beta, int x,
                                     int y) {
  double d1 = 1e300, d2 = 1e300;
  int best = -1;
  for (std::size_t i = 0; i < sites.size(); ++i) {
    const double d = planar_site_distance(sites[i], beta, x, y);
    if (d < d1)
      d2 = d1, d1 = d, best = int(i);
    else if (d < d2)
      d2 = d;
  }
  return {best, d2 - d1};
}

Rgb_image gradient_image(int w, int h) {
  Rgb_image image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      image.set(x, y, {{std::uint8_t(255 * x / w), std::uint8_t(255 * y / h), 128}});
  return image;
}

} // namespace

TEST_CASE("planar Voronoi labels equal brute force, however small the first windows",
          "[mosaic][planar]") {
  const int w = 160, h = 120;
  for (bool vary : {false, true}) {
    const auto sites = random_sites(w, h, 90, vary ? 7 : 3, vary);
    for (double window : {0.0, 1.0})
      for (bool certify : {true, false}) {
        Planar_voronoi_options o;
        o.beta = vary ? 1.3 : 1.0;
        o.window = window;
        o.certify = certify;
        const Planar_voronoi v = planar_voronoi(w, h, sites, o);
        std::size_t checked = 0, wrong = 0;
        for (int y = 0; y < h; ++y)
          for (int x = 0; x < w; ++x) {
            const auto [best, gap] = brute_nearest(sites, o.beta, x, y);
            if (gap < 1e-3)
              continue; // a tie up to float rounding
            ++checked;
            wrong += v.label_at(x, y) != best;
          }
        CHECK(checked > std::size_t(w * h * 9 / 10));
        if (window == 1.0)
          CHECK(v.grown_windows > 0);
        // The certificate makes every label exact. Without it, the border rule alone is exact for
        // one frame and scale (star-shaped cells); with random frames per site it misses a few
        // pixels of cells that are not star-shaped about their sites (from the default windows,
        // fewer than one in a thousand; from one-pixel windows, more).
        if (certify || !vary)
          CHECK(wrong == 0);
        else if (window == 0.0)
          CHECK(wrong < checked / 1000);
      }
  }
}

TEST_CASE("a constant field turns a jittered grid into a regular grid of equal squares",
          "[mosaic][planar]") {
  // A 10 x 10 grid of spacing 30 fills the image; each site is moved by up to 3 pixels.
  const int w = 300, h = 300;
  const double spacing = 30;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-3, 3);
  Planar_mosaic_options o;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j)
      o.initial_sites.push_back({{15 + spacing * i + jitter(rng), 15 + spacing * j + jitter(rng)}});
  o.iterations = 40;
  o.barrier_iterations = 0;
  o.fitting = Planar_tile_fitting::none;
  const Planar_mosaic_result r =
      planar_mosaic(gradient_image(w, h), Gray_image(), constant_planar_field(w, h, 0), o);
  REQUIRE(r);
  // Every cell is a square of side 30 up to a pixel or two: a site a pixel off the grid changes the
  // energy by less than the centroids' rounding can see, so Lloyd's steps stop there.
  std::vector<Planar_site> sites;
  for (const Planar_tile& t : r.tiles)
    sites.push_back({t.x, t.y, 0, 1});
  const Planar_voronoi v = planar_voronoi(w, h, sites);
  std::vector<int> x0(sites.size(), w), x1(sites.size(), -1), y0(sites.size(), h),
      y1(sites.size(), -1);
  std::vector<double> area(sites.size(), 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t l = std::size_t(v.label_at(x, y));
      x0[l] = std::min(x0[l], x), x1[l] = std::max(x1[l], x);
      y0[l] = std::min(y0[l], y), y1[l] = std::max(y1[l], y);
      area[l] += 1;
    }
  for (std::size_t i = 0; i < sites.size(); ++i) {
    CHECK(std::abs(x1[i] - x0[i] + 1 - 30) <= 2);
    CHECK(std::abs(y1[i] - y0[i] + 1 - 30) <= 2);
    // Nine tenths of its bounding box at least: a square up to pixel steps along its sides (a
    // diamond, the optimum of the L1 metric in the tile's own frame, fills half its box).
    CHECK(area[i] >= 0.9 * (x1[i] - x0[i] + 1) * (y1[i] - y0[i] + 1));
    CHECK(area[i] == Approx(900).epsilon(0.08));
    CHECK(r.tiles[i].angle == Approx(0).margin(1e-6));
  }
  // The energy of the ideal grid: the mean of max(|x|, |y|) over a square of side a is a/3.
  CHECK(r.stats.energy.back() == Approx(spacing / 3).epsilon(0.005));
}

TEST_CASE("from random sites the energy decreases and settles near the ideal grid's",
          "[mosaic][planar]") {
  const int w = 240, h = 240;
  Planar_mosaic_options o;
  o.tiles = 144; // spacing 20
  o.iterations = 40;
  o.barrier_iterations = 0;
  o.fitting = Planar_tile_fitting::none;
  const Planar_mosaic_result r =
      planar_mosaic(gradient_image(w, h), Gray_image(), constant_planar_field(w, h, 0.35), o);
  REQUIRE(r);
  const auto& e = r.stats.energy;
  REQUIRE(e.size() == 40);
  for (std::size_t k = 1; k < e.size(); ++k)
    CHECK(e[k] <= e[k - 1] * (1 + 1e-3));
  CHECK(e.back() < 0.8 * e.front());
  CHECK(e.back() == Approx(20 / 3.0).epsilon(0.03)); // the ideal grid's, a/3
  CHECK(r.tiles.size() == 144);
}

TEST_CASE("edge avoidance keeps tiles off a straight edge", "[mosaic][planar]") {
  const int w = 300, h = 200;
  Rgb_image image(w, h);
  Edge_curves edge;
  edge.polylines.push_back({{{-10, 14}}, {{310, 186}}}); // across the whole image
  const Gray_image mask = rasterize_edges(edge, w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      image.set(x, y,
                (x + 10) * 172 - (y - 14) * 320 > 0 ? std::array<std::uint8_t, 3>{{200, 40, 40}}
                                                    : std::array<std::uint8_t, 3>{{40, 40, 200}});
  Planar_mosaic_options o;
  o.tiles = 400;
  o.fitting = Planar_tile_fitting::none; // the layout alone, without cutting tiles to fit
  const Planar_mosaic_result with = planar_mosaic(image, mask, o);
  REQUIRE(with);
  const Planar_mosaic_quality q =
      planar_mosaic_quality(image, mask, with.field, with.tiles, o.shape);
  CHECK(q.straddling_tiles == 0);
  CHECK(q.orientation_error_median < 2);
  CHECK(q.overlap < 0.005);
  CHECK(q.coverage == Approx(0.64).margin(0.032));
  // Without barriers or the push off the edge, tiles sit on it: the check above can fail.
  o.barrier_iterations = 0;
  o.keep_off_edges = false;
  const Planar_mosaic_result without = planar_mosaic(image, mask, o);
  CHECK(planar_mosaic_quality(image, mask, without.field, without.tiles, o.shape).straddling_tiles >
        0);
}

TEST_CASE("the field follows the gradient of the distance to the edges", "[mosaic][planar]") {
  const int w = 120, h = 80;
  Edge_curves edge;
  edge.polylines.push_back({{{0, 40}}, {{119, 40}}}); // horizontal: the field is vertical
  const Planar_field f = planar_direction_field(rasterize_edges(edge, w, h));
  for (int y : {5, 20, 35, 45, 60, 75})
    for (int x : {10, 60, 110}) {
      CHECK(f.distance_at(x, y) == Approx(std::abs(y - 40)));
      CHECK(orientation_difference(f.angle_at(x, y), M_PI / 2, M_PI) < 1e-3);
    }
  // No edges: constant, infinitely far.
  const Planar_field none = planar_direction_field(Gray_image(w, h, 0));
  CHECK(none.angle_at(3, 4) == 0);
  CHECK(std::isinf(none.distance_at(3, 4)));
}

// Mean angle (degrees) between `f` and the analytic field `truth` over the pixels at distance
// [d0, d1) from the curve, away from the image border.
template <class Truth>
double mean_field_error(const Planar_field& f, Truth truth, double d0, double d1) {
  double sum = 0, n = 0;
  for (int y = 40; y < f.height - 40; ++y)
    for (int x = 40; x < f.width - 40; ++x)
      if (f.distance_at(x, y) >= d0 && f.distance_at(x, y) < d1)
        sum += orientation_difference(f.angle_at(x, y), truth(x, y), M_PI / 2), n += 1;
  REQUIRE(n > 100);
  return sum / n * 180 / M_PI;
}

TEST_CASE("the field is the normal of rasterized circles and slanted lines within 2 degrees",
          "[mosaic][planar]") {
  const int w = 440, h = 440;
  Edge_curves circle;
  circle.polylines.emplace_back();
  for (int i = 0; i <= 400; ++i)
    circle.polylines[0].push_back(
        {{220 + 150 * std::cos(2 * M_PI * i / 400), 220 + 150 * std::sin(2 * M_PI * i / 400)}});
  const auto radial = [](int x, int y) { return std::atan2(y - 220.0, x - 220.0); };
  const Gray_image circle_mask = rasterize_edges(circle, w, h);
  // Central differences of the distance to pixel centres point at single pixels of the staircase.
  Planar_field_options pixel_differences;
  pixel_differences.tangent_scale = 0;
  CHECK(mean_field_error(planar_direction_field(circle_mask, pixel_differences), radial, 1, 4) > 5);
  const Planar_field f = planar_direction_field(circle_mask);
  for (const auto& band : {std::array<double, 2>{{1, 4}}, {{4, 10}}, {{10, 25}}, {{25, 60}}})
    CHECK(mean_field_error(f, radial, band[0], band[1]) < 2);
  // Tiles in rows around the circle turn with the field under them by less than 2° (median).
  Planar_mosaic_options o;
  o.tiles = 600;
  const Rgb_image image(w, h);
  const Planar_mosaic_result r = planar_mosaic(image, circle_mask, o);
  REQUIRE(r);
  CHECK(planar_mosaic_quality(image, circle_mask, r.field, r.tiles, o.shape)
            .orientation_error_median < 1.5);
  for (double degrees : {10.0, 33.0}) {
    const double a = degrees * M_PI / 180;
    Edge_curves line;
    line.polylines.push_back({{{0, 220 - 220 * std::tan(a)}}, {{439, 220 + 219 * std::tan(a)}}});
    const auto normal = [a](int, int) { return a + M_PI / 2; };
    const Planar_field g = planar_direction_field(rasterize_edges(line, w, h));
    CAPTURE(degrees);
    CHECK(mean_field_error(g, normal, 1, 60) < 1.5);
  }
  // Beyond a segment's end the distance's gradient fans out from the end point.
  Edge_curves segment;
  segment.polylines.push_back({{{100, 220}}, {{200, 220}}});
  const Planar_field s = planar_direction_field(rasterize_edges(segment, w, h));
  CHECK(orientation_difference(s.angle_at(150, 240), M_PI / 2, M_PI / 2) < 0.02);
  CHECK(orientation_difference(s.angle_at(230, 250), M_PI / 4, M_PI / 2) < 0.05);
}

TEST_CASE("rejection sampling gives each region tiles of its size", "[mosaic][planar]") {
  const int w = 400, h = 200;
  Planar_mosaic_options o;
  o.tiles = 2000;
  o.region_labels = Gray_image(w, h, 0);
  for (int y = 0; y < h; ++y)
    for (int x = w / 2; x < w; ++x)
      o.region_labels.at(x, y) = 1;
  o.region_sizes = {1, 2}; // tiles twice as large on the right: a quarter of the density
  o.fitting = Planar_tile_fitting::none;
  for (std::size_t iterations : {0, 10}) {
    o.iterations = iterations;
    o.barrier_iterations = 0;
    const Planar_mosaic_result r = planar_mosaic(gradient_image(w, h), Gray_image(), o);
    REQUIRE(r);
    double left = 0, right = 0;
    for (const Planar_tile& t : r.tiles) {
      (t.region == 0 ? left : right) += 1;
      CHECK(t.width == Approx(r.tile_side * (t.region == 1 ? 2 : 1)));
      CHECK(t.region == (std::lround(t.x) < w / 2 ? 0 : 1));
    }
    CHECK(left / right == Approx(4).epsilon(0.12));
    // Σ_r A_r / (c s_r)² = n: 0.8·c = tile side, c² = (A/2)(1 + 1/4) / n.
    CHECK(r.tile_side == Approx(0.8 * std::sqrt(w * h / 2.0 * 1.25 / 2000)));
  }
}

TEST_CASE("planar mosaics are deterministic for a seed, and fitting removes all overlap",
          "[mosaic][planar]") {
  const Rgb_image image = gradient_image(200, 150);
  Edge_curves edge;
  edge.polylines.push_back({{{30, 20}}, {{100, 120}}, {{180, 40}}});
  const Gray_image mask = rasterize_edges(edge, 200, 150);
  Planar_mosaic_options o;
  o.tiles = 300;
  o.coloring = Planar_tile_coloring::area;
  const Planar_mosaic_result a = planar_mosaic(image, mask, o), b = planar_mosaic(image, mask, o);
  REQUIRE(a);
  REQUIRE(a.tiles.size() == b.tiles.size());
  for (std::size_t i = 0; i < a.tiles.size(); ++i) {
    CHECK(a.tiles[i].x == b.tiles[i].x);
    CHECK(a.tiles[i].angle == b.tiles[i].angle);
    CHECK(a.tiles[i].color == b.tiles[i].color);
  }
  o.seed = 2;
  const Planar_mosaic_result c = planar_mosaic(image, mask, o);
  CHECK(c.tiles.front().x != a.tiles.front().x);
  const Planar_mosaic_quality q = planar_mosaic_quality(image, mask, a.field, a.tiles, o.shape);
  CHECK(q.straddling_tiles == 0);
  CHECK(q.overlap < 0.005); // pixel centres in the half-pixel band fitting allows
  CHECK(a.stats.tiles_dropped + a.tiles.size() == 300);
  // Area colours of a smooth gradient are close to the image under the tiles.
  CHECK(q.color_error < 3);
}

TEST_CASE("planar mosaic options and images are checked", "[mosaic][planar]") {
  const Rgb_image image = gradient_image(64, 48);
  Planar_mosaic_options o;
  o.tiles = 0;
  CHECK(planar_mosaic(image, Gray_image(), o).status == Planar_mosaic_status::invalid_options);
  o.tiles = 50;
  o.beta = 2; // square tiles need β = 1
  CHECK(planar_mosaic(image, Gray_image(), o).status == Planar_mosaic_status::invalid_options);
  o.beta = 1;
  CHECK(planar_mosaic(image, Gray_image(10, 10), o).status == Planar_mosaic_status::size_mismatch);
  CHECK(planar_mosaic(Rgb_image(), Gray_image(), o).status == Planar_mosaic_status::empty_image);
  o.region_labels = Gray_image(64, 48, 2);
  o.region_sizes = {1, 2};
  CHECK(planar_mosaic(image, Gray_image(), o).status == Planar_mosaic_status::invalid_options);

  const std::string dir = test::output_path("");
  CHECK(read_image(dir + "/no-such-image.png").status == Image_read_status::cannot_open);
  std::ofstream(dir + "/empty.png").close();
  CHECK(read_image(dir + "/empty.png").status == Image_read_status::empty_file);
  std::ofstream(dir + "/garbage.png") << "this is not an image";
  CHECK(read_image(dir + "/garbage.png").status == Image_read_status::cannot_decode);
  // A PNG header that claims 100000 x 100000 pixels is refused before any pixel is allocated.
  std::vector<std::uint8_t> huge = {0x89, 'P', 'N',  'G',  '\r', '\n', 0x1a, '\n', 0,    0,
                                    0,    13,  'I',  'H',  'D',  'R',  0,    1,    0x86, 0xa0,
                                    0,    1,   0x86, 0xa0, 8,    2,    0,    0,    0};
  CHECK(decode_image(huge).status == Image_read_status::too_large);
  // A BMP header of 3072 x 262144 pixels (found by the image fuzzer: 2.4 GB once decoded).
  std::vector<std::uint8_t> bmp(64, 0);
  bmp[0] = 'B', bmp[1] = 'M', bmp[19] = 0x0c, bmp[24] = 0x04;
  CHECK(decode_image(bmp).status == Image_read_status::too_large);
  CHECK(decode_image({'G', 'I', 'F', '8', '9', 'a', 0, 0}).status ==
        Image_read_status::cannot_decode);
  huge[16] = huge[17] = huge[18] = huge[19] = 0; // zero width
  CHECK(decode_image(huge).status == Image_read_status::cannot_decode);
  const Image_read_result real = read_image(test::data_path("images/logo.png"));
  REQUIRE(real);
  CHECK(real.image.width == 500);
  CHECK(real.image.height == 500);
}

TEST_CASE("The field picture crosses its strokes for square tiles only, at the options' scale",
          "[mosaic][planar]") {
  Rgb_image white(64, 48);
  std::fill(white.pixels.begin(), white.pixels.end(), std::uint8_t(255));
  const Planar_field field = constant_planar_field(64, 48, 0.0);
  // Pixels of the strokes' blue: the faded white image stays white.
  auto stroke_pixels = [&](Planar_tile_shape shape, double scale) {
    Planar_drawing_options options;
    options.shape = shape;
    options.scale = scale;
    const std::string path = test::output_path("planar-field.png");
    const Render_result drawn = draw_planar_field(white, field, Gray_image(), path, options);
    INFO(drawn.message);
    REQUIRE(drawn);
    const Image_read_result read = read_image(path);
    REQUIRE(read);
    CHECK(read.image.width == int(64 * scale));
    CHECK(read.image.height == int(48 * scale));
    std::size_t count = 0;
    for (int y = 0; y < read.image.height; ++y)
      for (int x = 0; x < read.image.width; ++x) {
        const auto c = read.image.at(x, y);
        count += c[2] > c[0] + 50;
      }
    return count;
  };
  const std::size_t crossed = stroke_pixels(Planar_tile_shape::square, 2);
  const std::size_t single = stroke_pixels(Planar_tile_shape::rectangle, 2);
  INFO("square " << crossed << ", rectangle " << single);
  CHECK(single > 0);
  CHECK(crossed > single * 5 / 4); // the cross stroke is 0.6 times as long
  CHECK(stroke_pixels(Planar_tile_shape::square, 1) < crossed / 2);
  Planar_drawing_options bad;
  bad.scale = 0;
  CHECK(draw_planar_field(white, field, Gray_image(), test::output_path("no-field.png"), bad)
            .status == Render_status::invalid_scene);
}
