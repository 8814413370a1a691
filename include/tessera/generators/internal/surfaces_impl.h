// The bodies of generators/surfaces.h's generators: the torus, capsule and sphere soups, the
// genus-g plate's lattice and its Loop subdivision, and punch_holes()'s choice of far-apart
// vertices whose stars it removes. Included at the end of the public header.
#pragma once

#include <tessera/generators/surfaces.h>

#include <tessera/generators/internal/soup_to_mesh.h>
#include <tessera/internal/garbage.h>

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Random.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <queue>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace tessera {

template <typename MutableFaceGraph>
void make_torus(MutableFaceGraph& tm, double major_radius, double minor_radius,
                std::size_t u_segments, std::size_t v_segments) {
  if (u_segments < 3 || v_segments < 3)
    throw std::invalid_argument("make_torus: at least 3 segments in each direction");
  const double two_pi = 2 * std::acos(-1.0);
  std::vector<std::array<double, 3>> coords;
  std::vector<std::array<std::size_t, 3>> triangles;
  for (std::size_t i = 0; i < u_segments; ++i)
    for (std::size_t j = 0; j < v_segments; ++j) {
      const double u = two_pi * double(i) / double(u_segments);
      const double v = two_pi * double(j) / double(v_segments);
      const double rho = major_radius + minor_radius * std::cos(v);
      coords.push_back({{rho * std::cos(u), rho * std::sin(u), minor_radius * std::sin(v)}});
    }
  auto id = [&](std::size_t i, std::size_t j) {
    return (i % u_segments) * v_segments + (j % v_segments);
  };
  for (std::size_t i = 0; i < u_segments; ++i)
    for (std::size_t j = 0; j < v_segments; ++j) {
      triangles.push_back({{id(i, j), id(i + 1, j), id(i + 1, j + 1)}});
      triangles.push_back({{id(i, j), id(i + 1, j + 1), id(i, j + 1)}});
    }
  internal::soup_to_mesh(coords, triangles, tm);
}

template <typename MutableFaceGraph>
void make_capsule(MutableFaceGraph& tm, double radius, double length, std::size_t segments) {
  if (segments < 8 || segments % 4 != 0)
    throw std::invalid_argument("make_capsule: segments must be a multiple of 4, at least 8");
  const double pi = std::acos(-1.0);
  const std::size_t quarter = segments / 4;
  const double step = 2 * pi * radius / double(segments);
  const std::size_t body = std::max<std::size_t>(1, std::size_t(std::lround(length / step)));
  std::vector<std::array<double, 2>> profile; // (x, distance from the axis) of each ring
  for (std::size_t k = 1; k <= quarter; ++k) {
    const double phi = 0.5 * pi * double(k) / double(quarter);
    profile.push_back({{-0.5 * length - radius * std::cos(phi), radius * std::sin(phi)}});
  }
  for (std::size_t i = 1; i < body; ++i)
    profile.push_back({{-0.5 * length + length * double(i) / double(body), radius}});
  for (std::size_t k = quarter; k >= 1; --k) {
    const double phi = 0.5 * pi * double(k) / double(quarter);
    profile.push_back({{0.5 * length + radius * std::cos(phi), radius * std::sin(phi)}});
  }
  std::vector<std::array<double, 3>> coords;
  std::vector<std::array<std::size_t, 3>> triangles;
  coords.push_back({{-0.5 * length - radius, 0, 0}});
  for (const auto& ring : profile)
    for (std::size_t i = 0; i < segments; ++i) {
      const double theta = 2 * pi * double(i) / double(segments);
      coords.push_back({{ring[0], ring[1] * std::cos(theta), ring[1] * std::sin(theta)}});
    }
  coords.push_back({{0.5 * length + radius, 0, 0}});
  const std::size_t last = coords.size() - 1;
  auto id = [&](std::size_t ring, std::size_t i) { return 1 + ring * segments + i % segments; };
  for (std::size_t i = 0; i < segments; ++i) {
    triangles.push_back({{0, id(0, i + 1), id(0, i)}});
    for (std::size_t r = 0; r + 1 < profile.size(); ++r) {
      triangles.push_back({{id(r, i), id(r, i + 1), id(r + 1, i + 1)}});
      triangles.push_back({{id(r, i), id(r + 1, i + 1), id(r + 1, i)}});
    }
    triangles.push_back({{id(profile.size() - 1, i), id(profile.size() - 1, i + 1), last}});
  }
  internal::soup_to_mesh(coords, triangles, tm);
}

template <typename MutableFaceGraph>
void make_sphere(MutableFaceGraph& tm, double radius, std::size_t subdivisions) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<std::array<double, 3>> coords = {
      {{-1, t, 0}},  {{1, t, 0}},  {{-1, -t, 0}}, {{1, -t, 0}}, {{0, -1, t}},  {{0, 1, t}},
      {{0, -1, -t}}, {{0, 1, -t}}, {{t, 0, -1}},  {{t, 0, 1}},  {{-t, 0, -1}}, {{-t, 0, 1}}};
  std::vector<std::array<std::size_t, 3>> triangles = {
      {{0, 11, 5}}, {{0, 5, 1}},  {{0, 1, 7}},   {{0, 7, 10}}, {{0, 10, 11}},
      {{1, 5, 9}},  {{5, 11, 4}}, {{11, 10, 2}}, {{10, 7, 6}}, {{7, 1, 8}},
      {{3, 9, 4}},  {{3, 4, 2}},  {{3, 2, 6}},   {{3, 6, 8}},  {{3, 8, 9}},
      {{4, 9, 5}},  {{2, 4, 11}}, {{6, 2, 10}},  {{8, 6, 7}},  {{9, 8, 1}}};
  for (std::size_t s = 0; s < subdivisions; ++s) {
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> midpoint;
    auto mid = [&](std::size_t a, std::size_t b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = midpoint.find(key);
      if (it != midpoint.end())
        return it->second;
      coords.push_back({{(coords[a][0] + coords[b][0]) / 2, (coords[a][1] + coords[b][1]) / 2,
                         (coords[a][2] + coords[b][2]) / 2}});
      midpoint.emplace(key, coords.size() - 1);
      return coords.size() - 1;
    };
    std::vector<std::array<std::size_t, 3>> finer;
    finer.reserve(triangles.size() * 4);
    for (const auto& tr : triangles) {
      const std::size_t ab = mid(tr[0], tr[1]), bc = mid(tr[1], tr[2]), ca = mid(tr[2], tr[0]);
      finer.push_back({{tr[0], ab, ca}});
      finer.push_back({{tr[1], bc, ab}});
      finer.push_back({{tr[2], ca, bc}});
      finer.push_back({{ab, bc, ca}});
    }
    triangles.swap(finer);
  }
  for (auto& c : coords) {
    const double n = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    for (double& x : c)
      x *= radius / n;
  }
  internal::soup_to_mesh(coords, triangles, tm);
}

