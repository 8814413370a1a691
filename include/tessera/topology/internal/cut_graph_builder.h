// Internals of tessera::cut_to_disk (see tessera/topology/cut_graph.h): walks split at the cut,
// and `Cut_graph_builder`, which cuts a system of loops (Alg. 1), slits spheres and joins boundary
// cycles (Alg. 1 and 3) on an M_tiling.
#pragma once

#include <tessera/topology/cut_graph.h>

#include <boost/pending/disjoint_sets.hpp>

#include <CGAL/boost/graph/helpers.h>

#include <limits>
#include <numeric>
#include <vector>

namespace tessera {

namespace internal {

/// Removes back-and-forth steps from a closed walk (cyclic free reduction): the stick of a
/// lollipop-shaped tree-cotree loop disappears and its simple cycle remains.
template <typename TriangleMesh>
std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor> cyclically_reduced(
    const std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>& walk,
    const TriangleMesh& tm) {
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  std::vector<halfedge_descriptor> stack;
  for (halfedge_descriptor h : walk) {
    if (!stack.empty() && stack.back() == opposite(h, tm))
      stack.pop_back();
    else
      stack.push_back(h);
  }
  std::size_t a = 0, b = stack.size();
  while (b - a >= 2 && stack[b - 1] == opposite(stack[a], tm)) {
    ++a;
    --b;
  }
  return std::vector<halfedge_descriptor>(stack.begin() + long(a), stack.begin() + long(b));
}

/// Splits a walk at the vertices that lie on the current cut. A closed walk that does not touch the
/// cut comes back whole; pieces that run along an already cut edge are dropped.
template <typename TriangleMesh>
std::vector<std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>>
split_at_cut(std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor> walk,
             const M_tiling<TriangleMesh>& tiling) {
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  const TriangleMesh& tm = tiling.mesh();
  std::vector<std::vector<halfedge_descriptor>> pieces;
  if (walk.empty())
    return pieces;
  const bool closed = source(walk.front(), tm) == target(walk.back(), tm);
  if (closed) {
    std::size_t start = walk.size();
    for (std::size_t i = 0; i < walk.size(); ++i)
      if (tiling.is_on_cut(source(walk[i], tm))) {
        start = i;
        break;
      }
    if (start == walk.size()) {
      pieces.push_back(walk);
      return pieces;
    }
    std::rotate(walk.begin(), walk.begin() + long(start), walk.end());
  }
  std::vector<halfedge_descriptor> piece;
  for (halfedge_descriptor h : walk) {
    piece.push_back(h);
    if (tiling.is_on_cut(target(h, tm))) {
      pieces.push_back(piece);
      piece.clear();
    }
  }
  if (!piece.empty())
    pieces.push_back(piece);
  std::vector<std::vector<halfedge_descriptor>> kept;
  for (auto& p : pieces)
    if (tiling.check_path(p) == Cut_path_status::ok)
      kept.push_back(std::move(p));
  return kept;
}

/// How `Cut_graph_builder::lower_genus` takes the loops of a system.
enum class Loop_order {
  genus_lowering_first, ///< Alg. 1: pieces that lower the genus, shortest first, then any piece
  all_pieces            ///< every piece of every loop (the tree-cotree cut of the system)
};

template <typename TriangleMesh, typename EdgeCostMap> class Cut_graph_builder {
public:
  using GT = boost::graph_traits<TriangleMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using edge_descriptor = typename GT::edge_descriptor;
  using Path = std::vector<halfedge_descriptor>;

  Cut_graph_builder(M_tiling<TriangleMesh>& tiling, EdgeCostMap cost)
      : tiling_(tiling), tm_(tiling.mesh()), cost_(cost) {
    for (halfedge_descriptor h : halfedges(tm_))
      if (is_border(h, tm_)) {
        has_border_ = true;
        break;
      }
  }

  /// The boundary cycle on the side of `h` at its target (h arrives at a vertex on the cut).
  std::size_t cycle_at_target(halfedge_descriptor h, const std::vector<std::size_t>& labels) const {
    return labels[tiling_.indices().h(tiling_.wedge_border(h))];
  }

  /// Phase 1. With `genus_lowering_first` (Alg. 1): cut pieces of the candidate loops, shortest
  /// first, until the tile (of genus `genus`) has genus 0, first only pieces that lower the genus
  /// (both ends on the same boundary cycle, or a closed loop), then any piece. Without it: cut
  /// every piece of every loop, which is the tree-cotree cut graph of the system (less the loops'
  /// sticks). The candidates are a system of loops of the component with its holes capped
  /// (greedy_system_of_loops): their union does not separate the capped surface, but on a bordered
  /// surface a loop may pass through border vertices, and a piece between two of them can cut off
  /// a region with holes. Such a piece is never cut: every tile stays connected.
  void lower_genus(const std::vector<Path>& candidates, long genus, Loop_order order) {
    const bool genus_lowering_first = order == Loop_order::genus_lowering_first;
    for (int pass = genus_lowering_first ? 0 : 1; pass < 2; ++pass)
      for (const Path& loop : candidates) {
        if (genus_lowering_first && genus == 0)
          return;
        for (const Path& piece : split_at_cut(cyclically_reduced(loop, tm_), tiling_)) {
          if (tiling_.check_path(piece) != Cut_path_status::ok)
            continue;
          const vertex_descriptor a = source(piece.front(), tm_);
          bool lowers = a == target(piece.back(), tm_) && !tiling_.is_on_cut(a);
          if (!lowers) {
            const auto& labels = tiling_.boundary_cycle_labels();
            lowers = cycle_at_target(opposite(piece.front(), tm_), labels) ==
                     cycle_at_target(piece.back(), labels);
          }
          if (pass == 0 && !lowers)
            continue;
          // A piece with both ends on one cycle separates its tile or lowers its genus; one that
          // joins two cycles never separates. Without mesh borders the loops' complement is
          // connected and no piece separates (the walk would cost 70 % of the greedy cut of a
          // closed 1M-face genus-10 mesh).
          if (lowers && has_border_ && separates(piece))
            continue;
          if (tiling_.cut(piece) == Cut_path_status::ok && lowers)
            --genus;
          if (genus_lowering_first && genus == 0)
            return;
        }
      }
  }

  /// True when cutting `piece` would split its tile: no walk across faces, crossing neither the
  /// cut nor the piece, leads from the face on its left to the face on its right.
  bool separates(const Path& piece) {
    const auto& idx = tiling_.indices();
    if (visit_stamp_.size() != idx.n_faces)
      visit_stamp_.assign(idx.n_faces, 0);
    if (blocked_stamp_.size() != idx.n_edges)
      blocked_stamp_.assign(idx.n_edges, 0);
    ++stamp_;
    for (halfedge_descriptor h : piece)
      blocked_stamp_[idx.e(edge(h, tm_))] = stamp_;
    const auto from = face(piece.front(), tm_), to = face(opposite(piece.front(), tm_), tm_);
    std::vector<typename GT::face_descriptor> stack{from};
    visit_stamp_[idx.f(from)] = stamp_;
    while (!stack.empty()) {
      const auto f = stack.back();
      stack.pop_back();
      if (f == to)
        return false;
      for (halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm_), tm_)) {
        const edge_descriptor e = edge(h, tm_);
        if (tiling_.is_cut(e) || blocked_stamp_[idx.e(e)] == stamp_)
          continue;
        const auto g = face(opposite(h, tm_), tm_);
        if (visit_stamp_[idx.f(g)] == stamp_)
          continue;
        visit_stamp_[idx.f(g)] = stamp_;
        stack.push_back(g);
      }
    }
    return true;
  }

