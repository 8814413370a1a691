// Shortest cutting paths inside the tiles of an M-tiling, from several corners at once: the search
// behind Alg. 4 and Alg. 5 of the quadrangulation (Favreau et al. 2009, §4), laid out for the
// memory latency that bounds it on large meshes.
#pragma once

#include <tessera/topology/internal/double_geometry.h>
#include <tessera/topology/internal/huge_page_allocator.h>
#include <tessera/topology/m_tiling.h>

#include <boost/heap/d_ary_heap.hpp>
#include <boost/sort/spreadsort/integer_sort.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iterator>
#include <limits>
#include <memory>
#include <unordered_map>
#include <vector>

namespace tessera {
namespace internal {

/// Shortest cutting paths inside tiles, from several corners at once: a Dijkstra over the vertices
/// off the cut, where every vertex keeps its `labels` nearest distinct source corners (exact for
/// the k nearest: a vertex that lacks source s in its k nearest has k sources nearer than s, and so
/// do all vertices reached through it). Paths leave a source corner only into its wedge and arrive
/// at a target corner only through its wedge, and no inner vertex lies on the cut. Given target
/// corners, the search stops once no unsettled label can improve the best valid arrival found so
/// far, so its cost follows the length of the answer rather than the size of the tile.
///
/// The search is bound by memory latency on large meshes, and is laid out for it:
/// - One object serves a sequence of runs on a tiling whose cut grows (Alg. 5). Every vertex's
///   one-ring (neighbour indices and edge costs) is copied into a compact cache up front, in one
///   pass over the edges in storage order (walking each vertex's halfedges instead is a chain of
///   dependent cache misses, and the runs of Alg. 5 end up reading most rings anyway). Cuts do not
///   change one-rings; refinements do: `refresh` drops the rings they touched, which are read
///   again from the mesh on first expansion. Vertices on the cut stay marked across runs; only
///   new cut edges are read.
/// - Vertices are numbered internally along a Morton (Z-order) curve of their positions, so that
///   the data of a region is close in memory whatever the mesh's own vertex order.
/// - What a run knows of a vertex (settled and queued labels, A* estimate, target arrivals) fills
///   one 64-byte slot. Queued labels let most relaxations be dropped before they reach the heap.
/// - While one label is settled, the slot and ring of the next one (the heap's new top) and then
///   its neighbours' slots are prefetched, so that their cache misses overlap with the work.
/// - The arrays indexed by vertex, the ring blocks and the heap ask for transparent huge pages
///   (`Huge_page_allocator`): fewer page faults when they are first written, fewer TLB misses.
template <typename TriangleMesh,
          typename VertexPointMap =
              typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>
class Cutting_path_search {
public:
  using GT = boost::graph_traits<TriangleMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using edge_descriptor = typename GT::edge_descriptor;
  using Path = std::vector<halfedge_descriptor>;
  using Cost = std::function<double(edge_descriptor)>;

  struct Candidate {
    double length = std::numeric_limits<double>::infinity();
    std::size_t source = std::size_t(-1); // index into the sources of `run`
    /// The path's last halfedge, arriving at the target; with face diagonals, when the last step
    /// is a diagonal (`diagonal`), the halfedge of the face it crosses that arrives at the target.
    halfedge_descriptor last;
    vertex_descriptor from; ///< the vertex before the target
    bool diagonal = false;  ///< the last step crosses a face instead of following an edge
    /// False when no source reached the target.
    bool found() const { return source != std::size_t(-1); }
  };

  /// Accepts every (source, target) pair.
  struct Accept_all {
    bool operator()(std::size_t, std::size_t) const { return true; }
  };

