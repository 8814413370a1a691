// Combinatorics of the unsticking of a system of loops (Favreau et al. 2009, §3.3.1 and §4.2): the
// loops are split into half-strands (tree paths from the basepoint to one end of a generator), and
// a counterclockwise tour of the tree ranks them so that strands nested by rank never cross.
#pragma once

#include <tessera/topology/system_of_loops.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>

#include <cstddef>
#include <string>
#include <unordered_map>
#include <vector>

namespace tessera::internal {

/// Next outgoing halfedge counterclockwise around `source(h)`; the face between them is `face(h)`.
template <typename FaceGraph>
typename boost::graph_traits<FaceGraph>::halfedge_descriptor
ccw_next_out(typename boost::graph_traits<FaceGraph>::halfedge_descriptor h, const FaceGraph& g) {
  return opposite(prev(h, g), g);
}

/// Next outgoing halfedge clockwise around `source(h)`; the face between them is
/// `face(opposite(h))`.
template <typename FaceGraph>
typename boost::graph_traits<FaceGraph>::halfedge_descriptor
cw_next_out(typename boost::graph_traits<FaceGraph>::halfedge_descriptor h, const FaceGraph& g) {
  return next(opposite(h, g), g);
}

/// One half of a loop: the tree path from the basepoint to an end of the loop's generator, then the
/// generator leaving that end. Half-strand 2i runs forward along loop i up to its generator, 2i + 1
/// backward along loop i from its end down to the generator's other end.
template <typename FaceGraph> struct Half_strand {
  using halfedge_descriptor = typename boost::graph_traits<FaceGraph>::halfedge_descriptor;
  std::vector<halfedge_descriptor> path; // tree halfedges leading away from the basepoint
  halfedge_descriptor exit;              // the generator, oriented away from the path's end
  std::size_t rank = 0;                  // position in the tour: 0 is the outermost strand
  /// Edges crossed, in order, with the level of each crossing: while the strand turns around each
  /// path vertex from the edge it arrives by to the edge it leaves by, and where it passes to the
  /// other side of the edge it leaves by. Each halfedge leaves the vertex turned around; the point
  /// is at offset level / (number of strands) of the outer offset along it.
  std::vector<std::pair<halfedge_descriptor, std::size_t>> crossings;
};

/// The half-strands of a system of loops whose loops are tree paths joined by generators (as
/// `greedy_system_of_loops()` builds them), their tour ranks and crossings. `valid` is false, with
/// a message, when the loops are not of that form.
template <typename FaceGraph> struct Loop_strands {
  using GT = boost::graph_traits<FaceGraph>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using edge_descriptor = typename GT::edge_descriptor;

  bool valid = false;
  std::string message;
  std::vector<Half_strand<FaceGraph>> strands;
  /// Edges of the cut graph: the tree paths and the generators.
  std::vector<edge_descriptor> cut_edges;

  /// `g` is the graph the strands are realized in; it may be refined between calls of `route()`.
  Loop_strands(const FaceGraph& g, const System_of_loops<FaceGraph>& sys) : g_(g) {
    valid = split_loops(sys);
  }

  /// Ranks the half-strands by a counterclockwise tour of the tree and lists their crossings.
  /// A strand turns counterclockwise around a path vertex, on the right of its path, unless the
  /// border lies that way; then it turns clockwise, on the left. Ranks follow the tour, so the
  /// strands along an edge are ordered by rank from its right to its left, and the levels keep
  /// that order: n - rank on the right, rank + 1 on the left (n strands). A strand that must change
  /// sides between two path vertices crosses the edge joining them next to the first one, at its
  /// level there; the strands that do are the innermost ones, so they cross no other strand.
  /// False (with a message) where a vertex has the border on both ways, i.e. is not manifold.
  /// Call on the mesh as it is when the strands are realized.
  bool route(vertex_descriptor basepoint) {
    rank_by_tour(basepoint);
    const std::size_t n = strands.size();
    std::vector<halfedge_descriptor> swept;
    for (Half_strand<FaceGraph>& s : strands) {
      s.crossings.clear();
      bool was_ccw = true;
      std::size_t was_level = 0;
      for (std::size_t j = 0; j < s.path.size(); ++j) {
        const halfedge_descriptor in = s.path[j];
        const halfedge_descriptor out = j + 1 < s.path.size() ? s.path[j + 1] : s.exit;
        const bool ccw = sweep(in, out, true, swept);
        if (!ccw && !sweep(in, out, false, swept)) {
          message = "the mesh is not manifold at a vertex of the loops";
          return false;
        }
        const std::size_t level = ccw ? n - s.rank : s.rank + 1;
        // Turning counterclockwise at the previous vertex brought the strand to the right of `in`.
        if (j > 0 && ccw != was_ccw)
          s.crossings.push_back({in, was_level});
        for (halfedge_descriptor o : swept)
          s.crossings.push_back({o, level});
        was_ccw = ccw;
        was_level = level;
      }
    }
    return true;
  }

private:
  // The edges strictly between `opposite(in)` and `out` around their common vertex, turning
  // counterclockwise or clockwise; false if the border lies on the way.
  bool sweep(halfedge_descriptor in, halfedge_descriptor out, bool ccw,
             std::vector<halfedge_descriptor>& swept) const {
    swept.clear();
    for (halfedge_descriptor o = opposite(in, g_);;) {
      if (is_border(ccw ? o : opposite(o, g_), g_))
        return false;
      o = ccw ? ccw_next_out(o, g_) : cw_next_out(o, g_);
      if (o == out)
        return true;
      swept.push_back(o);
    }
  }

  bool fail(std::string why) {
    message = std::move(why);
    return false;
  }

  // Records `h` as the tree halfedge arriving at `target(h)`; false if another one already is.
  bool set_parent(halfedge_descriptor h, vertex_descriptor basepoint) {
    const vertex_descriptor v = target(h, g_);
    if (v == basepoint)
      return false;
    const halfedge_descriptor old = parent(v);
    if (old != GT::null_halfedge() && old != h)
      return false;
    parent_[v] = h;
    return true;
  }

  bool split_loops(const System_of_loops<FaceGraph>& sys) {
    const vertex_descriptor b = sys.basepoint;
    if (sys.generators.size() != sys.loops.size())
      return fail("the system has " + std::to_string(sys.generators.size()) + " generators for " +
                  std::to_string(sys.loops.size()) + " loops");
    std::vector<std::size_t> split(sys.loops.size());
    for (std::size_t i = 0; i < sys.loops.size(); ++i) {
      const auto& loop = sys.loops[i];
      const std::string which = "loop " + std::to_string(i);
      if (loop.empty() || source(loop.front(), g_) != b || target(loop.back(), g_) != b)
        return fail(which + " is not closed at the basepoint");
      std::size_t generator_at = loop.size();
      for (std::size_t k = 0; k < loop.size(); ++k) {
        if (k > 0 && source(loop[k], g_) != target(loop[k - 1], g_))
          return fail(which + " is not a connected halfedge path");
        if (is_border_edge(loop[k], g_))
          return fail(which + " runs along the border");
        if (edge(loop[k], g_) != sys.generators[i])
          continue;
        if (generator_at != loop.size())
          return fail(which + " passes its generator twice");
        generator_at = k;
      }
      if (generator_at == loop.size())
        return fail(which + " does not pass its generator");
      split[i] = generator_at;
      for (std::size_t k = 0; k < generator_at; ++k)
        if (!set_parent(loop[k], b))
          return fail(which + " is not made of tree paths from the basepoint (loops may cross)");
      for (std::size_t k = generator_at + 1; k < loop.size(); ++k)
        if (!set_parent(opposite(loop[k], g_), b))
          return fail(which + " is not made of tree paths from the basepoint (loops may cross)");
    }
    for (std::size_t i = 0; i < sys.loops.size(); ++i) {
      const auto& loop = sys.loops[i];
      const halfedge_descriptor gen = loop[split[i]];
      if (parent(target(gen, g_)) == gen || parent(source(gen, g_)) == opposite(gen, g_))
        return fail("the generator of loop " + std::to_string(i) + " is also a tree edge");
      if (stub(gen) != 0 || stub(opposite(gen, g_)) != 0)
        return fail("two loops share the generator of loop " + std::to_string(i));
      Half_strand<FaceGraph> forward, backward;
      forward.path.assign(loop.begin(), loop.begin() + std::ptrdiff_t(split[i]));
      forward.exit = gen;
      for (std::size_t k = loop.size(); k-- > split[i] + 1;)
        backward.path.push_back(opposite(loop[k], g_));
      backward.exit = opposite(gen, g_);
      stub_[forward.exit] = strands.size() + 1;
      strands.push_back(std::move(forward));
      stub_[backward.exit] = strands.size() + 1;
      strands.push_back(std::move(backward));
      cut_edges.push_back(edge(gen, g_));
    }
    // The tree edges in the graph's vertex order (the order the refinement splits faces in).
    for (vertex_descriptor v : vertices(g_))
      if (parent(v) != GT::null_halfedge())
        cut_edges.push_back(edge(parent(v), g_));
    return true;
  }

  // Depth-first tour of the tree and its generator stubs, counterclockwise around each vertex from
  // the edge to its parent. Strands leaving a vertex later in this order turn further around it, so
  // they must run closer to it: rank = order of appearance, and offsets shrink with the rank.
  void rank_by_tour(vertex_descriptor basepoint) {
    std::vector<halfedge_descriptor> stack;
    auto push_exits = [&](halfedge_descriptor from, bool include_from) {
      std::vector<halfedge_descriptor> around;
      if (include_from)
        around.push_back(from);
      for (halfedge_descriptor o = ccw_next_out(from, g_); o != from; o = ccw_next_out(o, g_))
        around.push_back(o);
      for (std::size_t k = around.size(); k-- > 0;) {
        const halfedge_descriptor o = around[k];
        if (stub(o) != 0 || parent(target(o, g_)) == o)
          stack.push_back(o);
      }
    };
    push_exits(opposite(halfedge(basepoint, g_), g_), true);
    std::size_t rank = 0;
    while (!stack.empty()) {
      const halfedge_descriptor o = stack.back();
      stack.pop_back();
      if (stub(o) != 0)
        strands[stub(o) - 1].rank = rank++;
      else
        push_exits(opposite(o, g_), false);
    }
  }

  // The tree halfedge arriving at a path vertex; null elsewhere.
  halfedge_descriptor parent(vertex_descriptor v) const {
    const auto p = parent_.find(v);
    return p == parent_.end() ? GT::null_halfedge() : p->second;
  }
  // 1 + the index of the half-strand that leaves by the generator halfedge `h`; 0 elsewhere.
  std::size_t stub(halfedge_descriptor h) const {
    const auto s = stub_.find(h);
    return s == stub_.end() ? 0 : s->second;
  }

  const FaceGraph& g_;
  // Hash maps, not property maps over the whole graph: they hold the loops' vertices and
  // generators only, so building the strands costs what the loops cost, not what the mesh does
  // (and the refinement that follows does not move them when the graph's arrays grow).
  std::unordered_map<vertex_descriptor, halfedge_descriptor> parent_;
  std::unordered_map<halfedge_descriptor, std::size_t> stub_;
};

} // namespace tessera::internal
