// Cut graphs that open a surface into disks (Favreau et al. 2009, §3): `greedy` (Alg. 1: cut loops
// that lower the genus, shortest first, then join the boundaries by shortest paths), `intermediate`
// (Alg. 3: the same, with joining paths that prefer to end at existing multipoints), and `schema`
// (Alg. 2: the polygonal schema, 2g loops through one basepoint made disjoint by refinement).
// Loops come from the greedy system of loops at the basepoint (Erickson & Whittlesey 2005), joins
// from one multi-source Dijkstra and a minimum spanning tree over the boundary cycles.
#pragma once

#include <tessera/progress.h>

#include <tessera/topology/edge_cost.h>
#include <tessera/topology/m_tiling.h>
#include <tessera/topology/system_of_loops.h>

#include <CGAL/boost/graph/helpers.h>

#include <limits>
#include <optional>
#include <numeric>
#include <string>
#include <vector>

namespace tessera {

enum class Cut_method {
  greedy,      ///< Alg. 1: genus-lowering loops, shortest first, then shortest boundary joins
               ///< (or the system-of-loops cut when that one is shorter)
  schema,      ///< Alg. 2: 2g disjoint loops through one basepoint (a 4g-gon at one vertex)
  intermediate ///< Alg. 3: as greedy, joins preferring to end at existing multipoints
};

enum class Cut_status {
  ok,
  invalid_mesh,      ///< not a triangle mesh
  invalid_basepoint, ///< the basepoint index is out of range
  refinement_failed, ///< the schema's loops could not be made disjoint
  not_a_disk,        ///< internal check failed: a component did not open into one disk
  canonical_failed   ///< `canonical` was asked and a polygon could not be brought into that form
};

struct Cut_options {
  Cut_method method = Cut_method::greedy;
  /// Costs used by the overload that takes no cost map.
  Edge_cost_options cost;
  /// Index of the basepoint (vertex index map value); none: the first vertex of each component.
  /// A basepoint applies to its own component; the others use their first vertex.
  std::optional<std::size_t> basepoint;
  /// With `schema`: bring every polygon of positive genus into the canonical form
  /// a1 b1 a1^-1 b1^-1 … ag bg ag^-1 bg^-1 by cut-and-paste on the mesh (each move cuts a new
  /// loop at the basepoint along a shortest diagonal of the disk and glues a side pair back; at
  /// most 2g moves; the mesh is refined where a diagonal needs room). Ignored by other methods.
  bool canonical = false;
  /// Called per component for each stage: its system of loops, the schema's refinement around
  /// them, the canonical form's moves.
  Progress_callback progress;
};

/// The polygon one connected component opens into.
template <typename TriangleMesh> struct Cut_polygon {
  using GT = boost::graph_traits<TriangleMesh>;
  /// Sides in boundary order, each with the disk on its left; sides along the cut appear twice
  /// (once reversed), sides along the mesh's own boundary once.
  std::vector<std::vector<typename GT::halfedge_descriptor>> sides;
  /// `corners[i]` is the mesh vertex where `sides[i]` starts (a multipoint).
  std::vector<typename GT::vertex_descriptor> corners;
  typename GT::vertex_descriptor basepoint;
  long genus = 0;
  std::size_t boundaries = 0;
  /// The sides labelled by partner pairs in boundary order from `sides[0]`: "a1 b1 a1^-1 b1^-1"
  /// (pairs named a1, b1, a2, … in order of first appearance, the second side of a pair with
  /// ^-1, B for a side along the mesh border).
  std::string word;
};

template <typename TriangleMesh> struct Cut_result {
  using GT = boost::graph_traits<TriangleMesh>;
  Cut_status status = Cut_status::ok;
  std::string message;
  Cut_method method = Cut_method::greedy;
  /// One polygon per connected component.
  std::vector<Cut_polygon<TriangleMesh>> polygons;
  /// Vertices where the cut graph branches or ends: the images of the polygons' corners.
  std::vector<typename GT::vertex_descriptor> multipoints;
  /// Sum of the costs of the seam edges (each once), and their Euclidean length.
  double cut_cost = 0;
  double cut_length = 0;
  /// Vertices the schema's refinement added to the mesh (its canonical form's included).
  std::size_t added_vertices = 0;
  /// True when the polygons were brought into canonical form (`Cut_options::canonical`).
  bool canonical = false;
  /// The cut-and-paste moves that took, over all polygons.
  std::size_t canonical_moves = 0;
  /// For `greedy`: true when the cut of the plain system of loops (cut shortest loop first, any
  /// piece that keeps the tile connected) was shorter than Alg. 1's and was returned instead.
  bool used_system_of_loops = false;
  explicit operator bool() const { return status == Cut_status::ok; }
};

/// Opens every connected component of `tm` into a disk along a cut graph chosen by
/// `options.method`, with edge costs from `cost`. The seams land in `seam_edges` and
/// `seam_vertices` (writable bool property maps, ready for `CGAL::Seam_mesh`). The `schema` method
/// refines `tm`.
///
/// Named parameters: `vertex_point_map` (written to for the schema's new vertices).
template <typename TriangleMesh, typename EdgeCostMap, typename SeamEdgeMap, typename SeamVertexMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Cut_result<TriangleMesh>
cut_to_disk(TriangleMesh& tm, EdgeCostMap cost, SeamEdgeMap seam_edges, SeamVertexMap seam_vertices,
            const Cut_options& options = {},
            const NamedParameters& np = CGAL::parameters::default_values());

/// As above, with edge costs computed from `options.cost` (Euclidean or curvature-weighted).
template <typename TriangleMesh, typename SeamEdgeMap, typename SeamVertexMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Cut_result<TriangleMesh>
cut_to_disk(TriangleMesh& tm, SeamEdgeMap seam_edges, SeamVertexMap seam_vertices,
            const Cut_options& options = {},
            const NamedParameters& np = CGAL::parameters::default_values()) {
  auto cost = get(CGAL::dynamic_edge_property_t<double>(), tm);
  compute_edge_costs(tm, cost, options.cost, np);
  return cut_to_disk(tm, cost, seam_edges, seam_vertices, options, np);
}

} // namespace tessera

#include <tessera/topology/internal/canonical_schema_impl.h>
#include <tessera/topology/internal/cut_graph_builder.h>
#include <tessera/topology/internal/cut_to_disk_impl.h>