  /// `labels` (at most 3) nearest sources are kept at every vertex; `cost(e)` is the non-negative
  /// cost of edge e (read once per edge and vertex until `refresh` says it changed).
  /// Positions are read from `vpm`.
  ///
  /// With `face_diagonals`, a path may also cross a face from one of its vertices to another
  /// (costing their Euclidean distance; the faces are convex and planar, as the pieces of a
  /// triangle cut along straight segments are), except between vertices on one straight side of
  /// the face: refinements then need not triangulate the faces they split (see
  /// `cut_into_quads`), and the caller inserts the diagonals a path takes (`insert_path`).
  Cutting_path_search(const M_tiling<TriangleMesh>& tiling, std::size_t labels, Cost cost,
                      VertexPointMap vpm, bool face_diagonals = false)
      : tiling_(tiling), tm_(tiling.mesh()), idx_(tiling.indices()), vpm_(vpm),
        cost_(std::move(cost)), k_(std::min<std::size_t>(labels, 3)), diagonals_(face_diagonals) {
    rebuild();
  }
  /// Positions are read from the mesh's internal point map.
  Cutting_path_search(const M_tiling<TriangleMesh>& tiling, std::size_t labels, Cost cost)
      : Cutting_path_search(tiling, labels, std::move(cost),
                            get(CGAL::vertex_point, tiling.mesh())) {}

  /// Follows the tiling's mesh after a local refinement that added the vertices `added` and that
  /// the tiling has absorbed (`M_tiling::absorb_refinement`), once the costs of the edges at these
  /// vertices are set: the rings of the new vertices and of their neighbours are read again.
  void refresh(const std::vector<vertex_descriptor>& added) {
    const std::size_t n = idx_.n_vertices;
    if (tiling_.renumberings() != renumberings_ || n != verts_.size() + added.size()) {
      rebuild();
      return;
    }
    std::size_t next = verts_.size();
    resize(n);
    for (vertex_descriptor v : added) {
      order_[idx_.v(v)] = std::uint32_t(next);
      verts_[next] = v;
      pos_[next] = internal::to_double_array(get(vpm_, v));
      ++next;
    }
    for (vertex_descriptor v : added)
      forget_around(v);
  }

  /// Follows vertices `vs` that moved (their positions read again; their rings, and those of
  /// the vertices they share a face with, read again on their next expansion). The costs of the
  /// edges at them must be set already.
  void move_vertices(const std::vector<vertex_descriptor>& vs) {
    for (vertex_descriptor v : vs) {
      pos_[at(v)] = internal::to_double_array(get(vpm_, v));
      forget_around(v);
    }
  }

  /// Reads the rings of `vs` again from the mesh on their next expansion (after a face at them
  /// was split, which changes the vertices a diagonal reaches).
  void forget_rings(const std::vector<vertex_descriptor>& vs) {
    for (vertex_descriptor v : vs)
      slots_[at(v)].ring = 0;
  }