  /// Phase 2: joins every boundary cycle of the tiles of `component_faces` into one, by shortest
  /// paths found with one multi-source Dijkstra from all cut vertices and a minimum spanning tree
  /// of the cycles. `multipoint_penalty` > 0 makes paths prefer to start and end at multipoints.
  void join_boundaries(double multipoint_penalty) {
    const auto& idx = tiling_.indices();
    const double inf = std::numeric_limits<double>::infinity();
    const std::size_t cycles = tiling_.number_of_boundary_cycles();
    if (cycles < 2)
      return;
    const std::vector<std::size_t> labels = tiling_.boundary_cycle_labels();

    std::vector<std::pair<vertex_descriptor, double>> sources;
    for (vertex_descriptor v : vertices(tm_))
      if (tiling_.is_on_cut(v))
        sources.emplace_back(v, tiling_.is_multipoint(v) ? 0.0 : multipoint_penalty);
    Shortest_path_tree<TriangleMesh> spt(tm_, idx);
    spt.run_seeded(sources, [&](edge_descriptor e) {
      // Never along the cut, and never onwards from a cut vertex reached from elsewhere.
      if (tiling_.is_cut(e))
        return inf;
      const vertex_descriptor s = source(e, tm_);
      if (tiling_.is_on_cut(s) && spt.parent(s) != GT::null_halfedge())
        return inf;
      return double(get(cost_, e));
    });
    // Cycle reached by each vertex: from the wedge its tree path leaves its root in.
    std::vector<std::size_t> region(idx.n_vertices, std::size_t(-1));
    for (vertex_descriptor v : spt.settled()) {
      const halfedge_descriptor h = spt.parent(v);
      if (h == GT::null_halfedge())
        continue;
      const vertex_descriptor u = source(h, tm_);
      region[idx.v(v)] = spt.parent(u) == GT::null_halfedge()
                             ? cycle_at_target(opposite(h, tm_), labels)
                             : region[idx.v(u)];
    }
    auto is_root = [&](vertex_descriptor v) {
      return tiling_.is_on_cut(v) && spt.reached(v) && spt.parent(v) == GT::null_halfedge();
    };
    auto usable = [&](vertex_descriptor v) {
      return is_root(v) || (!tiling_.is_on_cut(v) && spt.reached(v));
    };
    struct Link {
      halfedge_descriptor h; // from the side of cycle a to the side of cycle b
      double length;
      std::size_t a, b;
    };
    std::vector<Link> links;
    auto side_of = [&](halfedge_descriptor h_out) { // cycle label of the source side of h_out
      const vertex_descriptor u = source(h_out, tm_);
      return is_root(u) ? cycle_at_target(opposite(h_out, tm_), labels) : region[idx.v(u)];
    };
    for (halfedge_descriptor h : halfedges(tm_)) {
      if (is_border(h, tm_) || tiling_.is_cut(edge(h, tm_)))
        continue;
      const vertex_descriptor u = source(h, tm_), v = target(h, tm_);
      if (!usable(u))
        continue;
      std::size_t b = std::size_t(-1);
      double length = spt.distance(u) + double(get(cost_, edge(h, tm_)));
      if (usable(v)) {
        // Each edge between two usable vertices is seen from both sides: keep one.
        if (idx.h(opposite(h, tm_)) < idx.h(h))
          continue;
        b = side_of(opposite(h, tm_));
        length += spt.distance(v);
      } else if (tiling_.is_on_cut(v)) {
        // The path ends on a cut vertex that was reached from another root.
        b = cycle_at_target(h, labels);
        length += tiling_.is_multipoint(v) ? 0.0 : multipoint_penalty;
      }
      const std::size_t a = side_of(h);
      if (a == b || a == std::size_t(-1) || b == std::size_t(-1))
        continue;
      links.push_back({h, length, a, b});
    }
    std::sort(links.begin(), links.end(),
              [](const Link& x, const Link& y) { return x.length < y.length; });
    std::vector<std::size_t> rank(cycles, 0), parent(cycles);
    std::iota(parent.begin(), parent.end(), std::size_t(0));
    boost::disjoint_sets<std::size_t*, std::size_t*> sets(rank.data(), parent.data());
    std::vector<Path> joins;
    for (const Link& l : links) {
      if (sets.find_set(l.a) == sets.find_set(l.b))
        continue;
      sets.union_set(l.a, l.b);
      Path p = spt.path_to(source(l.h, tm_));
      p.push_back(l.h);
      if (usable(target(l.h, tm_)))
        for (halfedge_descriptor r : spt.path_to_reversed(target(l.h, tm_)))
          p.push_back(r);
      joins.push_back(std::move(p));
    }
    // Cut the joins in order; a join whose path now meets earlier cuts is cut only in its pieces
    // that still connect two different cycles.
    for (const Path& join : joins)
      for (const Path& piece : split_at_cut(join, tiling_)) {
        const auto& now = tiling_.boundary_cycle_labels();
        if (cycle_at_target(opposite(piece.front(), tm_), now) !=
            cycle_at_target(piece.back(), now))
          tiling_.cut(piece);
      }
  }

  /// A closed genus-0 component without cut: one slit along the shortest path from `b` to the
  /// vertex farthest from it, which opens the sphere into a disk with two corners.
  void slit_sphere(vertex_descriptor b) {
    Shortest_path_tree<TriangleMesh> spt(tm_, tiling_.indices());
    spt.run({b}, [&](edge_descriptor e) { return double(get(cost_, e)); });
    const vertex_descriptor far = spt.settled().back();
    if (far != b)
      tiling_.cut(spt.path_to(far));
  }

private:
  // Scratch of `separates()`: a face or edge is marked when its stamp equals `stamp_`.
  std::vector<std::uint32_t> visit_stamp_, blocked_stamp_;
  std::uint32_t stamp_ = 0;
  bool has_border_ = false;
  M_tiling<TriangleMesh>& tiling_;
  const TriangleMesh& tm_;
  EdgeCostMap cost_;
};

} // namespace internal

} // namespace tessera