inline std::size_t genus_surface_face_count(std::size_t genus, const Genus_surface_options& o) {
  const std::size_t n = o.cell_resolution, m = o.wall_resolution;
  const std::size_t solid_cells = (2 * genus + 1) * 3 - genus;
  const std::size_t boundary_steps = 2 * ((2 * genus + 1) + 3) * n + genus * 4 * n;
  std::size_t faces = 2 * (2 * solid_cells * n * n) + 2 * boundary_steps * m;
  for (std::size_t s = 0; s < o.subdivision_steps; ++s)
    faces *= 4;
  return faces;
}

template <typename MutableFaceGraph>
void make_genus_surface(MutableFaceGraph& tm, std::size_t genus,
                        const Genus_surface_options& options) {
  const long n = long(std::max<std::size_t>(1, options.cell_resolution));
  const long m = long(std::max<std::size_t>(1, options.wall_resolution));
  const long cells_x = 2 * long(genus) + 1, cells_y = 3;
  const long nx = cells_x * n, ny = cells_y * n;
  auto solid = [&](long X, long Y) { // lattice square (X, Y) belongs to the plate
    if (X < 0 || Y < 0 || X >= nx || Y >= ny)
      return false;
    const long cx = X / n, cy = Y / n;
    return !(cy == 1 && cx % 2 == 1);
  };
  std::vector<std::array<double, 3>> coords;
  std::map<std::tuple<long, long, long>, std::size_t> index;
  auto vertex = [&](long X, long Y, long level) {
    const auto key = std::make_tuple(X, Y, level);
    auto it = index.find(key);
    if (it != index.end())
      return it->second;
    const double z = options.thickness * (double(level) / double(m) - 0.5);
    coords.push_back({{double(X) / double(n), double(Y) / double(n), z}});
    index.emplace(key, coords.size() - 1);
    return coords.size() - 1;
  };
  std::vector<std::array<std::size_t, 3>> triangles;
  auto quad = [&](std::size_t a, std::size_t b, std::size_t c, std::size_t d) {
    triangles.push_back({{a, b, c}});
    triangles.push_back({{a, c, d}});
  };
  for (long X = 0; X < nx; ++X)
    for (long Y = 0; Y < ny; ++Y) {
      if (!solid(X, Y))
        continue;
      quad(vertex(X, Y, m), vertex(X + 1, Y, m), vertex(X + 1, Y + 1, m), vertex(X, Y + 1, m));
      quad(vertex(X, Y, 0), vertex(X, Y + 1, 0), vertex(X + 1, Y + 1, 0), vertex(X + 1, Y, 0));
      // Walls on the square's sides that face the outside; (p -> q) runs with the plate on the
      // left.
      const std::array<std::array<long, 5>, 4> sides = {{{{X, Y, X + 1, Y, 0}},
                                                         {{X + 1, Y, X + 1, Y + 1, 1}},
                                                         {{X + 1, Y + 1, X, Y + 1, 2}},
                                                         {{X, Y + 1, X, Y, 3}}}};
      const std::array<std::array<long, 2>, 4> outside = {
          {{{0, -1}}, {{1, 0}}, {{0, 1}}, {{-1, 0}}}};
      for (const auto& s : sides) {
        if (solid(X + outside[s[4]][0], Y + outside[s[4]][1]))
          continue;
        for (long k = 0; k < m; ++k)
          quad(vertex(s[2], s[3], k + 1), vertex(s[0], s[1], k + 1), vertex(s[0], s[1], k),
               vertex(s[2], s[3], k));
      }
    }
  internal::soup_to_mesh(coords, triangles, tm);
  if (options.subdivision_steps > 0)
    CGAL::Subdivision_method_3::Loop_subdivision(
        tm, CGAL::parameters::number_of_iterations(int(options.subdivision_steps)));
}

