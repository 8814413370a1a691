// Planar-mosaic figures at issue 14's size (a 900 × 900 image, 2000 tiles, 20 iterations): time
// per stage and end to end, and the quality report with and without tile fitting, on the three
// shared photographs scaled to 900 × 900, against the targets.
#include "harness.h"

#include <tessera/io/image.h>
#include <tessera/mosaic/planar_field.h>
#include <tessera/mosaic/planar_mosaic.h>
#include <tessera/mosaic/planar_quality.h>

#include <opencv2/imgproc.hpp>

#include <chrono>
#include <stdexcept>
#include <string>

namespace {

using namespace tessera;
using Clock = std::chrono::steady_clock;

Rgb_image load_scaled(const std::string& file, int side) {
  const Image_read_result r = read_image(bench::data_dir() + "/images/" + file);
  if (!r)
    throw std::runtime_error(r.message);
  cv::Mat in(r.image.height, r.image.width, CV_8UC3,
             const_cast<std::uint8_t*>(r.image.pixels.data()));
  cv::Mat out;
  cv::resize(in, out, cv::Size(side, side), 0, 0, cv::INTER_CUBIC);
  Rgb_image scaled(side, side);
  std::copy(out.data, out.data + scaled.pixels.size(), scaled.pixels.begin());
  return scaled;
}

void planar(bench::Report& report, const bench::Config& config) {
  const std::string table = "Planar mosaics: 900 x 900 image, 2000 square tiles, 20 iterations";
  const int side = config.quick ? 200 : 900;
  const std::size_t tiles = config.quick ? 300 : 2000;
  for (const char* file : {"coffee.png", "chelsea.png", "logo.png"}) {
    const Rgb_image image = load_scaled(file, side);
    for (Planar_tile_fitting fitting : {Planar_tile_fitting::shrink, Planar_tile_fitting::none}) {
      Planar_mosaic_options o;
      o.tiles = tiles;
      o.fitting = fitting;
      Planar_mosaic_result r;
      double edges_s = 0;
      Gray_image edges;
      // Best of three runs: the machine's other work shows as noise at these times.
      const double total = bench::time_best(
          [&] {
            const auto t0 = Clock::now();
            edges = rasterize_edges(detect_mosaic_edges(image, o), image.width, image.height);
            edges_s = std::chrono::duration<double>(Clock::now() - t0).count();
            r = planar_mosaic(image, edges, o);
          },
          3);
      const Planar_mosaic_quality q =
          planar_mosaic_quality(image, edges, r.field, r.tiles, o.shape);
      report.add(table,
                 {{"image", std::string(file) + (config.quick ? " (quick)" : "")},
                  {"fit", fitting == Planar_tile_fitting::shrink ? "shrink" : "none"},
                  {"edges", bench::fixed(edges_s, 3)},
                  {"field", bench::fixed(r.stats.seconds_field, 3)},
                  {"iterations", bench::fixed(r.stats.seconds_iterations, 3)},
                  {"tiles + fit", bench::fixed(r.stats.seconds_tiles + r.stats.seconds_fitting, 3)},
                  {"end to end", bench::fixed(total, 3)},
                  {"report", bench::fixed(q.seconds, 3)},
                  {"coverage", bench::fixed(q.coverage, 3)},
                  {"overlap %", bench::fixed(100 * q.overlap, 2)},
                  {"straddling", std::to_string(q.straddling_tiles)},
                  {"orientation median °", bench::fixed(q.orientation_error_median, 2)},
                  {"p95 °", bench::fixed(q.orientation_error_p95, 1)},
                  {"ΔE", bench::fixed(q.color_error, 2)},
                  {"cut / left out", std::to_string(r.stats.tiles_shrunk) + " / " +
                                         std::to_string(r.stats.tiles_dropped)}});
    }
  }
  report.note(
      table, "Targets (issue 14): end to end ≤ 0.5 s on this 2-core machine (the paper: ~20 s on a "
             "2001 GPU); with δ = 0.8 after edge avoidance, overlap ≤ 0.5 % of the image, no tile "
             "straddling an edge curve, median orientation error ≤ 2°, coverage within 5 % of "
             "δ² = 0.64. End to end = Canny edges + field + initialization + iterations + tiles "
             "(fitting, colours), from the decoded image; the report is timed apart; the stage "
             "columns come from the last of the three runs, end to end is the best. Edges found "
             "by Canny (`--edges auto`); images scaled with OpenCV's cubic filter.");
}

} // namespace

TESSERA_BENCHMARK("planar", planar);
