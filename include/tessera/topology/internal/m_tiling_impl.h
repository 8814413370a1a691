// The bodies of `M_tiling`'s members and of tile_corners() (tessera/topology/m_tiling.h): seams
// and marks kept by index and carried over refinements, paths checked and cut, tile ids by
// union-find, the tiles' boundary cycles and sides. Included at the end of the public header.
#pragma once

#include <tessera/topology/m_tiling.h>

#include <boost/pending/disjoint_sets.hpp>

#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

namespace tessera {

template <typename TriangleMesh>
M_tiling<TriangleMesh>::M_tiling(const TriangleMesh& tm)
    : tm_(tm), idx_(tm), seam_(idx_.n_edges, false), marked_(idx_.n_vertices, false),
      cut_degree_(idx_.n_vertices, 0) {
  for (edge_descriptor e : edges(tm_))
    if (is_border_edge(halfedge(e, tm_), tm_)) {
      cut_edges_.push_back(e);
      ++cut_degree_[idx_.v(source(halfedge(e, tm_), tm_))];
      ++cut_degree_[idx_.v(target(halfedge(e, tm_), tm_))];
    }
}

template <typename TriangleMesh> void M_tiling<TriangleMesh>::absorb_refinement() {
  idx_.refresh(tm_);
  seam_.resize(idx_.n_edges, false);
  marked_.resize(idx_.n_vertices, false);
  cut_degree_.resize(idx_.n_vertices, 0);
  if (!cycle_label_.empty())
    cycle_label_.resize(idx_.n_halfedges, std::size_t(-1));
  invalidate_tiles();
  if (indices_kept())
    return;
  // The indices moved: rebuild the index-keyed state from the descriptors.
  ++renumberings_;
  seam_.assign(idx_.n_edges, false);
  cut_degree_.assign(idx_.n_vertices, 0);
  marked_.assign(idx_.n_vertices, false);
  cycle_label_.clear();
  labeled_.clear();
  labels_dirty_ = true;
  for (edge_descriptor e : cut_edges_) {
    const halfedge_descriptor h = halfedge(e, tm_);
    if (!is_border_edge(h, tm_))
      seam_[idx_.e(e)] = true;
    ++cut_degree_[idx_.v(source(h, tm_))];
    ++cut_degree_[idx_.v(target(h, tm_))];
  }
  for (vertex_descriptor v : marked_list_)
    marked_[idx_.v(v)] = true;
}

template <typename TriangleMesh>
bool M_tiling<TriangleMesh>::is_multipoint(vertex_descriptor v) const {
  const std::size_t d = cut_degree(v);
  return d > 0 && (d != 2 || marked_[idx_.v(v)]);
}

template <typename TriangleMesh> void M_tiling<TriangleMesh>::mark_multipoint(vertex_descriptor v) {
  if (marked_[idx_.v(v)])
    return;
  tiles_cache_valid_ = false;
  marked_[idx_.v(v)] = true;
  marked_list_.push_back(v);
}

template <typename TriangleMesh>
void M_tiling<TriangleMesh>::unmark_multipoint(vertex_descriptor v) {
  if (!marked_[idx_.v(v)])
    return;
  tiles_cache_valid_ = false;
  marked_[idx_.v(v)] = false;
  marked_list_.erase(std::find(marked_list_.begin(), marked_list_.end(), v));
}

template <typename TriangleMesh> void M_tiling<TriangleMesh>::clear_marks() {
  tiles_cache_valid_ = false;
  for (vertex_descriptor v : marked_list_)
    marked_[idx_.v(v)] = false;
  marked_list_.clear();
}

template <typename TriangleMesh>
typename M_tiling<TriangleMesh>::halfedge_descriptor
M_tiling<TriangleMesh>::next_on_tile_border(halfedge_descriptor h) const {
  halfedge_descriptor n = next(h, tm_);
  while (!is_tile_border(n))
    n = next(opposite(n, tm_), tm_);
  return n;
}

template <typename TriangleMesh>
typename M_tiling<TriangleMesh>::halfedge_descriptor
M_tiling<TriangleMesh>::wedge_border(halfedge_descriptor h) const {
  // Turn backwards around the vertex, crossing only uncut edges, until the wedge's arriving edge.
  while (!is_tile_border(h))
    h = prev(opposite(h, tm_), tm_);
  return h;
}

template <typename TriangleMesh>
template <typename F>
void M_tiling<TriangleMesh>::for_each_in_wedge(halfedge_descriptor corner, F f) const {
  for (halfedge_descriptor g = opposite(next(corner, tm_), tm_); !is_cut(edge(g, tm_));
       g = opposite(next(g, tm_), tm_))
    f(g);
}

template <typename TriangleMesh>
Cut_path_status M_tiling<TriangleMesh>::cut(const std::vector<halfedge_descriptor>& path) {
  return cut_path(path, false);
}

template <typename TriangleMesh>
Cut_path_status
M_tiling<TriangleMesh>::cut_keeping_connected(const std::vector<halfedge_descriptor>& path) {
  return cut_path(path, true);
}

template <typename TriangleMesh>
void M_tiling<TriangleMesh>::uncut(const std::vector<halfedge_descriptor>& path) {
  std::vector<edge_descriptor> removed;
  for (halfedge_descriptor h : path) {
    const edge_descriptor e = edge(h, tm_);
    if (!seam_[idx_.e(e)])
      continue;
    seam_[idx_.e(e)] = false;
    removed.push_back(e);
    --cut_degree_[idx_.v(source(h, tm_))];
    --cut_degree_[idx_.v(target(h, tm_))];
  }
  if (removed.empty())
    return;
  // One pass over the cut edges rather than one search per removed edge.
  cut_edges_.erase(std::remove_if(cut_edges_.begin(), cut_edges_.end(),
                                  [&](edge_descriptor e) {
                                    return !seam_[idx_.e(e)] &&
                                           !is_border_edge(halfedge(e, tm_), tm_);
                                  }),
                   cut_edges_.end());
  labels_dirty_ = true;
  invalidate_tiles();
}

template <typename TriangleMesh>
Cut_path_status M_tiling<TriangleMesh>::cut_path(const std::vector<halfedge_descriptor>& path,
                                                 bool keep_connected) {
  const Cut_path_status s = check_path(path);
  if (s != Cut_path_status::ok)
    return s;
  const vertex_descriptor first = source(path.front(), tm_), last = target(path.back(), tm_);
  const bool closed = first == last && !is_on_cut(first);
  const std::size_t tiles_before = keep_connected ? number_of_tiles() : 0;
  for (halfedge_descriptor h : path)
    set_seam(edge(h, tm_), true);
  if (keep_connected && number_of_tiles() > tiles_before) {
    for (halfedge_descriptor h : path)
      set_seam(edge(h, tm_), false);
    return Cut_path_status::separates;
  }
  if (closed)
    mark_multipoint(first);
  return Cut_path_status::ok;
}

template <typename TriangleMesh>
Cut_path_status
M_tiling<TriangleMesh>::check_path(const std::vector<halfedge_descriptor>& path) const {
  if (path.empty())
    return Cut_path_status::empty_path;
  for (std::size_t i = 1; i < path.size(); ++i)
    if (source(path[i], tm_) != target(path[i - 1], tm_))
      return Cut_path_status::not_a_walk;
  for (halfedge_descriptor h : path)
    if (is_cut(edge(h, tm_)))
      return Cut_path_status::crosses_cut;
  const vertex_descriptor first = source(path.front(), tm_), last = target(path.back(), tm_);
  const bool closed = first == last && !is_on_cut(first);
  std::vector<std::size_t> sorted; // vertex indices of the path
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const vertex_descriptor v = target(path[i], tm_);
    if (is_on_cut(v))
      return Cut_path_status::crosses_cut;
    sorted.push_back(idx_.v(v));
  }
  sorted.push_back(idx_.v(first));
  if (!closed)
    sorted.push_back(idx_.v(last));
  std::sort(sorted.begin(), sorted.end());
  // An open path may start and end at the same multipoint (a loop from the cut to itself).
  const std::size_t repeats = std::size_t(sorted.end() - std::unique(sorted.begin(), sorted.end()));
  if (repeats > ((!closed && first == last) ? 1u : 0u))
    return Cut_path_status::repeats_vertex;
  return Cut_path_status::ok;
}

