// The colour reading behind read_color_regions() and read_face_colors()
// (tessera/fields/color_regions.h): the file's colours matched to the mesh's faces, and a face's
// region or colour from its corners' colours. Included at the end of color_regions.h.
#pragma once

#include <tessera/fields/color_regions.h>
#include <tessera/io/read_mesh.h>

#include <CGAL/IO/Color.h>
#include <CGAL/IO/PLY.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <system_error>
#include <vector>

namespace tessera {

namespace internal {

// Reads the colours of `path` for `tm` (see `read_color_regions()`) and calls
// `visit(f, palette, corners)` for each face f of `tm`: `palette` holds the file's distinct face
// colours (or vertex colours when it has no face colours) in colour order, `corners` the palette
// indices of the colours of f's three corners (three times the face's colour with face colours).
template <typename TriangleMesh, typename FaceVisitor>
Color_regions_result visit_corner_colors(const std::string& path, const TriangleMesh& tm,
                                         FaceVisitor visit) {
  Color_regions_result result;
  auto fail = [&](Color_regions_status s, std::string m) {
    result.status = s;
    result.message = path + ": " + std::move(m);
    return result;
  };
  std::vector<typename CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  std::vector<CGAL::IO::Color> vertex_colors, face_colors;
  const auto np = CGAL::parameters::vertex_color_output_iterator(std::back_inserter(vertex_colors))
                      .face_color_output_iterator(std::back_inserter(face_colors))
                      .verbose(false);
  const std::string ext = file_extension(path);
  bool ok = false;
  try {
    if (ext == ".off") {
      // Tessera's bounded OFF reader: CGAL 5.5's read_OFF reads colours past the end of a line
      // (internal/bounded_readers.h).
      std::error_code error;
      const std::uintmax_t bytes = std::filesystem::file_size(path, error);
      internal::Off_colors off_colors;
      std::string why;
      ok = !error && internal::read_off_bounded(path, bytes, points, polygons, why, &off_colors);
      vertex_colors = std::move(off_colors.vertex);
      face_colors = std::move(off_colors.face);
    } else if (ext == ".ply") {
      // The PLY checks read_mesh makes before CGAL's reader (internal/bounded_readers.h).
      std::error_code error;
      const std::uintmax_t bytes = std::filesystem::file_size(path, error);
      ok = !error && internal::check_ply(path, bytes).empty() &&
           CGAL::IO::read_PLY(path, points, polygons, np);
    } else {
      return fail(Color_regions_status::unsupported_extension,
                  "colours are read from .off or .ply files only");
    }
  } catch (const std::exception&) {
    ok = false;
  }
  if (!ok)
    return fail(Color_regions_status::read_failed, "cannot read the colours");
  result.face_colors = face_colors.size() == polygons.size() && !polygons.empty();
  if (!result.face_colors && vertex_colors.size() != points.size())
    return fail(Color_regions_status::no_colors, "has no per-face or per-vertex colours");
  if (points.size() != vertices(tm).size())
    return fail(Color_regions_status::mismatch, "the mesh does not have the file's vertices");

  const std::vector<CGAL::IO::Color>& colors = result.face_colors ? face_colors : vertex_colors;
  std::map<CGAL::IO::Color, std::size_t> id;
  for (const auto& c : colors)
    id.emplace(c, 0);
  std::vector<CGAL::IO::Color> palette;
  for (auto& entry : id) {
    entry.second = palette.size();
    palette.push_back(entry.first);
  }
  result.regions = palette.size();

  auto vertex_id = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  std::size_t k = 0;
  for (auto v : vertices(tm))
    put(vertex_id, v, k++);
  std::vector<std::vector<std::size_t>> polygons_at(points.size());
  for (std::size_t p = 0; p < polygons.size(); ++p)
    for (std::size_t v : polygons[p])
      if (v < points.size())
        polygons_at[v].push_back(p);
  for (auto f : faces(tm)) {
    std::vector<std::size_t> corners;
    for (auto v : CGAL::vertices_around_face(halfedge(f, tm), tm))
      corners.push_back(get(vertex_id, v));
    if (result.face_colors) {
      std::size_t polygon = polygons.size();
      for (std::size_t p : polygons_at[corners[0]]) {
        const auto& poly = polygons[p];
        if (std::all_of(corners.begin(), corners.end(), [&](std::size_t c) {
              return std::find(poly.begin(), poly.end(), c) != poly.end();
            })) {
          polygon = p;
          break;
        }
      }
      if (polygon == polygons.size())
        return fail(Color_regions_status::mismatch, "a face of the mesh is not in the file");
      const std::size_t c = id[colors[polygon]];
      visit(f, palette, std::array<std::size_t, 3>{{c, c, c}});
    } else {
      visit(f, palette,
            std::array<std::size_t, 3>{
                {id[colors[corners[0]]], id[colors[corners[1]]], id[colors[corners[2]]]}});
    }
  }
  return result;
}

// The palette index of a face with vertex colours: the one at least two of its corners share
// (else its first corner's).
inline std::size_t majority_corner(const std::array<std::size_t, 3>& c) {
  return (c[1] == c[2] && c[0] != c[1]) ? c[1] : c[0];
}

// The mean of the colours of a face's three corners (palette indices `c`), rounded per channel.
inline CGAL::IO::Color mean_corner_color(const std::vector<CGAL::IO::Color>& palette,
                                         const std::array<std::size_t, 3>& c) {
  auto channel = [&](std::size_t i) {
    const int sum = palette[c[0]][i] + palette[c[1]][i] + palette[c[2]][i];
    return static_cast<unsigned char>((sum + 1) / 3);
  };
  return CGAL::IO::Color(channel(0), channel(1), channel(2));
}

} // namespace internal

template <typename TriangleMesh, typename FaceRegionMap>
Color_regions_result read_color_regions(const std::string& path, const TriangleMesh& tm,
                                        FaceRegionMap face_region) {
  auto majority = [&](auto f, const std::vector<CGAL::IO::Color>&,
                      const std::array<std::size_t, 3>& c) {
    put(face_region, f, int(internal::majority_corner(c)));
  };
  return internal::visit_corner_colors(path, tm, majority);
}

template <typename TriangleMesh, typename FaceColorMap>
Color_regions_result read_face_colors(const std::string& path, const TriangleMesh& tm,
                                      FaceColorMap face_color) {
  auto mean = [&](auto f, const std::vector<CGAL::IO::Color>& palette,
                  const std::array<std::size_t, 3>& c) {
    put(face_color, f, internal::mean_corner_color(palette, c));
  };
  return internal::visit_corner_colors(path, tm, mean);
}

} // namespace tessera
