// Q-criterion quadrangulation (Favreau et al. 2009, §4): Alg. 4 cuts a tile of an M-tiling along a
// shortest cutting path between two of its corners; Alg. 5 starts from a cut graph (greedy, schema
// or intermediate) and cuts every tile with more than four corners until all tiles are quads.
#pragma once

#include <tessera/topology/cut_graph.h>
#include <tessera/topology/m_tiling.h>
#include <tessera/topology/internal/huge_page_allocator.h>

#include <boost/heap/d_ary_heap.hpp>
#include <boost/sort/spreadsort/integer_sort.hpp>

#include <CGAL/Subdivision_method_3/subdivision_hosts_3.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <functional>
#include <iterator>
#include <limits>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

namespace tessera {

/// The corners of a disk tile in boundary order. A corner is named by the tile-border halfedge that
/// arrives at its vertex in its wedge, so corners sharing a vertex (the schema's basepoint) differ.
/// Corner i is where `tile.sides[i]` starts. Empty when the boundary has no corner.
template <typename TriangleMesh>
std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>
tile_corners(const M_tiling<TriangleMesh>& tiling, const M_tile<TriangleMesh>& tile) {
  std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor> out;
  const auto& sides = tile.sides;
  if (sides.empty() || !tiling.is_multipoint(source(sides.front().halfedges.front(), tiling.mesh())))
    return out;
  for (std::size_t i = 0; i < sides.size(); ++i)
    out.push_back(sides[(i + sides.size() - 1) % sides.size()].halfedges.back());
  return out;
}

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
template <typename TriangleMesh>
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
    halfedge_descriptor last;             // the path's last halfedge, arriving at the target
  };

  /// Accepts every (source, target) pair.
  struct Accept_all {
    bool operator()(std::size_t, std::size_t) const { return true; }
  };

  /// `labels` (at most 3) nearest sources are kept at every vertex; `cost(e)` is the non-negative
  /// cost of edge e (read once per edge and vertex until `refresh` says it changed).
  Cutting_path_search(const M_tiling<TriangleMesh>& tiling, std::size_t labels, Cost cost)
      : tiling_(tiling), tm_(tiling.mesh()), idx_(tiling.indices()), cost_(std::move(cost)),
        k_(std::min<std::size_t>(labels, 3)) {
    rebuild();
  }

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
    for (vertex_descriptor v : added) {
      slots_[at(v)].ring = 0;
      for (halfedge_descriptor h : CGAL::halfedges_around_target(v, tm_)) slots_[at(source(h, tm_))].ring = 0;
    }
  }

  /// Runs from `sources` (corners). With `targets` (corners), the run stops as soon as every label
  /// still to settle is at least as far as the best arrival at some target t from a source s with
  /// `accept(s, t)` (indices into the two vectors); `best_arrival` is exact for these pairs, and
  /// only for them. When every edge costs at least `lower_bound` times its Euclidean length (1 for
  /// Euclidean costs), the search is an A* guided by that multiple of the straight-line distance to
  /// the nearest target, a consistent estimate, so labels still settle nearest first at every vertex
  /// and the answer is the same.
  template <typename Accept = Accept_all>
  void run(const std::vector<halfedge_descriptor>& sources, const std::vector<halfedge_descriptor>& targets = {},
           Accept accept = {}, double lower_bound = 0) {
    for (std::uint32_t v : touched_) slots_[v].clear();
    touched_.clear();
    // Vertices on the cut are blocked in the same slots, so that a neighbour costs one lookup. The
    // cut only grows between runs (Alg. 5), so only its new edges are read; should it have changed
    // otherwise, all of it is read again.
    const auto& cut = tiling_.cut_edges();
    if (blocked_edges_ > cut.size() || (blocked_edges_ > 0 && cut[blocked_edges_ - 1] != last_blocked_)) {
      for (Slot& sx : slots_) sx.on_cut = false;
      blocked_edges_ = 0;
    }
    for (; blocked_edges_ < cut.size(); ++blocked_edges_) {
      const halfedge_descriptor h = halfedge(cut[blocked_edges_], tm_);
      slots_[at(source(h, tm_))].on_cut = slots_[at(target(h, tm_))].on_cut = true;
    }
    if (!cut.empty()) last_blocked_ = cut.back();
    source_of_corner_.clear();
    for (std::size_t s = 0; s < sources.size(); ++s) source_of_corner_[idx_.h(sources[s])] = s;
    // The targets' wedge neighbours off the cut, and a first bound from single-edge paths.
    double bound = std::numeric_limits<double>::infinity();
    arrivals_.clear();
    for (std::size_t t = 0; t < targets.size(); ++t)
      tiling_.for_each_in_wedge(targets[t], [&](halfedge_descriptor g) {
        const vertex_descriptor u = source(g, tm_);
        const double w = cost_(edge(g, tm_));
        if (!tiling_.is_on_cut(u)) {
          Slot& su = slots_[at(u)];
          if (su.count == 0 && su.queued == 0 && su.first_arrival == none) touched_.push_back(std::uint32_t(at(u)));
          arrivals_.push_back({std::uint32_t(t), su.first_arrival, w});
          su.first_arrival = std::uint32_t(arrivals_.size() - 1);
          return;
        }
        const auto it = source_of_corner_.find(idx_.h(tiling_.wedge_border(opposite(g, tm_))));
        if (it != source_of_corner_.end() && accept(it->second, t)) bound = std::min(bound, w);
      });
    // The estimate: lower_bound (less a rounding margin) times the distance to the nearest target.
    std::vector<std::array<double, 3>> goals;
    for (halfedge_descriptor t : targets) goals.push_back(pos_[at(target(t, tm_))]);
    std::sort(goals.begin(), goals.end());
    goals.erase(std::unique(goals.begin(), goals.end()), goals.end());
    const double scale = goals.empty() ? 0.0 : std::max(0.0, lower_bound) * (1.0 - 1e-9);
    const auto estimate = [&](std::size_t v) {
      if (scale == 0) return 0.0;
      const auto& p = pos_[v];
      double best = std::numeric_limits<double>::infinity();
      for (const auto& g : goals)
        best = std::min(best, (p[0] - g[0]) * (p[0] - g[0]) + (p[1] - g[1]) * (p[1] - g[1]) + (p[2] - g[2]) * (p[2] - g[2]));
      return scale * std::sqrt(best);
    };
    queue_.clear();
    // Queues source `label` at distance d at vertex v, unless v has it already, or k other sources
    // are known to be at most as far (then `label` is not among v's k nearest through this way).
    const auto push = [&](double d, std::size_t v, std::size_t parent, std::size_t label) {
      Slot& sv = slots_[v];
      if (sv.on_cut || sv.count >= k_ || sv.has(label)) return;
      std::size_t nearer = 0, farthest = 0, same = none;
      for (std::size_t j = 0; j < sv.queued; ++j) {
        if (sv.queued_label[j] == label) same = j;
        else if (sv.queued_dist[j] <= d) ++nearer;
        if (sv.queued_dist[j] > sv.queued_dist[farthest]) farthest = j;
      }
      if (same != none) {
        if (sv.queued_dist[same] <= d) return;
        sv.queued_dist[same] = d;
      } else {
        if (nearer >= k_) return;
        if (sv.queued == 0 && sv.count == 0) {
          if (sv.first_arrival == none) touched_.push_back(std::uint32_t(v));
          sv.estimate = estimate(v);
        }
        const std::size_t j = sv.queued < 3 ? sv.queued++ : farthest; // the farthest is beyond d
        sv.queued_label[j] = std::uint32_t(label);
        sv.queued_dist[j] = d;
      }
      queue_.push({d + sv.estimate, d, std::uint32_t(v), std::uint32_t(parent), std::uint32_t(label)});
    };
    for (std::size_t s = 0; s < sources.size(); ++s)
      tiling_.for_each_in_wedge(sources[s], [&](halfedge_descriptor g) {
        const vertex_descriptor x = source(g, tm_);
        if (!tiling_.is_on_cut(x)) push(cost_(edge(g, tm_)), at(x), at(target(g, tm_)), s);
      });
    while (!queue_.empty()) {
      const Entry top = queue_.top();
      queue_.pop();
      if (top.f >= bound) break;
      // The next entry to settle is known now: ask for its slot and ring while this one is
      // processed (about a quarter of the search's time is saved on large meshes), and for those
      // of the root's children, among which is the one after (the heap's iterators run over its
      // array in storage order; another order would only make this hint useless).
      if (!queue_.empty()) prefetch_vertex(queue_.top().v);
      if (queue_.size() > 4) {
        auto child = std::next(queue_.begin());
        for (int c = 0; c < 4; ++c, ++child) prefetch_vertex(child->v);
      }
      const std::size_t v = top.v;
      Slot& sv = slots_[v];
      const std::size_t n = sv.count;
      if (n >= k_ || sv.has(top.label)) continue; // (queued vertices are off the cut)
      sv.label[n] = top.label;
      dist_[v * k_ + n] = top.d;
      parent_[v * k_ + n] = top.parent;
      ++sv.count;
      for (std::uint32_t a = sv.first_arrival; a != none; a = arrivals_[a].next)
        if (accept(top.label, arrivals_[a].target)) bound = std::min(bound, top.d + arrivals_[a].cost);
      if (sv.ring == 0) cache_ring(v);
      if (sv.ring != overflow) {
        const Ring& r = ring(v);
        for (std::size_t j = 0; j < sv.ring; ++j) push(top.d + r.cost[j], r.neighbour[j], v, top.label);
      } else {
        const auto [begin, end] = overflow_[v];
        for (std::size_t j = begin; j < end; ++j) push(top.d + overflow_cost_[j], overflow_vertex_[j], v, top.label);
      }
      // The next entry's neighbours' slots, which its relaxations will read.
      if (!queue_.empty()) prefetch_neighbours(queue_.top().v);
    }
  }

  /// The shortest path found by the last `run` that arrives at corner `target` from a source s with
  /// `accept(s)`: through a vertex off the cut, or along one uncut edge from a source corner.
  Candidate best_arrival(halfedge_descriptor target, const std::function<bool(std::size_t)>& accept) const {
    Candidate best;
    tiling_.for_each_in_wedge(target, [&](halfedge_descriptor g) {
      const vertex_descriptor u = source(g, tm_);
      const double w = cost_(edge(g, tm_));
      if (!tiling_.is_on_cut(u)) {
        const std::size_t ui = at(u);
        for (std::size_t k = 0; k < slots_[ui].count; ++k)
          if (accept(slots_[ui].label[k])) {
            if (dist_[ui * k_ + k] + w < best.length) best = {dist_[ui * k_ + k] + w, slots_[ui].label[k], g};
            break; // slots are in increasing distance
          }
        return;
      }
      const auto it = source_of_corner_.find(idx_.h(tiling_.wedge_border(opposite(g, tm_))));
      if (it != source_of_corner_.end() && accept(it->second) && w < best.length) best = {w, it->second, g};
    });
    return best;
  }

  /// The halfedges of `c`'s path, from its source corner to its target.
  Path path(const Candidate& c) const {
    Path p{c.last};
    vertex_descriptor v = source(c.last, tm_);
    while (!tiling_.is_on_cut(v)) {
      const std::size_t vi = at(v);
      std::size_t k = 0;
      while (slots_[vi].label[k] != c.source) ++k;
      const std::size_t parent = parent_[vi * k_ + k];
      for (halfedge_descriptor h : CGAL::halfedges_around_target(v, tm_))
        if (at(source(h, tm_)) == parent) {
          p.push_back(h);
          break;
        }
      v = source(p.back(), tm_);
    }
    std::reverse(p.begin(), p.end());
    return p;
  }