template <typename TriangleMesh> std::size_t M_tiling<TriangleMesh>::number_of_tiles() const {
  update_tiles();
  return tile_count_;
}

template <typename TriangleMesh>
std::size_t M_tiling<TriangleMesh>::tile_of(face_descriptor f) const {
  update_tiles();
  return tile_id_[idx_.f(f)];
}

template <typename TriangleMesh>
std::vector<M_tile<TriangleMesh>> M_tiling<TriangleMesh>::describe_tiles(bool with_faces) const {
  update_tiles();
  // Without faces, the description is kept until the tiling changes (Alg. 5 asks for it several
  // times in a row).
  if (!with_faces && tiles_cache_valid_)
    return tiles_cache_;
  std::vector<M_tile<TriangleMesh>> out(tile_count_);
  std::vector<long> chi(tile_count_, 0);
  for (face_descriptor f : faces(tm_)) {
    const std::size_t t = tile_id_[idx_.f(f)];
    ++chi[t];
    if (with_faces)
      out[t].faces.push_back(f);
  }
  for (vertex_descriptor v : vertices(tm_)) {
    if (is_on_cut(v) || halfedge(v, tm_) == GT::null_halfedge())
      continue;
    ++chi[tile_id_[idx_.f(face(halfedge(v, tm_), tm_))]];
  }
  for (edge_descriptor e : edges(tm_))
    if (!is_cut(e))
      --chi[tile_id_[idx_.f(face(halfedge(e, tm_), tm_))]];
  // Boundary cycles: every tile-border halfedge belongs to exactly one.
  std::vector<bool> seen(idx_.n_halfedges, false);
  std::vector<halfedge_descriptor> border_halfedges;
  for (edge_descriptor e : cut_edges_) {
    border_halfedges.push_back(halfedge(e, tm_));
    border_halfedges.push_back(opposite(halfedge(e, tm_), tm_));
  }
  for (halfedge_descriptor h : border_halfedges) {
    if (!is_tile_border(h) || seen[idx_.h(h)])
      continue;
    M_tile<TriangleMesh>& tile = out[tile_id_[idx_.f(face(h, tm_))]];
    std::vector<halfedge_descriptor> cycle;
    halfedge_descriptor c = h;
    do {
      seen[idx_.h(c)] = true;
      cycle.push_back(c);
      c = next_on_tile_border(c);
    } while (c != h);
    // Rotate so the cycle starts right after a corner, if it has one.
    for (std::size_t i = 0; i < cycle.size(); ++i)
      if (is_multipoint(source(cycle[i], tm_))) {
        std::rotate(cycle.begin(), cycle.begin() + long(i), cycle.end());
        break;
      }
    const std::size_t b = tile.boundaries.size();
    typename M_tile<TriangleMesh>::Side side;
    side.boundary = b;
    for (halfedge_descriptor x : cycle) {
      side.halfedges.push_back(x);
      if (is_multipoint(target(x, tm_))) {
        tile.sides.push_back(side);
        side.halfedges.clear();
      }
    }
    if (!side.halfedges.empty())
      tile.sides.push_back(side);
    tile.boundaries.push_back(std::move(cycle));
  }
  for (std::size_t t = 0; t < tile_count_; ++t) {
    // V and E both count one per tile-border halfedge, which cancels: chi = V_in - E_in + F.
    out[t].euler_characteristic = chi[t];
    out[t].genus = (2 - chi[t] - long(out[t].boundaries.size())) / 2;
  }
  if (!with_faces) {
    tiles_cache_ = out;
    tiles_cache_valid_ = true;
  }
  return out;
}

