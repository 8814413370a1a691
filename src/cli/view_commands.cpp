// tessera view: one self-contained HTML page showing a result directory in 3D (three.js inlined).
#include "commands.h"
#include "output_dir.h"

#include <tessera/view.h>

#include <filesystem>
#include <iostream>

namespace tessera::cli {
namespace {

namespace fs = std::filesystem;

struct View_arguments {
  std::string result, out, mesh, image;
  bool force = false;
};

int run_view(const View_arguments& a) {
  // A check report's page goes beside it (report.json: report.html).
  const std::string out = !a.out.empty() ? a.out
                          : fs::is_regular_file(a.result)
                              ? fs::path(a.result).replace_extension(".html").string()
                              : (fs::path(a.result) / "view.html").string();
  std::error_code ec;
  const bool in_our_directory = fs::exists(fs::path(out).parent_path() / ".tessera-output", ec) &&
                                fs::path(out).filename() == "view.html";
  if (fs::exists(out, ec) && !a.force && !in_our_directory)
    throw User_error(out + ": exists (pass --force to overwrite it)");
  const View_scene_result scene = read_view_scene(a.result, a.image.empty() ? a.mesh : a.image);
  if (!scene)
    throw User_error(scene.message);
  write_view(scene.scene, out);
  print_written({out});
  return exit_ok;
}

} // namespace

void register_view_commands(CLI::App& app, std::function<int()>& run) {
  auto args = std::make_shared<View_arguments>();
  auto* cmd = app.add_subcommand(
      "view", "One self-contained HTML page showing a result directory in 3D (opens offline)");
  cmd->add_option("RESULT_DIR", args->result,
                  "Output directory of cut, quadrangulate, field, mosaic, planar-mosaic, resize "
                  "or deform, or a report file of check --report")
      ->required();
  cmd->add_option(
      "--out", args->out,
      "Page to write (default RESULT_DIR/view.html; for a report, its name with .html)");
  cmd->add_option("--mesh", args->mesh,
                  "Input mesh, for results that do not write theirs (field; mosaic, resize and "
                  "deform when report.json's path does not open from here)");
  cmd->add_option("--image", args->image,
                  "Input image of planar-mosaic, when report.json's path does not open from here");
  cmd->add_flag("--force", args->force, "Overwrite an existing page");
  cmd->callback([&run, args] { run = [args] { return run_view(*args); }; });
}

} // namespace tessera::cli
