// The greedy system of loops at a basepoint (Erickson & Whittlesey, "Greedy optimal homotopy and
// homology generators", SODA 2005): a shortest-path tree T from the basepoint, then a maximum
// spanning tree of the dual graph (edges not in T, weighted by the length of the loop they close);
// each of the 2g edges left over closes one loop. The result is the shortest system of loops
// through the basepoint, computed in O(n log n). Holes count as dual vertices, so on a bordered
// surface the loops are those of the surface with its holes capped.
#pragma once

#include <boost/graph/graph_traits.hpp>

#include <vector>

namespace tessera {

/// Loops based at one vertex, each a closed halfedge path that starts and ends at `basepoint`.
template <typename TriangleMesh> struct System_of_loops {
  using GT = boost::graph_traits<TriangleMesh>;
  typename GT::vertex_descriptor basepoint;
  /// Loops in order of increasing length.
  std::vector<std::vector<typename GT::halfedge_descriptor>> loops;
  std::vector<double> lengths;
  /// For each loop, the edge outside the tree and the cotree that closes it.
  std::vector<typename GT::edge_descriptor> generators;
};

/// Computes the greedy (shortest) system of loops at `basepoint` on its connected component of
/// `tm`, with edge lengths from `cost` (a readable edge property map of non-negative doubles).
/// Border edges are never used by loops. The system has 2g loops, g the genus of the component.
template <typename TriangleMesh, typename EdgeCostMap>
System_of_loops<TriangleMesh>
greedy_system_of_loops(const TriangleMesh& tm,
                       typename boost::graph_traits<TriangleMesh>::vertex_descriptor basepoint,
                       EdgeCostMap cost);

} // namespace tessera

#include <tessera/topology/internal/system_of_loops_impl.h>
