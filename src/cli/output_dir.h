// The --out directory of a command: created when missing, reused when Tessera made it, refused when it
// holds other files (unless --force), and never a place where an input file would be overwritten.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace tessera::cli {

class Output_directory {
public:
  /// Prepares `dir`; `inputs` are the files the command reads. Throws User_error when refused.
  Output_directory(const std::string& dir, bool force, std::vector<std::string> inputs);
  /// Path of output file `name` inside the directory; throws User_error if it is an input file.
  std::string file(const std::string& name) const;
  const std::filesystem::path& path() const { return dir_; }

private:
  std::filesystem::path dir_;
  std::vector<std::string> inputs_;
};

} // namespace tessera::cli