private:
  static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  // What a run knows of a vertex: the sources of its settled labels; up to three queued arrivals
  // (distinct sources, upper bounds of their distances), which let a relaxation be dropped when it
  // cannot make a label; the A* estimate, set when first queued; the target arrivals through it.
  struct alignas(64) Slot {
    std::uint8_t count = 0; // labels settled
    std::uint8_t queued = 0;
    std::uint8_t ring = 0;  // kept across runs: the cached ring's size, `overflow`, or 0 (not cached)
    bool on_cut = false;    // kept across runs
    std::uint32_t first_arrival = none; // into `arrivals_`
    std::uint32_t label[3] = {0, 0, 0};
    std::uint32_t queued_label[3] = {0, 0, 0};
    double queued_dist[3] = {0, 0, 0};
    double estimate = 0;
    bool has(std::size_t l) const {
      for (std::size_t k = 0; k < count && k < 3; ++k)
        if (label[k] == l) return true;
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
    void operator()(Ring* p) const { Huge_page_allocator<Ring>().deallocate(p, std::size_t(1) << block_bits); }
  };
  Ring& ring(std::size_t v) const { return blocks_[v >> block_bits].get()[v & ((std::size_t(1) << block_bits) - 1)]; }
  void cache_ring(std::size_t v) {
    const std::size_t begin = overflow_vertex_.size();
    for (halfedge_descriptor h : CGAL::halfedges_around_target(verts_[v], tm_)) {
      overflow_vertex_.push_back(std::uint32_t(at(source(h, tm_))));
      overflow_cost_.push_back(cost_(edge(h, tm_)));
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
      if (n == pending) return;
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
      ends.push_back({std::uint32_t(at(source(h, tm_))), std::uint32_t(at(target(h, tm_))), cost_(e)});
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
      if (sx.ring == pending) sx.ring = 0;
      else if (sx.ring == 0) sx.ring = overflow; // no neighbour: an empty ring reads nothing
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
    if (n == 0 || n == overflow) return;
    const Ring& r = ring(v);
    for (std::size_t j = 0; j < n; ++j) prefetch(&slots_[r.neighbour[j]]);
  }

  // The internal index of a vertex.
  std::size_t at(vertex_descriptor v) const { return order_[idx_.v(v)]; }

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
    for (vertex_descriptor v : vertices(tm_)) points.emplace_back(v, internal::to_double_array(get(vpm_, v)));
    std::array<double, 3> lo{{0, 0, 0}}, hi{{0, 0, 0}};
    if (!points.empty()) lo = hi = points.front().second;
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
        keyed.begin(), keyed.end(), [](const auto& k, unsigned offset) { return k.first >> offset; },
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
  typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type vpm_ = get(CGAL::vertex_point, tm_);
  Cost cost_;
  std::size_t k_;
  std::size_t renumberings_ = 0;
  std::size_t blocked_edges_ = 0; // cut edges whose vertices are marked `on_cut` in the slots
  edge_descriptor last_blocked_;
  // The arrays indexed by vertex are tens of megabytes on large meshes and read at random: they
  // ask for huge pages.
  template <typename T>
  using Vertex_array = std::vector<T, Huge_page_allocator<T>>;
  Vertex_array<std::uint32_t> order_;          // internal index by mesh index
  Vertex_array<vertex_descriptor> verts_;      // by internal index, as is everything below
  Vertex_array<std::array<double, 3>> pos_;
  std::vector<std::unique_ptr<Ring, Block_deleter>> blocks_;
  Vertex_array<std::pair<std::uint32_t, std::uint32_t>> overflow_;
  Vertex_array<Slot> slots_;
  Vertex_array<double> dist_;                  // k per vertex, as the slot's labels
  Vertex_array<std::uint32_t> parent_;         // k per vertex: the previous vertex
  std::vector<std::uint32_t> overflow_vertex_;
  std::vector<double> overflow_cost_;
  std::vector<std::uint32_t> touched_;        // vertices whose slot is in use
  std::vector<Arrival> arrivals_;
  boost::heap::d_ary_heap<Entry, boost::heap::arity<4>, boost::heap::allocator<Huge_page_allocator<Entry>>> queue_;
  std::unordered_map<std::size_t, std::size_t> source_of_corner_;
};

/// Geometry mask for CGAL's primal triangle quadrisection that puts new vertices at edge midpoints
/// and keeps old ones: the refined mesh is the same surface (exactly so with exact constructions).
template <typename TriangleMesh, typename VertexPointMap>
struct Midpoint_mask_3 {
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  TriangleMesh* tm;
  VertexPointMap vpm;
  void edge_node(typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h, Point& p) {
    p = CGAL::midpoint(get(vpm, source(h, *tm)), get(vpm, target(h, *tm)));
  }
  void vertex_node(typename boost::graph_traits<TriangleMesh>::vertex_descriptor v, Point& p) {
    p = get(vpm, v);
  }
  void border_node(typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h, Point& ep, Point& vp) {
    edge_node(h, ep);
    vp = get(vpm, target(h, *tm));
  }
};

/// Splits every triangle of `tm` into four at its edge midpoints (property maps of `tm` that grow
/// with the mesh, as Surface_mesh's do, stay valid).
template <typename TriangleMesh>
void subdivide_at_midpoints(TriangleMesh& tm) {
  const auto vpm = get(CGAL::vertex_point, tm);
  CGAL::Subdivision_method_3::PTQ(tm, Midpoint_mask_3<TriangleMesh, decltype(vpm)>{&tm, vpm},
                                  CGAL::parameters::number_of_iterations(1));
}

} // namespace internal

