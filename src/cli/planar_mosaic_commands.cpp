// tessera planar-mosaic: a decorative mosaic of an image (Hausner 2001) whose tiles follow its edge
// curves, written as mosaic.png, mosaic.svg, tiles.json, field.png and report.json (and view.html
// with --view).
#include "choices.h"
#include "commands.h"
#include "output_dir.h"

#include <tessera/io/image.h>
#include <tessera/io/mosaic_reports.h>
#include <tessera/mosaic/draw_planar_mosaic.h>
#include <tessera/mosaic/planar_field.h>
#include <tessera/mosaic/planar_mosaic.h>
#include <tessera/mosaic/planar_mosaic_names.h>
#include <tessera/mosaic/planar_quality.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

namespace tessera::cli {
namespace {

using Clock = std::chrono::steady_clock;

std::string fixed(double x, int decimals) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(decimals) << x;
  return s.str();
}

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

Rgb_image read_image_or_throw(const std::string& path, const std::string& what) {
  Image_read_result r = read_image(path);
  if (!r)
    throw User_error(what + ": " + r.message);
  return std::move(r.image);
}

// Edge curves as JSON: {"polylines": [[[x, y], ...], ...]} or the bare list of polylines, in
// pixel coordinates.
Edge_curves read_edge_json(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw User_error("--edges: cannot open " + path);
  nlohmann::json j;
  try {
    in >> j;
  } catch (const nlohmann::json::exception& e) {
    throw User_error("--edges: " + path + ": malformed JSON (" + e.what() + ")");
  }
  const nlohmann::json& lines = j.is_object() && j.contains("polylines") ? j["polylines"] : j;
  if (!lines.is_array())
    throw User_error("--edges: " + path +
                     ": expected a list of polylines or {\"polylines\": [...]}");
  Edge_curves curves;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const nlohmann::json& line = lines[i];
    if (!line.is_array())
      throw User_error("--edges: polyline " + std::to_string(i) + " is not a list of points");
    std::vector<std::array<double, 2>> points;
    for (const nlohmann::json& p : line) {
      if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
        throw User_error("--edges: polyline " + std::to_string(i) +
                         " has a point that is not [x, y] (two numbers)");
      const double x = p[0].get<double>(), y = p[1].get<double>();
      if (!std::isfinite(x) || !std::isfinite(y))
        throw User_error("--edges: polyline " + std::to_string(i) + " has a non-finite point");
      points.push_back({{x, y}});
    }
    curves.polylines.push_back(std::move(points));
  }
  return curves;
}

// Region map: each distinct colour of the picture is a region; regions are numbered from the
// darkest colour to the lightest (ties by red, green, blue).
Gray_image region_labels(const Rgb_image& map, std::size_t& regions) {
  std::map<std::array<int, 4>, int> colors;
  auto key = [](std::array<std::uint8_t, 3> c) {
    return std::array<int, 4>{{299 * c[0] + 587 * c[1] + 114 * c[2], c[0], c[1], c[2]}};
  };
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) {
      colors.emplace(key(map.at(x, y)), 0);
      if (colors.size() > 255)
        throw User_error("--regions: the map has more than 255 colours; use one flat colour per "
                         "region");
    }
  int next = 0;
  for (auto& c : colors)
    c.second = next++;
  Gray_image labels(map.width, map.height);
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x)
      labels.at(x, y) = std::uint8_t(colors[key(map.at(x, y))]);
  regions = colors.size();
  return labels;
}

Color parse_color(const std::string& s) {
  unsigned r = 0, g = 0, b = 0;
  char rest = 0;
  if (s.size() == 7 && s[0] == '#' &&
      std::sscanf(s.c_str() + 1, "%2x%2x%2x%c", &r, &g, &b, &rest) == 3)
    return {r / 255.0, g / 255.0, b / 255.0};
  if (std::sscanf(s.c_str(), "%u,%u,%u%c", &r, &g, &b, &rest) == 3 && r < 256 && g < 256 && b < 256)
    return {r / 255.0, g / 255.0, b / 255.0};
  throw User_error("--grout must be a colour as #rrggbb or R,G,B with values 0-255 (got '" + s +
                   "')");
}

