// Q-criterion quadrangulation (Favreau et al. 2009, §4): Alg. 4 cuts a tile of an M-tiling along a
// shortest cutting path between two of its corners; Alg. 5 starts from a cut graph (greedy, schema
// or intermediate) and cuts every tile with more than four corners until all tiles are quads.
// The search for cutting paths is in internal/cutting_path_search.h, the rest of Alg. 5's machinery
// in internal/quadrangulate_impl.h, the entry points' bodies in
// internal/quadrangulate_entry_points_impl.h.
#pragma once

#include <tessera/progress.h>
#include <tessera/topology/cut_graph.h>
#include <tessera/topology/m_tiling.h>

#include <cstddef>
#include <string>
#include <vector>

namespace tessera {

/// Alg. 4's cutting path: the shortest path inside the tile from corner `a` to corner `b` (corners
/// as returned by `tile_corners`; they may share a vertex). Empty when every route would touch the
/// cut.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh, typename EdgeCostMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>
shortest_cutting_path(const M_tiling<TriangleMesh>& tiling,
                      typename boost::graph_traits<TriangleMesh>::halfedge_descriptor a,
                      typename boost::graph_traits<TriangleMesh>::halfedge_descriptor b,
                      EdgeCostMap cost,
                      const NamedParameters& np = CGAL::parameters::default_values());

/// Alg. 4: cuts the tile of corners `a` and `b` along `shortest_cutting_path`; `empty_path` when
/// there is none. The corners' vertices are marked as multipoints first, so that they stay corners
/// whatever their cut degree becomes.
template <typename TriangleMesh, typename EdgeCostMap>
Cut_path_status
cut_tile_between_corners(M_tiling<TriangleMesh>& tiling,
                         typename boost::graph_traits<TriangleMesh>::halfedge_descriptor a,
                         typename boost::graph_traits<TriangleMesh>::halfedge_descriptor b,
                         EdgeCostMap cost);

enum class Quadrangulation_status {
  ok,
  invalid_mesh,          ///< not a valid triangle mesh
  invalid_basepoint,     ///< the basepoint index is out of range or on a border
  cut_refinement_failed, ///< the schema cut's loops could not be made disjoint
                         ///< (`Cut_status::refinement_failed`)
  cut_not_a_disk, ///< the source cut left a component that is not a disk (`Cut_status::not_a_disk`)
  cut_canonical_failed, ///< the schema could not be made canonical (`Cut_status::canonical_failed`)
  no_cutting_path       ///< some tile had no valid cutting path even after `max_refinements`
};

struct Quadrangulation_options {
  /// The source cut graph (`cut.method`), the edge costs of all paths, and the basepoint.
  Cut_options cut;
  /// Midpoint subdivisions of the whole mesh allowed when a tile has no valid cutting path even
  /// after its local refinement (see `quadrangulate`).
  std::size_t max_refinements = 3;
  /// Called after each cutting path of Alg. 5 (stage "cutting paths", total as planned).
  Progress_callback progress;
};

/// One quad: four corners and four sides in boundary order, the tile on the sides' left.
template <typename TriangleMesh> struct Quad_tile {
  using GT = boost::graph_traits<TriangleMesh>;
  /// `sides[i]` runs from `corners[i]` to `corners[(i + 1) % 4]`.
  std::vector<std::vector<typename GT::halfedge_descriptor>> sides;
  std::vector<typename GT::vertex_descriptor> corners;
};

template <typename TriangleMesh> struct Quadrangulation_result {
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

/// Alg. 5: opens `tm` along a cut graph (`options.cut`), makes every polygon's corner count even
/// and at least 4 (see below), then cuts tiles along shortest Q-criterion cutting paths until every
/// tile is a quad: an m-gon gives m/2 - 1 quads, the schema's 4g-gon 2g - 1. Paths run strictly
/// inside their tile, so every tile is a disk whose boundary touches other tiles and the mesh
/// border only along sides and at its 4 corners.
///
/// Refinement, local first: before a tile is searched, its corners whose wedge has at most one
/// inner edge get more (the wedge faces' edges opposite the corner are split at their midpoints, or
/// a centroid inserted), and its chords (uncut edges with both ends on the cut, the only edges
/// across a one-triangle-wide strip between two sides) are split at their midpoints
/// (`local_refinements` counts the tiles this changed; chords only appear where a cutting path
/// joins the cut, so after the first search they are split along each new path, for both tiles it
/// leaves). The tiling follows these edits, so no work is repeated. Split faces stay convex
/// polygons while Alg. 5 runs (a path may cross one along a diagonal) and are triangulated once at
/// the end, so a strip between two cut lines keeps its rungs however many paths run along it
/// (doc/topology.md, "Polygonal refinement"). Only if a tile still has no valid cutting path is
/// every triangle split 1-to-4 at its edge midpoints, keeping all cuts made so far (split seam
/// edges stay seams; `refinements`, at most `options.max_refinements`, then the status is
/// `no_cutting_path`). New vertices lie on the input surface (exactly, with an
/// exact-constructions kernel); `tm` is modified.
///
/// Corners on bordered surfaces: a side along the mesh border appears once in a polygon, so the
/// corner count may be odd; the longest border side is then split at its middle vertex (a new
/// corner). Counts below 4 (a closed sphere's slit has 2, a disk without cut 0) are raised by
/// splitting the longest side, a seam side adding a corner on both of its copies.
///
/// Outputs: tile ids in `tile_of_face` (writable face property map of std::size_t), the seams (all
/// tile borders) in `seam_edges`/`seam_vertices`, ready for `CGAL::Seam_mesh`.
///
/// Named parameters: `vertex_point_map` (written to for new vertices).
template <typename TriangleMesh, typename FaceTileMap, typename SeamEdgeMap, typename SeamVertexMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Quadrangulation_result<TriangleMesh>
quadrangulate(TriangleMesh& tm, FaceTileMap tile_of_face, SeamEdgeMap seam_edges,
              SeamVertexMap seam_vertices, const Quadrangulation_options& options = {},
              const NamedParameters& np = CGAL::parameters::default_values());

} // namespace tessera

#include <tessera/topology/internal/quadrangulate_entry_points_impl.h>
