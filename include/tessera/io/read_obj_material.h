// The texture image an OBJ file names: its `mtllib` material libraries' first `map_Kd` (the diffuse
// colour map), as Blender, MeshLab and most exporters write them.
#pragma once

#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

namespace tessera {

/// The path of the first `map_Kd` image in the material libraries `obj_path` names (`mtllib`),
/// resolved against the library's folder; nothing when the file names none or cannot be read.
/// Options before the file name (`-s 1 1 1`, `-bm 0.5`) are skipped: the name is the last token.
inline std::optional<std::string> read_obj_texture_path(const std::string& obj_path) {
  namespace fs = std::filesystem;
  std::ifstream obj(obj_path);
  std::string line;
  while (obj && std::getline(obj, line)) {
    std::istringstream words(line);
    std::string key, library;
    if (!(words >> key) || key != "mtllib")
      continue;
    while (words >> library) {
      const fs::path mtl = fs::path(obj_path).parent_path() / library;
      std::ifstream in(mtl);
      std::string entry;
      while (in && std::getline(in, entry)) {
        std::istringstream w(entry);
        std::string k, token, last;
        if (!(w >> k) || k != "map_Kd")
          continue;
        while (w >> token)
          last = token;
        if (!last.empty())
          return (mtl.parent_path() / last).string();
      }
    }
  }
  return std::nullopt;
}

} // namespace tessera
