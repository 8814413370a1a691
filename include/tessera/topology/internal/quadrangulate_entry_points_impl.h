// The bodies of topology/quadrangulate.h's entry points (Favreau et al. 2009, §4): Alg. 4's
// shortest_cutting_path() and cut_tile_between_corners(), and Alg. 5's quadrangulate() over the
// machinery of internal/quadrangulate_impl.h. Included at the end of the public header.
#pragma once

#include <tessera/topology/quadrangulate.h>

#include <tessera/topology/internal/cutting_path_search.h>
#include <tessera/topology/internal/quadrangulate_impl.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace tessera {

template <typename TriangleMesh, typename EdgeCostMap, typename NamedParameters>
std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>
shortest_cutting_path(const M_tiling<TriangleMesh>& tiling,
                      typename boost::graph_traits<TriangleMesh>::halfedge_descriptor a,
                      typename boost::graph_traits<TriangleMesh>::halfedge_descriptor b,
                      EdgeCostMap cost, const NamedParameters& np) {
  const auto vpm = internal::vertex_point_map(tiling.mesh(), np);
  internal::Cutting_path_search<TriangleMesh, decltype(vpm)> search(
      tiling, 1, [&](auto e) { return double(get(cost, e)); }, vpm);
  search.run({a});
  const auto best = search.best_arrival(b, [](std::size_t) { return true; });
  if (!best.found())
    return {};
  return search.path(best);
}

template <typename TriangleMesh, typename EdgeCostMap>
Cut_path_status
cut_tile_between_corners(M_tiling<TriangleMesh>& tiling,
                         typename boost::graph_traits<TriangleMesh>::halfedge_descriptor a,
                         typename boost::graph_traits<TriangleMesh>::halfedge_descriptor b,
                         EdgeCostMap cost) {
  const auto path = shortest_cutting_path(tiling, a, b, cost);
  tiling.mark_multipoint(target(a, tiling.mesh()));
  tiling.mark_multipoint(target(b, tiling.mesh()));
  return path.empty() ? Cut_path_status::empty_path : tiling.cut(path);
}

template <typename TriangleMesh, typename FaceTileMap, typename SeamEdgeMap, typename SeamVertexMap,
          typename NamedParameters>
