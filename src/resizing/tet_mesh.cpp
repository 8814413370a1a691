// TetGen tetrahedralization, the protective grid, and carrying surface values into a volume.
#include <tessera/mosaic/internal/point_search.h>
#include <tessera/resizing/tet_mesh.h>

#include <tetgen.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>

namespace tessera {

namespace {

using P3 = std::array<double, 3>;

double signed_volume(const P3& a, const P3& b, const P3& c, const P3& d) {
  const P3 u{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const P3 v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const P3 w{d[0] - a[0], d[1] - a[1], d[2] - a[2]};
  return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
          u[2] * (v[0] * w[1] - v[1] * w[0])) /
         6.0;
}

// TetGen's exit codes (terminatetetgen() in tetgen.h).
std::string tetgen_error(int code) {
  switch (code) {
  case 1:
    return "TetGen ran out of memory";
  case 2:
    return "TetGen hit an internal error";
  case 3:
    return "TetGen found a self-intersection";
  case 4:
    return "TetGen found a feature smaller than its tolerance";
  case 5:
    return "TetGen found two very close input facets";
  case 10:
    return "TetGen found a problem in the input surface";
  default:
    return "TetGen failed with code " + std::to_string(code);
  }
}

} // namespace

std::vector<double> Tet_mesh::surface_values(const double* volume_values) const {
  if (!embedded())
    return {volume_values, volume_values + surface_vertices};
  std::vector<double> out(embedding_tet.size(), 0.0);
  for (std::size_t i = 0; i < out.size(); ++i)
    for (std::size_t k = 0; k < 4; ++k)
      out[i] += embedding_weights[i][k] * volume_values[tets[embedding_tet[i]][k]];
  return out;
}

std::vector<P3> Tet_mesh::surface_positions(const std::vector<P3>& volume_points) const {
  std::vector<P3> out(embedded() ? embedding_tet.size() : surface_vertices);
  std::vector<double> coordinate(volume_points.size());
  for (std::size_t c = 0; c < 3; ++c) {
    for (std::size_t v = 0; v < volume_points.size(); ++v)
      coordinate[v] = volume_points[v][c];
    const std::vector<double> values = surface_values(coordinate.data());
    for (std::size_t i = 0; i < out.size(); ++i)
      out[i][c] = values[i];
  }
  return out;
}

CGAL::Bbox_3 bounding_box(const std::vector<P3>& points) {
  CGAL::Bbox_3 box;
  for (const P3& p : points)
    box += CGAL::Bbox_3(p[0], p[1], p[2], p[0], p[1], p[2]);
  return box;
}

double Tet_mesh::tet_volume(std::size_t t) const {
  const auto& q = tets[t];
  return signed_volume(points[q[0]], points[q[1]], points[q[2]], points[q[3]]);
}

Tetrahedralize_result
tetrahedralize_surface(const std::vector<P3>& points,
                       const std::vector<std::array<std::size_t, 3>>& triangles,
                       const Tetrahedralize_options& options) {
  Tetrahedralize_result result;
  if (points.empty() || triangles.empty()) {
    result.status = Tetrahedralize_status::empty_input;
    result.message = "the surface has no faces";
    return result;
  }
  tetgenio in, out;
  in.firstnumber = 0;
  in.numberofpoints = int(points.size());
  in.pointlist = new REAL[3 * points.size()];
  // Regular surfaces (a generator's rings, a scanner's grid) put many points on common spheres,
  // and TetGen's exact in-sphere tests then take most of its time: 1.30 of 2.45 s for the
  // 26k-vertex capsule of the texture benchmark, and 0.59 s more recovering Delaunayness. TetGen
  // sees each point moved by at most `perturbation` × the bounding box's diagonal (a fixed
  // pseudo-random offset per index), which breaks those ties (0.14 s and 0.08 s). The volume mesh
  // keeps the moved points: putting the exact ones back would turn the tetrahedra of points on a
  // common plane (a cylinder's rings give many) into flat or inverted ones.
  const CGAL::Bbox_3 box = bounding_box(points);
  const double shift = std::max(options.perturbation, 0.0) *
                       std::sqrt(box.x_span() * box.x_span() + box.y_span() * box.y_span() +
                                 box.z_span() * box.z_span());
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      // splitmix64 of (index, axis), mapped to [-1, 1).
      std::uint64_t z = (std::uint64_t(3 * i + std::size_t(c)) + 1) * 0x9E3779B97F4A7C15ull;
      z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
      z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
      z ^= z >> 31;
      const double unit = double(z >> 11) * 0x1.0p-52 - 1.0;
      in.pointlist[3 * i + std::size_t(c)] = points[i][c] + shift * unit;
    }
  in.numberoffacets = int(triangles.size());
  in.facetlist = new tetgenio::facet[triangles.size()];
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    tetgenio::facet& facet = in.facetlist[f];
    tetgenio::init(&facet);
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&facet.polygonlist[0]);
    facet.polygonlist[0].numberofvertices = 3;
    facet.polygonlist[0].vertexlist = new int[3];
    for (int k = 0; k < 3; ++k)
      facet.polygonlist[0].vertexlist[k] = int(triangles[f][std::size_t(k)]);
  }
  // p: the input is a piecewise linear complex; Y: no Steiner points on it, so the surface's
  // vertices stay the volume's first ones; Q: quiet; z: indices from 0.
  std::ostringstream switches;
  switches << "pYQz";
  // Optimization by flips alone, one pass (level 1, scheme 1): without it the slivers of the
  // broken ties stay and a capsule resized 2x along its axis narrowed by 2 % (perturbed by 1e-9;
  // by 70 % at 1e-12); TetGen's default optimization spent 4 s on them.
  if (shift > 0)
    switches << "O1/1";
  if (options.radius_edge_ratio > 0)
    switches << 'q' << options.radius_edge_ratio;
  if (options.max_volume > 0)
    switches << 'a' << options.max_volume;
  std::string text = switches.str();
  try {
    tetrahedralize(text.data(), &in, &out);
  } catch (int code) {
    result.status = Tetrahedralize_status::tetgen_failed;
    result.message = tetgen_error(code);
    return result;
  }
  if (out.numberofpoints < int(points.size()) || out.numberoftetrahedra <= 0) {
    result.status = Tetrahedralize_status::tetgen_failed;
    result.message = "TetGen returned no tetrahedra";
    return result;
  }
  Tet_mesh& mesh = result.mesh;
  mesh.surface_vertices = points.size();
  mesh.points.resize(std::size_t(out.numberofpoints));
  for (std::size_t i = 0; i < mesh.points.size(); ++i)
    for (int c = 0; c < 3; ++c)
      mesh.points[i][c] = out.pointlist[3 * i + std::size_t(c)];
  mesh.tets.resize(std::size_t(out.numberoftetrahedra));
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    for (std::size_t k = 0; k < 4; ++k)
      mesh.tets[t][k] = std::size_t(out.tetrahedronlist[std::size_t(out.numberofcorners) * t + k]);
    if (mesh.tet_volume(t) < 0)
      std::swap(mesh.tets[t][0], mesh.tets[t][1]);
  }
  return result;
}

