// The body of read_mesh() (tessera/io/read_mesh.h) and the checks it makes on the file: non-finite
// tokens, unused or duplicated points, coordinates too large or a mesh too small for double
// precision. Included at the end of the public header.
#pragma once

#include <tessera/io/read_mesh.h>

#include <tessera/io/internal/bounded_readers.h>
#include <tessera/io/internal/repair_soup.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace tessera {
namespace internal {

/// The vector area of `polygon` (Newell's normal, twice the area long), zero when its corners lie
/// on one line.
template <typename Point, typename Index>
std::array<double, 3> newell_vector(const std::vector<Point>& points,
                                    const std::vector<Index>& polygon) {
  std::array<double, 3> n{{0, 0, 0}};
  const std::size_t k = polygon.size();
  for (std::size_t j = 0; j < k; ++j) {
    const auto &a = points[polygon[j]], &b = points[polygon[(j + 1) % k]];
    const double px = CGAL::to_double(a.x()), py = CGAL::to_double(a.y()),
                 pz = CGAL::to_double(a.z()), qx = CGAL::to_double(b.x()),
                 qy = CGAL::to_double(b.y()), qz = CGAL::to_double(b.z());
    n[0] += (py - qy) * (pz + qz);
    n[1] += (pz - qz) * (px + qx);
    n[2] += (px - qx) * (py + qy);
  }
  return n;
}

/// The first corner of `polygon` that lies, seen along the polygon's (Newell) normal, within a
/// billionth of the polygon's size of an earlier corner, or `polygon.size()` when none does (also
/// when the polygon has no normal: its zero area is reported elsewhere).
template <typename Point, typename Index>
std::size_t corners_seen_together(const std::vector<Point>& points,
                                  const std::vector<Index>& polygon) {
  const std::size_t k = polygon.size();
  std::array<double, 3> n = newell_vector(points, polygon);
  std::vector<std::array<double, 3>> p(k);
  for (std::size_t j = 0; j < k; ++j) {
    const auto& a = points[polygon[j]];
    p[j] = {{CGAL::to_double(a.x()), CGAL::to_double(a.y()), CGAL::to_double(a.z())}};
  }
  const double ln = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (!(ln > 0) || !std::isfinite(ln))
    return k;
  for (double& c : n)
    c /= ln;
  // A unit vector u orthogonal to n, and v = n × u.
  std::array<double, 3> u = std::abs(n[0]) < 0.9 ? std::array<double, 3>{{0, -n[2], n[1]}}
                                                 : std::array<double, 3>{{-n[2], 0, n[0]}};
  const double lu = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  for (double& c : u)
    c /= lu;
  const std::array<double, 3> v{
      {n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]}};
  std::vector<std::pair<std::array<double, 2>, std::size_t>> seen(k);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t j = 0; j < k; ++j) {
    const auto& q = p[j];
    seen[j] = {{{q[0] * u[0] + q[1] * u[1] + q[2] * u[2], q[0] * v[0] + q[1] * v[1] + q[2] * v[2]}},
               j};
    lo = std::min({lo, seen[j].first[0], seen[j].first[1]});
    hi = std::max({hi, seen[j].first[0], seen[j].first[1]});
  }
  const double tolerance = 1e-9 * (hi - lo);
  std::sort(seen.begin(), seen.end());
  std::size_t first = k;
  for (std::size_t a = 0; a < k; ++a)
    for (std::size_t b = a + 1; b < k && seen[b].first[0] - seen[a].first[0] <= tolerance; ++b)
      if (std::abs(seen[b].first[1] - seen[a].first[1]) <= tolerance)
        first = std::min(first, std::max(seen[a].second, seen[b].second));
  return first;
}

/// `x` in 6 significant digits ("1e+300").
inline std::string short_number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", x);
  return buffer;
}