/// Alg. 4's cutting path: the shortest path inside the tile from corner `a` to corner `b` (corners as
/// returned by `tile_corners`; they may share a vertex). Empty when every route would touch the cut.
template <typename TriangleMesh, typename EdgeCostMap>
std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>
shortest_cutting_path(const M_tiling<TriangleMesh>& tiling,
                      typename boost::graph_traits<TriangleMesh>::halfedge_descriptor a,
                      typename boost::graph_traits<TriangleMesh>::halfedge_descriptor b, EdgeCostMap cost) {
  internal::Cutting_path_search<TriangleMesh> search(tiling, 1, [&](auto e) { return double(get(cost, e)); });
  search.run({a});
  const auto best = search.best_arrival(b, [](std::size_t) { return true; });
  if (best.source == std::size_t(-1)) return {};
  return search.path(best);
}

/// Alg. 4: cuts the tile of corners `a` and `b` along `shortest_cutting_path`; `empty_path` when
/// there is none. The corners' vertices are marked as multipoints first, so that they stay corners
/// whatever their cut degree becomes.
template <typename TriangleMesh, typename EdgeCostMap>
Cut_path_status cut_tile_between_corners(M_tiling<TriangleMesh>& tiling,
                                         typename boost::graph_traits<TriangleMesh>::halfedge_descriptor a,
                                         typename boost::graph_traits<TriangleMesh>::halfedge_descriptor b,
                                         EdgeCostMap cost) {
  const auto path = shortest_cutting_path(tiling, a, b, cost);
  tiling.mark_multipoint(target(a, tiling.mesh()));
  tiling.mark_multipoint(target(b, tiling.mesh()));
  return path.empty() ? Cut_path_status::empty_path : tiling.cut(path);
}