Tet_mesh grid_tet_mesh(const std::vector<P3>& points, const Grid_tet_mesh_options& options) {
  Tet_mesh mesh;
  if (points.empty())
    return mesh;
  const CGAL::Bbox_3 box = bounding_box(points);
  const double longest = std::max({box.x_span(), box.y_span(), box.z_span()});
  const std::size_t resolution = std::max<std::size_t>(options.resolution, 1);
  const double cell = longest > 0 ? longest / double(resolution) : 1.0;
  std::array<std::size_t, 3> cells{};
  P3 origin{};
  for (int c = 0; c < 3; ++c) {
    const double extent = box.max(c) - box.min(c) + 2 * options.margin * cell;
    cells[c] = std::max<std::size_t>(1, std::size_t(std::ceil(extent / cell - 1e-9)));
    origin[c] = 0.5 * (box.min(c) + box.max(c)) - 0.5 * double(cells[c]) * cell;
  }
  const std::size_t nx = cells[0] + 1, ny = cells[1] + 1, nz = cells[2] + 1;
  auto node = [&](std::size_t i, std::size_t j, std::size_t k) { return (k * ny + j) * nx + i; };
  mesh.points.resize(nx * ny * nz);
  for (std::size_t k = 0; k < nz; ++k)
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i)
        mesh.points[node(i, j, k)] = {origin[0] + double(i) * cell, origin[1] + double(j) * cell,
                                      origin[2] + double(k) * cell};
  // Kuhn's subdivision: the six tetrahedra of a cube are the monotone paths from its corner 000 to
  // 111 along the axes in each order; every cube uses the same diagonal, so faces match.
  static const std::array<std::array<int, 3>, 6> orders{
      {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  auto tet_of = [&](std::size_t i, std::size_t j, std::size_t k, const std::array<int, 3>& order) {
    std::array<std::size_t, 4> q{};
    std::array<std::size_t, 3> at{i, j, k};
    q[0] = node(at[0], at[1], at[2]);
    for (int s = 0; s < 3; ++s) {
      ++at[std::size_t(order[std::size_t(s)])];
      q[std::size_t(s) + 1] = node(at[0], at[1], at[2]);
    }
    return q;
  };
  // A path's orientation is the sign of its axis order, the same in every cube: the odd orders
  // get their first two corners swapped so every tetrahedron has a positive volume.
  std::array<bool, 6> flipped{};
  for (std::size_t o = 0; o < 6; ++o) {
    const auto q = tet_of(0, 0, 0, orders[o]);
    flipped[o] = signed_volume(mesh.points[q[0]], mesh.points[q[1]], mesh.points[q[2]],
                               mesh.points[q[3]]) < 0;
  }
  for (std::size_t k = 0; k < cells[2]; ++k)
    for (std::size_t j = 0; j < cells[1]; ++j)
      for (std::size_t i = 0; i < cells[0]; ++i)
        for (std::size_t o = 0; o < 6; ++o) {
          mesh.tets.push_back(tet_of(i, j, k, orders[o]));
          if (flipped[o])
            std::swap(mesh.tets.back()[0], mesh.tets.back()[1]);
        }
  mesh.embedding_tet.resize(points.size());
  mesh.embedding_weights.resize(points.size());
  for (std::size_t v = 0; v < points.size(); ++v) {
    std::array<std::size_t, 3> at{};
    P3 local{};
    for (int c = 0; c < 3; ++c) {
      const double u = (points[v][c] - origin[c]) / cell;
      const double f = std::clamp(std::floor(u), 0.0, double(cells[c] - 1));
      at[c] = std::size_t(f);
      local[c] = std::clamp(u - f, 0.0, 1.0);
    }
    // The tetrahedron whose path visits the axes in decreasing order of the local coordinates.
    std::array<int, 3> order{0, 1, 2};
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return local[std::size_t(a)] > local[std::size_t(b)]; });
    const std::size_t o =
        std::size_t(std::find(orders.begin(), orders.end(), order) - orders.begin());
    const std::size_t cell_index = (at[2] * cells[1] + at[1]) * cells[0] + at[0];
    mesh.embedding_tet[v] = 6 * cell_index + o;
    const double l0 = local[std::size_t(order[0])], l1 = local[std::size_t(order[1])],
                 l2 = local[std::size_t(order[2])];
    std::array<double, 4> w{1 - l0, l0 - l1, l1 - l2, l2};
    if (flipped[o])
      std::swap(w[0], w[1]);
    mesh.embedding_weights[v] = w;
  }
  mesh.surface_vertices = points.size();
  return mesh;
}

std::vector<P3> carry_to_volume(const Tet_mesh& mesh, const std::vector<P3>& surface_points,
                                const std::vector<P3>& surface_values, double falloff) {
  std::vector<P3> out(mesh.points.size(), P3{0, 0, 0});
  std::vector<internal::Vec3> sites(surface_points.size());
  for (std::size_t i = 0; i < sites.size(); ++i)
    sites[i] = internal::Vec3{surface_points[i]};
  internal::Point_search search(sites);
  for (std::size_t v = 0; v < mesh.points.size(); ++v) {
    if (!mesh.embedded() && v < mesh.surface_vertices) {
      out[v] = surface_values[v];
      continue;
    }
    search.nearest(internal::Vec3{mesh.points[v]}, 1, [&](std::size_t i, double squared) {
      double factor = 1;
      if (falloff > 0)
        factor = std::max(0.0, 1 - std::sqrt(squared) / falloff);
      for (int c = 0; c < 3; ++c)
        out[v][c] = factor * surface_values[i][c];
    });
  }
  return out;
}

} // namespace tessera
