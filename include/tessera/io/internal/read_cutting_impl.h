// The readers behind read_cutting.h: the checked number parser, and the bodies of read_seams(),
// read_obj_with_uvs() (parsing, the surface, the chart vertices, the pinched pairs) and
// read_exact_polygon_soup(). Included at the end of tessera/io/read_cutting.h.
#pragma once

#include <tessera/io/read_cutting.h>
#include <tessera/topology/pinched_texture_vertex.h>

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <istream>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <type_traits>
#include <utility>
#include <vector>

namespace tessera {

namespace internal {

inline Cutting_read_result cutting_error(Cutting_read_status s, std::size_t line,
                                         const std::string& what) {
  return {s, (line ? "line " + std::to_string(line) + ": " : std::string()) + what, 0};
}

/// Reads one number into `x` through FT's own parser, after checking the token's shape and size:
/// an exact number type expands `1e3000000` into three million digits (minutes of work), so a
/// one-token edit of a file must not reach it. Accepted: decimals `[+-]d[.d][e[+-]d]` with at most
/// 2000 digits and an exponent of at most 2000 in size (every double's exact decimal fits), and
/// rationals `[+-]d/d` with at most 100000 digits and a denominator that is not zero.
template <typename FT> bool read_number(std::istream& in, FT& x) {
  std::string token;
  if (!(in >> token))
    return false;
  std::size_t i = token[0] == '+' || token[0] == '-' ? 1 : 0;
  const auto digits = [&] {
    const std::size_t start = i;
    while (i < token.size() && std::isdigit(static_cast<unsigned char>(token[i])))
      ++i;
    return i - start;
  };
  std::size_t count = digits();
  if (i < token.size() && token[i] == '/') {
    ++i;
    const std::size_t start = i, denominator = digits();
    if (count == 0 || denominator == 0 || i != token.size() || count + denominator > 100000 ||
        token.find_first_not_of('0', start) == std::string::npos) // p/0: GMP traps
      return false;
  } else {
    if (i < token.size() && token[i] == '.') {
      ++i;
      count += digits();
    }
    if (count == 0 || count > 2000)
      return false;
    if (i < token.size() && (token[i] == 'e' || token[i] == 'E')) {
      ++i;
      if (i < token.size() && (token[i] == '+' || token[i] == '-'))
        ++i;
      const std::size_t start = i;
      if (digits() == 0 || i - start > 4 || std::stoi(token.substr(start, i - start)) > 2000)
        return false;
    }
    if (i != token.size())
      return false;
  }
  if constexpr (std::is_same_v<FT, double>) {
    // Doubles straight from the text (a stream per number took most of reading a large OBJ);
    // from_chars takes no '+', and leaves to the stream what it cannot represent.
    const char* first = token.data() + (token[0] == '+' ? 1 : 0);
    const char* last = token.data() + token.size();
    const auto [end, error] = std::from_chars(first, last, x);
    if (error == std::errc() && end == last)
      return true;
  }
  std::istringstream ts(token);
  return bool(ts >> x);
}

// Reads the numbers of `x` in turn with `read_number()`; false at the first that fails.
template <typename FT, std::size_t N> bool read_numbers(std::istream& in, FT (&x)[N]) {
  for (std::size_t k = 0; k < N; ++k)
    if (!read_number(in, x[k]))
      return false;
  return true;
}

// What read_exact_polygon_soup() says of a vertex line it cannot read.
constexpr const char* exact_vertex_error =
    "a vertex needs three numbers (decimal, at most 2000 digits and exponent 2000, or p/q)";

// Whether `x` is a finite number (not NaN, not infinite) once rounded to double.
template <typename FT> bool is_finite_number(const FT& x) {
  const double d = CGAL::to_double(x);
  return d == d && std::abs(d) <= std::numeric_limits<double>::max();
}

// The pinched pairs of an OBJ's chart vertices: chart vertices of one surface vertex (of
// `number_of_vertices`) with the same vt (a vertex has a few chart vertices, listed per vertex),
// given the surface vertex and the vt of each chart vertex, in the order of their first chart
// vertex.
inline std::vector<Pinched_texture_vertex>
pinched_texture_vertices(std::size_t number_of_vertices,
                         const std::vector<std::size_t>& mesh_of_chart_vertex,
                         const std::vector<std::size_t>& texture_of_chart_vertex) {
  std::vector<Pinched_texture_vertex> pinched;
  std::vector<std::size_t> start(number_of_vertices + 1, 0);
  for (std::size_t v : mesh_of_chart_vertex)
    ++start[v + 1];
  for (std::size_t v = 0; v < number_of_vertices; ++v)
    start[v + 1] += start[v];
  std::vector<std::size_t> of_vertex(mesh_of_chart_vertex.size()), fill(start);
  for (std::size_t cv = 0; cv < mesh_of_chart_vertex.size(); ++cv)
    of_vertex[fill[mesh_of_chart_vertex[cv]]++] = cv; // ascending within each vertex
  for (std::size_t v = 0; v < number_of_vertices; ++v)
    for (std::size_t a = start[v]; a < start[v + 1]; ++a) {
      const std::size_t cv = of_vertex[a];
      bool first = true, shared = false;
      for (std::size_t b = start[v]; b < start[v + 1]; ++b)
        if (b != a && texture_of_chart_vertex[of_vertex[b]] == texture_of_chart_vertex[cv]) {
          shared = true;
          first = first && of_vertex[b] > cv;
        }
      if (!shared || !first)
        continue;
      Pinched_texture_vertex x{v, texture_of_chart_vertex[cv], {}};
      for (std::size_t b = start[v]; b < start[v + 1]; ++b)
        if (texture_of_chart_vertex[of_vertex[b]] == texture_of_chart_vertex[cv])
          x.chart_vertices.push_back(of_vertex[b]);
      pinched.push_back(std::move(x));
    }
  std::sort(pinched.begin(), pinched.end(), [](const auto& x, const auto& y) {
    return x.chart_vertices.front() < y.chart_vertices.front();
  });
  return pinched;
}

// Reads `in` line by line and calls read_line(ls, first, number) for each line that holds a token:
// `first` is its first token, `ls` the rest of the line, `number` the line's number from 1. Stops
// at the first line read_line refuses and returns its result; what to do with comments is
// read_line's to decide. One stream serves every line (constructing one costs a locale).
template <typename ReadLine>
Cutting_read_result read_lines(std::istream& in, ReadLine&& read_line) {
  std::string line, first;
  std::istringstream ls;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    ls.clear();
    ls.str(line);
    if (!(ls >> first))
      continue;
    if (Cutting_read_result r = read_line(ls, first, number); !r)
      return r;
  }
  if (in.bad())
    return cutting_error(Cutting_read_status::parse_error, 0, "read error");
  return {};
}

} // namespace internal

