// Guards around CGAL 5.5's mesh readers for the hostile inputs that fuzzing found
// (doc/reliability.md): counts that the OFF and PLY readers trust and allocate before reading ("OFF
// 3 4000000000 0", a face line "1e10 0 1 2", a PLY list of 2^31 entries), and PLY headers with a
// property before any element.
#pragma once

#include <CGAL/IO/Color.h>
#include <CGAL/IO/OFF/File_header_extended_OFF.h>
#include <CGAL/IO/OFF/File_scanner_OFF.h>
#include <CGAL/IO/binary_file_io.h>
#include <CGAL/IO/io.h>
#include <CGAL/Kernel_traits.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace tessera::internal {

/// Colours an OFF file gave, one per vertex and one per face, when every vertex (face) line had
/// one; read by `read_off_bounded()` when asked.
struct Off_colors {
  std::vector<CGAL::IO::Color> vertex, face;
};

// The colour of an ASCII OFF line, read as CGAL's scanner reads it (1 number: an index into the OFF
// colour map; 3 or 4: RGB(A) as integers, or as fractions when one is not an integer), from
// `count` numbers at `first`; false when the line has none or a count CGAL's scanner would read
// past (2, or more than 4).
inline bool off_line_color(const std::vector<double>& entries, std::size_t first, std::size_t count,
                           CGAL::IO::Color& color) {
  if (count == 1) {
    const double id = entries[first];
    if (!(id >= 0 && id < 149 && id == std::floor(id)))
      return false; // the colour map has 149 entries, and CGAL 5.5 does not check the index
    color = CGAL::File_scanner_OFF::get_indexed_color(int(id));
    return true;
  }
  if (count != 3 && count != 4)
    return false;
  const double* c = &entries[first];
  const bool integers =
      std::floor(c[0]) == c[0] && std::floor(c[1]) == c[1] && std::floor(c[2]) == c[2];
  auto channel = [&](double v) {
    const double x = integers ? v : 255 * v;
    return static_cast<unsigned char>(std::isfinite(x) ? std::clamp(x, 0.0, 255.0) : 0.0);
  };
  color = CGAL::IO::Color(channel(c[0]), channel(c[1]), channel(c[2]));
  return true;
}

/// The counts of an OFF header (vertices, faces, edges), read with the stream operations of CGAL
/// 5.5's header parser (`File_header_OFF_impl.h`) so that they are the numbers it will see: the
/// leading '#' lines, the keyword (ST, C, N, 4, n prefixes; OFF or SKEL), then either the counts as
/// text or "BINARY" and big-endian 32-bit integers. That parser sizes a hint from them as `2 * E`
/// and `int(double(V + F + 10) * 2.1)`, a signed overflow or an out-of-range cast for a header
/// announcing a billion faces; this check runs first and refuses what would overflow. Returns
/// false with `why` set when the counts are out of bounds; true otherwise, also when the header is
/// not one this reads (CGAL's parser then refuses it without reaching the arithmetic).
inline bool off_header_counts_fit(std::istream& in, std::uintmax_t file_bytes, std::string& why) {
  char c = 0;
  while ((in >> c) && c == '#')
    in >> CGAL::skip_until_EOL;
  if (!in)
    return true;
  std::string keyword(1, c);
  while (keyword.size() < 41 && in.get(c) && std::isalnum(static_cast<unsigned char>(c)))
    keyword += c;
  const bool skel = keyword.size() >= 4 && keyword.compare(keyword.size() - 4, 4, "SKEL") == 0;
  const bool dimensional = keyword.size() >= 4 && keyword[keyword.size() - 4] == 'n';
  in >> CGAL::skip_comment_OFF >> c;
  if (!in)
    return true;
  long long v = 0, f = 0, e = 0;
  if (c >= 0 && std::isdigit(static_cast<unsigned char>(c))) {
    in.putback(c);
    long long dimension = 0;
    if (dimensional)
      in >> dimension;
    in >> v >> f;
    if (!skel)
      in >> e;
  } else {
    std::string word(1, c);
    while (word.size() < 41 && in.get(c) && std::isalnum(static_cast<unsigned char>(c)))
      word += c;
    if (word != "BINARY")
      return true;
    if (c != '\n')
      in >> CGAL::skip_until_EOL;
    std::int32_t a = 0, b = 0, d = 0;
    CGAL::I_Binary_read_big_endian_integer32(in, a);
    if (dimensional)
      CGAL::I_Binary_read_big_endian_integer32(in, a);
    CGAL::I_Binary_read_big_endian_integer32(in, b);
    if (!skel)
      CGAL::I_Binary_read_big_endian_integer32(in, d);
    v = a;
    f = b;
    e = d;
  }
  // A count that did not read is left to CGAL's parser, which fails on it the same way.
  const long long bytes = static_cast<long long>(std::min<std::uintmax_t>(file_bytes, 1ULL << 40));
  if (v < 0 || f < 0 || e < 0 || v > bytes / 6 + 1 || f > bytes / 2 + 1 || e > bytes / 2 + 1) {
    why = "the header announces " + std::to_string(v) + " vertices and " + std::to_string(f) +
          " faces" + (e > bytes / 2 + 1 || e < 0 ? " and " + std::to_string(e) + " edges" : "") +
          (v < 0 || f < 0 || e < 0
               ? std::string(", a negative count")
               : ", more than the file's " + std::to_string(file_bytes) + " bytes can hold");
    return false;
  }
  return true;
}

