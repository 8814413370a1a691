// Guards around CGAL 5.5's mesh readers for the hostile inputs that fuzzing found
// (doc/reliability.md): counts that the OFF and PLY readers trust and allocate before reading ("OFF
// 3 4000000000 0", a face line "1e10 0 1 2", a PLY list of 2^31 entries), and PLY headers with a
// property before any element.
#pragma once

#include <CGAL/IO/OFF/File_scanner_OFF.h>
#include <CGAL/Kernel_traits.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace tessera::internal {

/// Reads an OFF file into a soup with CGAL's `File_scanner_OFF`, the loop of CGAL's `read_OFF()`
/// with every count checked against the bytes of the file before anything is allocated: a vertex
/// takes at least 6 bytes ("0 0 0\n", 12 in binary OFF) and a face index at least 2. On failure
/// `why` says what was wrong when it is more than "not a valid off file".
template <typename Point>
bool read_off_bounded(const std::string& path, std::uintmax_t file_bytes,
                      std::vector<Point>& points, std::vector<std::vector<std::size_t>>& polygons,
                      std::string& why) {
  std::ifstream is(path, std::ios::binary);
  if (!is)
    return false;
  CGAL::File_scanner_OFF scanner(is, false);
  if (is.fail())
    return false;
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
    if (!is.good())
      return false;
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
    if (!is.good())
      return false;
  }
  for (std::size_t i = 0; i < nf; ++i) {
    std::size_t size = std::size_t(-1);
    scanner.scan_facet(size, i);
    if ((!is.eof() && !is.good()) || size == std::size_t(-1))
      return false;
    if (size > file_bytes / 2) {
      why = "face " + std::to_string(i) + " announces " + std::to_string(size) +
            " vertices, more than the file can hold";
      return false;
    }
    polygons[i].resize(size);
    for (std::size_t j = 0; j < size; ++j) {
      std::size_t id = 0;
      scanner.scan_facet_vertex_index(id, j + 1, i);
      if (!is)
        return false;
      polygons[i][j] = id;
    }
    if (scanner.has_fcolors()) {
      unsigned char r, g, b;
      scanner.scan_color(r, g, b);
    }
  }
  return !is.fail();
}

