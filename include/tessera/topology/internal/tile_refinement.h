// Local refinements of an M-tiling's mesh that let cutting paths through: midpoints of chords
// (uncut edges with both ends on the cut, the only edges across a one-triangle-wide strip between
// two sides) and of the edges opposite a corner whose wedge is too narrow to leave by. They split
// only uncut edges and faces, so the tiling follows them (`M_tiling::absorb_refinement`). Used by
// the quadrangulation (Alg. 5) and by the canonical schema's diagonals. Not for direct use.
#pragma once

#include <tessera/topology/m_tiling.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/Kernel/global_functions.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

namespace tessera {
namespace internal {

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

} // namespace internal
} // namespace tessera