Quadrangulation_result<TriangleMesh>
quadrangulate(TriangleMesh& tm, FaceTileMap tile_of_face, SeamEdgeMap seam_edges,
              SeamVertexMap seam_vertices, const Quadrangulation_options& options,
              const NamedParameters& np) {
  using GT = boost::graph_traits<TriangleMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  const auto vpm = internal::writable_vertex_point_map(tm, np);
  Quadrangulation_result<TriangleMesh> result;
  result.cut = cut_to_disk(tm, seam_edges, seam_vertices, options.cut, np);
  if (!result.cut) {
    switch (result.cut.status) {
    case Cut_status::invalid_mesh:
      result.status = Quadrangulation_status::invalid_mesh;
      break;
    case Cut_status::invalid_basepoint:
      result.status = Quadrangulation_status::invalid_basepoint;
      break;
    case Cut_status::refinement_failed:
      result.status = Quadrangulation_status::cut_refinement_failed;
      break;
    case Cut_status::canonical_failed:
      result.status = Quadrangulation_status::cut_canonical_failed;
      break;
    default:
      result.status = Quadrangulation_status::cut_not_a_disk;
    }
    result.message = result.cut.message;
    return result;
  }
  // The state that survives refinements: seams as vertex pairs (a split seam edge becomes the two
  // halves through its midpoint) and the corners, all marked so that they stay corners.
  std::vector<std::pair<vertex_descriptor, vertex_descriptor>> seams;
  for (auto e : edges(tm))
    if (get(seam_edges, e))
      seams.emplace_back(source(halfedge(e, tm), tm), target(halfedge(e, tm), tm));
  std::vector<vertex_descriptor> marks = result.cut.multipoints;
  for (const auto& polygon : result.cut.polygons)
    marks.insert(marks.end(), polygon.corners.begin(), polygon.corners.end());
  bool evened = false;

  for (;;) {
    auto cost = get(CGAL::dynamic_edge_property_t<double>(), tm);
    compute_edge_costs(tm, cost, options.cut.cost, np);
    M_tiling<TriangleMesh> tiling(tm);
    for (const auto& [a, b] : seams) {
      const auto h = halfedge(a, b, tm);
      if (h.second) {
        tiling.cut({h.first});
        continue;
      }
      for (halfedge_descriptor g :
           CGAL::halfedges_around_target(a, tm)) { // a was split at the midpoint m
        const vertex_descriptor m = source(g, tm);
        const auto to_b = halfedge(m, b, tm);
        if (!to_b.second)
          continue;
        tiling.cut({opposite(g, tm)});
        tiling.cut({to_b.first});
        break;
      }
    }
    for (vertex_descriptor v : marks)
      tiling.mark_multipoint(v);

    bool done = false;
    if (!evened) {
      const long added = internal::even_corner_counts(tiling, cost);
      if (added >= 0) {
        evened = true;
        result.added_corners = std::size_t(added);
        for (const auto& tile : tiling.tiles_without_faces())
          result.polygon_corners.push_back(tile_corners(tiling, tile).size());
      }
    }
    internal::Edge_point_spacing<TriangleMesh, std::remove_const_t<decltype(vpm)>> spacing;
    if (evened)
      done = internal::cut_into_quads(tm, tiling, cost, options, result, vpm, spacing);

    if (done) {
      // The polygons Alg. 5 left are triangulated and the mesh renumbered: its tiling is read
      // again.
      auto seam_now = get(CGAL::dynamic_edge_property_t<bool>(), tm);
      auto mark_now = get(CGAL::dynamic_vertex_property_t<bool>(), tm);
      const long removed = internal::finish_polygonal(tm, tiling, spacing, vpm, seam_now, mark_now);
      if (removed < 0) {
        result.status = Quadrangulation_status::no_cutting_path;
        result.message = "a refined face could not be triangulated";
        return result;
      }
      M_tiling<TriangleMesh> final_tiling(tm);
      for (auto e : edges(tm))
        if (get(seam_now, e))
          final_tiling.cut({halfedge(e, tm)});
      for (auto v : vertices(tm))
        if (get(mark_now, v))
          final_tiling.mark_multipoint(v);
      for (const auto& tile : final_tiling.tiles_without_faces()) {
        Quad_tile<TriangleMesh> quad;
        for (const auto& side : tile.sides) {
          quad.sides.push_back(side.halfedges);
          quad.corners.push_back(source(side.halfedges.front(), tm));
        }
        result.tiles.push_back(std::move(quad));
      }
      for (auto f : faces(tm))
        put(tile_of_face, f, final_tiling.tile_of(f));
      for (auto v : vertices(tm))
        if (final_tiling.is_multipoint(v))
          result.multipoints.push_back(v);
      final_tiling.export_seams(seam_edges, seam_vertices);
      for (auto e : final_tiling.seam_edges()) {
        const halfedge_descriptor h = halfedge(e, tm);
        // After finishing, the costs of the edges the triangulation made are not set.
        result.cut_cost += edge_cost(e, tm, options.cut.cost, np);
        result.cut_length += std::sqrt(CGAL::to_double(
            CGAL::squared_distance(get(vpm, source(h, tm)), get(vpm, target(h, tm)))));
      }
      return result;
    }
    seams.clear();
    for (auto e : tiling.seam_edges())
      seams.emplace_back(source(halfedge(e, tm), tm), target(halfedge(e, tm), tm));
    marks.clear();
    for (vertex_descriptor v : vertices(tm))
      if (tiling.is_multipoint(v))
        marks.push_back(v);
    if (result.refinements == options.max_refinements) {
      result.status = Quadrangulation_status::no_cutting_path;
      result.message = "a tile has no cutting path inside it after " +
                       std::to_string(result.refinements) + " subdivisions";
      return result;
    }
    if (!CGAL::is_triangle_mesh(tm)) { // Alg. 5's polygons, which it failed to triangulate
      result.status = Quadrangulation_status::no_cutting_path;
      result.message = "a tile has no cutting path inside it, and a refined face could not be "
                       "triangulated for the midpoint subdivision";
      return result;
    }
    internal::subdivide_at_midpoints(tm, vpm);
    ++result.refinements;
  }
}

} // namespace tessera
