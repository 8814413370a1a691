// Implementation of tessera::greedy_system_of_loops (see tessera/topology/system_of_loops.h).
#pragma once

#include <tessera/topology/system_of_loops.h>

#include <tessera/topology/internal/graph_search.h>

#include <boost/pending/disjoint_sets.hpp>
#include <boost/sort/spreadsort/integer_sort.hpp>

#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numeric>
#include <unordered_map>
#include <vector>

namespace tessera {

template <typename TriangleMesh, typename EdgeCostMap>
System_of_loops<TriangleMesh>
greedy_system_of_loops(const TriangleMesh& tm,
                       typename boost::graph_traits<TriangleMesh>::vertex_descriptor basepoint,
                       EdgeCostMap cost) {
  using GT = boost::graph_traits<TriangleMesh>;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using edge_descriptor = typename GT::edge_descriptor;
  const double inf = std::numeric_limits<double>::infinity();

  internal::Mesh_indices<TriangleMesh> idx(tm);
  internal::Shortest_path_tree<TriangleMesh> spt(tm, idx);
  // Border edges are never used: infinite weight. One pass in storage order, so the search reads
  // an array instead of the mesh's faces and the cost map per edge it examines.
  std::vector<double> weight(idx.n_edges, inf);
  for (edge_descriptor e : edges(tm))
    if (!is_border_edge(halfedge(e, tm), tm))
      weight[idx.e(e)] = double(get(cost, e));
  spt.run_with_weights(basepoint, weight);

  // Dual vertices: faces, then one per hole (boundary cycle) of the mesh.
  const std::size_t nf = idx.n_faces;
  std::unordered_map<std::size_t, std::size_t> hole_of; // by border halfedge index
  std::size_t holes = 0;
  for (halfedge_descriptor h : halfedges(tm)) {
    if (!is_border(h, tm) || hole_of.count(idx.h(h)) > 0)
      continue;
    for (halfedge_descriptor c : CGAL::halfedges_around_face(h, tm))
      hole_of[idx.h(c)] = holes;
    ++holes;
  }
  auto dual_vertex = [&](halfedge_descriptor h) {
    return is_border(h, tm) ? nf + hole_of.at(idx.h(h)) : idx.f(face(h, tm));
  };

  // `key` orders the loop lengths (non-negative or infinite) longest first as unsigned integers:
  // the complement of the double's bits.
  // 16 bytes on Surface_mesh (the sort moves every non-tree edge); the length is read back from
  // the key.
  struct Candidate {
    std::uint64_t key;
    std::uint32_t index; // (fewer than 2^32 edges)
    edge_descriptor e;
  };
  std::vector<Candidate> candidates;
  candidates.reserve(idx.n_edges);
  for (edge_descriptor e : edges(tm)) {
    const halfedge_descriptor h = halfedge(e, tm);
    if (spt.is_tree_edge(e) || (!spt.reached(source(h, tm)) && !spt.reached(target(h, tm))))
      continue;
    double len = inf;
    if (!is_border_edge(h, tm) && spt.reached(source(h, tm)) && spt.reached(target(h, tm)))
      len = spt.distance(source(h, tm)) + double(get(cost, e)) + spt.distance(target(h, tm));
    std::uint64_t bits;
    std::memcpy(&bits, &len, sizeof bits);
    candidates.push_back({~bits, std::uint32_t(idx.e(e)), e});
  }
  // Longest first; ties by edge index, so the result does not depend on the sort's stability. A
  // radix sort (Boost's spreadsort) on the keys.
  boost::sort::spreadsort::integer_sort(
      candidates.begin(), candidates.end(),
      [](const Candidate& c, unsigned offset) { return c.key >> offset; },
      [](const Candidate& a, const Candidate& b) {
        return a.key < b.key || (a.key == b.key && a.index < b.index);
      });

  std::vector<std::uint32_t> rank(nf + holes, 0), parent(nf + holes); // (fewer than 2^32 faces)
  std::iota(parent.begin(), parent.end(), std::uint32_t(0));
  boost::disjoint_sets<std::uint32_t*, std::uint32_t*> dual(rank.data(), parent.data());

  System_of_loops<TriangleMesh> result;
  result.basepoint = basepoint;
  for (const Candidate& c : candidates) {
    const halfedge_descriptor h = halfedge(c.e, tm);
    const std::uint32_t a = dual.find_set(std::uint32_t(dual_vertex(h)));
    const std::uint32_t b = dual.find_set(std::uint32_t(dual_vertex(opposite(h, tm))));
    if (a != b) {
      dual.link(a, b);
      continue;
    }
    const std::uint64_t bits = ~c.key;
    double loop_length;
    std::memcpy(&loop_length, &bits, sizeof loop_length);
    if (!std::isfinite(loop_length))
      continue; // a border edge closing a dual cycle: no loop
    std::vector<halfedge_descriptor> loop = spt.path_to(source(h, tm));
    loop.push_back(h);
    for (halfedge_descriptor r : spt.path_to_reversed(target(h, tm)))
      loop.push_back(r);
    result.loops.push_back(std::move(loop));
    result.lengths.push_back(loop_length);
    result.generators.push_back(c.e);
  }
  // Candidates were visited longest first: list the loops shortest first.
  std::reverse(result.loops.begin(), result.loops.end());
  std::reverse(result.lengths.begin(), result.lengths.end());
  std::reverse(result.generators.begin(), result.generators.end());
  return result;
}

} // namespace tessera
