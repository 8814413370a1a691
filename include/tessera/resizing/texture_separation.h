// Telling several geometric textures apart (Chen and Meng 2010, §3.4: the mushroom's cap and stem
// are each synthesized from their own sample): the texture region's connected pieces, each with the
// texel period of its own mean curvature (texel_period.h restricted to it); pieces of one period
// are one texture, and scraps too small to hold a few texels join the largest texture.
#pragma once

#include <tessera/internal/named_parameters.h>
#include <tessera/resizing/texel_period.h>

#include <CGAL/Named_function_parameters.h>

#include <cstddef>
#include <string>
#include <vector>

namespace tessera {

struct Texture_separation_options {
  /// Two pieces are one texture when their periods differ by at most this fraction of the
  /// larger one.
  double period_tolerance = 0.15;
  /// A piece whose area is under this many squared periods of the largest piece (fewer than
  /// about this many texels) is a scrap of the segmentation and joins the largest texture.
  double min_texel_cells = 6;
};

enum class Texture_separation_status {
  ok,
  empty_mesh,
  /// No vertex is texture.
  no_texture
};

/// One texture: connected pieces of the texture region sharing one period.
struct Separated_texture {
  std::size_t pieces = 0;
  std::size_t vertices = 0;
  /// Area of the triangles whose corners are all in this texture.
  double area = 0;
  /// The period of the texture's own mean curvature (`estimate_texel_period` over its vertices);
  /// not measured (0) when the texture region is one piece, whose period is the surface's.
  Texel_period period;
};

struct Texture_separation_result {
  Texture_separation_status status = Texture_separation_status::ok;
  std::string message;
  /// Indexed by the texture ids written per vertex, largest area first.
  std::vector<Separated_texture> textures;
  /// Connected pieces of the texture region, and how many of them were scraps.
  std::size_t pieces = 0, scraps = 0;
  explicit operator bool() const { return status == Texture_separation_status::ok; }
};

/// The id `separate_textures` writes for a vertex that is not texture.
constexpr std::size_t no_texture_id = std::size_t(-1);

/// Splits the texture of `tm` (vertices where `is_texture` is true) into separate textures and
/// writes each vertex's texture id (an index into `result.textures`, `no_texture_id` off the
/// texture) to `texture_id` (a writable vertex map of `std::size_t`). The pieces are the texture
/// region's connected components along edges; each one's period is the first autocorrelation
/// peak of the mean curvature over its own vertices; pieces whose periods agree within
/// `period_tolerance` are one texture (so one texture broken by a smooth band keeps one sample).
/// Pieces are not split further: two textures that touch are one piece.
///
/// Named parameters: `vertex_point_map`, `vertex_index_map`.
template <typename TriangleMesh, typename VertexTextureMap, typename VertexIdMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Texture_separation_result
separate_textures(const TriangleMesh& tm, VertexTextureMap is_texture, VertexIdMap texture_id,
                  const Texture_separation_options& options = {},
                  const NamedParameters& np = CGAL::parameters::default_values());

} // namespace tessera

#include <tessera/resizing/internal/texture_separation_impl.h>
