// Local refinements of an M-tiling's mesh that let cutting paths through: midpoints of chords
// (uncut edges with both ends on the cut, the only edges across a one-triangle-wide strip between
// two sides) and of the edges opposite a corner whose wedge is too narrow to leave by. They split
// only uncut edges and faces, so the tiling follows them (`M_tiling::absorb_refinement`). Used by
// the quadrangulation (Alg. 5) and by the canonical schema's diagonals. The canonical schema
// triangulates every split (`triangulate`, the default); Alg. 5 passes `triangulate` false, which
// leaves split faces as convex polygons (a path then crosses them along face diagonals,
// `insert_path`), so that a strip between two cut lines keeps its rungs however many paths run
// along it. Not for direct use.
#pragma once

#include <tessera/topology/m_tiling.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/Kernel/global_functions.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <map>
#include <utility>
#include <vector>

namespace tessera {
namespace internal {

/// Splits edge `h` at its midpoint and, with `triangulate`, the triangles on both sides in two;
/// returns the new vertex.
template <typename TriangleMesh, typename VertexPointMap>
typename boost::graph_traits<TriangleMesh>::vertex_descriptor
split_edge_at_midpoint(TriangleMesh& tm,
                       typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h,
                       VertexPointMap vpm, bool triangulate = true) {
  const auto p = CGAL::midpoint(get(vpm, source(h, tm)), get(vpm, target(h, tm)));
  const auto hnew = CGAL::Euler::split_edge(h, tm); // hnew arrives at the new vertex, then h
  put(vpm, target(hnew, tm), p);
  if (triangulate)
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
    VertexPointMap vpm, bool triangulate = true) {
  std::sort(chords.begin(), chords.end());
  chords.erase(std::unique(chords.begin(), chords.end()), chords.end());
  for (const auto& [a, c] : chords)
    added.push_back(split_edge_at_midpoint(tm, halfedge(a, c, tm).first, vpm, triangulate));
  return chords.size();
}

/// Splits the *chords* of a disk tile (uncut edges whose two ends lie on the cut; `corners` as
/// returned by `tile_corners`) at their midpoints and, with `triangulate`, joins each midpoint to
/// the opposite corners of its faces. A strip of faces between two sides that run side by side (a
/// cutting path beside an earlier one, or two parallel schema strands) has only chords across it
/// and so no vertex inside; afterwards the chord midpoints form a path through it. The midpoints
/// are not on the cut, so no new chord appears. Appends the new vertices to `added`; returns the
/// number of chords split.
template <typename TriangleMesh, typename VertexPointMap>
std::size_t split_tile_chords(
    TriangleMesh& tm, const M_tiling<TriangleMesh>& tiling,
    const std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>& corners,
    std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& added,
    VertexPointMap vpm, bool triangulate = true) {
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
  return split_chords(tm, chords, added, vpm, triangulate);
}

/// Splits the chords at `vertices` (vertices just added to the cut, such as a cutting path's inner
/// vertices) as `split_tile_chords` does. A chord can only appear when a vertex joins the cut, so
/// splitting these after every cut keeps every tile chord-free without walking tile boundaries.
template <typename TriangleMesh, typename VertexPointMap>
std::size_t split_chords_at(
    TriangleMesh& tm, const M_tiling<TriangleMesh>& tiling,
    const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& vertices,
    std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& added,
    VertexPointMap vpm, bool triangulate = true) {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  std::vector<std::pair<vertex_descriptor, vertex_descriptor>> chords;
  for (vertex_descriptor v : vertices)
    for (auto h : CGAL::halfedges_around_target(v, tm))
      if (!tiling.is_cut(edge(h, tm)) && tiling.is_on_cut(source(h, tm)))
        chords.emplace_back(std::min(source(h, tm), v), std::max(source(h, tm), v));
  return split_chords(tm, chords, added, vpm, triangulate);
}

/// Refinement for corners with a narrow wedge. A corner whose wedge is a single face has no uncut
/// edge into its tile, so no cutting path can start or end there (and midpoint subdivision keeps it
/// so); one whose wedge has a single inner edge becomes two such corners once a path uses that
/// edge. For each of these corners, the edges of the wedge's faces opposite the corner are split at
/// their midpoints when uncut (the midpoints are new neighbours inside the tile); when none is, the
/// centroid of the corner's face is inserted. Without `triangulate`, faces may be polygons left
/// whole, and a wedge is narrow when fewer than two vertices off the cut are in reach of the corner
/// (through an edge, or across a face as `exits` counts them); the edges are split the same way
/// (the midpoint is then in reach across the face). Appends the new vertices to `added`; returns
/// false when no corner needed it.
template <typename TriangleMesh, typename VertexPointMap, typename Exits>
bool open_narrow_wedges(
    TriangleMesh& tm, const M_tiling<TriangleMesh>& tiling,
    const std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>& corners,
    std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& added,
    VertexPointMap vpm, bool triangulate, Exits exits) {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  std::vector<std::pair<vertex_descriptor, vertex_descriptor>> to_split;
  std::vector<std::array<vertex_descriptor, 3>> to_star;
  for (halfedge_descriptor b : corners) {
    std::vector<halfedge_descriptor> wedge{b}; // halfedges arriving at the corner, one per face
    tiling.for_each_in_wedge(b, [&](halfedge_descriptor g) { wedge.push_back(g); });
    if (triangulate ? wedge.size() > 2 : exits(b) >= 2)
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
    added.push_back(split_edge_at_midpoint(tm, h.first, vpm, triangulate));
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

/// The narrow-wedge refinement of triangle meshes (see above).
template <typename TriangleMesh, typename VertexPointMap>
bool open_narrow_wedges(
    TriangleMesh& tm, const M_tiling<TriangleMesh>& tiling,
    const std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>& corners,
    std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& added,
    VertexPointMap vpm) {
  return open_narrow_wedges(tm, tiling, corners, added, vpm, true,
                            [](auto) { return std::size_t(0); });
}

/// Keeps the points that polygonal refinement puts on an edge evenly spaced along it. Without
/// triangulation, every vertex a refinement adds lies on an edge of the mesh as it was before the
/// first one (a *base edge*; cutting paths are cut and never split), so the points on each base
/// edge can be placed anywhere along it in the same order: the faces, pieces of one base face cut
/// by segments between points on its border, stay convex and keep their combinatorics. Midpoints
/// alone would not do: where successive paths pass between a vertex and the previous path, each
/// splits the previous gap in two, and after 50 paths the points coincide in double precision.
/// As normal coordinates would place them, the k points on a base edge go to i / (k + 1) of it.
template <typename TriangleMesh, typename VertexPointMap> class Edge_point_spacing {
public:
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;

  /// Records the vertices `added` by the last refinement: each vertex of degree 2 split an edge
  /// between its two neighbours (a vertex of another degree, a face's centre, is a base vertex).
  void record(const TriangleMesh& tm, const std::vector<vertex_descriptor>& added) {
    for (vertex_descriptor m : added) {
      const auto h = halfedge(m, tm);
      if (degree(m, tm) != 2)
        continue;
      const vertex_descriptor x = source(h, tm), y = target(next(h, tm), tm);
      std::size_t l = line_of(x);
      if (l == none)
        l = line_of(y);
      if (l == none) { // x and y are the base edge's ends
        const auto key = std::minmax(x, y);
        const auto it = base_line_.find(key);
        if (it == base_line_.end()) {
          l = lines_.size();
          lines_.push_back({key.first, key.second, {}, false});
          base_line_.emplace(key, l);
        } else {
          l = it->second;
        }
      }
      Line& line = lines_[l];
      // Between x and y, which are adjacent along the line.
      const auto at = [&](vertex_descriptor v) -> std::size_t {
        if (v == line.a)
          return 0;
        if (v == line.b)
          return line.inner.size() + 1;
        return std::size_t(std::find(line.inner.begin(), line.inner.end(), v) -
                           line.inner.begin()) +
               1;
      };
      const std::size_t i = std::max(at(x), at(y)); // m becomes the i-th point
      line.inner.insert(line.inner.begin() + long(i - 1), m);
      line_of_[m] = l;
      if (!line.dirty)
        dirty_.push_back(l);
      line.dirty = true;
    }
  }

  /// Removes the points that no cutting path went through (off the cut, so still of degree 2),
  /// joining their two edges into one again (the later edge goes, so the earlier keeps its
  /// descriptor), and marks every line for `respace`. The tiling is not told (it must be built
  /// again); a Surface_mesh keeps the removed vertices as garbage. Returns the number removed.
  template <typename Tiling> std::size_t remove_unused(TriangleMesh& tm, const Tiling& tiling) {
    std::size_t removed = 0;
    for (std::size_t l = 0; l < lines_.size(); ++l) {
      Line& line = lines_[l];
      std::vector<vertex_descriptor> kept;
      for (vertex_descriptor v : line.inner) {
        if (tiling.is_on_cut(v) || degree(v, tm) != 2) {
          kept.push_back(v);
          continue;
        }
        auto h = opposite(halfedge(v, tm), tm);   // from v
        const auto g = next(halfedge(v, tm), tm); // the other edge, from v
        if (tiling.indices().e(edge(g, tm)) > tiling.indices().e(edge(h, tm)))
          h = g;
        CGAL::Euler::join_vertex(h, tm);
        line_of_.erase(v);
        ++removed;
      }
      line.inner = std::move(kept);
      if (!line.dirty)
        dirty_.push_back(l);
      line.dirty = true;
    }
    return removed;
  }

  /// Moves the points of the lines that changed since the last call to their even places;
  /// returns the vertices moved.
  std::vector<vertex_descriptor> respace(VertexPointMap vpm) {
    using Point = typename boost::property_traits<VertexPointMap>::value_type;
    using FT = typename CGAL::Kernel_traits<Point>::Kernel::FT;
    std::vector<vertex_descriptor> moved;
    for (std::size_t l : dirty_) {
      Line& line = lines_[l];
      line.dirty = false;
      const Point a = get(vpm, line.a), b = get(vpm, line.b);
      const std::size_t k = line.inner.size();
      for (std::size_t i = 0; i < k; ++i) {
        put(vpm, line.inner[i], a + (b - a) * (FT(int(i + 1)) / FT(int(k + 1))));
        moved.push_back(line.inner[i]);
      }
    }
    dirty_.clear();
    return moved;
  }

private:
  static constexpr std::size_t none = std::size_t(-1);
  struct Line {
    vertex_descriptor a, b;               // the base edge's ends
    std::vector<vertex_descriptor> inner; // the points on it, from a to b
    bool dirty;
  };
  std::size_t line_of(vertex_descriptor v) const {
    const auto it = line_of_.find(v);
    return it == line_of_.end() ? none : it->second;
  }
  std::vector<Line> lines_;
  std::map<std::pair<vertex_descriptor, vertex_descriptor>, std::size_t> base_line_;
  std::map<vertex_descriptor, std::size_t> line_of_;
  std::vector<std::size_t> dirty_;
};

/// Inserts a path found with face diagonals (`Cutting_path_search::path_vertices`; `vs` from the
/// source corner's vertex to the target corner's) into the mesh and returns its halfedges: a step
/// along an existing edge takes it, a step across a face splits the face along it. A step at a
/// corner stays in the corner's wedge (`source_corner`, `target_corner`: the corners' tile border
/// halfedges, as `tile_corners` gives them). Appends the vertices of split faces to `touched`.
/// Returns an empty path when a step has no edge or face (not expected from the search).
template <typename TriangleMesh>
std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>
insert_path(TriangleMesh& tm, const M_tiling<TriangleMesh>& tiling,
            const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& vs,
            typename boost::graph_traits<TriangleMesh>::halfedge_descriptor source_corner,
            typename boost::graph_traits<TriangleMesh>::halfedge_descriptor target_corner,
            std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& touched) {
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  std::vector<halfedge_descriptor> path;
  // h arrives at its target from inside the face the step uses at that end.
  const auto in_wedges = [&](halfedge_descriptor at_u, halfedge_descriptor at_w) {
    return (!tiling.is_on_cut(target(at_u, tm)) || tiling.wedge_border(at_u) == source_corner) &&
           (!tiling.is_on_cut(target(at_w, tm)) || tiling.wedge_border(at_w) == target_corner);
  };
  for (std::size_t i = 0; i + 1 < vs.size(); ++i) {
    const auto u = vs[i], w = vs[i + 1];
    const auto e = halfedge(u, w, tm);
    if (e.second && !tiling.is_cut(edge(e.first, tm)) &&
        in_wedges(opposite(e.first, tm), e.first)) {
      path.push_back(e.first);
      continue;
    }
    halfedge_descriptor step;
    bool found = false;
    for (halfedge_descriptor h : CGAL::halfedges_around_target(u, tm)) {
      if (is_border(h, tm))
        continue;
      for (halfedge_descriptor g = next(next(h, tm), tm); g != prev(h, tm); g = next(g, tm))
        if (target(g, tm) == w && in_wedges(h, g)) {
          for (auto x : CGAL::vertices_around_face(h, tm))
            touched.push_back(x);
          step = CGAL::Euler::split_face(h, g, tm); // from u to w
          found = true;
          break;
        }
      if (found)
        break;
    }
    if (!found)
      return {};
    path.push_back(step);
  }
  return path;
}

} // namespace internal
} // namespace tessera