template <typename PolygonMesh, typename SeamEdgeMap>
Cutting_read_result read_seams(std::istream& in, const PolygonMesh& tm, SeamEdgeMap seam_edges) {
  const std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> vs(
      vertices(tm).begin(), vertices(tm).end());
  Cutting_read_result r;
  const auto read_line = [&](std::istream& ls, const std::string& first,
                             std::size_t number) -> Cutting_read_result {
    if (first[0] == '#')
      return {};
    std::string tokens[2] = {first, {}}, rest;
    ls >> tokens[1];
    std::size_t ids[2] = {0, 0};
    for (int k = 0; k < 2; ++k) {
      const std::string& t = tokens[k];
      if (t.empty() || t.size() > 19 || t.find_first_not_of("0123456789") != std::string::npos)
        return internal::cutting_error(Cutting_read_status::parse_error, number,
                                       "expected two vertex ids");
      ids[k] = std::stoull(t);
      if (ids[k] >= vs.size())
        return internal::cutting_error(Cutting_read_status::index_out_of_range, number,
                                       "vertex ids must be below " + std::to_string(vs.size()));
    }
    const std::size_t a = ids[0], b = ids[1];
    if (ls >> rest)
      return internal::cutting_error(Cutting_read_status::parse_error, number,
                                     "more than two vertex ids");
    const auto [h, found] = halfedge(vs[a], vs[b], tm);
    if (!found || a == b)
      return internal::cutting_error(Cutting_read_status::not_an_edge, number,
                                     "vertices " + std::to_string(a) + " and " + std::to_string(b) +
                                         " share no edge");
    put(seam_edges, edge(h, tm), true);
    ++r.count;
    return {};
  };
  if (Cutting_read_result lines = internal::read_lines(in, read_line); !lines)
    return lines;
  return r;
}