template <typename TriangleMesh>
template <typename SeamEdgeMap, typename SeamVertexMap>
void M_tiling<TriangleMesh>::export_seams(SeamEdgeMap seam_edges,
                                          SeamVertexMap seam_vertices) const {
  for (vertex_descriptor v : vertices(tm_))
    put(seam_vertices, v, false);
  for (edge_descriptor e : edges(tm_)) {
    const bool s = is_seam(e);
    put(seam_edges, e, s);
    if (s) {
      put(seam_vertices, source(halfedge(e, tm_), tm_), true);
      put(seam_vertices, target(halfedge(e, tm_), tm_), true);
    }
  }
}

template <typename TriangleMesh>
const std::vector<std::size_t>& M_tiling<TriangleMesh>::boundary_cycle_labels() const {
  if (!labels_dirty_)
    return cycle_label_;
  // Sized on first use: only the cut-graph builders ask for labels.
  if (cycle_label_.size() < idx_.n_halfedges)
    cycle_label_.resize(idx_.n_halfedges, std::size_t(-1));
  for (halfedge_descriptor h : labeled_)
    cycle_label_[idx_.h(h)] = std::size_t(-1);
  labeled_.clear();
  cycle_count_ = 0;
  for (edge_descriptor e : cut_edges_)
    for (halfedge_descriptor h : {halfedge(e, tm_), opposite(halfedge(e, tm_), tm_)}) {
      if (!is_tile_border(h) || cycle_label_[idx_.h(h)] != std::size_t(-1))
        continue;
      halfedge_descriptor c = h;
      do {
        cycle_label_[idx_.h(c)] = cycle_count_;
        labeled_.push_back(c);
        c = next_on_tile_border(c);
      } while (c != h);
      ++cycle_count_;
    }
  labels_dirty_ = false;
  return cycle_label_;
}

