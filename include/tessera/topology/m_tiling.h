// M-tiles and M-tilings (Favreau, Marzais, Gerard, Barra, "Tiling surfaces with M-tiles", 2009,
// §2): a set of cut edges (seams) on a mesh splits its faces into tiles; each tile is a compact
// surface with boundary whose boundary cycles are split into sides (1-faces) at corners (0-faces),
// the images of which are the multipoints. Cutting a tile along a path is marking the path's edges
// as seams; the tile's vertices on the path are then twins on both sides of the cut (as in a
// CGAL::Seam_mesh), without copying the mesh. Every intermediate state of the cutting algorithms of
// tessera/topology is an M-tiling.
#pragma once

#include <tessera/topology/internal/graph_search.h>

#include <CGAL/boost/graph/helpers.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tessera {

/// One M-tile: its faces, its boundary cycles (tile-border halfedges, the tile on their left) and
/// the sides these split into at corners.
template <typename TriangleMesh> struct M_tile {
  using GT = boost::graph_traits<TriangleMesh>;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using vertex_descriptor = typename GT::vertex_descriptor;

  /// A side: a maximal run of boundary halfedges between two corners, the tile on its left.
  struct Side {
    std::vector<halfedge_descriptor> halfedges;
    std::size_t boundary = 0;
  };

  std::vector<typename GT::face_descriptor> faces;
  /// Each boundary cycle starts right after a corner when it has one.
  std::vector<std::vector<halfedge_descriptor>> boundaries;
  /// Sides of every boundary, in walking order; a boundary without corners is one closed side.
  std::vector<Side> sides;
  long euler_characteristic = 0;
  long genus = 0;
};

/// Outcome of `M_tiling::cut()`.
enum class Cut_path_status {
  ok,
  empty_path,
  not_a_walk,     ///< consecutive halfedges do not share a vertex
  crosses_cut,    ///< an edge of the path is already cut, or an inner vertex lies on the cut
  repeats_vertex, ///< the path is not simple
  separates       ///< rejected because it would split the tile (only with `keep_connected`)
};