template <typename PolygonMesh>
Cutting_read_result read_obj_with_uvs(std::istream& in, Uv_layout<PolygonMesh>& out) {
  using Point = typename Uv_layout<PolygonMesh>::Point;
  using FT = typename Uv_layout<PolygonMesh>::FT;
  std::vector<Point> points;
  std::vector<std::array<FT, 2>> uvs;
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> polygons;
  std::vector<std::size_t> polygon_line;
  const auto read_line = [&](std::istream& ls, const std::string& key,
                             std::size_t number) -> Cutting_read_result {
    if (key == "v") {
      FT c[3];
      if (!internal::read_numbers(ls, c) || !internal::is_finite_number(c[0]) ||
          !internal::is_finite_number(c[1]) || !internal::is_finite_number(c[2]))
        return internal::cutting_error(Cutting_read_status::parse_error, number,
                                       "a vertex needs three finite coordinates");
      points.emplace_back(c[0], c[1], c[2]);
    } else if (key == "vt") {
      FT c[2];
      if (!internal::read_numbers(ls, c) || !internal::is_finite_number(c[0]) ||
          !internal::is_finite_number(c[1]))
        return internal::cutting_error(Cutting_read_status::parse_error, number,
                                       "a texture coordinate needs two finite numbers");
      uvs.push_back({c[0], c[1]});
    } else if (key == "f") {
      std::vector<std::pair<std::size_t, std::size_t>> corners;
      std::string token;
      while (ls >> token) {
        const auto slash = token.find('/');
        if (slash == std::string::npos)
          return internal::cutting_error(Cutting_read_status::parse_error, number,
                                         "face corner '" + token +
                                             "' has no texture coordinate (v/vt)");
        const auto end = token.find('/', slash + 1);
        long long idx[2];
        const std::string_view parts[2] = {
            std::string_view(token).substr(0, slash),
            std::string_view(token).substr(slash + 1, end == std::string::npos ? std::string::npos
                                                                               : end - slash - 1)};
        const std::size_t sizes[2] = {points.size(), uvs.size()};
        for (int k = 0; k < 2; ++k) {
          const char* first = parts[k].data() + (!parts[k].empty() && parts[k][0] == '+' ? 1 : 0);
          const char* last = parts[k].data() + parts[k].size();
          const auto [stop, error] = std::from_chars(first, last, idx[k]);
          if (first == last || error != std::errc() || stop != last || idx[k] == 0)
            return internal::cutting_error(Cutting_read_status::parse_error, number,
                                           "bad face corner '" + token + "'");
          // OBJ indices are 1-based; negative ones count back from the last element read.
          const long long i = idx[k] > 0 ? idx[k] - 1 : (long long)sizes[k] + idx[k];
          if (i < 0 || i >= (long long)sizes[k])
            return internal::cutting_error(Cutting_read_status::index_out_of_range, number,
                                           std::string(k ? "texture coordinate" : "vertex") +
                                               " index in '" + token + "' is out of range");
          idx[k] = i;
        }
        corners.emplace_back(std::size_t(idx[0]), std::size_t(idx[1]));
      }
      if (corners.size() < 3)
        return internal::cutting_error(Cutting_read_status::parse_error, number,
                                       "a face needs three corners");
      polygons.push_back(std::move(corners));
      polygon_line.push_back(number);
    }
    return {};
  };
  if (Cutting_read_result lines = internal::read_lines(in, read_line); !lines)
    return lines;
  if (polygons.empty())
    return internal::cutting_error(Cutting_read_status::no_faces, 0, "no faces");

  // The surface, face by face, refusing what a halfedge structure cannot hold.
  clear(out.mesh);
  clear(out.charts);
  out.chart_to_mesh.clear();
  out.uv.clear();
  out.pinched.clear();
  using vertex_descriptor = typename Uv_layout<PolygonMesh>::vertex_descriptor;
  std::vector<vertex_descriptor> mesh_vertex;
  auto pm = get(CGAL::vertex_point, out.mesh);
  for (const Point& p : points) {
    mesh_vertex.push_back(add_vertex(out.mesh));
    put(pm, mesh_vertex.back(), p);
  }
  using halfedge_descriptor = typename boost::graph_traits<PolygonMesh>::halfedge_descriptor;
  std::vector<vertex_descriptor> mv;
  std::vector<halfedge_descriptor> face_halfedge; // of each face: the one leaving its first corner
  auto face_number = get(CGAL::dynamic_face_property_t<std::size_t>(), out.mesh);
  for (std::size_t p = 0; p < polygons.size(); ++p) {
    mv.clear();
    for (const auto& corner : polygons[p])
      mv.push_back(mesh_vertex[corner.first]);
    const auto f = CGAL::Euler::can_add_face(mv, out.mesh)
                       ? CGAL::Euler::add_face(mv, out.mesh)
                       : boost::graph_traits<PolygonMesh>::null_face();
    if (f == boost::graph_traits<PolygonMesh>::null_face())
      return internal::cutting_error(
          Cutting_read_status::not_a_surface, polygon_line[p],
          "this face makes the surface non-manifold or inconsistently oriented");
    put(face_number, f, p);
    halfedge_descriptor h = halfedge(f, out.mesh);
    while (source(h, out.mesh) != mv.front())
      h = next(h, out.mesh);
    face_halfedge.push_back(h);
  }
  // The chart vertices: the face corners of one (v, vt) pair joined across the chart edges they
  // share (a surface edge whose two faces give both its ends the same vt), so that each fan of
  // faces around the pair becomes a vertex (union-find over the corners, numbered face by face).
  std::vector<std::size_t> first_corner(polygons.size() + 1, 0);
  for (std::size_t p = 0; p < polygons.size(); ++p)
    first_corner[p + 1] = first_corner[p] + polygons[p].size();
  std::vector<std::size_t> parent(first_corner.back());
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto find = [&](std::size_t c) {
    while (parent[c] != c)
      c = parent[c] = parent[parent[c]];
    return c;
  };
  for (std::size_t p = 0; p < polygons.size(); ++p) {
    halfedge_descriptor h = face_halfedge[p]; // from corner i to corner i + 1
    for (std::size_t i = 0, k = polygons[p].size(); i < k; ++i, h = next(h, out.mesh)) {
      const halfedge_descriptor o = opposite(h, out.mesh);
      if (is_border(o, out.mesh))
        continue;
      const std::size_t q = get(face_number, face(o, out.mesh));
      if (q < p)
        continue; // each edge once
      // The corner j of q where o starts (at corner i + 1's vertex).
      std::size_t j = 0;
      for (halfedge_descriptor g = face_halfedge[q]; g != o; g = next(g, out.mesh))
        ++j;
      const std::size_t k2 = polygons[q].size();
      const std::size_t at_b = first_corner[p] + (i + 1) % k, at_a = first_corner[p] + i;
      const std::size_t twin_b = first_corner[q] + j, twin_a = first_corner[q] + (j + 1) % k2;
      if (polygons[p][(i + 1) % k].second == polygons[q][j].second &&
          polygons[p][i].second == polygons[q][(j + 1) % k2].second) {
        parent[find(at_b)] = find(twin_b);
        parent[find(at_a)] = find(twin_a);
      }
    }
  }
  using Pair = std::pair<std::size_t, std::size_t>;
  std::vector<std::size_t> chart_vertex_of(parent.size(), std::size_t(-1)); // by root
  std::vector<std::vector<std::size_t>> chart_polygons(polygons.size());
  std::vector<Point> chart_points;
  std::vector<std::size_t> texture_of_chart_vertex;
  std::vector<std::size_t> mesh_of_chart_vertex;
  for (std::size_t p = 0; p < polygons.size(); ++p)
    for (std::size_t i = 0; i < polygons[p].size(); ++i) {
      const std::size_t root = find(first_corner[p] + i);
      if (chart_vertex_of[root] == std::size_t(-1)) {
        const Pair& corner = polygons[p][i];
        chart_vertex_of[root] = chart_points.size();
        chart_points.push_back(points[corner.first]);
        out.chart_to_mesh.push_back(mesh_vertex[corner.first]);
        out.uv.push_back(uvs[corner.second]);
        mesh_of_chart_vertex.push_back(corner.first);
        texture_of_chart_vertex.push_back(corner.second);
      }
      chart_polygons[p].push_back(chart_vertex_of[root]);
    }
  // Pinched pairs: chart vertices of one surface vertex with the same vt.
  out.pinched = internal::pinched_texture_vertices(points.size(), mesh_of_chart_vertex,
                                                   texture_of_chart_vertex);
  if (!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(chart_polygons))
    return internal::cutting_error(
        Cutting_read_status::not_a_surface, 0,
        "the texture coordinates glue the faces in a way the surface does not allow");
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(chart_points, chart_polygons,
                                                              out.charts);
  Cutting_read_result r;
  r.count = polygons.size();
  return r;
}

