// Internals of the quadrangulation (Favreau et al. 2009, §4): midpoint subdivision as a last
// resort, corner evening, local refinement and the loop of Alg. 5. Included by
// topology/quadrangulate.h after its public types; not for direct use.
#pragma once

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

/// Splits edge `h` at its midpoint and the faces on both sides in two; returns the new vertex.
template <typename TriangleMesh, typename VertexPointMap>
typename boost::graph_traits<TriangleMesh>::vertex_descriptor
split_edge_at_midpoint(TriangleMesh& tm,
                       typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h,
                       VertexPointMap vpm) {
  const auto p = CGAL::midpoint(get(vpm, source(h, tm)), get(vpm, target(h, tm)));
  const auto hnew = CGAL::Euler::split_edge(h, tm); // hnew arrives at the new vertex, then h
  put(vpm, target(hnew, tm), p);
  for (auto g : {hnew, opposite(h, tm)})
    if (!is_border(g, tm))
      CGAL::Euler::split_face(g, next(next(g, tm), tm), tm);
  return target(hnew, tm);
}

/// Splits the edges `chords` (vertex pairs, smaller first; repeats allowed) at their midpoints,
/// each once, appending the new vertices to `added`; returns the number of edges split.
template <typename TriangleMesh, typename VertexPointMap>
std::size_t split_chords(
    TriangleMesh& tm,
    std::vector<std::pair<typename boost::graph_traits<TriangleMesh>::vertex_descriptor,
                          typename boost::graph_traits<TriangleMesh>::vertex_descriptor>>& chords,
    std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& added,
    VertexPointMap vpm) {
  std::sort(chords.begin(), chords.end());
  chords.erase(std::unique(chords.begin(), chords.end()), chords.end());
  for (const auto& [a, c] : chords)
    added.push_back(split_edge_at_midpoint(tm, halfedge(a, c, tm).first, vpm));
  return chords.size();
}

/// Splits the *chords* of a disk tile (uncut edges whose two ends lie on the cut; `corners` as
/// returned by `tile_corners`) at their midpoints and joins each midpoint to the opposite corners
/// of its faces. A strip of faces between two sides that run side by side (a cutting path beside an
/// earlier one, or two parallel schema strands) has only chords across it and so no vertex inside;
/// afterwards the chord midpoints form a path through it. The midpoints are not on the cut, so no
/// new chord appears. Appends the new vertices to `added`; returns the number of chords split.
template <typename TriangleMesh, typename VertexPointMap>
std::size_t split_tile_chords(
    TriangleMesh& tm, const M_tiling<TriangleMesh>& tiling,
    const std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>& corners,
    std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& added,
    VertexPointMap vpm) {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  if (corners.empty())
    return 0;
  // Every chord of the tile leaves one of its boundary vertices inside a wedge of the tile.
  std::vector<std::pair<vertex_descriptor, vertex_descriptor>> chords;
  const halfedge_descriptor start = corners.front();
  halfedge_descriptor h = start;
  do {
    tiling.for_each_in_wedge(h, [&](halfedge_descriptor g) {
      if (tiling.is_on_cut(source(g, tm)))
        chords.emplace_back(std::min(source(g, tm), target(g, tm)),
                            std::max(source(g, tm), target(g, tm)));
    });
    h = tiling.next_on_tile_border(h);
  } while (h != start);
  return split_chords(tm, chords, added, vpm);
}

/// Splits the chords at `vertices` (vertices just added to the cut, such as a cutting path's inner
/// vertices) as `split_tile_chords` does. A chord can only appear when a vertex joins the cut, so
/// splitting these after every cut keeps every tile chord-free without walking tile boundaries.
template <typename TriangleMesh, typename VertexPointMap>
std::size_t split_chords_at(
    TriangleMesh& tm, const M_tiling<TriangleMesh>& tiling,
    const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& vertices,
    std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& added,
    VertexPointMap vpm) {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  std::vector<std::pair<vertex_descriptor, vertex_descriptor>> chords;
  for (vertex_descriptor v : vertices)
    for (auto h : CGAL::halfedges_around_target(v, tm))
      if (!tiling.is_cut(edge(h, tm)) && tiling.is_on_cut(source(h, tm)))
        chords.emplace_back(std::min(source(h, tm), v), std::max(source(h, tm), v));
  return split_chords(tm, chords, added, vpm);
}

