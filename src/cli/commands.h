// Subcommands of the tessera tool. Each module's file registers its own; main() only dispatches.
#pragma once

#include <CLI/CLI.hpp>

#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace tessera::cli {

/// Exit codes: 0 success, 1 bad input or refused request (one line on stderr), 2 internal error.
enum Exit_code { exit_ok = 0, exit_bad_input = 1, exit_internal = 2 };

/// A failure to report to the user as one line, with exit code 1.
struct User_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// How a command may repair its input mesh (`--strict`, `--repair`; see mesh_input.h).
struct Mesh_input_flags {
  bool strict = false;
  bool repair = false;
};

/// Registers `info`, `render` and `demo`. Each command stores its action in `run`.
void register_mesh_commands(CLI::App& app, std::function<int()>& run);

/// Arguments of `tessera cut`.
struct Cut_arguments {
  std::string mesh;
  std::string out;
  std::string method = "greedy";
  std::string cost = "euclidean";
  double curvature_weight = 0.5;
  long basepoint = -1;
  std::string kernel = "double";
  bool canonical = false;
  bool force = false;
  /// --view: also write view.html.
  bool view = false;
  Mesh_input_flags input;
};

/// Runs `tessera cut` (also used by `tessera demo`).
int run_cut(const Cut_arguments& arguments);

/// Registers `cut`.
void register_topology_commands(CLI::App& app, std::function<int()>& run);

/// Arguments of `tessera check`.
struct Check_arguments {
  /// Result directories, meshes (with --seams or --original), OBJ layouts, or directories of OBJ
  /// layouts; several give one line each and a combined report.
  std::vector<std::string> inputs;
  std::string seams, expect, original, report;
  bool exact = false;
  bool force = false;
};

/// Runs `tessera check`: exit 0 when the cutting is valid, 2 when not.
int run_check(const Check_arguments& arguments);

/// Registers `check` (validation of any cutting, optionally exact).
void register_check_commands(CLI::App& app, std::function<int()>& run);

/// Arguments of `tessera quadrangulate`.
struct Quad_arguments {
  std::string mesh, out, from = "greedy", cost = "euclidean";
  double curvature_weight = 0.5;
  long basepoint = -1;
  std::string interior = "mean-value";
  std::string kernel = "double";
  bool canonical = false;
  bool force = false;
  /// --view: also write view.html.
  bool view = false;
  Mesh_input_flags input;
};

/// Runs `tessera quadrangulate` (also used by `tessera demo`).
int run_quadrangulate(const Quad_arguments& arguments);

/// Registers `quadrangulate` (Q-criterion quads from a cut graph, one UV square per quad).
void register_quad_commands(CLI::App& app, std::function<int()>& run);

/// The --control, --features and --align arguments of `field` and `mosaic` (see field_input.h).
struct Field_input_arguments {
  std::string control, features, feature_file, align = "parallel";
  bool principal = false;
};

/// Arguments of `tessera field`.
struct Field_arguments {
  std::string mesh, out;
  int symmetry = 4;
  bool force = false, view = false;
  Field_input_arguments field;
  Mesh_input_flags input;
};

/// Runs `tessera field`.
int run_field(const Field_arguments& arguments);

/// Registers `field` (smoothest direction fields, singularities and their picture).
void register_field_commands(CLI::App& app, std::function<int()>& run);

/// Arguments of `tessera mosaic`.
struct Mosaic_arguments {
  std::string mesh, out, texture, energy = "soft-box", colors = "region", start = "automatic",
                                  count = "about", tile_size_field;
  std::vector<double> tile_size;
  // Signed, so that a negative value gets the command's own message.
  // The library's defaults (Surface_mosaic_options, Mosaic_tile_size).
  long long tiles = 0, iterations = 150;
  double aspect = 1, grout = 0.1;
  /// Tile_scale_options::time.
  double tile_scale_smoothing = 0.08;
  unsigned seed = 1;
  bool teleport = false, cut_tiles = false, force = false, thin_parts = true, view = false,
       smooth_planes = false;
  Field_input_arguments field;
  Mesh_input_flags input;
  /// Whether --tiles and --aspect were given (a count, not a size; an aspect only with a count).
  bool tiles_given = false, aspect_given = false;
};

/// Runs `tessera mosaic` (also used by `tessera demo`).
int run_mosaic(const Mosaic_arguments& arguments);

/// Registers `mosaic` (surface mosaics: tiles along the smoothest field, their report and picture).
void register_mosaic_commands(CLI::App& app, std::function<int()>& run);

/// Arguments of `tessera planar-mosaic`.
struct Planar_mosaic_arguments {
  std::string image, out, edges = "auto", regions, colors = "point", shape = "square",
                          grout = "#403d3a", fit = "shrink";
  std::vector<double> sizes;
  // Signed, so that a negative value gets the command's own message.
  long long tiles = 2000, iterations = 20, barrier_iterations = 14;
  double delta = 0.8, aspect = 1;
  unsigned seed = 1;
  bool force = false;
  /// --view: also write view.html.
  bool view = false;
};
/// Runs `tessera planar-mosaic` (also used by `tessera demo`).
int run_planar_mosaic(const Planar_mosaic_arguments& arguments);
/// Registers `planar-mosaic` (Hausner's decorative mosaics of images).
void register_planar_mosaic_commands(CLI::App& app, std::function<int()>& run);

/// Registers `resize` (non-homogeneous resizing) and `deform` (deformation by handles).
void register_resize_commands(CLI::App& app, std::function<int()>& run);

/// Registers `view` (a result in 3D as one self-contained HTML page).
void register_view_commands(CLI::App& app, std::function<int()>& run);

} // namespace tessera::cli