template <typename Point>
Cutting_read_result read_exact_polygon_soup(const std::string& path, std::vector<Point>& points,
                                            std::vector<std::vector<std::size_t>>& polygons) {
  using FT = typename CGAL::Kernel_traits<Point>::Kernel::FT;
  points.clear();
  polygons.clear();
  std::ifstream in(path);
  if (!in)
    return {Cutting_read_status::cannot_open, path + ": cannot open", 0};
  const auto dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot);
  for (char& c : ext)
    c = char(std::tolower(static_cast<unsigned char>(c)));
  auto fail = [&](Cutting_read_status s, std::size_t line, const std::string& what) {
    Cutting_read_result r = internal::cutting_error(s, line, what);
    r.message = path + ": " + r.message;
    return r;
  };
  std::string line;
  std::size_t number = 0;
  if (ext == ".obj") {
    std::vector<std::pair<std::size_t, std::vector<long long>>> faces; // (line, raw indices)
    while (std::getline(in, line)) {
      ++number;
      std::istringstream ls(line);
      std::string key;
      if (!(ls >> key))
        continue;
      if (key == "v") {
        FT c[3];
        if (!internal::read_numbers(ls, c))
          return fail(Cutting_read_status::parse_error, number, internal::exact_vertex_error);
        points.emplace_back(c[0], c[1], c[2]);
      } else if (key == "f") {
        std::vector<long long> corner;
        std::string token;
        while (ls >> token) {
          std::istringstream ts(token.substr(0, token.find('/')));
          long long i = 0;
          if (!(ts >> i) || i == 0)
            return fail(Cutting_read_status::parse_error, number,
                        "'" + token + "' is not a vertex index");
          // Negative indices count back from the vertices read so far.
          corner.push_back(i > 0 ? i - 1 : static_cast<long long>(points.size()) + i);
        }
        faces.emplace_back(number, std::move(corner));
      }
    }
    for (auto& [line_number, corner] : faces) {
      std::vector<std::size_t> polygon;
      for (long long i : corner) {
        if (i < 0 || i >= static_cast<long long>(points.size()))
          return fail(Cutting_read_status::index_out_of_range, line_number,
                      "a face names a vertex that is not in the file");
        polygon.push_back(std::size_t(i));
      }
      if (polygon.size() < 3)
        return fail(Cutting_read_status::parse_error, line_number, "a face needs three vertices");
      polygons.push_back(std::move(polygon));
    }
  } else if (ext == ".off") {
    // Header, counts, vertices, then faces; '#' starts a comment.
    std::size_t expected = 0, expected_faces = 0;
    int stage = 0; // 0 header, 1 counts, 2 vertices, 3 faces, 4 done
    while (stage < 4 && std::getline(in, line)) {
      ++number;
      line = line.substr(0, line.find('#'));
      std::istringstream ls(line);
      std::string token;
      if (!(ls >> token))
        continue;
      if (stage == 0) {
        if (token != "OFF" && token != "COFF")
          return fail(Cutting_read_status::parse_error, number,
                      "exact coordinates are read from OFF or COFF text, not '" + token + "'");
        stage = 1;
        line = line.substr(line.find(token) + token.size());
        if (!(std::istringstream(line) >> token))
          continue; // counts on the next line
      }
      if (stage == 1) {
        std::istringstream counts(line);
        if (!(counts >> expected >> expected_faces))
          return fail(Cutting_read_status::parse_error, number,
                      "expected the vertex and face counts");
        stage = expected ? 2 : expected_faces ? 3 : 4;
        continue;
      }
      std::istringstream vs(line);
      if (stage == 2) {
        FT c[3];
        if (!internal::read_numbers(vs, c))
          return fail(Cutting_read_status::parse_error, number, internal::exact_vertex_error);
        points.emplace_back(c[0], c[1], c[2]);
        if (points.size() == expected)
          stage = expected_faces ? 3 : 4;
        continue;
      }
      std::size_t k = 0;
      if (!(vs >> k) || k < 3)
        return fail(Cutting_read_status::parse_error, number,
                    "a face starts with its vertex count, at least 3");
      std::vector<std::size_t> polygon;
      for (std::size_t i = 0, id = 0; i < k; ++i) {
        if (!(vs >> id))
          return fail(Cutting_read_status::parse_error, number,
                      "a face with fewer vertex ids than its count");
        if (id >= expected)
          return fail(Cutting_read_status::index_out_of_range, number,
                      "vertex id " + std::to_string(id) + " is out of range");
        polygon.push_back(id);
      }
      polygons.push_back(std::move(polygon));
      if (polygons.size() == expected_faces)
        stage = 4;
    }
    if (points.size() != expected)
      return fail(Cutting_read_status::parse_error, number, "fewer vertices than the header says");
    if (polygons.size() != expected_faces)
      return fail(Cutting_read_status::parse_error, number, "fewer faces than the header says");
  } else {
    return {Cutting_read_status::parse_error,
            path + ": exact coordinates are read from OFF or OBJ text", 0};
  }
  return {Cutting_read_status::ok, "", points.size()};
}

} // namespace tessera