/// True when a text file holds a token such as "nan", "-inf" or "Infinity": stream parsers stop at
/// such tokens, so this tells a user why a file that looks right does not read.
inline bool has_non_finite_token(const std::string& path) {
  std::ifstream in(path);
  std::string token;
  while (in >> token) {
    std::string t;
    for (char c : token)
      if (c != '+' && c != '-')
        t += char(std::tolower(static_cast<unsigned char>(c)));
    if (t == "nan" || t == "inf" || t == "infinity")
      return true;
  }
  return false;
}

/// True when some point is used by no face or equals another point: either makes the file's soup
/// differ from the surface it describes.
template <typename Point>
bool has_unused_or_duplicated_points(const std::vector<Point>& points,
                                     const std::vector<std::vector<std::size_t>>& polygons) {
  std::vector<char> used(points.size(), 0);
  for (const auto& poly : polygons)
    for (std::size_t v : poly)
      used[v] = 1;
  if (std::find(used.begin(), used.end(), 0) != used.end())
    return true;
  std::vector<std::size_t> order(points.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return points[a] < points[b]; });
  for (std::size_t i = 1; i < order.size(); ++i)
    if (points[order[i]] == points[order[i - 1]])
      return true;
  return false;
}

} // namespace internal

template <typename TriangleMesh>
Read_mesh_result read_mesh(const std::string& path, TriangleMesh& tm,
                           const Read_mesh_options& options) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using Point = typename boost::property_traits<
      typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type>::value_type;

  clear(tm);
  Read_mesh_result result;
  auto fail = [&](Read_status s, std::string msg) {
    clear(tm);
    result.status = s;
    result.message = path + ": " + std::move(msg);
    return result;
  };

  const std::string ext = file_extension(path);
  if (!is_supported_mesh_extension(ext))
    return fail(Read_status::unsupported_extension,
                "unsupported extension '" + ext + "' (expected .off, .obj, .ply or .stl)");
  {
    std::ifstream probe(path, std::ios::binary);
    if (!probe)
      return fail(Read_status::file_not_found, "cannot open file (missing or unreadable)");
    if (probe.peek() == std::ifstream::traits_type::eof())
      return fail(Read_status::empty_file, "file is empty");
  }

  // Coordinates are read as doubles whatever the mesh kernel, so NaN and inf can be detected.
  std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> coords;
  std::vector<std::vector<std::size_t>> polygons;
  bool parsed = false;
  std::string why;
  std::error_code size_error;
  const std::uintmax_t bytes = std::filesystem::file_size(path, size_error);
  if (ext == ".ply" && !size_error)
    why = internal::check_ply(path, bytes);
  if (why.empty() && !size_error) {
    try {
      if (ext == ".off") {
        parsed = internal::read_off_bounded(path, bytes, coords, polygons, why);
      } else {
        parsed =
            CGAL::IO::read_polygon_soup(path, coords, polygons, CGAL::parameters::verbose(false));
      }
    } catch (const std::exception&) {
      parsed = false;
    }
  }
  if (!parsed && internal::has_non_finite_token(path))
    return fail(Read_status::non_finite_coordinates, "holds a NaN or infinite coordinate");
  if (!parsed)
    return fail(Read_status::parse_error,
                "not a valid " + ext.substr(1) + " file" + (why.empty() ? "" : ": " + why));
  result.input_vertices = coords.size();
  result.input_faces = polygons.size();
  if (polygons.empty())
    return fail(Read_status::no_faces, "file holds no faces");

  for (std::size_t i = 0; i < coords.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(coords[i][k]))
        return fail(Read_status::non_finite_coordinates,
                    "vertex " + std::to_string(i) + " has a NaN or infinite coordinate");
  {
    // Every command squares lengths in doubles: beyond 1e150 they overflow, below 1e-150 they
    // vanish (found by the degenerate-geometry sweep of issue 17: NaN fields written with exit
    // code 0, TetGen aborting).
    double extent = 0;
    std::array<double, 3> lo{}, hi{};
    for (std::size_t i = 0; i < coords.size(); ++i)
      for (int k = 0; k < 3; ++k) {
        const double x = coords[i][k];
        if (std::abs(x) > 1e150)
          return fail(Read_status::degenerate_geometry,
                      "vertex " + std::to_string(i) + " has a coordinate of " +
                          internal::short_number(x) +
                          ", beyond 1e150: squared lengths overflow double precision (rescale "
                          "the mesh)");
        lo[k] = i == 0 ? x : std::min(lo[k], x);
        hi[k] = i == 0 ? x : std::max(hi[k], x);
      }
    for (int k = 0; k < 3; ++k)
      extent = std::max(extent, hi[k] - lo[k]);
    if (!coords.empty() && extent < 1e-150)
      return fail(Read_status::degenerate_geometry,
                  extent == 0 ? std::string("every vertex is at the same point")
                              : "the mesh is " + internal::short_number(extent) +
                                    " across, below 1e-150: squared lengths vanish in double "
                                    "precision (rescale the mesh)");
  }
  bool needs_repair = false;
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    const auto& poly = polygons[f];
    for (std::size_t v : poly)
      if (v >= coords.size())
        return fail(Read_status::invalid_face,
                    "face " + std::to_string(f) + " refers to a vertex that does not exist");
    if (poly.size() < 3) {
      if (options.repair == Mesh_repair::none)
        return fail(Read_status::invalid_face,
                    "face " + std::to_string(f) + " has fewer than 3 vertices");
      needs_repair = true;
    }
  }

  std::vector<Point> points;
  points.reserve(coords.size());
  for (const auto& c : coords)
    points.emplace_back(c.x(), c.y(), c.z());

  // A clean file keeps its vertex ids; anything else goes through the counted repair.
  needs_repair = needs_repair || internal::has_unused_or_duplicated_points(coords, polygons) ||
                 !PMP::is_polygon_soup_a_polygon_mesh(polygons);
  if (needs_repair) {
    const internal::Soup_repair repair = internal::repair_soup(points, polygons, options.repair);
    result.changes = repair.changes;
    if (repair.refused_by_policy)
      return fail(Read_status::needs_repair,
                  repair.refusal + "; refused because repairs are off (--strict)");
    if (!repair.refusal.empty())
      return fail(Read_status::non_manifold, "not a manifold surface: " + repair.refusal);
    if (polygons.empty())
      return fail(Read_status::no_faces, "file holds no valid faces");
  }
  for (std::size_t f = 0; f < polygons.size(); ++f)
    if (polygons[f].size() > 3) {
      if (!options.triangulate)
        return fail(Read_status::invalid_face, "face " + std::to_string(f) + " is not a triangle");
      ++result.triangulated_faces;
    }

  bool some_area = false;
  for (const auto& poly : polygons) {
    // Checked on the soup, before a mesh is built for nothing.
    const std::array<double, 3> n = internal::newell_vector(points, poly);
    if (n[0] != 0 || n[1] != 0 || n[2] != 0) {
      some_area = true;
      break;
    }
  }
  if (!some_area)
    return fail(Read_status::degenerate_geometry,
                "every face has zero area (all its vertices on one line)");
  // CGAL triangulates a polygon in its plane (a constrained Delaunay triangulation of its corners
  // seen along its normal); two corners seen at one place there (a corner above another of a
  // twisted polygon) break that triangulation's precondition (found by fuzzing).
  for (std::size_t f = 0; f < polygons.size() && result.triangulated_faces > 0; ++f)
    if (polygons[f].size() > 3) {
      const std::size_t k = internal::corners_seen_together(points, polygons[f]);
      if (k < polygons[f].size())
        return fail(Read_status::invalid_face,
                    "face " + std::to_string(f) + " cannot be triangulated: its corner " +
                        std::to_string(k) +
                        " lies on another seen along the face's normal (a twisted polygon)");
    }
  PMP::polygon_soup_to_polygon_mesh(points, polygons, tm);
  if (result.triangulated_faces > 0 && !PMP::triangulate_faces(tm))
    return fail(Read_status::invalid_face, "a polygon could not be triangulated");
  if (!CGAL::is_valid_polygon_mesh(tm))
    return fail(Read_status::non_manifold, "the faces do not form a valid surface");
  return result;
}

} // namespace tessera
