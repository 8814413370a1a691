// Colour regions of a mesh read from an OFF or PLY file's per-face or per-vertex colours, as integer
// region ids per face: the borders between regions are feature lines for the field (Lai et al., §5).
#pragma once

#include <tessera/io/read_mesh.h>

#include <CGAL/IO/Color.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>

#include <algorithm>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace tessera {

enum class Color_regions_status { ok, unsupported_extension, read_failed, no_colors, mismatch };

/// Summary of `read_color_regions()`.
struct Color_regions_result {
  Color_regions_status status = Color_regions_status::ok;
  std::string message;
  /// Where the colours came from.
  bool face_colors = false;
  /// Number of distinct colours (regions are numbered 0 .. regions−1 in colour order).
  std::size_t regions = 0;
  explicit operator bool() const { return status == Color_regions_status::ok; }
};

/// Reads the colours of `path` (OFF or PLY) for `tm`, which must have been read from the same file by
/// `read_mesh()` (vertices in file order). Face colours win over vertex colours; with vertex colours a
/// face takes the colour that at least two of its corners share (else its first corner's). Faces
/// that `read_mesh()` made by splitting a polygon keep the polygon's colour. `face_region` receives
/// an integer region id per face.
template <typename TriangleMesh, typename FaceRegionMap>
Color_regions_result read_color_regions(const std::string& path, const TriangleMesh& tm,
                                        FaceRegionMap face_region) {
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
    if (ext == ".off") ok = CGAL::IO::read_OFF(path, points, polygons, np);
    else if (ext == ".ply") ok = CGAL::IO::read_PLY(path, points, polygons, np);
    else return fail(Color_regions_status::unsupported_extension, "colours are read from .off or .ply files only");
  } catch (const std::exception&) {
    ok = false;
  }
  if (!ok) return fail(Color_regions_status::read_failed, "cannot read the colours");
  result.face_colors = face_colors.size() == polygons.size() && !polygons.empty();
  if (!result.face_colors && vertex_colors.size() != points.size())
    return fail(Color_regions_status::no_colors, "has no per-face or per-vertex colours");
  if (points.size() != vertices(tm).size())
    return fail(Color_regions_status::mismatch, "the mesh does not have the file's vertices");

  std::map<CGAL::IO::Color, int> id;
  for (const auto& c : result.face_colors ? face_colors : vertex_colors) id.emplace(c, 0);
  int next = 0;
  for (auto& entry : id) entry.second = next++;
  result.regions = id.size();

  auto vertex_id = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  std::size_t k = 0;
  for (auto v : vertices(tm)) put(vertex_id, v, k++);
  std::vector<std::vector<std::size_t>> polygons_at(points.size());
  for (std::size_t p = 0; p < polygons.size(); ++p)
    for (std::size_t v : polygons[p])
      if (v < points.size()) polygons_at[v].push_back(p);
  for (auto f : faces(tm)) {
    std::vector<std::size_t> corners;
    for (auto v : CGAL::vertices_around_face(halfedge(f, tm), tm)) corners.push_back(get(vertex_id, v));
    if (result.face_colors) {
      int region = -1;
      for (std::size_t p : polygons_at[corners[0]]) {
        const auto& poly = polygons[p];
        if (std::all_of(corners.begin(), corners.end(),
                        [&](std::size_t c) { return std::find(poly.begin(), poly.end(), c) != poly.end(); })) {
          region = id[face_colors[p]];
          break;
        }
      }
      if (region < 0) return fail(Color_regions_status::mismatch, "a face of the mesh is not in the file");
      put(face_region, f, region);
    } else {
      const CGAL::IO::Color& a = vertex_colors[corners[0]];
      const CGAL::IO::Color& b = vertex_colors[corners[1]];
      const CGAL::IO::Color& c = vertex_colors[corners[2]];
      put(face_region, f, id[(b == c && !(a == b)) ? b : a]);
    }
  }
  return result;
}

} // namespace tessera