Planar_mosaic_options planar_options(const Planar_mosaic_arguments& a) {
  Planar_mosaic_options o;
  if (a.tiles < 1)
    throw User_error("--tiles must be a positive number (got " + std::to_string(a.tiles) + ")");
  o.tiles = std::size_t(a.tiles);
  if (!(a.delta > 0 && a.delta <= 2))
    throw User_error("--delta must be in (0, 2] (got " + fixed(a.delta, 3) + ")");
  o.delta = a.delta;
  if (!(a.aspect > 0 && a.aspect < 100))
    throw User_error("--aspect must be a positive number (got " + fixed(a.aspect, 3) + ")");
  o.beta = a.aspect;
  o.shape = parse_choice(planar_tile_shape_names, a.shape, "--shape");
  if (o.shape == Planar_tile_shape::square && a.aspect != 1)
    throw User_error("--aspect needs --shape rect or ellipse (square tiles have aspect 1)");
  o.coloring = parse_choice(planar_tile_coloring_names, a.colors, "--colors");
  o.fitting = parse_choice(planar_tile_fitting_names, a.fit, "--fit");
  if (a.iterations < 0 || a.iterations > 10000)
    throw User_error("--iterations must be in [0, 10000] (got " + std::to_string(a.iterations) +
                     ")");
  o.iterations = std::size_t(a.iterations);
  if (a.barrier_iterations < 0)
    throw User_error("--barrier-iterations must not be negative");
  o.barrier_iterations = std::min(std::size_t(a.barrier_iterations), o.iterations);
  o.seed = a.seed;
  return o;
}

// The files the command reads, which its output directory must not overwrite.
std::vector<std::string> planar_inputs(const Planar_mosaic_arguments& a) {
  std::vector<std::string> inputs{a.image};
  if (!a.regions.empty())
    inputs.push_back(a.regions);
  if (a.edges != "auto" && a.edges != "none")
    inputs.push_back(a.edges);
  return inputs;
}

// "--what: the NAME is W x H but the image W x H" when `picture` is not the image's size.
void check_same_size(const Rgb_image& picture, const Rgb_image& image, const std::string& what,
                     const std::string& name) {
  if (picture.width != image.width || picture.height != image.height)
    throw User_error(what + ": the " + name + " is " + std::to_string(picture.width) + " x " +
                     std::to_string(picture.height) + " but the image " +
                     std::to_string(image.width) + " x " + std::to_string(image.height));
}

// The edge pixels of --edges, with the number of curves they were drawn from (0 for a mask).
struct Mosaic_edges {
  Gray_image pixels;
  std::size_t curves = 0;
};

// Edges: found by Canny, none, a JSON file of polylines, or a mask picture.
Mosaic_edges read_edges(const Planar_mosaic_arguments& a, const Rgb_image& image,
                        const Planar_mosaic_options& options) {
  Mosaic_edges edges;
  if (a.edges == "auto" || ends_with(a.edges, ".json")) {
    const Edge_curves curves =
        a.edges == "auto" ? detect_mosaic_edges(image, options) : read_edge_json(a.edges);
    edges.curves = curves.polylines.size();
    edges.pixels = rasterize_edges(curves, image.width, image.height);
  } else if (a.edges != "none") {
    const Rgb_image mask = read_image_or_throw(a.edges, "--edges");
    check_same_size(mask, image, "--edges", "mask");
    edges.pixels = edge_mask_from_image(mask);
  }
  return edges;
}

// --regions and --sizes into the options: a region per colour of the map, a size per region.
void read_regions(const Planar_mosaic_arguments& a, const Rgb_image& image,
                  Planar_mosaic_options& options) {
  if (a.regions.empty()) {
    if (!a.sizes.empty())
      throw User_error("--sizes goes with --regions");
    return;
  }
  const Rgb_image map = read_image_or_throw(a.regions, "--regions");
  check_same_size(map, image, "--regions", "map");
  std::size_t regions = 0;
  options.region_labels = region_labels(map, regions);
  if (a.sizes.size() != regions)
    throw User_error("--regions: the map has " + std::to_string(regions) +
                     " colours (regions, darkest first) but --sizes gives " +
                     std::to_string(a.sizes.size()) + " sizes");
  options.region_sizes = a.sizes;
}

// mosaic.png, mosaic.svg, field.png and tiles.json; returns them in the order they are printed.
std::vector<std::string> write_planar_outputs(const Output_directory& dir, const Rgb_image& image,
                                              const Gray_image& edges,
                                              const Planar_mosaic_options& options,
                                              const Planar_mosaic_result& r, const Color& grout) {
  const std::string png = dir.file("mosaic.png"), svg = dir.file("mosaic.svg"),
                    tiles_json = dir.file("tiles.json"), field_png = dir.file("field.png");
  Planar_drawing_options drawing;
  drawing.shape = options.shape;
  drawing.grout = grout;
  drawing.scale = std::max(1.0, std::min(4.0, 1200.0 / std::max(image.width, image.height)));
  for (const std::string& path : {png, svg})
    write_checked(path, [&](const std::string& tmp) {
      return draw_planar_mosaic(r.tiles, image.width, image.height, tmp, drawing);
    });
  drawing.stroke_spacing = 1.5 * r.tile_side;
  write_checked(field_png, [&](const std::string& tmp) {
    return draw_planar_field(image, r.field, edges, tmp, drawing);
  });
  write_checked_stream(tiles_json, [&](std::ostream& out) {
    return write_planar_mosaic_tiles_report(out, Planar_mosaic_tiles_report{r.tiles});
  });
  return {png, svg, tiles_json, field_png};
}