  /// Runs from `sources` (corners). With `targets` (corners), the run stops as soon as every label
  /// still to settle is at least as far as the best arrival at some target t from a source s with
  /// `accept(s, t)` (indices into the two vectors); `best_arrival` is exact for these pairs, and
  /// only for them. When every edge costs at least `lower_bound` times its Euclidean length (1 for
  /// Euclidean costs), the search is an A* guided by that multiple of the straight-line distance to
  /// the nearest target, a consistent estimate, so labels still settle nearest first at every
  /// vertex and the answer is the same.
  template <typename Accept = Accept_all>
  void run(const std::vector<halfedge_descriptor>& sources,
           const std::vector<halfedge_descriptor>& targets = {}, Accept accept = {},
           double lower_bound = 0) {
    for (std::uint32_t v : touched_)
      slots_[v].clear();
    touched_.clear();
    // Vertices on the cut are blocked in the same slots, so that a neighbour costs one lookup. The
    // cut only grows between runs (Alg. 5), so only its new edges are read; should it have changed
    // otherwise, all of it is read again.
    const auto& cut = tiling_.cut_edges();
    if (blocked_edges_ > cut.size() ||
        (blocked_edges_ > 0 && cut[blocked_edges_ - 1] != last_blocked_)) {
      for (Slot& sx : slots_)
        sx.on_cut = false;
      blocked_edges_ = 0;
    }
    for (; blocked_edges_ < cut.size(); ++blocked_edges_) {
      const halfedge_descriptor h = halfedge(cut[blocked_edges_], tm_);
      slots_[at(source(h, tm_))].on_cut = slots_[at(target(h, tm_))].on_cut = true;
    }
    if (!cut.empty())
      last_blocked_ = cut.back();
    source_of_corner_.clear();
    for (std::size_t s = 0; s < sources.size(); ++s)
      source_of_corner_[idx_.h(sources[s])] = s;
    // The targets' wedge neighbours off the cut, and a first bound from single-edge paths.
    double bound = std::numeric_limits<double>::infinity();
    arrivals_.clear();
    for (std::size_t t = 0; t < targets.size(); ++t)
      for_each_exit(targets[t], [&](vertex_descriptor u, double w, halfedge_descriptor to_u, bool) {
        if (!tiling_.is_on_cut(u)) {
          Slot& su = slots_[at(u)];
          if (su.count == 0 && su.queued == 0 && su.first_arrival == none)
            touched_.push_back(std::uint32_t(at(u)));
          arrivals_.push_back({std::uint32_t(t), su.first_arrival, w});
          su.first_arrival = std::uint32_t(arrivals_.size() - 1);
          return;
        }
        const auto it = source_of_corner_.find(idx_.h(tiling_.wedge_border(to_u)));
        if (it != source_of_corner_.end() && accept(it->second, t))
          bound = std::min(bound, w);
      });
    // The estimate: lower_bound (less a rounding margin) times the distance to the nearest target.
    std::vector<std::array<double, 3>> goals;
    for (halfedge_descriptor t : targets)
      goals.push_back(pos_[at(target(t, tm_))]);
    std::sort(goals.begin(), goals.end());
    goals.erase(std::unique(goals.begin(), goals.end()), goals.end());
    const double scale = goals.empty() ? 0.0 : std::max(0.0, lower_bound) * (1.0 - 1e-9);
    const auto estimate = [&](std::size_t v) {
      if (scale == 0)
        return 0.0;
      const auto& p = pos_[v];
      double best = std::numeric_limits<double>::infinity();
      for (const auto& g : goals)
        best = std::min(best, (p[0] - g[0]) * (p[0] - g[0]) + (p[1] - g[1]) * (p[1] - g[1]) +
                                  (p[2] - g[2]) * (p[2] - g[2]));
      return scale * std::sqrt(best);
    };
    queue_.clear();
    // Queues source `label` at distance d at vertex v, unless v has it already, or k other sources
    // are known to be at most as far (then `label` is not among v's k nearest through this way).
    const auto push = [&](double d, std::size_t v, std::size_t parent, std::size_t label) {
      Slot& sv = slots_[v];
      if (sv.on_cut || sv.count >= k_ || sv.has(label))
        return;
      std::size_t nearer = 0, farthest = 0, same = none;
      for (std::size_t j = 0; j < sv.queued; ++j) {
        if (sv.queued_label[j] == label)
          same = j;
        else if (sv.queued_dist[j] <= d)
          ++nearer;
        if (sv.queued_dist[j] > sv.queued_dist[farthest])
          farthest = j;
      }
      if (same != none) {
        if (sv.queued_dist[same] <= d)
          return;
        sv.queued_dist[same] = d;
      } else {
        if (nearer >= k_)
          return;
        if (sv.queued == 0 && sv.count == 0) {
          if (sv.first_arrival == none)
            touched_.push_back(std::uint32_t(v));
          sv.estimate = estimate(v);
        }
        const std::size_t j = sv.queued < 3 ? sv.queued++ : farthest; // the farthest is beyond d
        sv.queued_label[j] = std::uint32_t(label);
        sv.queued_dist[j] = d;
      }
      queue_.push(
          {d + sv.estimate, d, std::uint32_t(v), std::uint32_t(parent), std::uint32_t(label)});
    };
    for (std::size_t s = 0; s < sources.size(); ++s)
      for_each_exit(sources[s], [&](vertex_descriptor x, double w, halfedge_descriptor, bool) {
        if (!tiling_.is_on_cut(x))
          push(w, at(x), at(target(sources[s], tm_)), s);
      });
    while (!queue_.empty()) {
      const Entry top = queue_.top();
      queue_.pop();
      if (top.f >= bound)
        break;
      // The next entry to settle is known now: ask for its slot and ring while this one is
      // processed (about a quarter of the search's time is saved on large meshes), and for those
      // of the root's children, among which is the one after (the heap's iterators run over its
      // array in storage order; another order would only make this hint useless).
      if (!queue_.empty())
        prefetch_vertex(queue_.top().v);
      if (queue_.size() > 4) {
        auto child = std::next(queue_.begin());
        for (int c = 0; c < 4; ++c, ++child)
          prefetch_vertex(child->v);
      }
      const std::size_t v = top.v;
      Slot& sv = slots_[v];
      const std::size_t n = sv.count;
      if (n >= k_ || sv.has(top.label))
        continue; // (queued vertices are off the cut)
      sv.label[n] = top.label;
      dist_[v * k_ + n] = top.d;
      parent_[v * k_ + n] = top.parent;
      ++sv.count;
      for (std::uint32_t a = sv.first_arrival; a != none; a = arrivals_[a].next)
        if (accept(top.label, arrivals_[a].target))
          bound = std::min(bound, top.d + arrivals_[a].cost);
      if (sv.ring == 0)
        cache_ring(v);
      if (sv.ring != overflow) {
        const Ring& r = ring(v);
        for (std::size_t j = 0; j < sv.ring; ++j)
          push(top.d + r.cost[j], r.neighbour[j], v, top.label);
      } else {
        const auto [begin, end] = overflow_[v];
        for (std::size_t j = begin; j < end; ++j)
          push(top.d + overflow_cost_[j], overflow_vertex_[j], v, top.label);
      }
      // The next entry's neighbours' slots, which its relaxations will read.
      if (!queue_.empty())
        prefetch_neighbours(queue_.top().v);
    }
  }

