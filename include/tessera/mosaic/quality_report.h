// How good a mosaic is, measured on the surface: coverage and overlap of the tiles, their
// orientation against the field, how well neighbours line up in rows, the grout gaps, and tiles
// that cross a feature line. Works on any tiles (Tessera's or another tool's) given as
// `Mosaic_tile`s.
#pragma once

#include <tessera/fields/feature_lines.h>
#include <tessera/mosaic/tile.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <cstddef>
#include <vector>

namespace tessera {

/// Options of `mosaic_quality()`.
struct Mosaic_quality_options {
  /// Surface samples per tile (spread by error diffusion, i.e. uniform in area): the coverage and
  /// overlap figures are fractions of these samples, exact to about 1/√(samples) each.
  double samples_per_tile = 40;
  /// Tiles a bare sample's distance to the nearest tile is also taken over (the nearest centres),
  /// where no tile within covering reach is near it.
  std::size_t candidates = 12;
  /// Symmetry n of the field for the orientation error (angles are taken modulo 2π/n).
  int symmetry = 4;
  unsigned seed = 7;
};

/// The figures of a mosaic. Fractions are of the surface area A; angles in degrees; lengths in the
/// mesh's units.
struct Mosaic_quality {
  std::size_t tiles = 0, samples = 0;
  double area = 0;
  /// Area covered by at least one tile (tiles taken in their planes, a sample counting as covered
  /// when its projection along the tile's normal falls inside the tile, within half a tile's size
  /// of its plane and on the side its normal faces), over A.
  double coverage = 0;
  /// Area covered by two tiles or more, over A.
  double overlap = 0;
  /// Angle between each tile's x axis and the field at its centre, modulo 2π/n: median, 95th
  /// percentile, largest.
  double orientation_error_median = 0, orientation_error_p95 = 0, orientation_error_max = 0;
  /// Angle between the direction to each tile's nearest neighbour (in the tile's plane) and the
  /// tile's nearest axis: 0 when tiles sit in rows and columns along the field, 45 for a diagonal.
  double row_alignment_median = 0, row_alignment_p95 = 0;
  /// Gap between each tile and its nearest neighbour along the axis that separates them (negative
  /// when they overlap): mean and smallest over the tiles; the layout's ideal is the grout width.
  double gap_mean = 0, gap_min = 0, gap_ideal = 0;
  /// Course drift: angle between the x axes of neighbouring tiles (each tile against its
  /// neighbours within 1.5 spacings on its side of the surface, the other's axis turned into its
  /// plane by the least rotation that takes the other's normal to its own, as a connection
  /// transports it), modulo 2π/n: median and 95th percentile. What a viewer sees as rows that bend
  /// or tiles at odd angles, whatever the field was.
  double course_drift_median = 0, course_drift_p95 = 0;
  /// The widest bare patch: the diameter of the largest disk of the surface that no tile touches
  /// (twice the largest distance from an uncovered sample to its nearest tile facing less than 120°
  /// away from the sample's face: across a crease, not across a thin part; or to the surface's
  /// open border, where the surface and the disk end), in units of the tile side √(l_x·l_y) (the
  /// median over the tiles). A regular layout's is about the grout width, ~0.05 tiles at g = 0.1;
  /// a bare strip w wide along a border reads w.
  double largest_gap = 0;
  /// Where that disk is: the uncovered sample farthest from every tile (0, 0, 0 when none is).
  std::array<double, 3> largest_gap_center{{0, 0, 0}};
  /// Tiles whose rectangle crosses a feature line of their connected component, within half the
  /// tile's smaller side of its plane and beside a face within 60° of it.
  std::size_t tiles_crossing_features = 0;
};

/// Measures `tiles` on `tm` against `field` (a vertex property map of vectors) and `features`.
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh, typename VertexFieldMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Mosaic_quality mosaic_quality(
    const TriangleMesh& tm,
    const std::vector<Mosaic_tile<typename boost::graph_traits<TriangleMesh>::face_descriptor>>&
        tiles,
    const VertexFieldMap& field,
    const std::vector<
        Feature_line<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>>& features,
    const Mosaic_quality_options& options = {},
    const NamedParameters& np = CGAL::parameters::default_values());

} // namespace tessera

#include <tessera/mosaic/internal/quality_report_impl.h>
