// Independent checks of a quadrangulation (tessera::quadrangulate, Favreau et al. 2009, §4): the
// mesh opened along all tile borders has one disk per tile, each with exactly four corners; every
// vertex where tile borders meet or touch the mesh border is a corner; and an m-gon gave m/2 - 1
// quads.
#pragma once

#include <tessera/topology/quadrangulate.h>

#include <string>
#include <vector>

namespace tessera {

enum class Quadrangulation_validation_status { valid, invalid };

struct Quadrangulation_validation {
  Quadrangulation_validation_status status = Quadrangulation_validation_status::invalid;
  /// The first problem, or "valid".
  std::string message;
  /// The opened mesh has one component per tile, each a disk (chi 1, one boundary loop), and the
  /// face tile map agrees with these components.
  bool tiles_are_disks = false;
  /// Every tile has 4 sides that chain around its opened boundary, and 4 distinct corners on it.
  bool four_corners = false;
  /// On every tile's boundary the corners are exactly the vertices where the cut graph (tile
  /// borders and mesh border) branches or ends, plus the result's marked multipoints.
  bool corners_where_borders_meet = false;
  /// Number of tiles = sum over the source polygons of corners / 2 - 1, and a closed schema of
  /// genus g has 4g corners (2g - 1 quads).
  bool tile_count = false;
  std::vector<std::string> problems;
  explicit operator bool() const { return status == Quadrangulation_validation_status::valid; }
};

/// Checks `result` (with its seams in `seam_edges`/`seam_vertices` and tile ids in `tile_of_face`)
/// against the mesh opened along the seams.
template <typename TriangleMesh, typename FaceTileMap, typename SeamEdgeMap, typename SeamVertexMap>
Quadrangulation_validation
validate_quadrangulation(const TriangleMesh& tm, FaceTileMap tile_of_face, SeamEdgeMap seam_edges,
                         SeamVertexMap seam_vertices,
                         const Quadrangulation_result<TriangleMesh>& result);

} // namespace tessera

#include <tessera/topology/internal/validate_quadrangulation_impl.h>
