// Per-tile parameterization (Favreau et al. 2009, §5.2): every quad of a quadrangulation onto the
// unit square with its four corners at the square's corners (CGAL's square border with a mean-value
// or discrete conformal interior), other tiles with a free border (LSCM or ARAP), each on its own
// copy cut out along the tile borders (the seams of one CGAL::Seam_mesh); with angle, area and
// stretch distortion per tile.
#pragma once

#include <tessera/progress.h>

#include <cstddef>
#include <string>
#include <type_traits>
#include <vector>

namespace tessera {

/// Interior method of a quad with its border fixed on the unit square.
enum class Quad_interior {
  mean_value,        ///< Floater's mean-value coordinates: one-to-one for a convex border
  discrete_conformal ///< the discrete conformal map (cotangent weights) the paper uses; may flip
                     ///< triangles next to obtuse angles
};

/// Method for tiles that are not quads (such as the single disk of a cut).
enum class Free_border_method { lscm, arap };

struct Tile_parameterization_options {
  Quad_interior quad_interior = Quad_interior::mean_value;
  Free_border_method free_border = Free_border_method::lscm;
  /// Called after each tile (stage "parameterizing tiles").
  Progress_callback progress;
};

/// Distortion of one tile's parameterization, from the Jacobian of the map from UV to the surface
/// (singular values s1 >= s2) per triangle, area-weighted over the tile's non-degenerate triangles.
struct Tile_distortion {
  bool parameterized = false;
  std::string message; ///< why CGAL could not parameterize the tile
  /// Mean of s1 / s2: 1 for a conformal map.
  double angle = 1;
  /// Mean of max(r, 1/r), r the triangle's share of the UV area over its share of the surface area.
  double area = 1;
  /// L2 stretch of Sander et al. (2001), scaled so that an isometry up to scale gives 1.
  double stretch = 1;
  /// Triangles with negative (flipped) or zero UV orientation, by CGAL's exact orientation test.
  std::size_t flipped = 0;
  std::size_t degenerate = 0;
};

enum class Tile_parameterization_status {
  ok,
  tile_failed ///< CGAL could not parameterize a tile (see `message` and the tile's `message`)
};

struct Tile_parameterization_result {
  Tile_parameterization_status status = Tile_parameterization_status::ok;
  std::string message;
  std::vector<Tile_distortion> tiles;
  /// The tile of largest stretch.
  std::size_t worst_tile = 0;
  std::size_t flipped = 0;
  std::size_t degenerate = 0;
  explicit operator bool() const { return status == Tile_parameterization_status::ok; }
};

/// The property maps that describe a cutting of a mesh into tiles, as `quadrangulate` fills them:
/// the tile id of each face (readable face map of std::size_t) and the seams, i.e. the tile borders
/// (readable edge and vertex maps of bool). Made by `tile_maps(tile_of_face, seam_edges,
/// seam_vertices)`.
template <typename FaceTileMap, typename SeamEdgeMap, typename SeamVertexMap> struct Tile_maps {
  FaceTileMap tile_of_face;
  SeamEdgeMap seam_edges;
  SeamVertexMap seam_vertices;
};

template <typename FaceTileMap, typename SeamEdgeMap, typename SeamVertexMap>
Tile_maps<FaceTileMap, SeamEdgeMap, SeamVertexMap>
tile_maps(FaceTileMap tile_of_face, SeamEdgeMap seam_edges, SeamVertexMap seam_vertices) {
  return {tile_of_face, seam_edges, seam_vertices};
}

} // namespace tessera

#include <tessera/topology/internal/parameterize_tiles_impl.h>

namespace tessera {

/// Parameterizes every tile of `tiles` (each with `sides`, a vector of halfedge paths in boundary
/// order with the tile on their left, such as `Quad_tile` or `Cut_polygon`; tile t holds the faces
/// with `maps.tile_of_face` t), cut open along `maps.seam_edges`/`maps.seam_vertices`. A tile with
/// 4 sides goes onto the unit square, side i starting at corner (0,0), (1,0), (1,1), (0,1) in turn
/// (or their mirror image (v, u), whichever keeps the triangles' orientation); other tiles get a
/// free border. Output: `uv[h]` (writable halfedge map of a 2D point) is, for every halfedge h with
/// a face, the UV of target(h) in the parameterization of that face's tile.
/// On a mesh whose coordinates are not doubles (e.g. CGAL::Epeck's), the tiles are parameterized on
/// a copy in doubles: CGAL's parameterizers solve in double precision and do not compile for exact
/// number types, and a UV map is approximate anyway. Reads the mesh's internal point map: CGAL's
/// parameterizers take no other.
template <typename TriangleMesh, typename Tile, typename FaceTileMap, typename SeamEdgeMap,
          typename SeamVertexMap, typename HalfedgeUVMap>
Tile_parameterization_result
parameterize_tiles(const TriangleMesh& tm, const std::vector<Tile>& tiles,
                   const Tile_maps<FaceTileMap, SeamEdgeMap, SeamVertexMap>& maps, HalfedgeUVMap uv,
                   const Tile_parameterization_options& options = {}) {
  using Point_3 = typename boost::property_traits<
      typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type;
  if constexpr (std::is_floating_point_v<typename CGAL::Kernel_traits<Point_3>::Kernel::FT>)
    return internal::parameterize_tiles_impl(tm, tiles, maps.tile_of_face, maps.seam_edges,
                                             maps.seam_vertices, uv, options);
  else
    return internal::parameterize_tiles_in_doubles(tm, tiles, maps.tile_of_face, maps.seam_edges,
                                                   maps.seam_vertices, uv, options);
}

} // namespace tessera