  /// The shortest path found by the last `run` that arrives at corner `target` from a source s with
  /// `accept(s)`: through a vertex off the cut, or along one uncut edge from a source corner.
  Candidate best_arrival(halfedge_descriptor target_corner,
                         const std::function<bool(std::size_t)>& accept) const {
    Candidate best;
    const vertex_descriptor t = target(target_corner, tm_);
    for_each_exit(target_corner,
                  [&](vertex_descriptor u, double w, halfedge_descriptor to_u, bool diagonal) {
                    // The halfedge arriving at the target: the edge's, or the crossed face's.
                    halfedge_descriptor last = opposite(to_u, tm_);
                    if (diagonal) {
                      last = to_u;
                      while (target(last, tm_) != t)
                        last = next(last, tm_);
                    }
                    if (!tiling_.is_on_cut(u)) {
                      const std::size_t ui = at(u);
                      for (std::size_t k = 0; k < slots_[ui].count; ++k)
                        if (accept(slots_[ui].label[k])) {
                          if (dist_[ui * k_ + k] + w < best.length)
                            best = {dist_[ui * k_ + k] + w, slots_[ui].label[k], last, u, diagonal};
                          break; // slots are in increasing distance
                        }
                      return;
                    }
                    const auto it = source_of_corner_.find(idx_.h(tiling_.wedge_border(to_u)));
                    if (it != source_of_corner_.end() && accept(it->second) && w < best.length)
                      best = {w, it->second, last, u, diagonal};
                  });
    return best;
  }

  /// The vertices of `c`'s path, from its source corner's to its target's.
  std::vector<vertex_descriptor> path_vertices(const Candidate& c) const {
    std::vector<vertex_descriptor> p{target(c.last, tm_), c.from};
    for (vertex_descriptor v = c.from; !tiling_.is_on_cut(v);) {
      const std::size_t vi = at(v);
      std::size_t k = 0;
      while (slots_[vi].label[k] != c.source)
        ++k;
      v = verts_[parent_[vi * k_ + k]];
      p.push_back(v);
    }
    std::reverse(p.begin(), p.end());
    return p;
  }

