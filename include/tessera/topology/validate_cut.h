// Independent checks of a cut (tessera::cut_to_disk or any seam set with polygon sides): the mesh
// opened along the seams is one disk per component; sides along the cut pair up with exactly one
// reversed partner; corners are exactly the branch points and ends of the cut graph; and, for a
// polygonal schema, a closed component gives 4g sides whose corners are all the basepoint. Schema
// loops can also be checked to be non-contractible with CGAL's Curves_on_surface_topology.
#pragma once

#include <tessera/topology/cut_graph.h>

#include <string>
#include <vector>

namespace tessera {

struct Validate_cut_options {
  /// For schema cuts: check with CGAL's Curves_on_surface_topology that every side is a
  /// non-contractible loop (costs a copy of the mesh into a combinatorial map).
  bool check_loops_non_contractible = false;
};

enum class Cut_validation_status { valid, invalid };

struct Cut_validation {
  Cut_validation_status status = Cut_validation_status::invalid;
  /// The first problem, or "valid".
  std::string message;
  bool opens_to_disks = false;
  bool sides_paired = false;
  bool corners_are_branch_points = false;
  /// True when not a schema, or when every closed component gives 4g sides at the basepoint.
  bool schema_shape = false;
  /// True when not checked or when every schema loop is non-contractible.
  bool loops_non_contractible = true;
  /// True when the result does not claim the canonical form (`Cut_result::canonical`), or when
  /// every polygon of genus g reads, from its first side, g commutators x y x^-1 y^-1 (closed:
  /// the whole word a1 b1 a1^-1 b1^-1 … ag bg ag^-1 bg^-1).
  bool canonical_form = true;
  std::vector<std::string> problems;
  explicit operator bool() const { return status == Cut_validation_status::valid; }
};

/// Checks `result` against the mesh opened along `seam_edges`/`seam_vertices`.
template <typename TriangleMesh, typename SeamEdgeMap, typename SeamVertexMap>
Cut_validation validate_cut(const TriangleMesh& tm, SeamEdgeMap seam_edges,
                            SeamVertexMap seam_vertices, const Cut_result<TriangleMesh>& result,
                            const Validate_cut_options& options = {});

} // namespace tessera

#include <tessera/topology/internal/validate_cut_impl.h>