/// Empty when a PLY file is one CGAL's reader handles safely; otherwise what is wrong with it.
/// CGAL 5.5 dereferences the last element of an empty list for a property declared before any
/// element, and resizes a list to the count it reads ("list int int": a count of 2^31 allocates
/// 8 GB). Lists whose count is one byte cannot do harm; files with wider counts are walked once,
/// and every count must fit in the bytes that are left.
inline std::string check_ply(const std::string& path, std::uintmax_t file_bytes) {
  std::ifstream in(path, std::ios::binary);
  struct Property {
    int count_bytes = 0; // 0: a scalar
    int item_bytes = 0;
    bool integer_items = false;
  };
  auto is_integer_type = [](const std::string& type) {
    return type != "float" && type != "float32" && type != "double" && type != "float64";
  };
  // In an ASCII file every value must read as its type: CGAL 5.5 reads a value that does not (a
  // word, or "1.5" for an int) into an uninitialized variable and goes on, and a list count read
  // that way resized a list to gigabytes (found by fuzz_read_ply, only now and then: it depends on
  // what the stack held).
  auto reads_as = [](const std::string& token, bool integer) {
    if (token.empty())
      return false;
    char* end = nullptr;
    if (integer)
      (void)std::strtoll(token.c_str(), &end, 10);
    else
      (void)std::strtod(token.c_str(), &end);
    return end == token.c_str() + token.size();
  };
  struct Element {
    std::uintmax_t count = 0;
    std::vector<Property> properties;
  };
  auto bytes_of = [](const std::string& type) {
    if (type == "char" || type == "uchar" || type == "int8" || type == "uint8")
      return 1;
    if (type == "short" || type == "ushort" || type == "int16" || type == "uint16")
      return 2;
    if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" ||
        type == "float32")
      return 4;
    if (type == "double" || type == "float64")
      return 8;
    return 0;
  };
  std::vector<Element> elements;
  std::string line, format;
  bool wide_counts = false, ended = false;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "end_header") {
      ended = true;
      break;
    }
    if (number == 2)
      words >> format; // as CGAL does: line 2's second word, whatever its first
    if (keyword == "element") {
      elements.emplace_back();
      std::string name;
      // Every item takes at least one byte.
      if (!(words >> name >> elements.back().count) || elements.back().count > file_bytes)
        return "header line " + std::to_string(number) +
               " announces more items than the file can hold";
    }
    if (keyword == "property") {
      if (elements.empty())
        return "header line " + std::to_string(number) + " declares a property before any element";
      std::string type, count_type, item_type;
      words >> type;
      Property property;
      if (type == "list") {
        words >> count_type >> item_type;
        property.count_bytes = bytes_of(count_type);
        property.item_bytes = bytes_of(item_type);
        property.integer_items = is_integer_type(item_type);
        wide_counts = wide_counts || property.count_bytes > 1;
      } else {
        property.item_bytes = bytes_of(type);
        property.integer_items = is_integer_type(type);
      }
      // A property of unknown type is dropped, as CGAL drops it (the rows are read without it).
      if (property.item_bytes > 0 && (type != "list" || property.count_bytes > 0))
        elements.back().properties.push_back(property);
    }
  }
  // Without end_header CGAL 5.5 goes on to read a list count from the end of the file.
  if (!ended)
    return "the header has no end_header line";
  if (!wide_counts)
    return {};
  const bool binary = format != "ascii";
  const bool big_endian = format == "binary_big_endian";
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const auto& properties = elements[e].properties;
    if (binary && std::all_of(properties.begin(), properties.end(),
                              [](const Property& p) { return p.count_bytes == 0; })) {
      // Fixed-size rows (the vertices, as a rule): one seek.
      std::uintmax_t row = 0;
      for (const Property& p : properties)
        row += std::uintmax_t(p.item_bytes);
      in.seekg(std::streamoff(row * elements[e].count), std::ios::cur);
      if (!in || std::uintmax_t(in.tellg()) > file_bytes)
        return "the file ends inside element " + std::to_string(e);
      continue;
    }
    for (std::uintmax_t i = 0; i < elements[e].count; ++i)
      for (const Property& p : elements[e].properties) {
        // CGAL 5.5 reads a list count past the end of the file as an uninitialized value.
        if (!in)
          return "the file ends inside element " + std::to_string(e) + " item " + std::to_string(i);
        std::uintmax_t items = 1;
        if (p.count_bytes > 0) {
          if (binary) {
            unsigned char raw[8] = {};
            in.read(reinterpret_cast<char*>(raw), p.count_bytes);
            std::uint64_t count = 0;
            for (int k = 0; k < p.count_bytes; ++k)
              count |= std::uint64_t(raw[big_endian ? p.count_bytes - 1 - k : k]) << (8 * k);
            // Counts are signed in most files: a negative one reads as a huge unsigned count.
            items = count;
          } else {
            std::string token;
            in >> token;
            if (in && !reads_as(token, true))
              return "element " + std::to_string(e) + " item " + std::to_string(i) +
                     ": the list count '" + token + "' is not an integer";
            const double count = in ? std::strtod(token.c_str(), nullptr) : 0;
            items = count >= 0 && count < double(file_bytes)
                        ? std::uintmax_t(count)
                        : std::numeric_limits<std::uintmax_t>::max();
          }
          if (!in)
            return "the file ends inside element " + std::to_string(e) + " item " +
                   std::to_string(i);
          if (items > file_bytes / 2)
            return "element " + std::to_string(e) + " item " + std::to_string(i) +
                   " has a list of " + std::to_string(items) +
                   " entries, more than the file can hold";
        }
        if (binary) {
          in.seekg(std::streamoff(items * std::uintmax_t(p.item_bytes)), std::ios::cur);
        } else {
          std::string token;
          for (std::uintmax_t k = 0; k < items && in >> token; ++k)
            if (!reads_as(token, p.integer_items))
              return "element " + std::to_string(e) + " item " + std::to_string(i) + ": '" + token +
                     "' is not " + (p.integer_items ? "an integer" : "a number");
        }
      }
  }
  return {};
}

} // namespace tessera::internal
