// Shared machinery of the topology module: dense element indices of a FaceGraph and a multi-source
// shortest-path tree over its edges (boost::dijkstra_shortest_paths on the mesh's BGL interface),
// with a cost function that may forbid an edge in one direction (infinite cost) to keep paths
// inside a tile.
#pragma once

#include <boost/graph/detail/d_ary_heap.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <boost/property_map/function_property_map.hpp>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <vector>

namespace tessera::internal {

/// Dense indices 0..n-1 of the vertices, halfedges, edges and faces of a FaceGraph.
template <typename FaceGraph> struct Mesh_indices {
  using GT = boost::graph_traits<FaceGraph>;
  decltype(CGAL::get_initialized_vertex_index_map(std::declval<const FaceGraph&>())) vim;
  decltype(CGAL::get_initialized_halfedge_index_map(std::declval<const FaceGraph&>())) him;
  decltype(CGAL::get_initialized_edge_index_map(std::declval<const FaceGraph&>())) eim;
  decltype(CGAL::get_initialized_face_index_map(std::declval<const FaceGraph&>())) fim;
  std::size_t n_vertices, n_halfedges, n_edges, n_faces;

  explicit Mesh_indices(const FaceGraph& g)
      : vim(CGAL::get_initialized_vertex_index_map(g)),
        him(CGAL::get_initialized_halfedge_index_map(g)),
        eim(CGAL::get_initialized_edge_index_map(g)), fim(CGAL::get_initialized_face_index_map(g)),
        n_vertices(std::size_t(num_vertices(g))), n_halfedges(std::size_t(num_halfedges(g))),
        n_edges(std::size_t(num_edges(g))), n_faces(std::size_t(num_faces(g))) {}

  /// Re-reads the maps and counts after `g` grew. Meshes with intrinsic indices (Surface_mesh) keep
  /// them; meshes that store ids in their elements get the new elements numbered (CGAL numbers in
  /// iteration order, where new elements come last), which keeps the old ids when they were
  /// numbered that way, as CGAL does.
  void refresh(const FaceGraph& g) { *this = Mesh_indices(g); }

  std::size_t v(typename GT::vertex_descriptor x) const { return std::size_t(get(vim, x)); }
  std::size_t h(typename GT::halfedge_descriptor x) const { return std::size_t(get(him, x)); }
  std::size_t e(typename GT::edge_descriptor x) const { return std::size_t(get(eim, x)); }
  std::size_t f(typename GT::face_descriptor x) const { return std::size_t(get(fim, x)); }
};

/// Thrown by the search visitor to stop Dijkstra early.
struct Search_done {};

/// Shortest paths from a set of sources over the edges of a FaceGraph. The cost of an edge is asked
/// with the edge oriented away from the vertex being expanded (`source(e)`), so a cost function can
/// forbid leaving a vertex (return infinity) while still allowing to arrive at it.
template <typename FaceGraph> class Shortest_path_tree {
public:
  using GT = boost::graph_traits<FaceGraph>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using edge_descriptor = typename GT::edge_descriptor;

  Shortest_path_tree(const FaceGraph& g, const Mesh_indices<FaceGraph>& idx) : g_(g), idx_(idx) {}

  /// Runs from `sources` (all at distance 0); stops as soon as a vertex with `stop_at(v)` true and
  /// a positive distance is settled (if `stop_at` is given).
  template <typename Cost>
  void run(const std::vector<vertex_descriptor>& sources, Cost cost,
           std::function<bool(vertex_descriptor)> stop_at = {}) {
    std::vector<std::pair<vertex_descriptor, double>> seeded;
    seeded.reserve(sources.size());
    for (vertex_descriptor s : sources)
      seeded.emplace_back(s, 0.0);
    run_seeded(seeded, cost, std::move(stop_at));
  }

  /// Runs from `sources`, each starting at its own initial distance (an offset that makes some
  /// sources less attractive than others).
  template <typename Cost>
  void run_seeded(const std::vector<std::pair<vertex_descriptor, double>>& sources, Cost cost,
                  std::function<bool(vertex_descriptor)> stop_at = {}) {
    const double inf = std::numeric_limits<double>::infinity();
    dist_.assign(idx_.n_vertices, inf);
    pred_.assign(idx_.n_vertices, GT::null_halfedge());
    reached_.clear();
    first_settled_stop_ = GT::null_vertex();
    auto weight = boost::make_function_property_map<edge_descriptor, double>(
        [&](edge_descriptor e) { return double(cost(e)); });
    auto dist = boost::make_iterator_property_map(dist_.begin(), idx_.vim);
    std::vector<vertex_descriptor> pred_v(idx_.n_vertices);
    auto pred = boost::make_iterator_property_map(pred_v.begin(), idx_.vim);
    std::vector<boost::default_color_type> color_v(idx_.n_vertices, boost::white_color);
    auto color = boost::make_iterator_property_map(color_v.begin(), idx_.vim);
    std::vector<vertex_descriptor> starts;
    for (const auto& [s, d0] : sources) {
      if (d0 < dist_[idx_.v(s)])
        dist_[idx_.v(s)] = d0;
      starts.push_back(s);
    }
    Visitor vis{this, stop_at};
    try {
      boost::dijkstra_shortest_paths_no_init(g_, starts.begin(), starts.end(), pred, dist, weight,
                                             idx_.vim, std::less<double>(),
                                             boost::closed_plus<double>(inf), 0.0, vis, color);
    } catch (const Search_done&) {
    }
  }

  /// The same tree as `run({start}, cost)` for a cost that does not depend on the direction,
  /// given as `weight[e]` per edge index (infinity forbids the edge): the same settling order, the
  /// same heap (Boost's 4-ary heap, as `boost::dijkstra_shortest_paths` uses) and the same ties,
  /// without the per-edge calls through property maps, the colour map and the visitor.
  void run_with_weights(vertex_descriptor start, const std::vector<double>& weight) {
    const double inf = std::numeric_limits<double>::infinity();
    dist_.assign(idx_.n_vertices, inf);
    pred_.assign(idx_.n_vertices, GT::null_halfedge());
    reached_.clear();
    reached_.reserve(idx_.n_vertices);
    first_settled_stop_ = GT::null_vertex();
    // 0 white (never queued), 1 gray (queued), 2 black (settled), as in breadth_first_visit.
    std::vector<unsigned char> color(idx_.n_vertices, 0);
    std::vector<std::size_t> index_in_heap(idx_.n_vertices);
    auto dist = boost::make_iterator_property_map(dist_.begin(), idx_.vim);
    auto heap_index = boost::make_iterator_property_map(index_in_heap.begin(), idx_.vim);
    boost::d_ary_heap_indirect<vertex_descriptor, 4, decltype(heap_index), decltype(dist),
                               std::less<double>>
        queue(dist, heap_index);
    // closed_plus: infinity absorbs.
    auto combine = [inf](double a, double b) { return a == inf || b == inf ? inf : a + b; };
    dist_[idx_.v(start)] = 0.0;
    color[idx_.v(start)] = 1;
    queue.push(start);
    while (!queue.empty()) {
      const vertex_descriptor u = queue.top();
      queue.pop();
      reached_.push_back(u);
      const std::size_t iu = idx_.v(u);
      const double du = dist_[iu];
      const halfedge_descriptor hu = halfedge(u, g_);
      if (hu != GT::null_halfedge())
        // out_edges(u) in CGAL's order: the opposites of the halfedges around u.
        for (halfedge_descriptor h : CGAL::halfedges_around_target(hu, g_)) {
          const vertex_descriptor v = source(h, g_);
          const std::size_t iv = idx_.v(v);
          const unsigned char c = color[iv];
          if (c == 2)
            continue;
          const double dv = dist_[iv];
          const double through = combine(du, weight[idx_.e(edge(h, g_))]);
          const bool decreased = through < dv;
          if (decreased) {
            dist_[iv] = through;
            pred_[iv] = opposite(h, g_);
          }
          if (c == 0) {
            color[iv] = 1;
            queue.push(v);
          } else if (decreased) {
            queue.update(v);
          }
        }
      color[iu] = 2;
    }
  }

  bool reached(vertex_descriptor v) const {
    return dist_[idx_.v(v)] < std::numeric_limits<double>::infinity();
  }
  double distance(vertex_descriptor v) const { return dist_[idx_.v(v)]; }
  /// Halfedge of the tree arriving at `v` (null for a source or an unreached vertex).
  halfedge_descriptor parent(vertex_descriptor v) const { return pred_[idx_.v(v)]; }
  bool is_tree_edge(edge_descriptor e) const {
    const halfedge_descriptor h = halfedge(e, g_);
    return parent(target(h, g_)) == h || parent(source(h, g_)) == opposite(h, g_);
  }
  /// The vertex where the search stopped (null if it ran to the end).
  vertex_descriptor stopped_at() const { return first_settled_stop_; }
  /// Vertices in the order they were settled.
  const std::vector<vertex_descriptor>& settled() const { return reached_; }

  /// Tree path from its source to `v`, as halfedges in walking order.
  std::vector<halfedge_descriptor> path_to(vertex_descriptor v) const {
    std::vector<halfedge_descriptor> path;
    for (halfedge_descriptor h = parent(v); h != GT::null_halfedge(); h = parent(source(h, g_)))
      path.push_back(h);
    std::reverse(path.begin(), path.end());
    return path;
  }
  /// Tree path from `v` back to its source.
  std::vector<halfedge_descriptor> path_to_reversed(vertex_descriptor v) const {
    std::vector<halfedge_descriptor> path;
    for (halfedge_descriptor h = parent(v); h != GT::null_halfedge(); h = parent(source(h, g_)))
      path.push_back(opposite(h, g_));
    return path;
  }
  /// The source at the root of `v`'s branch.
  vertex_descriptor root(vertex_descriptor v) const {
    for (halfedge_descriptor h = parent(v); h != GT::null_halfedge(); h = parent(v))
      v = source(h, g_);
    return v;
  }

private:
  struct Visitor : boost::default_dijkstra_visitor {
    Shortest_path_tree* self;
    std::function<bool(vertex_descriptor)> stop_at;
    Visitor(Shortest_path_tree* s, std::function<bool(vertex_descriptor)> f)
        : self(s), stop_at(std::move(f)) {}
    template <typename Graph> void edge_relaxed(edge_descriptor e, const Graph& g) const {
      // The relaxed edge is oriented from the settled vertex to the improved one.
      halfedge_descriptor h = halfedge(e, g);
      if (target(h, g) != target(e, g))
        h = opposite(h, g);
      self->pred_[self->idx_.v(target(e, g))] = h;
    }
    template <typename Graph> void examine_vertex(vertex_descriptor v, const Graph&) const {
      self->reached_.push_back(v);
      if (stop_at && self->parent(v) != GT::null_halfedge() && stop_at(v)) {
        self->first_settled_stop_ = v;
        throw Search_done{};
      }
    }
  };

  const FaceGraph& g_;
  const Mesh_indices<FaceGraph>& idx_;
  std::vector<double> dist_;
  std::vector<halfedge_descriptor> pred_;
  std::vector<vertex_descriptor> reached_;
  vertex_descriptor first_settled_stop_;
};

} // namespace tessera::internal