/// Refinement for corners with a narrow wedge. A corner whose wedge is a single face has no uncut
/// edge into its tile, so no cutting path can start or end there (and midpoint subdivision keeps it
/// so); one whose wedge has a single inner edge becomes two such corners once a path uses that
/// edge. For each of these corners, the edges of the wedge's faces opposite the corner are split at
/// their midpoints when uncut (the midpoints are new neighbours inside the tile); when none is, the
/// centroid of the corner's face is inserted. Appends the new vertices to `added`; returns false
/// when no corner needed it.
template <typename TriangleMesh, typename VertexPointMap>
bool open_narrow_wedges(
    TriangleMesh& tm, const M_tiling<TriangleMesh>& tiling,
    const std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>& corners,
    std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& added,
    VertexPointMap vpm) {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  std::vector<std::pair<vertex_descriptor, vertex_descriptor>> to_split;
  std::vector<std::array<vertex_descriptor, 3>> to_star;
  for (halfedge_descriptor b : corners) {
    std::vector<halfedge_descriptor> wedge{b}; // halfedges arriving at the corner, one per face
    tiling.for_each_in_wedge(b, [&](halfedge_descriptor g) { wedge.push_back(g); });
    if (wedge.size() > 2)
      continue;
    const std::size_t before = to_split.size();
    for (halfedge_descriptor g : wedge)
      if (!tiling.is_cut(edge(prev(g, tm), tm)))
        to_split.emplace_back(source(prev(g, tm), tm), target(prev(g, tm), tm));
    if (to_split.size() == before)
      to_star.push_back({{source(b, tm), target(b, tm), target(next(b, tm), tm)}});
  }
  std::sort(to_split.begin(), to_split.end());
  to_split.erase(std::unique(to_split.begin(), to_split.end()), to_split.end());
  bool changed = false;
  for (const auto& [a, b] : to_split) {
    const auto h = halfedge(a, b, tm);
    if (!h.second)
      continue;
    added.push_back(split_edge_at_midpoint(tm, h.first, vpm));
    changed = true;
  }
  for (const auto& t : to_star) {
    const auto h = halfedge(t[0], t[1], tm);
    if (!h.second || is_border(h.first, tm) || target(next(h.first, tm), tm) != t[2])
      continue;
    const auto p = CGAL::centroid(get(vpm, t[0]), get(vpm, t[1]), get(vpm, t[2]));
    const auto center = target(CGAL::Euler::add_center_vertex(h.first, tm), tm);
    put(vpm, center, p);
    added.push_back(center);
    changed = true;
  }
  return changed;
}

/// Alg. 5 on a tiling whose tiles are disks with even corner counts of at least 4: while some tile
/// has more than 4 corners, cut it along the shortest cutting path between corners i and j with
/// j - i odd and 3 <= j - i <= m - 3 (the Q-criterion). Tiles are tracked by their corners: a cut
/// from corner p to corner q of an m-gon leaves the (q - p + 1)-gon p..q and the (m - q + p +
/// 1)-gon q..p, both even, so only the first step walks the whole mesh. Before its search, a tile
/// is refined locally where paths could not pass (narrow wedges opened; chords split, for the
/// source cut's tiles by walking their boundary, later at each cutting path right after its cut;
/// `tm` changes, the tiling follows): a disk tile without chords whose corners all have an inner
/// edge always has a valid cutting path. Returns false when a tile still has none.
template <typename TriangleMesh, typename EdgeCostMap, typename VertexPointMap>
bool cut_into_quads(TriangleMesh& tm, M_tiling<TriangleMesh>& tiling, EdgeCostMap cost,
                    const Quadrangulation_options& options,
                    Quadrangulation_result<TriangleMesh>& result, VertexPointMap vpm) {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  using Search = Cutting_path_search<TriangleMesh, VertexPointMap>;
  // Each vertex keeps its 3 nearest even corners: at most two of them (the target's neighbours)
  // violate the Q-criterion for a given odd target, so the best valid source is always among them.
  Search search(
      tiling, 3, [&](auto e) { return double(get(cost, e)); }, vpm);
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
  // Each step reads the tiling, so it takes in the previous step's new elements first.
  const auto absorb = [&] {
    tiling.absorb_refinement();
    for (vertex_descriptor v : added)
      for (halfedge_descriptor h : CGAL::halfedges_around_target(v, tm))
        put(cost, edge(h, tm),
            edge_cost(edge(h, tm), tm, options.cut.cost, CGAL::parameters::vertex_point_map(vpm)));
    search.refresh(added);
    added.clear();
  };
  while (!work.empty()) {
    std::vector<halfedge_descriptor> corners = std::move(work.back());
    const bool source_tile = work.size() <= walked;
    work.pop_back();
    walked = std::min(walked, work.size());
    added.clear();
    const bool opened = open_narrow_wedges(tm, tiling, corners, added, vpm);
    if (opened)
      absorb();
    const bool split = source_tile && split_tile_chords(tm, tiling, corners, added, vpm) > 0;
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
    if (best.found())
      path = search.path(best);
    if (!path.empty() && tiling.cut(path) == Cut_path_status::ok) {
      ++result.cutting_paths;
      if (options.progress)
        options.progress({"cutting paths", result.cutting_paths - paths_before, planned});
      std::vector<vertex_descriptor> inner;
      for (std::size_t i = 0; i + 1 < path.size(); ++i)
        inner.push_back(target(path[i], tm));
      if (split_chords_at(tm, tiling, inner, added, vpm) > 0)
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
    return false;
  }
  return true;
}

} // namespace internal
} // namespace tessera