template <typename TriangleMesh>
std::size_t M_tiling<TriangleMesh>::number_of_boundary_cycles() const {
  boundary_cycle_labels();
  return cycle_count_;
}

template <typename TriangleMesh>
std::vector<typename M_tiling<TriangleMesh>::edge_descriptor>
M_tiling<TriangleMesh>::seam_edges() const {
  std::vector<edge_descriptor> out;
  for (edge_descriptor e : cut_edges_)
    if (is_seam(e))
      out.push_back(e);
  return out;
}

template <typename TriangleMesh> bool M_tiling<TriangleMesh>::indices_kept() const {
  for (edge_descriptor e : cut_edges_) {
    const std::size_t i = idx_.e(e);
    if (i >= seam_.size() || (!seam_[i] && !is_border_edge(halfedge(e, tm_), tm_)))
      return false;
  }
  for (vertex_descriptor v : marked_list_)
    if (idx_.v(v) >= marked_.size() || !marked_[idx_.v(v)])
      return false;
  for (halfedge_descriptor h : labeled_)
    if (idx_.h(h) >= cycle_label_.size() || cycle_label_[idx_.h(h)] == std::size_t(-1))
      return false;
  return true;
}

template <typename TriangleMesh> void M_tiling<TriangleMesh>::set_seam(edge_descriptor e, bool on) {
  if (seam_[idx_.e(e)] == on)
    return;
  seam_[idx_.e(e)] = on;
  if (on) {
    cut_edges_.push_back(e);
  } else {
    cut_edges_.erase(std::find(cut_edges_.begin(), cut_edges_.end(), e));
  }
  labels_dirty_ = true;
  const halfedge_descriptor h = halfedge(e, tm_);
  for (vertex_descriptor v : {source(h, tm_), target(h, tm_)}) {
    if (on)
      ++cut_degree_[idx_.v(v)];
    else
      --cut_degree_[idx_.v(v)];
  }
  invalidate_tiles();
}

template <typename TriangleMesh> void M_tiling<TriangleMesh>::invalidate_tiles() {
  tiles_dirty_ = true;
  tiles_cache_valid_ = false;
}

template <typename TriangleMesh> void M_tiling<TriangleMesh>::update_tiles() const {
  if (!tiles_dirty_)
    return;
  std::vector<std::uint32_t> rank(idx_.n_faces, 0), parent(idx_.n_faces);
  std::iota(parent.begin(), parent.end(), std::uint32_t(0));
  boost::disjoint_sets<std::uint32_t*, std::uint32_t*> sets(rank.data(), parent.data());
  for (edge_descriptor e : edges(tm_)) {
    if (is_cut(e))
      continue;
    const halfedge_descriptor h = halfedge(e, tm_);
    sets.union_set(std::uint32_t(idx_.f(face(h, tm_))),
                   std::uint32_t(idx_.f(face(opposite(h, tm_), tm_))));
  }
  // The roots' labels go into `rank`, no longer needed.
  constexpr std::uint32_t unset = std::numeric_limits<std::uint32_t>::max();
  std::fill(rank.begin(), rank.end(), unset);
  tile_id_.resize(idx_.n_faces);
  tile_count_ = 0;
  for (face_descriptor f : faces(tm_)) {
    const std::uint32_t r = sets.find_set(std::uint32_t(idx_.f(f)));
    if (rank[r] == unset)
      rank[r] = std::uint32_t(tile_count_++);
    tile_id_[idx_.f(f)] = rank[r];
  }
  tiles_dirty_ = false;
}

template <typename TriangleMesh>
std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>
tile_corners(const M_tiling<TriangleMesh>& tiling, const M_tile<TriangleMesh>& tile) {
  std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor> out;
  const auto& sides = tile.sides;
  if (sides.empty() ||
      !tiling.is_multipoint(source(sides.front().halfedges.front(), tiling.mesh())))
    return out;
  for (std::size_t i = 0; i < sides.size(); ++i)
    out.push_back(sides[(i + sides.size() - 1) % sides.size()].halfedges.back());
  return out;
}

} // namespace tessera