  /// The halfedges of `c`'s path, from its source corner to its target, when it crosses no face
  /// (always so without face diagonals; with them, see `insert_path`).
  Path path(const Candidate& c) const {
    const std::vector<vertex_descriptor> vs = path_vertices(c);
    Path p;
    for (std::size_t i = 0; i + 1 < vs.size(); ++i)
      p.push_back(i + 2 == vs.size() ? c.last : halfedge(vs[i], vs[i + 1], tm_).first);
    return p;
  }

  /// Calls f(u, cost, to_u, diagonal) for each way out of `corner`'s wedge: along each uncut edge
  /// to its other end u (to_u: the edge's halfedge arriving at u), and with face diagonals, across
  /// each of the wedge's faces to each vertex u of it that is neither the corner nor next to it
  /// on the face (to_u: the face's halfedge arriving at u).
  template <typename F> void for_each_exit(halfedge_descriptor corner, F f) const {
    const std::size_t c = at(target(corner, tm_));
    const auto across = [&](halfedge_descriptor in_face) { // in_face arrives at the corner
      for_each_diagonal(in_face, [&](halfedge_descriptor h) {
        f(target(h, tm_), distance(c, at(target(h, tm_))), h, true);
      });
    };
    across(corner);
    tiling_.for_each_in_wedge(corner, [&](halfedge_descriptor g) {
      f(source(g, tm_), cost_(edge(g, tm_)), opposite(g, tm_), false);
      across(g);
    });
  }

private:
  static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  // What a run knows of a vertex: the sources of its settled labels; up to three queued arrivals
  // (distinct sources, upper bounds of their distances), which let a relaxation be dropped when it
  // cannot make a label; the A* estimate, set when first queued; the target arrivals through it.
  struct alignas(64) Slot {
    std::uint8_t count = 0; // labels settled
    std::uint8_t queued = 0;
    std::uint8_t ring =
        0;               // kept across runs: the cached ring's size, `overflow`, or 0 (not cached)
    bool on_cut = false; // kept across runs
    std::uint32_t first_arrival = none; // into `arrivals_`
    std::uint32_t label[3] = {0, 0, 0};
    std::uint32_t queued_label[3] = {0, 0, 0};
    double queued_dist[3] = {0, 0, 0};
    double estimate = 0;
    bool has(std::size_t l) const {
      for (std::size_t k = 0; k < count && k < 3; ++k)
        if (label[k] == l)
          return true;
      return false;
    }
    void clear() {
      count = queued = 0;
      first_arrival = none;
    }
  };
  static_assert(sizeof(Slot) == 64, "a slot fills one cache line");

  struct Entry {
    double f; // d plus the estimate
    double d;
    std::uint32_t v, parent, label;
    bool operator<(const Entry& o) const { return f > o.f; }
  };