enum class Quadrangulation_status {
  ok,
  invalid_mesh,       ///< not a valid triangle mesh
  invalid_basepoint,  ///< the basepoint index is out of range or on a border
  cut_failed,         ///< the source cut graph could not be built
  no_cutting_path     ///< some tile had no valid cutting path even after `max_refinements`
};

struct Quadrangulation_options {
  /// The source cut graph (`cut.method`), the edge costs of all paths, and the basepoint.
  Cut_options cut;
  /// Midpoint subdivisions of the whole mesh allowed when a tile has no valid cutting path even after
  /// its local refinement (see `quadrangulate`).
  std::size_t max_refinements = 3;
};

/// One quad: four corners and four sides in boundary order, the tile on the sides' left.
template <typename TriangleMesh>
struct Quad_tile {
  using GT = boost::graph_traits<TriangleMesh>;
  /// `sides[i]` runs from `corners[i]` to `corners[(i + 1) % 4]`.
  std::vector<std::vector<typename GT::halfedge_descriptor>> sides;
  std::vector<typename GT::vertex_descriptor> corners;
};

template <typename TriangleMesh>
struct Quadrangulation_result {
  using GT = boost::graph_traits<TriangleMesh>;
  Quadrangulation_status status = Quadrangulation_status::ok;
  std::string message;
  /// The source cut graph as computed before any refinement (after one, its sides' halfedge paths
  /// describe the mesh as it was; its counts and method stay meaningful).
  Cut_result<TriangleMesh> cut;
  /// The quads; tile i is the one with id i in the face tile map.
  std::vector<Quad_tile<TriangleMesh>> tiles;
  /// Per source polygon (connected component), its number of corners after evening (see
  /// `quadrangulate`); it gives corners / 2 - 1 quads.
  std::vector<std::size_t> polygon_corners;
  /// Multipoints marked to make every polygon's corner count even and at least 4.
  std::size_t added_corners = 0;
  /// Cutting paths added by Alg. 5.
  std::size_t cutting_paths = 0;
  /// Midpoint subdivisions of the whole mesh that were needed (see `quadrangulate`).
  std::size_t refinements = 0;
  /// Tiles refined locally before their search: narrow wedges opened, chords across strips split
  /// (see `quadrangulate`).
  std::size_t local_refinements = 0;
  /// All seams (source cut and cutting paths, each edge once): summed cost and Euclidean length.
  double cut_cost = 0;
  double cut_length = 0;
  /// Vertices where tile borders meet or end, plus the marked corners: the images of all corners.
  std::vector<typename GT::vertex_descriptor> multipoints;
  std::size_t number_of_quads() const { return tiles.size(); }
  explicit operator bool() const { return status == Quadrangulation_status::ok; }
};

