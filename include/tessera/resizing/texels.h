// Measuring whether a resize preserved a geometric texture (issue 16's measure): texels are the
// connected groups of vertices whose detail height exceeds a threshold; each one's footprint aspect
// and size come from the principal axes of the surface above the threshold, and their spacing from
// the distances between the footprints' centroids. Simple scaling by 2 along x doubles the aspect
// and keeps the count; texture-preserving resizing keeps aspect, size and spacing and adds texels.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace tessera {

struct Texel_footprint {
  std::size_t vertices = 0;
  /// √(λ1/λ2) of the two largest principal variances of the texel's footprint, the surface where
  /// the height exceeds the threshold (1 for a round texel).
  double aspect = 1;
  /// 2·(λ1·λ2)^(1/4): the radius of a disc with the same variances.
  double size = 0;
  /// The footprint's area.
  double area = 0;
  /// The footprint's centroid.
  std::array<double, 3> center{{0, 0, 0}};
  /// Distance from `center` to the nearest other texel's (0 when it is the only one).
  double spacing = 0;
};

struct Texel_measure {
  std::vector<Texel_footprint> texels;
  double median_aspect = 0;
  double median_size = 0;
  /// Median over the texels of the distance to the nearest other texel: the lattice's spacing
  /// for a square or hexagonal lattice (0 with fewer than two texels).
  double median_spacing = 0;
};

/// Texels of `tm` where `height` (a vertex property map of double, e.g. the detail height or a
/// generator's ground truth) exceeds `threshold`, connected along edges; groups of fewer than
/// `min_vertices` vertices are left out. Each texel's footprint is the part of the surface where
/// the height, interpolated linearly over each triangle, exceeds the threshold; aspect and size
/// come from its area moments. Positions are read from `vpm`.
template <typename TriangleMesh, typename VertexPointMap, typename HeightMap>
Texel_measure measure_texels(const TriangleMesh& tm, VertexPointMap vpm, HeightMap height,
                             double threshold, std::size_t min_vertices = 4);

} // namespace tessera

#include <tessera/resizing/internal/texels_impl.h>