/// A mesh with seams: the M-tiling those seams define. `TriangleMesh` is a FaceGraph; the tiling
/// keeps a reference to it, which must outlive the tiling and must not change meanwhile, except by
/// local refinements off the cut that `absorb_refinement()` is then told about.
template <typename TriangleMesh> class M_tiling {
public:
  using GT = boost::graph_traits<TriangleMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using edge_descriptor = typename GT::edge_descriptor;
  using face_descriptor = typename GT::face_descriptor;

  /// The tiling without seams: one tile per connected component.
  explicit M_tiling(const TriangleMesh& tm);

  const TriangleMesh& mesh() const { return tm_; }

  /// Takes in a refinement of the mesh made since the tiling was built (or last told): Euler
  /// operations that split uncut edges and faces (CGAL::Euler::split_edge, split_face,
  /// add_center_vertex), so that every new vertex and edge is off the cut and every cut edge and
  /// tile-border halfedge is kept. Seams, marks and boundary cycles carry over; tile ids are
  /// recomputed when next asked. In time proportional to the cut when the old elements keep their
  /// indices (Surface_mesh; ids numbered in iteration order), else to the mesh.
  void absorb_refinement();

  const internal::Mesh_indices<TriangleMesh>& indices() const { return idx_; }
  /// How many times `absorb_refinement` found the old elements under new indices (so that data
  /// kept by index elsewhere must be rebuilt).
  std::size_t renumberings() const { return renumberings_; }

  bool is_seam(edge_descriptor e) const { return seam_[idx_.e(e)]; }
  /// A seam or a border edge of the mesh.
  bool is_cut(edge_descriptor e) const {
    return is_seam(e) || is_border_edge(halfedge(e, tm_), tm_);
  }
  /// Number of seam and border edges at `v`.
  std::size_t cut_degree(vertex_descriptor v) const { return cut_degree_[idx_.v(v)]; }
  bool is_on_cut(vertex_descriptor v) const { return cut_degree(v) > 0; }

  /// Multipoints: vertices where sides meet, i.e. where the cut graph (seams and mesh borders)
  /// branches or ends (cut degree other than 2), plus vertices marked explicitly (such as the
  /// basepoint of a single cut loop).
  bool is_multipoint(vertex_descriptor v) const;
  void mark_multipoint(vertex_descriptor v);
  void unmark_multipoint(vertex_descriptor v);
  /// Clears all explicit marks, leaving as multipoints exactly the branch points and ends of the
  /// cut graph.
  void clear_marks();
  /// The vertices marked explicitly, in marking order.
  const std::vector<vertex_descriptor>& marked_vertices() const { return marked_list_; }

  /// True when `h` (a halfedge with a face) lies on the boundary of its tile.
  bool is_tile_border(halfedge_descriptor h) const {
    return !is_border(h, tm_) && is_cut(edge(h, tm_));
  }

  /// The tile-border halfedge that follows `h` on its boundary cycle.
  halfedge_descriptor next_on_tile_border(halfedge_descriptor h) const;

  /// For a halfedge `h` with a face, arriving at a vertex on the cut: the tile-border halfedge that
  /// arrives at the same vertex in the same wedge (the sector of faces between two cut edges).
  halfedge_descriptor wedge_border(halfedge_descriptor h) const;

  /// Calls `f(g)` for every halfedge g that arrives at the vertex of `corner` through the inside of
  /// its wedge, turning from `corner` (the wedge's arriving tile-border halfedge) to the next cut
  /// edge; g's face is in the wedge and g's edge is uncut.
  template <typename F> void for_each_in_wedge(halfedge_descriptor corner, F f) const;

  /// Cuts along `path`, a walk of halfedges that is either a closed simple loop whose vertices are
  /// all off the cut (its first vertex becomes a marked multipoint), or a simple open path whose
  /// inner vertices and edges are off the cut; its ends may lie on the cut (joining it) or not (a
  /// slit). The ends become multipoints.
  Cut_path_status cut(const std::vector<halfedge_descriptor>& path);

  /// As `cut`, but a cut that would split a tile is refused (`Cut_path_status::separates`).
  Cut_path_status cut_keeping_connected(const std::vector<halfedge_descriptor>& path);

  /// Removes the seams along `path` (halfedges of seam edges; border edges are left alone), as
  /// when two tiles are glued back along a side pair. Marks stay; a vertex left with cut degree 0
  /// is inside its tile again.
  void uncut(const std::vector<halfedge_descriptor>& path);

private:
  Cut_path_status cut_path(const std::vector<halfedge_descriptor>& path, bool keep_connected);

public:
  /// Checks that `path` could be cut (see `cut()`), without cutting.
  Cut_path_status check_path(const std::vector<halfedge_descriptor>& path) const;

  /// Number of tiles (recomputed after cuts, in O(n)).
  std::size_t number_of_tiles() const;
  /// Tile index of face `f`, in [0, number_of_tiles()).
  std::size_t tile_of(face_descriptor f) const;

  /// The description of every tile: boundary cycles, sides, Euler characteristic, genus, and its
  /// faces.
  std::vector<M_tile<TriangleMesh>> tiles() const { return describe_tiles(true); }

  /// As `tiles()` without the faces (`M_tile::faces` empty): cheaper, and kept until the tiling
  /// changes.
  std::vector<M_tile<TriangleMesh>> tiles_without_faces() const { return describe_tiles(false); }

private:
  std::vector<M_tile<TriangleMesh>> describe_tiles(bool with_faces) const;

public:
  /// Writes the seams into property maps that `CGAL::Seam_mesh` accepts: an edge is a seam edge,
  /// and a vertex a seam vertex when it lies on a seam edge.
  template <typename SeamEdgeMap, typename SeamVertexMap>
  void export_seams(SeamEdgeMap seam_edges, SeamVertexMap seam_vertices) const;

  /// Labels of the boundary cycles: for every tile-border halfedge (by halfedge index) the index of
  /// its cycle, and `std::size_t(-1)` for other halfedges. Recomputed after a cut in time
  /// proportional to the number of cut edges, not to the mesh.
  const std::vector<std::size_t>& boundary_cycle_labels() const;
  /// Number of boundary cycles over all tiles.
  std::size_t number_of_boundary_cycles() const;

  /// Border edges of the mesh, then seams in the order they were cut.
  const std::vector<edge_descriptor>& cut_edges() const { return cut_edges_; }

  /// Seam edges, each once, in the order they were cut.
  std::vector<edge_descriptor> seam_edges() const;

private:
  // Whether the seams, marks and labelled halfedges are still found at their indices.
  bool indices_kept() const;

  void set_seam(edge_descriptor e, bool on);

  void invalidate_tiles();

  // Tile ids: union-find of the faces across uncut edges, numbered in face order.
  void update_tiles() const;

  const TriangleMesh& tm_;
  internal::Mesh_indices<TriangleMesh> idx_;
  std::vector<bool> seam_;
  std::vector<bool> marked_;
  std::vector<vertex_descriptor> marked_list_;
  std::vector<std::size_t> cut_degree_;
  std::vector<edge_descriptor> cut_edges_; // border edges, then seams in cutting order
  mutable std::vector<std::size_t> cycle_label_;
  mutable std::vector<halfedge_descriptor> labeled_;
  mutable std::size_t cycle_count_ = 0;
  mutable bool labels_dirty_ = true;
  mutable std::vector<std::uint32_t> tile_id_; // (meshes of fewer than 2^32 faces)
  mutable std::size_t tile_count_ = 0;
  mutable bool tiles_dirty_ = true;
  mutable std::vector<M_tile<TriangleMesh>> tiles_cache_; // tiles_without_faces() while valid
  mutable bool tiles_cache_valid_ = false;
  std::size_t renumberings_ = 0;
};

/// The corners of a disk tile in boundary order. A corner is named by the tile-border halfedge that
/// arrives at its vertex in its wedge, so corners sharing a vertex (the schema's basepoint) differ.
/// Corner i is where `tile.sides[i]` starts. Empty when the boundary has no corner.
template <typename TriangleMesh>
std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>
tile_corners(const M_tiling<TriangleMesh>& tiling, const M_tile<TriangleMesh>& tile);

} // namespace tessera

#include <tessera/topology/internal/m_tiling_impl.h>