namespace internal {

/// Marks corners until every tile has an even number of them, and at least 4: a polygon side along
/// the mesh's border appears once in the boundary, so an odd count is evened by splitting the longest
/// border side; counts below 4 (a sphere's slit, a disk without cut) by splitting the longest side.
/// A side is split at its inner vertex nearest to half its length; splitting a seam side splits its
/// partner too (+2 corners, pairing kept), a border side only itself (+1). Returns the number of marks,
/// or -1 when a side to split has no inner vertex.
template <typename TriangleMesh, typename EdgeCostMap>
long even_corner_counts(M_tiling<TriangleMesh>& tiling, EdgeCostMap cost) {
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  const TriangleMesh& tm = tiling.mesh();
  long marks = 0;
  for (bool changed = true; changed;) {
    changed = false;
    for (const auto& tile : tiling.tiles(false)) {
      if (tile.sides.empty()) continue;
      const std::size_t m = tile_corners(tiling, tile).size();
      if (m % 2 == 0 && m >= 4) continue;
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
        if (side.halfedges.size() < 2 || (m % 2 == 1 && !border)) continue;
        double length = 0;
        for (halfedge_descriptor h : side.halfedges) length += double(get(cost, edge(h, tm)));
        if (length > longest) {
          longest = length;
          chosen = &side.halfedges;
        }
      }
      if (chosen == nullptr) return -1;
      double along = 0, best = std::numeric_limits<double>::infinity();
      typename boost::graph_traits<TriangleMesh>::vertex_descriptor split = target(chosen->front(), tm);
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
template <typename TriangleMesh>
typename boost::graph_traits<TriangleMesh>::vertex_descriptor
split_edge_at_midpoint(TriangleMesh& tm, typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h) {
  const auto vpm = get(CGAL::vertex_point, tm);
  const auto p = CGAL::midpoint(get(vpm, source(h, tm)), get(vpm, target(h, tm)));
  const auto hnew = CGAL::Euler::split_edge(h, tm); // hnew arrives at the new vertex, then h
  put(vpm, target(hnew, tm), p);
  for (auto g : {hnew, opposite(h, tm)})
    if (!is_border(g, tm)) CGAL::Euler::split_face(g, next(next(g, tm), tm), tm);
  return target(hnew, tm);
}

/// Splits the edges `chords` (vertex pairs, smaller first; repeats allowed) at their midpoints, each
/// once, appending the new vertices to `added`; returns the number of edges split.
template <typename TriangleMesh>
std::size_t split_chords(
    TriangleMesh& tm,
    std::vector<std::pair<typename boost::graph_traits<TriangleMesh>::vertex_descriptor,
                          typename boost::graph_traits<TriangleMesh>::vertex_descriptor>>& chords,
    std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& added) {
  std::sort(chords.begin(), chords.end());
  chords.erase(std::unique(chords.begin(), chords.end()), chords.end());
  for (const auto& [a, c] : chords) added.push_back(split_edge_at_midpoint(tm, halfedge(a, c, tm).first));
  return chords.size();
}

/// Splits the *chords* of a disk tile (uncut edges whose two ends lie on the cut; `corners` as
/// returned by `tile_corners`) at their midpoints and joins each midpoint to the opposite corners of
/// its faces. A strip of faces between two sides that run side by side (a cutting path beside an
/// earlier one, or two parallel schema strands) has only chords across it and so no vertex inside;
/// afterwards the chord midpoints form a path through it. The midpoints are not on the cut, so no
/// new chord appears. Appends the new vertices to `added`; returns the number of chords split.
template <typename TriangleMesh>
std::size_t split_tile_chords(TriangleMesh& tm, const M_tiling<TriangleMesh>& tiling,
                              const std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>& corners,
                              std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& added) {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  if (corners.empty()) return 0;
  // Every chord of the tile leaves one of its boundary vertices inside a wedge of the tile.
  std::vector<std::pair<vertex_descriptor, vertex_descriptor>> chords;
  const halfedge_descriptor start = corners.front();
  halfedge_descriptor h = start;
  do {
    tiling.for_each_in_wedge(h, [&](halfedge_descriptor g) {
      if (tiling.is_on_cut(source(g, tm)))
        chords.emplace_back(std::min(source(g, tm), target(g, tm)), std::max(source(g, tm), target(g, tm)));
    });
    h = tiling.next_on_tile_border(h);
  } while (h != start);
  return split_chords(tm, chords, added);
}

/// Splits the chords at `vertices` (vertices just added to the cut, such as a cutting path's inner
/// vertices) as `split_tile_chords` does. A chord can only appear when a vertex joins the cut, so
/// splitting these after every cut keeps every tile chord-free without walking tile boundaries.
template <typename TriangleMesh>
std::size_t split_chords_at(TriangleMesh& tm, const M_tiling<TriangleMesh>& tiling,
                            const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& vertices,
                            std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& added) {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  std::vector<std::pair<vertex_descriptor, vertex_descriptor>> chords;
  for (vertex_descriptor v : vertices)
    for (auto h : CGAL::halfedges_around_target(v, tm))
      if (!tiling.is_cut(edge(h, tm)) && tiling.is_on_cut(source(h, tm)))
        chords.emplace_back(std::min(source(h, tm), v), std::max(source(h, tm), v));
  return split_chords(tm, chords, added);
}

/// Refinement for corners with a narrow wedge. A corner whose wedge is a single face has no uncut
/// edge into its tile, so no cutting path can start or end there (and midpoint subdivision keeps it
/// so); one whose wedge has a single inner edge becomes two such corners once a path uses that edge.
/// For each of these corners, the edges of the wedge's faces opposite the corner are split at their
/// midpoints when uncut (the midpoints are new neighbours inside the tile); when none is, the centroid
/// of the corner's face is inserted. Appends the new vertices to `added`; returns false when no
/// corner needed it.
template <typename TriangleMesh>
bool open_narrow_wedges(TriangleMesh& tm, const M_tiling<TriangleMesh>& tiling,
                        const std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>& corners,
                        std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& added) {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  std::vector<std::pair<vertex_descriptor, vertex_descriptor>> to_split;
  std::vector<std::array<vertex_descriptor, 3>> to_star;
  for (halfedge_descriptor b : corners) {
    std::vector<halfedge_descriptor> wedge{b}; // halfedges arriving at the corner, one per face
    tiling.for_each_in_wedge(b, [&](halfedge_descriptor g) { wedge.push_back(g); });
    if (wedge.size() > 2) continue;
    const std::size_t before = to_split.size();
    for (halfedge_descriptor g : wedge)
      if (!tiling.is_cut(edge(prev(g, tm), tm))) to_split.emplace_back(source(prev(g, tm), tm), target(prev(g, tm), tm));
    if (to_split.size() == before) to_star.push_back({{source(b, tm), target(b, tm), target(next(b, tm), tm)}});
  }
  std::sort(to_split.begin(), to_split.end());
  to_split.erase(std::unique(to_split.begin(), to_split.end()), to_split.end());
  bool changed = false;
  for (const auto& [a, b] : to_split) {
    const auto h = halfedge(a, b, tm);
    if (!h.second) continue;
    added.push_back(split_edge_at_midpoint(tm, h.first));
    changed = true;
  }
  const auto vpm = get(CGAL::vertex_point, tm);
  for (const auto& t : to_star) {
    const auto h = halfedge(t[0], t[1], tm);
    if (!h.second || is_border(h.first, tm) || target(next(h.first, tm), tm) != t[2]) continue;
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
/// from corner p to corner q of an m-gon leaves the (q - p + 1)-gon p..q and the (m - q + p + 1)-gon
/// q..p, both even, so only the first step walks the whole mesh. Before its search, a tile is
/// refined locally where paths could not pass (narrow wedges opened; chords split, for the source
/// cut's tiles by walking their boundary, later at each cutting path right after its cut; `tm`
/// changes, the tiling follows): a disk tile without chords whose corners all have an inner edge
/// always has a valid cutting path. Returns false when a tile still has none; `stuck` then holds the corners of
/// all tiles still to cut.
template <typename TriangleMesh, typename EdgeCostMap>
bool cut_into_quads(TriangleMesh& tm, M_tiling<TriangleMesh>& tiling, EdgeCostMap cost,
                    const Quadrangulation_options& options, Quadrangulation_result<TriangleMesh>& result,
                    std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>& stuck) {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  using Search = Cutting_path_search<TriangleMesh>;
  // Each vertex keeps its 3 nearest even corners: at most two of them (the target's neighbours)
  // violate the Q-criterion for a given odd target, so the best valid source is always among them.
  Search search(tiling, 3, [&](auto e) { return double(get(cost, e)); });
  // The tiles of the source cut are walked once for chords; later tiles are kept chord-free by
  // splitting the chords at each cutting path right after its cut.
  std::vector<std::vector<halfedge_descriptor>> work;
  for (const auto& tile : tiling.tiles(false)) {
    std::vector<halfedge_descriptor> corners = tile_corners(tiling, tile);
    if (corners.size() > 4) work.push_back(std::move(corners));
  }
  std::size_t walked = work.size(); // work[0, walked) are tiles of the source cut still to walk
  std::vector<vertex_descriptor> added;
  // Each step reads the tiling, so it takes in the previous step's new elements first.
  const auto absorb = [&] {
    tiling.absorb_refinement();
    for (vertex_descriptor v : added)
      for (halfedge_descriptor h : CGAL::halfedges_around_target(v, tm))
        put(cost, edge(h, tm), edge_cost(edge(h, tm), tm, options.cut.cost));
    search.refresh(added);
    added.clear();
  };
  while (!work.empty()) {
    std::vector<halfedge_descriptor> corners = std::move(work.back());
    const bool source_tile = work.size() <= walked;
    work.pop_back();
    walked = std::min(walked, work.size());
    added.clear();
    const bool opened = open_narrow_wedges(tm, tiling, corners, added);
    if (opened) absorb();
    const bool split = source_tile && split_tile_chords(tm, tiling, corners, added) > 0;
    if (split) absorb();
    if (opened || split) ++result.local_refinements;
    const std::size_t m = corners.size();
    std::vector<halfedge_descriptor> even, odd;
    for (std::size_t i = 0; i < m; ++i) (i % 2 == 0 ? even : odd).push_back(corners[i]);
    // Source s is corner 2s, target t corner 2t + 1.
    const auto valid = [m](std::size_t s, std::size_t t) {
      const std::size_t d = (2 * t + 1 + m - 2 * s) % m;
      return d >= 3 && d <= m - 3;
    };
    search.run(even, odd, valid, edge_cost_lower_bound(options.cut.cost));
    typename Search::Candidate best;
    std::size_t best_target = 0;
    for (std::size_t t = 0; t < odd.size(); ++t) {
      const auto candidate = search.best_arrival(odd[t], [&](std::size_t s) { return valid(s, t); });
      if (candidate.length < best.length) {
        best = candidate;
        best_target = t;
      }
    }
    std::vector<halfedge_descriptor> path;
    if (best.source != std::size_t(-1)) path = search.path(best);
    if (!path.empty() && tiling.cut(path) == Cut_path_status::ok) {
      ++result.cutting_paths;
      std::vector<vertex_descriptor> inner;
      for (std::size_t i = 0; i + 1 < path.size(); ++i) inner.push_back(target(path[i], tm));
      if (split_chords_at(tm, tiling, inner, added) > 0) absorb();
      const std::size_t p = 2 * best.source, q = 2 * best_target + 1;
      // Corner halfedges arrive in their wedges: the path's ends start the two new corner lists.
      std::vector<halfedge_descriptor> left{path.back()}, right{opposite(path.front(), tm)};
      for (std::size_t i = (q + 1) % m;; i = (i + 1) % m) {
        left.push_back(corners[i]);
        if (i == p) break;
      }
      for (std::size_t i = (p + 1) % m;; i = (i + 1) % m) {
        right.push_back(corners[i]);
        if (i == q) break;
      }
      if (left.size() > 4) work.push_back(std::move(left));
      if (right.size() > 4) work.push_back(std::move(right));
      continue;
    }
    work.push_back(std::move(corners));
    for (const auto& w : work) stuck.insert(stuck.end(), w.begin(), w.end());
    return false;
  }
  return true;
}

} // namespace internal

/// Alg. 5: opens `tm` along a cut graph (`options.cut`), makes every polygon's corner count even and
/// at least 4 (see below), then cuts tiles along shortest Q-criterion cutting paths until every tile
/// is a quad: an m-gon gives m/2 - 1 quads, the schema's 4g-gon 2g - 1. Paths run strictly inside
/// their tile, so every tile is a disk whose boundary touches other tiles and the mesh border only
/// along sides and at its 4 corners.
///
/// Refinement, local first: before a tile is searched, its corners whose wedge has at most one
/// inner edge get more (the wedge faces' edges opposite the corner are split at their midpoints, or
/// a centroid inserted), and its chords (uncut edges with both ends on the cut, the only edges across
/// a one-triangle-wide strip between two sides) are split at their midpoints (`local_refinements`
/// counts the tiles this changed; chords only appear where a cutting path joins the cut, so after
/// the first search they are split along each new path, for both tiles it leaves). The tiling
/// follows these edits, so no work is repeated. Only if
/// a tile still has no valid cutting path is every triangle split 1-to-4 at its edge midpoints,
/// keeping all cuts made so far (split seam edges stay seams; `refinements`, at most
/// `options.max_refinements`, then the status is `no_cutting_path`). New vertices lie on the input
/// surface (exactly, with an exact-constructions kernel); `tm` is modified.
///
/// Corners on bordered surfaces: a side along the mesh border appears once in a polygon, so the
/// corner count may be odd; the longest border side is then split at its middle vertex (a new
/// corner). Counts below 4 (a closed sphere's slit has 2, a disk without cut 0) are raised by
/// splitting the longest side, a seam side adding a corner on both of its copies.
///
/// Outputs: tile ids in `tile_of_face` (writable face property map of std::size_t), the seams (all
/// tile borders) in `seam_edges`/`seam_vertices`, ready for `CGAL::Seam_mesh`.
template <typename TriangleMesh, typename FaceTileMap, typename SeamEdgeMap, typename SeamVertexMap>
Quadrangulation_result<TriangleMesh> quadrangulate(TriangleMesh& tm, FaceTileMap tile_of_face,
                                                   SeamEdgeMap seam_edges, SeamVertexMap seam_vertices,
                                                   const Quadrangulation_options& options = {}) {
  using GT = boost::graph_traits<TriangleMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  Quadrangulation_result<TriangleMesh> result;
  result.cut = cut_to_disk(tm, seam_edges, seam_vertices, options.cut);
  if (!result.cut) {
    result.status = result.cut.status == Cut_status::invalid_mesh        ? Quadrangulation_status::invalid_mesh
                    : result.cut.status == Cut_status::invalid_basepoint ? Quadrangulation_status::invalid_basepoint
                                                                         : Quadrangulation_status::cut_failed;
    result.message = result.cut.message;
    return result;
  }
  // The state that survives refinements: seams as vertex pairs (a split seam edge becomes the two
  // halves through its midpoint) and the corners, all marked so that they stay corners.
  std::vector<std::pair<vertex_descriptor, vertex_descriptor>> seams;
  for (auto e : edges(tm))
    if (get(seam_edges, e)) seams.emplace_back(source(halfedge(e, tm), tm), target(halfedge(e, tm), tm));
  std::vector<vertex_descriptor> marks = result.cut.multipoints;
  for (const auto& polygon : result.cut.polygons) marks.insert(marks.end(), polygon.corners.begin(), polygon.corners.end());
  bool evened = false;

  for (;;) {
    auto cost = get(CGAL::dynamic_edge_property_t<double>(), tm);
    compute_edge_costs(tm, cost, options.cut.cost);
    M_tiling<TriangleMesh> tiling(tm);
    for (const auto& [a, b] : seams) {
      const auto h = halfedge(a, b, tm);
      if (h.second) {
        tiling.cut({h.first});
        continue;
      }
      for (halfedge_descriptor g : CGAL::halfedges_around_target(a, tm)) { // a was split at the midpoint m
        const vertex_descriptor m = source(g, tm);
        const auto to_b = halfedge(m, b, tm);
        if (!to_b.second) continue;
        tiling.cut({opposite(g, tm)});
        tiling.cut({to_b.first});
        break;
      }
    }
    for (vertex_descriptor v : marks) tiling.mark_multipoint(v);

    std::vector<halfedge_descriptor> stuck;
    bool done = false;
    if (!evened) {
      const long added = internal::even_corner_counts(tiling, cost);
      if (added >= 0) {
        evened = true;
        result.added_corners = std::size_t(added);
        for (const auto& tile : tiling.tiles(false)) result.polygon_corners.push_back(tile_corners(tiling, tile).size());
      }
    }
    if (evened) done = internal::cut_into_quads(tm, tiling, cost, options, result, stuck);

    if (done) {
      for (const auto& tile : tiling.tiles(false)) {
        Quad_tile<TriangleMesh> quad;
        for (const auto& side : tile.sides) {
          quad.sides.push_back(side.halfedges);
          quad.corners.push_back(source(side.halfedges.front(), tm));
        }
        result.tiles.push_back(std::move(quad));
      }
      for (auto f : faces(tm)) put(tile_of_face, f, tiling.tile_of(f));
      for (auto v : vertices(tm))
        if (tiling.is_multipoint(v)) result.multipoints.push_back(v);
      tiling.export_seams(seam_edges, seam_vertices);
      const auto vpm = get(CGAL::vertex_point, tm);
      for (auto e : tiling.seam_edges()) {
        const halfedge_descriptor h = halfedge(e, tm);
        result.cut_cost += get(cost, e);
        result.cut_length += std::sqrt(CGAL::to_double(
            CGAL::squared_distance(get(vpm, source(h, tm)), get(vpm, target(h, tm)))));
      }
      return result;
    }
    seams.clear();
    for (auto e : tiling.seam_edges()) seams.emplace_back(source(halfedge(e, tm), tm), target(halfedge(e, tm), tm));
    marks.clear();
    for (vertex_descriptor v : vertices(tm))
      if (tiling.is_multipoint(v)) marks.push_back(v);
    if (result.refinements == options.max_refinements) {
      result.status = Quadrangulation_status::no_cutting_path;
      result.message = "a tile has no cutting path inside it after " + std::to_string(result.refinements) +
                       " subdivisions";
      return result;
    }
    internal::subdivide_at_midpoints(tm);
    ++result.refinements;
  }
}

} // namespace tessera
