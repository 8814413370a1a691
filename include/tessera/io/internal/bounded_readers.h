// Guards around CGAL 5.5's mesh readers for the hostile inputs that fuzzing found (doc/reliability.md):
// counts that the OFF reader trusts and allocates before reading ("OFF 3 4000000000 0", a face line
// "1e10 0 1 2"), and PLY headers that declare a property before any element.
#pragma once

#include <CGAL/IO/OFF/File_scanner_OFF.h>
#include <CGAL/Kernel_traits.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace tessera::internal {

/// Reads an OFF file into a soup with CGAL's `File_scanner_OFF`, the loop of CGAL's `read_OFF()`
/// with every count checked against the bytes of the file before anything is allocated: a vertex
/// takes at least 6 bytes ("0 0 0\n", 12 in binary OFF) and a face index at least 2. On failure
/// `why` says what was wrong when it is more than "not a valid off file".
template <typename Point>
bool read_off_bounded(const std::string& path, std::uintmax_t file_bytes, std::vector<Point>& points,
                      std::vector<std::vector<std::size_t>>& polygons, std::string& why) {
  std::ifstream is(path, std::ios::binary);
  if (!is) return false;
  CGAL::File_scanner_OFF scanner(is, false);
  if (is.fail()) return false;
  const std::size_t nv = scanner.size_of_vertices(), nf = scanner.size_of_facets();
  if (nv > file_bytes / 6 || nf > file_bytes / 2) {
    why = "the header announces " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
          " faces, more than the file's " + std::to_string(file_bytes) + " bytes can hold";
    return false;
  }
  points.resize(nv);
  polygons.resize(nf);
  for (std::size_t i = 0; i < nv; ++i) {
    double x = 0, y = 0, z = 0, w = 1;
    scanner.scan_vertex(x, y, z, w);
    if (!is.good()) return false;
    if (w == 0) {
      why = "vertex " + std::to_string(i) + " has homogeneous weight 0";
      return false;
    }
    points[i] = Point(x / w, y / w, z / w);
    // Per-vertex extras are read to stay in step with the file, then dropped.
    if (scanner.has_normals()) {
      double nx, ny, nz;
      scanner.scan_normal(nx, ny, nz);
    }
    if (scanner.has_vcolors()) {
      unsigned char r, g, b;
      scanner.scan_color(r, g, b);
    }
    if (scanner.has_textures()) {
      double u, v;
      scanner.scan_texture(u, v);
    }
    if (!is.good()) return false;
  }
  for (std::size_t i = 0; i < nf; ++i) {
    std::size_t size = std::size_t(-1);
    scanner.scan_facet(size, i);
    if ((!is.eof() && !is.good()) || size == std::size_t(-1)) return false;
    if (size > file_bytes / 2) {
      why = "face " + std::to_string(i) + " announces " + std::to_string(size) +
            " vertices, more than the file can hold";
      return false;
    }
    polygons[i].resize(size);
    for (std::size_t j = 0; j < size; ++j) {
      std::size_t id = 0;
      scanner.scan_facet_vertex_index(id, j + 1, i);
      if (!is) return false;
      polygons[i][j] = id;
    }
    if (scanner.has_fcolors()) {
      unsigned char r, g, b;
      scanner.scan_color(r, g, b);
    }
  }
  return !is.fail();
}

/// Empty when the PLY header is one CGAL's reader handles safely; otherwise what is wrong with it.
/// (CGAL 5.5 dereferences the last element of an empty list for a property before any element.)
inline std::string check_ply_header(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  bool element_seen = false;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "end_header") return {};
    if (keyword == "element") element_seen = true;
    if (keyword == "property" && !element_seen)
      return "header line " + std::to_string(number) + " declares a property before any element";
  }
  return {};
}

} // namespace tessera::internal
