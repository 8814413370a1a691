// Internals of the quadrangulation (Favreau et al. 2009, §4): midpoint subdivision as a last
// resort, corner evening, local refinement and the loop of Alg. 5. Included by
// internal/quadrangulate_entry_points_impl.h after topology/quadrangulate.h's public types; not for
// direct use.
#pragma once

#include <tessera/internal/garbage.h>
#include <tessera/topology/internal/tile_refinement.h>

#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Subdivision_method_3/subdivision_hosts_3.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace tessera {
namespace internal {

/// Geometry mask for CGAL's primal triangle quadrisection that puts new vertices at edge midpoints
/// and keeps old ones: the refined mesh is the same surface (exactly so with exact constructions).
template <typename TriangleMesh, typename VertexPointMap> struct Midpoint_mask_3 {
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  TriangleMesh* tm;
  VertexPointMap vpm;
  void edge_node(typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h, Point& p) {
    p = CGAL::midpoint(get(vpm, source(h, *tm)), get(vpm, target(h, *tm)));
  }
  void vertex_node(typename boost::graph_traits<TriangleMesh>::vertex_descriptor v, Point& p) {
    p = get(vpm, v);
  }
  void border_node(typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h, Point& ep,
                   Point& vp) {
    edge_node(h, ep);
    vp = get(vpm, target(h, *tm));
  }
};

/// Splits every triangle of `tm` into four at its edge midpoints (property maps of `tm` that grow
/// with the mesh, as Surface_mesh's do, stay valid).
template <typename TriangleMesh, typename VertexPointMap>
void subdivide_at_midpoints(TriangleMesh& tm, VertexPointMap vpm) {
  CGAL::Subdivision_method_3::PTQ(tm, Midpoint_mask_3<TriangleMesh, VertexPointMap>{&tm, vpm},
                                  CGAL::parameters::number_of_iterations(1).vertex_point_map(vpm));
}

/// Marks corners until every tile has an even number of them, and at least 4: a polygon side along
/// the mesh's border appears once in the boundary, so an odd count is evened by splitting the
/// longest border side; counts below 4 (a sphere's slit, a disk without cut) by splitting the
/// longest side. A side is split at its inner vertex nearest to half its length; splitting a seam
/// side splits its partner too (+2 corners, pairing kept), a border side only itself (+1). Returns
/// the number of marks, or -1 when a side to split has no inner vertex.
template <typename TriangleMesh, typename EdgeCostMap>
long even_corner_counts(M_tiling<TriangleMesh>& tiling, EdgeCostMap cost) {
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  const TriangleMesh& tm = tiling.mesh();
  long marks = 0;
  for (bool changed = true; changed;) {
    changed = false;
    for (const auto& tile : tiling.tiles_without_faces()) {
      if (tile.sides.empty())
        continue;
      const std::size_t m = tile_corners(tiling, tile).size();
      if (m % 2 == 0 && m >= 4)
        continue;
      if (m == 0) { // a boundary without corner: one corner anywhere starts the splitting
        tiling.mark_multipoint(source(tile.sides.front().halfedges.front(), tm));
        ++marks;
        changed = true;
        continue;
      }
      double longest = -1;
      const std::vector<halfedge_descriptor>* chosen = nullptr;
      for (const auto& side : tile.sides) {
        const bool border = is_border(opposite(side.halfedges.front(), tm), tm);
        if (side.halfedges.size() < 2 || (m % 2 == 1 && !border))
          continue;
        double length = 0;
        for (halfedge_descriptor h : side.halfedges)
          length += double(get(cost, edge(h, tm)));
        if (length > longest) {
          longest = length;
          chosen = &side.halfedges;
        }
      }
      if (chosen == nullptr)
        return -1;
      double along = 0, best = std::numeric_limits<double>::infinity();
      typename boost::graph_traits<TriangleMesh>::vertex_descriptor split =
          target(chosen->front(), tm);
      for (std::size_t i = 0; i + 1 < chosen->size(); ++i) {
        along += double(get(cost, edge((*chosen)[i], tm)));
        if (std::abs(along - longest / 2) < best) {
          best = std::abs(along - longest / 2);
          split = target((*chosen)[i], tm);
        }
      }
      tiling.mark_multipoint(split);
      ++marks;
      changed = true;
    }
  }
  return marks;
}

/// Alg. 5 on a tiling whose tiles are disks with even corner counts of at least 4: while some tile
/// has more than 4 corners, cut it along the shortest cutting path between corners i and j with
/// j - i odd and 3 <= j - i <= m - 3 (the Q-criterion). Tiles are tracked by their corners: a cut
/// from corner p to corner q of an m-gon leaves the (q - p + 1)-gon p..q and the (m - q + p +
/// 1)-gon q..p, both even, so only the first step walks the whole mesh. Before its search, a tile
/// is refined locally where paths could not pass (narrow wedges opened; chords split, for the
/// source cut's tiles by walking their boundary, later at each cutting path right after its cut;
/// `tm` changes, the tiling follows): a disk tile without chords whose corners all have an inner
/// edge always has a valid cutting path. The splits leave convex polygons, paths cross them along
/// diagonals, and the points they add on each edge are kept evenly spaced (`spacing`); on success
/// the caller finishes the mesh (`finish_polygonal`), on failure every face is triangulated
/// (CGAL's `triangulate_faces`) before returning. Returns false when a tile still has no cutting
/// path.
template <typename TriangleMesh, typename EdgeCostMap, typename VertexPointMap>
bool cut_into_quads(TriangleMesh& tm, M_tiling<TriangleMesh>& tiling, EdgeCostMap cost,
                    const Quadrangulation_options& options,
                    Quadrangulation_result<TriangleMesh>& result, VertexPointMap vpm,
                    Edge_point_spacing<TriangleMesh, VertexPointMap>& spacing) {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  using Search = Cutting_path_search<TriangleMesh, VertexPointMap>;
  // Each vertex keeps its 3 nearest even corners: at most two of them (the target's neighbours)
  // violate the Q-criterion for a given odd target, so the best valid source is always among them.
  Search search(
      tiling, 3, [&](auto e) { return double(get(cost, e)); }, vpm, true);
  // Every face a triangle again, the tiling following (new edges are inside tiles), for the
  // midpoint subdivision that may follow a failure.
  const auto triangulate = [&] {
    CGAL::Polygon_mesh_processing::triangulate_faces(tm, CGAL::parameters::vertex_point_map(vpm));
    tiling.absorb_refinement();
  };
  // Off-cut vertices a corner reaches (the narrow-wedge test among polygons).
  const auto exits = [&](halfedge_descriptor corner) {
    std::size_t n = 0;
    search.for_each_exit(corner, [&](vertex_descriptor u, double, halfedge_descriptor, bool) {
      n += tiling.is_on_cut(u) ? 0 : 1;
    });
    return n;
  };
  // The tiles of the source cut are walked once for chords; later tiles are kept chord-free by
  // splitting the chords at each cutting path right after its cut.
  std::vector<std::vector<halfedge_descriptor>> work;
  for (const auto& tile : tiling.tiles_without_faces()) {
    std::vector<halfedge_descriptor> corners = tile_corners(tiling, tile);
    if (corners.size() > 4)
      work.push_back(std::move(corners));
  }
  std::size_t walked = work.size(); // work[0, walked) are tiles of the source cut still to walk
  // An m-gon takes m/2 - 2 cutting paths to become m/2 - 1 quads.
  std::size_t planned = 0;
  for (const auto& w : work)
    planned += w.size() / 2 - 2;
  const std::size_t paths_before = result.cutting_paths;
  std::vector<vertex_descriptor> added;
  const auto update_cost = [&](halfedge_descriptor h) {
    put(cost, edge(h, tm),
        edge_cost(edge(h, tm), tm, options.cut.cost, CGAL::parameters::vertex_point_map(vpm)));
  };
  // Each step reads the tiling, so it takes in the previous step's new elements first.
  const auto absorb = [&] {
    tiling.absorb_refinement();
    spacing.record(tm, added);
    std::vector<vertex_descriptor> moved = spacing.respace(vpm);
    for (const auto* vs : {&added, &moved})
      for (vertex_descriptor v : *vs)
        for (halfedge_descriptor h : CGAL::halfedges_around_target(v, tm))
          update_cost(h);
    search.refresh(added);
    search.move_vertices(moved);
    added.clear();
  };
  while (!work.empty()) {
    std::vector<halfedge_descriptor> corners = std::move(work.back());
    const bool source_tile = work.size() <= walked;
    work.pop_back();
    walked = std::min(walked, work.size());
    added.clear();
    const bool opened = open_narrow_wedges(tm, tiling, corners, added, vpm, false, exits);
    if (opened)
      absorb();
    const bool split = source_tile && split_tile_chords(tm, tiling, corners, added, vpm, false) > 0;
    if (split)
      absorb();
    if (opened || split)
      ++result.local_refinements;
    const std::size_t m = corners.size();
    std::vector<halfedge_descriptor> even, odd;
    for (std::size_t i = 0; i < m; ++i)
      (i % 2 == 0 ? even : odd).push_back(corners[i]);
    // Source s is corner 2s, target t corner 2t + 1.
    const auto valid = [m](std::size_t s, std::size_t t) {
      const std::size_t d = (2 * t + 1 + m - 2 * s) % m;
      return d >= 3 && d <= m - 3;
    };
    search.run(even, odd, valid, edge_cost_lower_bound(options.cut.cost));
    typename Search::Candidate best;
    std::size_t best_target = 0;
    for (std::size_t t = 0; t < odd.size(); ++t) {
      const auto candidate =
          search.best_arrival(odd[t], [&](std::size_t s) { return valid(s, t); });
      if (candidate.length < best.length) {
        best = candidate;
        best_target = t;
      }
    }
    std::vector<halfedge_descriptor> path;
    if (best.found()) {
      std::vector<vertex_descriptor> touched;
      path = insert_path(tm, tiling, search.path_vertices(best), even[best.source],
                         odd[best_target], touched);
      if (!touched.empty()) {
        tiling.absorb_refinement();
        for (halfedge_descriptor h : path)
          update_cost(h);
        search.refresh({});
        search.forget_rings(touched);
      }
    }
    if (!path.empty() && tiling.cut(path) == Cut_path_status::ok) {
      ++result.cutting_paths;
      if (options.progress)
        options.progress({"cutting paths", result.cutting_paths - paths_before, planned});
      std::vector<vertex_descriptor> inner;
      for (std::size_t i = 0; i + 1 < path.size(); ++i)
        inner.push_back(target(path[i], tm));
      if (split_chords_at(tm, tiling, inner, added, vpm, false) > 0)
        absorb();
      const std::size_t p = 2 * best.source, q = 2 * best_target + 1;
      // Corner halfedges arrive in their wedges: the path's ends start the two new corner lists.
      std::vector<halfedge_descriptor> left{path.back()}, right{opposite(path.front(), tm)};
      for (std::size_t i = (q + 1) % m;; i = (i + 1) % m) {
        left.push_back(corners[i]);
        if (i == p)
          break;
      }
      for (std::size_t i = (p + 1) % m;; i = (i + 1) % m) {
        right.push_back(corners[i]);
        if (i == q)
          break;
      }
      if (left.size() > 4)
        work.push_back(std::move(left));
      if (right.size() > 4)
        work.push_back(std::move(right));
      continue;
    }
    triangulate();
    return false;
  }
  return true;
}

/// Finishes Alg. 5 after `cut_into_quads` succeeded on its polygons: removes
/// the points no cutting path went through, spaces the rest evenly along their edges, triangulates
/// every face and collects removed elements. The seams and multipoints go into `seam` and `mark`
/// (property maps that follow a renumbering) for the caller to build its tiling again. Returns
/// the number of points removed, or -1 when a face could not be triangulated.
template <typename TriangleMesh, typename VertexPointMap, typename SeamMap, typename MarkMap>
long finish_polygonal(TriangleMesh& tm, const M_tiling<TriangleMesh>& tiling,
                      Edge_point_spacing<TriangleMesh, VertexPointMap>& spacing, VertexPointMap vpm,
                      SeamMap seam, MarkMap mark) {
  for (auto e : edges(tm))
    put(seam, e, tiling.is_seam(e));
  for (auto v : vertices(tm))
    put(mark, v, tiling.is_multipoint(v));
  const std::size_t removed = spacing.remove_unused(tm, tiling);
  spacing.respace(vpm);
  const bool ok =
      CGAL::Polygon_mesh_processing::triangulate_faces(tm, CGAL::parameters::vertex_point_map(vpm));
  collect_garbage_if_any(tm);
  return ok ? long(removed) : -1;
}

} // namespace internal
} // namespace tessera