  // A cached one-ring: neighbour indices and the costs of the edges to them, at the vertex's
  // internal index (Morton order) in blocks allocated uninitialized, so the cache grows with the
  // explored region and the mesh without copies. Rings of more than `ring_capacity` vertices go to
  // `overflow_`, appended.
  static constexpr std::size_t ring_capacity = 8;
  static constexpr std::uint8_t overflow = std::numeric_limits<std::uint8_t>::max();
  struct Ring {
    std::uint32_t neighbour[ring_capacity];
    double cost[ring_capacity];
  };
  // Blocks of 2^16 rings, 6 MiB: a whole number of 2 MiB huge pages.
  static constexpr std::size_t block_bits = 16;
  struct Block_deleter {
    void operator()(Ring* p) const {
      Huge_page_allocator<Ring>().deallocate(p, std::size_t(1) << block_bits);
    }
  };
  Ring& ring(std::size_t v) const {
    return blocks_[v >> block_bits].get()[v & ((std::size_t(1) << block_bits) - 1)];
  }
  void cache_ring(std::size_t v) {
    const std::size_t begin = overflow_vertex_.size();
    for (halfedge_descriptor h : CGAL::halfedges_around_target(verts_[v], tm_)) {
      overflow_vertex_.push_back(std::uint32_t(at(source(h, tm_))));
      overflow_cost_.push_back(cost_(edge(h, tm_)));
      for_each_diagonal(h, [&](halfedge_descriptor g) {
        overflow_vertex_.push_back(std::uint32_t(at(target(g, tm_))));
        overflow_cost_.push_back(distance(v, at(target(g, tm_))));
      });
    }
    const std::size_t size = overflow_vertex_.size() - begin;
    if (size > ring_capacity) {
      overflow_[v] = {std::uint32_t(begin), std::uint32_t(overflow_vertex_.size())};
      slots_[v].ring = overflow;
      return;
    }
    Ring& r = ring(v);
    std::copy(overflow_vertex_.begin() + long(begin), overflow_vertex_.end(), r.neighbour);
    std::copy(overflow_cost_.begin() + long(begin), overflow_cost_.end(), r.cost);
    overflow_vertex_.resize(begin);
    overflow_cost_.resize(begin);
    slots_[v].ring = std::uint8_t(size == 0 ? overflow : size); // an empty ring reads nothing
  }

  // Caches the rings of all vertices from the edges in their storage order: the mesh's arrays are
  // read in sequence, and the rings written to are prefetched a few edges ahead, unlike the walk
  // around each vertex that `cache_ring` does (a chain of dependent loads). A vertex with more
  // than `ring_capacity` neighbours is left to `cache_ring`.
  void cache_all_rings() {
    constexpr std::uint8_t pending = overflow - 1;
    const auto add = [&](std::size_t v, std::size_t u, double c) {
      std::uint8_t& n = slots_[v].ring;
      if (n == pending)
        return;
      if (n == ring_capacity) {
        n = pending;
        return;
      }
      Ring& r = ring(v);
      r.neighbour[n] = std::uint32_t(u);
      r.cost[n] = c;
      ++n;
    };
    struct End_pair {
      std::uint32_t a, b;
      double cost;
    };
    std::vector<End_pair> ends;
    ends.reserve(idx_.n_edges);
    for (edge_descriptor e : edges(tm_)) {
      const halfedge_descriptor h = halfedge(e, tm_);
      ends.push_back(
          {std::uint32_t(at(source(h, tm_))), std::uint32_t(at(target(h, tm_))), cost_(e)});
    }
    constexpr std::size_t ahead = 8; // edges
    for (std::size_t i = 0; i < ends.size(); ++i) {
      if (i + ahead < ends.size())
        for (const std::uint32_t x : {ends[i + ahead].a, ends[i + ahead].b}) {
          prefetch(&slots_[x]);
          prefetch(&ring(x));
          prefetch(reinterpret_cast<const char*>(&ring(x)) + sizeof(Ring) - 1);
        }
      add(ends[i].a, ends[i].b, ends[i].cost);
      add(ends[i].b, ends[i].a, ends[i].cost);
    }
    for (Slot& sx : slots_)
      if (sx.ring == pending)
        sx.ring = 0;
      else if (sx.ring == 0)
        sx.ring = overflow; // no neighbour: an empty ring reads nothing
    if (diagonals_)         // rings with diagonals are read by `cache_ring`
      for (auto f : faces(tm_))
        if (CGAL::halfedges_around_face(halfedge(f, tm_), tm_).size() > 3)
          for (vertex_descriptor u : CGAL::vertices_around_face(halfedge(f, tm_), tm_))
            slots_[at(u)].ring = 0;
  }

  // Calls f(g) for each halfedge g of in_face's face whose target a diagonal from target(in_face)
  // reaches: not the vertex itself nor its two neighbours on the face, and across the face
  // (`crosses_face`). Nothing without face diagonals, on a border halfedge, or in a triangle.
  template <typename F> void for_each_diagonal(halfedge_descriptor in_face, F f) const {
    if (!diagonals_ || is_border(in_face, tm_))
      return;
    for (halfedge_descriptor g = next(next(in_face, tm_), tm_); g != prev(in_face, tm_);
         g = next(g, tm_))
      if (crosses_face(in_face, g))
        f(g);
  }

