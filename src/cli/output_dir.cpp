#include "output_dir.h"

#include "commands.h"

#include <tessera/view.h>

#include <cstring>
#include <iostream>
#include <fstream>

namespace tessera::cli {
namespace fs = std::filesystem;

namespace {
const char* const marker = ".tessera-output";
}

Output_directory::Output_directory(const std::string& dir, bool force,
                                   std::vector<std::string> inputs)
    : dir_(dir), inputs_(std::move(inputs)) {
  std::error_code ec;
  if (dir.empty())
    throw User_error("--out needs a directory");
  if (fs::exists(dir_, ec)) {
    if (!fs::is_directory(dir_, ec))
      throw User_error(dir + ": exists and is not a directory");
    const bool ours = fs::exists(dir_ / marker, ec);
    const bool empty = fs::is_empty(dir_, ec);
    if (!ours && !empty && !force)
      throw User_error(dir + ": directory holds files Tessera did not write; pass --force to "
                             "write into it anyway");
  } else if (!fs::create_directories(dir_, ec) || ec) {
    throw User_error(dir + ": cannot create directory (" + ec.message() + ")");
  }
  write_text_file((dir_ / marker).string(), "This directory holds output of the tessera tool.\n");
}

std::string Output_directory::file(const std::string& name) const {
  const fs::path p = dir_ / name;
  for (const std::string& in : inputs_) {
    std::error_code ec;
    if (fs::exists(p, ec) && fs::equivalent(p, in, ec))
      throw User_error(p.string() + " is an input file; refusing to overwrite it");
  }
  return p.string();
}

std::string write_failure(const std::string& path) {
  const int e = errno;
  return "cannot write " + path + (e != 0 ? std::string(": ") + std::strerror(e) : std::string());
}

void write_text_file(const std::string& path, const std::string& text) {
  write_checked_stream(path, [&](std::ostream& out) {
    out << text;
    return true;
  });
}

void write_view(const View_scene& scene, const std::string& path) {
  write_checked(path, [&](const std::string& tmp) { return write_view_html(scene, tmp); });
}

void add_view_flag(CLI::App* cmd, bool& view) {
  cmd->add_flag("--view", view, "Also write view.html: the result in 3D (see `tessera view`)");
}

std::string write_result_view(const Output_directory& dir, const std::string& mesh) {
  const View_scene_result scene = read_view_scene(dir.path().string(), mesh);
  if (!scene)
    throw User_error(scene.message);
  const std::string page = dir.file("view.html");
  write_view(scene.scene, page);
  return page;
}

std::vector<std::string> with_view(std::vector<std::string> written, const Output_directory& dir,
                                   bool view, const std::string& mesh) {
  if (view)
    written.push_back(write_result_view(dir, mesh));
  return written;
}

void print_written(const std::vector<std::string>& written) {
  std::cout << "wrote";
  for (std::size_t i = 0; i < written.size(); ++i)
    std::cout << (i ? ", " : " ") << written[i];
  std::cout << "\n";
}

} // namespace tessera::cli