template <typename MutableFaceGraph>
std::size_t punch_holes(MutableFaceGraph& tm, std::size_t holes, unsigned seed) {
  using GT = boost::graph_traits<MutableFaceGraph>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using face_descriptor = typename GT::face_descriptor;
  auto blocked = get(CGAL::dynamic_vertex_property_t<bool>(), tm);
  auto dist = get(CGAL::dynamic_vertex_property_t<int>(), tm);
  for (vertex_descriptor v : vertices(tm)) {
    put(blocked, v, false);
    put(dist, v, -1);
  }
  auto block_around = [&](const std::vector<vertex_descriptor>& sources, int radius) {
    std::queue<vertex_descriptor> q;
    std::vector<vertex_descriptor> touched;
    for (vertex_descriptor s : sources) {
      put(dist, s, 0);
      q.push(s);
      touched.push_back(s);
    }
    while (!q.empty()) {
      const vertex_descriptor v = q.front();
      q.pop();
      put(blocked, v, true);
      if (get(dist, v) == radius)
        continue;
      for (vertex_descriptor w : CGAL::vertices_around_target(halfedge(v, tm), tm))
        if (get(dist, w) < 0) {
          put(dist, w, get(dist, v) + 1);
          q.push(w);
          touched.push_back(w);
        }
    }
    for (vertex_descriptor v : touched)
      put(dist, v, -1);
  };
  std::vector<vertex_descriptor> border;
  for (vertex_descriptor v : vertices(tm))
    if (CGAL::is_border(v, tm))
      border.push_back(v);
  if (!border.empty())
    block_around(border, 4);

  std::vector<vertex_descriptor> order(vertices(tm).begin(), vertices(tm).end());
  CGAL::Random rng(seed);
  for (std::size_t i = order.size(); i > 1; --i)
    std::swap(order[i - 1], order[std::size_t(rng.get_int(0, int(i)))]);
  std::vector<vertex_descriptor> centres;
  for (vertex_descriptor v : order) {
    if (centres.size() == holes)
      break;
    if (get(blocked, v))
      continue;
    centres.push_back(v);
    block_around({v}, 4);
  }
  for (vertex_descriptor c : centres) {
    std::vector<face_descriptor> star;
    for (face_descriptor f : CGAL::faces_around_target(halfedge(c, tm), tm))
      star.push_back(f);
    for (face_descriptor f : star)
      CGAL::Euler::remove_face(halfedge(f, tm), tm);
  }
  internal::collect_garbage_if_any(tm);
  return centres.size();
}

} // namespace tessera