  // Drops the cached rings that a change at v (new, moved, or with new edges) makes stale: its
  // own, its neighbours' and, with face diagonals, those of every vertex of its faces.
  void forget_around(vertex_descriptor v) {
    slots_[at(v)].ring = 0;
    for (halfedge_descriptor h : CGAL::halfedges_around_target(v, tm_)) {
      slots_[at(source(h, tm_))].ring = 0;
      if (diagonals_ && !is_border(h, tm_))
        for (vertex_descriptor u : CGAL::vertices_around_face(h, tm_))
          slots_[at(u)].ring = 0;
    }
  }

  double distance(std::size_t a, std::size_t b) const {
    const auto &p = pos_[a], &q = pos_[b];
    return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                     (p[2] - q[2]) * (p[2] - q[2]));
  }
  // Whether the segment from target(a) to target(b), two vertices of one face, crosses the face:
  // some vertex on each of the face's two chains between them is off their line (by more than
  // rounding: 1e-9 of the segment's length). A chord along one straight side of the face, which
  // midpoints split into several edges, does not.
  bool crosses_face(halfedge_descriptor a, halfedge_descriptor b) const {
    const auto& p = pos_[at(target(a, tm_))];
    const auto& q = pos_[at(target(b, tm_))];
    const double d[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
    const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    const auto off_line = [&](halfedge_descriptor from, halfedge_descriptor to) {
      for (halfedge_descriptor h = next(from, tm_); h != to; h = next(h, tm_)) {
        const auto& x = pos_[at(target(h, tm_))];
        const double e[3] = {x[0] - p[0], x[1] - p[1], x[2] - p[2]};
        const double c[3] = {d[1] * e[2] - d[2] * e[1], d[2] * e[0] - d[0] * e[2],
                             d[0] * e[1] - d[1] * e[0]};
        if (c[0] * c[0] + c[1] * c[1] + c[2] * c[2] > 1e-18 * dd * dd)
          return true;
      }
      return false;
    };
    return off_line(a, b) && off_line(b, a);
  }

  static void prefetch(const void* p) {
#if defined(__GNUC__) || defined(__clang__)
    __builtin_prefetch(p);
#else
    (void)p;
#endif
  }
  void prefetch_vertex(std::size_t v) const {
    prefetch(&slots_[v]);
    const char* r = reinterpret_cast<const char*>(&ring(v));
    prefetch(r);
    prefetch(r + sizeof(Ring) - 1);
  }
  void prefetch_neighbours(std::size_t v) const {
    const std::uint8_t n = slots_[v].ring;
    if (n == 0 || n == overflow)
      return;
    const Ring& r = ring(v);
    for (std::size_t j = 0; j < n; ++j)
      prefetch(&slots_[r.neighbour[j]]);
  }

  // The internal index of a vertex.
  std::size_t at(vertex_descriptor v) const {
    return order_[idx_.v(v)];
  }

  void resize(std::size_t n) {
    order_.resize(n);
    verts_.resize(n);
    pos_.resize(n);
    overflow_.resize(n);
    while (blocks_.size() << block_bits < n)
      blocks_.emplace_back(Huge_page_allocator<Ring>().allocate(std::size_t(1) << block_bits));
    slots_.resize(n);
    dist_.resize(n * k_);
    parent_.resize(n * k_);
  }
  // Everything indexed by vertex, from the mesh as it is now.
  void rebuild() {
    renumberings_ = tiling_.renumberings();
    verts_.clear();
    overflow_vertex_.clear();
    overflow_cost_.clear();
    touched_.clear();
    slots_.assign(idx_.n_vertices, Slot());
    blocked_edges_ = 0;
    resize(idx_.n_vertices);
    // Morton order: 21 bits per axis of the position in the bounding box, interleaved.
    std::vector<std::pair<vertex_descriptor, std::array<double, 3>>> points;
    points.reserve(idx_.n_vertices);
    for (vertex_descriptor v : vertices(tm_))
      points.emplace_back(v, internal::to_double_array(get(vpm_, v)));
    std::array<double, 3> lo{{0, 0, 0}}, hi{{0, 0, 0}};
    if (!points.empty())
      lo = hi = points.front().second;
    for (const auto& vp : points)
      for (int i = 0; i < 3; ++i) {
        lo[i] = std::min(lo[i], vp.second[i]);
        hi[i] = std::max(hi[i], vp.second[i]);
      }
    const auto spread = [](std::uint64_t x) { // bit i of x to bit 3i
      x &= 0x1fffff;
      x = (x | x << 32) & 0x1f00000000ffffULL;
      x = (x | x << 16) & 0x1f0000ff0000ffULL;
      x = (x | x << 8) & 0x100f00f00f00f00fULL;
      x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
      x = (x | x << 2) & 0x1249249249249249ULL;
      return x;
    };
    std::vector<std::pair<std::uint64_t, std::size_t>> keyed; // (key, index into points)
    keyed.reserve(points.size());
    for (std::size_t j = 0; j < points.size(); ++j) {
      std::uint64_t key = 0;
      for (int i = 0; i < 3; ++i) {
        const double t = hi[i] > lo[i] ? (points[j].second[i] - lo[i]) / (hi[i] - lo[i]) : 0.0;
        key |= spread(std::uint64_t(std::clamp(t, 0.0, 1.0) * double(0x1fffff))) << i;
      }
      keyed.emplace_back(key, j);
    }
    boost::sort::spreadsort::integer_sort(
        keyed.begin(), keyed.end(),
        [](const auto& k, unsigned offset) { return k.first >> offset; },
        [](const auto& a, const auto& b) { return a < b; });
    for (std::size_t i = 0; i < keyed.size(); ++i) {
      const auto& [v, p] = points[keyed[i].second];
      order_[idx_.v(v)] = std::uint32_t(i);
      verts_[i] = v;
      pos_[i] = p;
    }
    cache_all_rings();
  }

  struct Arrival {
    std::uint32_t target;
    std::uint32_t next; // next arrival at the same vertex, or `none`
    double cost;
  };

  const M_tiling<TriangleMesh>& tiling_;
  const TriangleMesh& tm_;
  const Mesh_indices<TriangleMesh>& idx_;
  VertexPointMap vpm_;
  Cost cost_;
  std::size_t k_;
  bool diagonals_ = false;
  std::size_t renumberings_ = 0;
  std::size_t blocked_edges_ = 0; // cut edges whose vertices are marked `on_cut` in the slots
  edge_descriptor last_blocked_;
  // The arrays indexed by vertex are tens of megabytes on large meshes and read at random: they
  // ask for huge pages.
  template <typename T> using Vertex_array = std::vector<T, Huge_page_allocator<T>>;
  Vertex_array<std::uint32_t> order_;     // internal index by mesh index
  Vertex_array<vertex_descriptor> verts_; // by internal index, as is everything below
  Vertex_array<std::array<double, 3>> pos_;
  std::vector<std::unique_ptr<Ring, Block_deleter>> blocks_;
  Vertex_array<std::pair<std::uint32_t, std::uint32_t>> overflow_;
  Vertex_array<Slot> slots_;
  Vertex_array<double> dist_;          // k per vertex, as the slot's labels
  Vertex_array<std::uint32_t> parent_; // k per vertex: the previous vertex
  std::vector<std::uint32_t> overflow_vertex_;
  std::vector<double> overflow_cost_;
  std::vector<std::uint32_t> touched_; // vertices whose slot is in use
  std::vector<Arrival> arrivals_;
  boost::heap::d_ary_heap<Entry, boost::heap::arity<4>,
                          boost::heap::allocator<Huge_page_allocator<Entry>>>
      queue_;
  std::unordered_map<std::size_t, std::size_t> source_of_corner_;
};

} // namespace internal
} // namespace tessera
