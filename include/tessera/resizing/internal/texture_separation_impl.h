// Implementation of tessera::separate_textures (see tessera/resizing/texture_separation.h).
#pragma once

#include <tessera/resizing/texture_separation.h>

#include <tessera/internal/named_parameters.h>
#include <tessera/resizing/internal/signed_curvatures.h>
#include <tessera/resizing/internal/texel_period.h>
#include <tessera/resizing/internal/texture_pieces.h>
#include <tessera/resizing/texel_period.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <string>
#include <vector>

namespace tessera {

template <typename TriangleMesh, typename VertexTextureMap, typename VertexIdMap,
          typename NamedParameters>
Texture_separation_result
separate_textures(const TriangleMesh& tm, VertexTextureMap is_texture, VertexIdMap texture_id,
                  const Texture_separation_options& options, const NamedParameters& np) {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Point = Kernel::Point_3;
  Texture_separation_result result;
  const auto vpm = internal::vertex_point_map(tm, np);
  const auto index = CGAL::get_initialized_vertex_index_map(tm, np);
  for (vertex_descriptor v : vertices(tm))
    put(texture_id, v, no_texture_id);
  if (faces(tm).empty()) {
    result.status = Texture_separation_status::empty_mesh;
    result.message = "the mesh has no faces";
    return result;
  }
  const std::size_t n = std::size_t(num_vertices(tm));
  auto point = [&](vertex_descriptor w) {
    const auto& p = get(vpm, w);
    return Point(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  };

  // Connected pieces of the texture region.
  std::vector<char> inside(n, 0);
  for (vertex_descriptor v : vertices(tm))
    inside[get(index, v)] = get(is_texture, v) ? 1 : 0;
  std::vector<std::size_t> piece_vertices;
  const std::vector<std::size_t> piece =
      internal::texture_pieces(tm, index, inside, piece_vertices);
  result.pieces = piece_vertices.size();
  if (result.pieces == 0) {
    result.status = Texture_separation_status::no_texture;
    result.message = "no vertex is texture";
    return result;
  }

  // Each piece's area (triangles with all corners in it).
  std::vector<double> piece_area(result.pieces, 0);
  for (auto f : faces(tm)) {
    std::array<Point, 3> p;
    std::array<std::size_t, 3> c{};
    std::size_t k = 0;
    for (vertex_descriptor w : CGAL::vertices_around_face(halfedge(f, tm), tm))
      if (k < 3) {
        c[k] = get(index, w);
        p[k++] = point(w);
      }
    if (inside[c[0]] && inside[c[1]] && inside[c[2]])
      piece_area[piece[c[0]]] += std::sqrt(CGAL::squared_area(p[0], p[1], p[2]));
  }
  if (result.pieces == 1) {
    // Nothing to tell apart: the texture's period is the surface's (`estimate_texel_period`).
    result.textures.resize(1);
    result.textures[0].pieces = 1;
    result.textures[0].vertices = piece_vertices[0];
    result.textures[0].area = piece_area[0];
    for (vertex_descriptor v : vertices(tm))
      if (inside[get(index, v)])
        put(texture_id, v, std::size_t(0));
    return result;
  }
  const internal::Mean_curvature_samples samples = internal::mean_curvature_samples(tm, vpm, index);
  auto period_of = [&](auto member) { return internal::texel_period_over(samples, member); };

  // Pieces by area, largest first; scraps join the largest; the others join the first texture of
  // their period, or start one.
  std::vector<std::size_t> order(result.pieces);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return piece_area[a] > piece_area[b]; });
  std::vector<Texel_period> piece_period(result.pieces);
  std::vector<std::size_t> texture_of(result.pieces, no_texture_id);
  std::vector<std::size_t> first_piece; // per texture
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::size_t p = order[k];
    piece_period[p] = period_of([&](std::size_t i) { return piece[i] == p; });
    if (k == 0) {
      texture_of[p] = 0;
      first_piece.push_back(p);
      continue;
    }
    const double largest = piece_period[order[0]].period;
    if (!(piece_period[p].period > 0) ||
        piece_area[p] < options.min_texel_cells * largest * largest) {
      texture_of[p] = 0;
      ++result.scraps;
      continue;
    }
    for (std::size_t t = 0; t < first_piece.size() && texture_of[p] == no_texture_id; ++t) {
      const double a = piece_period[first_piece[t]].period, b = piece_period[p].period;
      if (std::abs(a - b) <= options.period_tolerance * std::max(a, b))
        texture_of[p] = t;
    }
    if (texture_of[p] == no_texture_id) {
      texture_of[p] = first_piece.size();
      first_piece.push_back(p);
    }
  }
  result.textures.resize(first_piece.size());
  for (std::size_t p = 0; p < result.pieces; ++p) {
    Separated_texture& t = result.textures[texture_of[p]];
    ++t.pieces;
    t.vertices += piece_vertices[p];
    t.area += piece_area[p];
  }
  // Each texture's period over all its pieces (the piece's own when it has one).
  for (std::size_t t = 0; t < result.textures.size(); ++t)
    result.textures[t].period =
        result.textures[t].pieces == 1 && piece_period[first_piece[t]].period > 0
            ? piece_period[first_piece[t]]
            : period_of([&](std::size_t i) {
                return piece[i] != no_texture_id && texture_of[piece[i]] == t;
              });
  for (vertex_descriptor v : vertices(tm)) {
    const std::size_t i = get(index, v);
    if (inside[i])
      put(texture_id, v, texture_of[piece[i]]);
  }
  return result;
}

} // namespace tessera