void print_planar_mosaic(const Planar_mosaic_result& r, const Planar_mosaic_quality& q) {
  const Planar_mosaic_stats& s = r.stats;
  std::cout << "planar mosaic: " << r.tiles.size() << " tiles of side " << fixed(r.tile_side, 1)
            << " px, " << s.iterations << " iterations, coverage " << fixed(q.coverage, 3)
            << ", overlap " << fixed(q.overlap, 4) << ", " << q.straddling_tiles
            << " tiles straddling edges, orientation error median "
            << fixed(q.orientation_error_median, 1) << "°, colour error ΔE "
            << fixed(q.color_error, 1) << " (" << s.tiles_shrunk << " tiles cut to fit, "
            << s.tiles_dropped << " left out)\n";
}

} // namespace

int run_planar_mosaic(const Planar_mosaic_arguments& a) {
  const auto start = Clock::now();
  Planar_mosaic_options options = planar_options(a);
  const Color grout = parse_color(a.grout);
  const Rgb_image image = read_image_or_throw(a.image, "image");
  const Mosaic_edges edges = read_edges(a, image, options);
  read_regions(a, image, options);
  const Output_directory dir(a.out, a.force, planar_inputs(a));

  const Planar_mosaic_result r = planar_mosaic(image, edges.pixels, options);
  if (!r)
    throw User_error(r.message);
  const Planar_mosaic_quality q =
      planar_mosaic_quality(image, edges.pixels, r.field, r.tiles, options.shape);
  std::vector<std::string> written =
      write_planar_outputs(dir, image, edges.pixels, options, r, grout);

  Planar_mosaic_report report =
      make_planar_mosaic_report(a.image, image, a.edges, edges.curves, edges.pixels, options, r, q);
  report.options.shape = internal::enum_name(planar_tile_shape_names, options.shape);
  report.options.colors = internal::enum_name(planar_tile_coloring_names, options.coloring);
  report.options.fit = internal::enum_name(planar_tile_fitting_names, options.fitting);
  report.seconds_total = std::chrono::duration<double>(Clock::now() - start).count();
  written.push_back(dir.file("report.json"));
  write_checked_stream(written.back(),
                       [&](std::ostream& out) { return write_planar_mosaic_report(out, report); });
  print_planar_mosaic(r, q);
  print_written(with_view(written, dir, a.view, a.image));
  return exit_ok;
}

void register_planar_mosaic_commands(CLI::App& app, std::function<int()>& run) {
  auto a = std::make_shared<Planar_mosaic_arguments>();
  auto* cmd = app.add_subcommand(
      "planar-mosaic", "Decorative mosaic of an image, tiles along its edges (Hausner 2001)");
  cmd->add_option("image", a->image, "Image (PNG, JPEG or BMP)")->required();
  cmd->add_option("--tiles", a->tiles, "Number of tiles")->capture_default_str();
  cmd->add_option("--edges", a->edges,
                  "auto (Canny), none, FILE.json (polylines in pixels) or MASK.png (edge pixels)")
      ->capture_default_str();
  cmd->add_option("--regions", a->regions, "Region map: one flat colour per region");
  cmd->add_option("--sizes", a->sizes, "Tile size factor per region, darkest colour first")
      ->delimiter(',');
  cmd->add_option("--delta", a->delta, "Tile side as a fraction of the spacing sqrt(hw/n)")
      ->capture_default_str();
  cmd->add_option("--aspect", a->aspect, "beta: tiles d/beta across the rows, d*beta along them")
      ->capture_default_str();
  cmd->add_option("--colors", a->colors,
                  "point (pixel at the centre) or area (mean under the tile)")
      ->capture_default_str();
  cmd->add_option("--shape", a->shape, internal::enum_name_list(planar_tile_shape_names))
      ->capture_default_str();
  cmd->add_option("--grout", a->grout, "Grout colour, #rrggbb or R,G,B")->capture_default_str();
  cmd->add_option("--fit", a->fit, "shrink (cut tiles off edges and neighbours) or none")
      ->capture_default_str();
  cmd->add_option("--iterations", a->iterations, "Lloyd iterations")->capture_default_str();
  cmd->add_option("--barrier-iterations", a->barrier_iterations,
                  "First iterations with thick edge barriers")
      ->capture_default_str();
  cmd->add_option("--seed", a->seed, "Seed of the random initial sites")->capture_default_str();
  cmd->add_option("--out", a->out, "Output directory")->required();
  cmd->add_flag("--force", a->force, "Write into a non-empty directory Tessera did not create");
  add_view_flag(cmd, a->view);
  cmd->callback([&run, a] { run = [a] { return run_planar_mosaic(*a); }; });
}

} // namespace tessera::cli