/// Reads an OFF file into a soup, with every count checked against the bytes of the file before
/// anything is allocated: a vertex takes at least 6 bytes ("0 0 0\n", 12 in binary OFF) and a face
/// index at least 2. CGAL's `File_scanner_OFF` reads the header and the body of a binary file (the
/// loop of CGAL's `read_OFF()`); the body of an ASCII file is read here, line by line as that
/// scanner reads it (comment lines skipped, the rest of a line after '#' dropped), because CGAL
/// 5.5's ASCII scanner takes the first coloured line's layout for every later line and reads
/// colours past the numbers of a shorter one (fuzz_read_off), casts a face's size and indices to
/// `std::size_t` unchecked (a negative size is undefined behaviour) and indexes its colour map
/// unchecked. With `colors`, the vertex and face colours are kept (a list stays empty unless every
/// line of its kind has a colour). On failure `why` says what was wrong when it is more than "not a
/// valid off file".
template <typename Point>
bool read_off_bounded(const std::string& path, std::uintmax_t file_bytes,
                      std::vector<Point>& points, std::vector<std::vector<std::size_t>>& polygons,
                      std::string& why, Off_colors* colors = nullptr) {
  std::ifstream is(path, std::ios::binary);
  if (!is)
    return false;
  if (!off_header_counts_fit(is, file_bytes, why))
    return false;
  is.clear();
  is.seekg(0);
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
  if (scanner.binary()) {
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
    }
    return !is.fail();
  }

  std::vector<double> entries;
  std::string line;
  auto read_line = [&]() {
    is >> CGAL::skip_comment_OFF;
    std::getline(is, line);
    const std::size_t hash = line.find('#');
    if (hash != std::string::npos)
      line.resize(hash);
    std::istringstream numbers(line);
    entries.clear();
    double d;
    while (numbers >> CGAL::IO::iformat(d)) // CGAL's own number syntax
      entries.push_back(d);
    return bool(is) || !line.empty();
  };
  const std::size_t h = scanner.is_homogeneous() ? 1 : 0;
  const std::size_t coordinates = 3 + h, normals = scanner.has_normals() ? 3 + h : 0,
                    textures = scanner.has_textures() ? 2 + h : 0;
  std::vector<CGAL::IO::Color> vertex_colors, face_colors;
  for (std::size_t i = 0; i < nv; ++i) {
    if (!read_line() || entries.size() < coordinates + normals + textures)
      return false;
    const double w = h ? entries[3] : 1;
    if (w == 0) {
      why = "vertex " + std::to_string(i) + " has homogeneous weight 0";
      return false;
    }
    points[i] = Point(entries[0] / w, entries[1] / w, entries[2] / w);
    CGAL::IO::Color c;
    if (colors && scanner.has_colors() && vertex_colors.size() == i &&
        off_line_color(entries, coordinates + normals,
                       entries.size() - coordinates - normals - textures, c))
      vertex_colors.push_back(c);
  }
  for (std::size_t i = 0; i < nf; ++i) {
    if (!read_line() || entries.empty())
      return false;
    // A face's size and indices must be whole numbers in range before they are cast.
    auto whole = [](double v, double below) { return v >= 0 && v < below && v == std::floor(v); };
    if (!whole(entries[0], double(file_bytes) / 2 + 1)) {
      why = "face " + std::to_string(i) + " announces " +
            (entries[0] >= 0 ? "more vertices than the file can hold" : "a negative size");
      return false;
    }
    const std::size_t size = std::size_t(entries[0]);
    if (entries.size() < size + 1)
      return false;
    polygons[i].resize(size);
    for (std::size_t j = 0; j < size; ++j) {
      if (!whole(entries[j + 1], double(nv))) {
        why = "face " + std::to_string(i) + " has a vertex index out of range";
        return false;
      }
      polygons[i][j] = std::size_t(entries[j + 1]);
    }
    CGAL::IO::Color c;
    if (colors && scanner.has_colors() && face_colors.size() == i &&
        off_line_color(entries, size + 1, entries.size() - size - 1, c))
      face_colors.push_back(c);
  }
  if (colors) {
    colors->vertex =
        vertex_colors.size() == nv ? std::move(vertex_colors) : std::vector<CGAL::IO::Color>{};
    colors->face =
        face_colors.size() == nf ? std::move(face_colors) : std::vector<CGAL::IO::Color>{};
  }
  return true;
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
