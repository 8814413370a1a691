// Finding the geometric texture of a surface (Chen and Meng, "Anisotropic resizing and
// deformation preserving geometric textures", 2010, §3.2): per vertex, the mean and variance of
// the Gaussian and mean curvatures (CGAL's jet fitting) over its n-ring join its position in a
// feature vector; mean shift clusters the vertices, and the regions whose curvature varies are
// the texture.
#pragma once

#include <tessera/resizing/internal/texel_period.h>
#include <tessera/resizing/texel_period.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cstddef>
#include <string>
#include <vector>

namespace tessera {

struct Texture_segmentation_options {
  /// The radius ρ over which the curvatures are averaged (eqs. 1–2) is, by default, a third of
  /// the texel period (`texel_period`). `rings` > 0 sets it to that many mean edge lengths
  /// instead.
  std::size_t rings = 0;
  /// The texels' period in model units (the distance between neighbouring texels); 0: read from
  /// the surface (`estimate_texel_period`, reported in `Texture_segmentation_result::period`).
  double texel_period = 0;
  /// Vertices in a sample of the texture (about one texel): rings n = ⌈(√s − 1)/2⌉, those of a
  /// square patch of s vertices. Used when `rings` is 0 and this is positive.
  double sample_size = 0;
  /// Rings of each vertex its jet is fitted to (2 or more: a degree-2 jet needs 6 points).
  std::size_t fitting_rings = 2;
  /// Mean-shift windows: h_p on positions (model units), h_q on the curvature means and h_t on
  /// the curvature variances (both scale-free, see `segment_texture`). 0 picks each
  /// automatically: h_p = 4ρ (ρ = n mean edge lengths, the rings' radius), h_q and h_t half the
  /// 90th percentile of the vertices' distances from the median mean and from zero variance.
  double position_window = 0, mean_window = 0, variance_window = 0;
  /// A region is texture when its mean scale-free variance of the mean curvature, ρ²·D_H, exceeds
  /// this.
  double texture_threshold = 0.02;
  std::size_t max_iterations = 30;
  /// A mean-shift path stops once a step moves less than this fraction of each window.
  double convergence = 0.02;
  /// Vertices the mean shift's density estimate is taken from, at most (drawn at random, seeded;
  /// 0: all). Fewer is faster, but fewer than about 4000 makes region labels noticeably noisier.
  std::size_t max_samples = 16000;
  static constexpr std::size_t automatic = std::size_t(-1);
  /// Rings of the closing that joins texels into one texture (`automatic`: a closing by half the
  /// texel period (or by ρ when `rings` or `sample_size` set it) along the edges, which does not
  /// depend on how the surface is sampled).
  std::size_t closing_rings = automatic;
};

enum class Texture_segmentation_status {
  ok,
  empty_mesh,
  /// No vertex has the 6 points in its rings that a jet needs.
  no_curvature,
  /// A window or the threshold is negative or not finite.
  invalid_options
};

struct Texture_region {
  std::size_t vertices = 0;
  /// Means over the region's vertices of the scale-free variances ρ²·D_H and ρ⁴·D_K.
  double mean_curvature_variance = 0;
  double gaussian_curvature_variance = 0;
  bool texture = false;
};

struct Texture_segmentation_result {
  Texture_segmentation_status status = Texture_segmentation_status::ok;
  std::string message;
  /// The mean-shift modes, indexed by the region ids written per vertex.
  std::vector<Texture_region> regions;
  std::size_t texture_vertices = 0;
  /// ρ, the scale the features are measured at, and its value in mean edge lengths.
  std::size_t rings = 0;
  double ring_radius = 0;
  /// The texels' period found from the mean curvature's autocorrelation (whether or not ρ was
  /// set by the options).
  Texel_period period;
  /// Periods of coarser textures found among the pieces too small for `period` (texels of a
  /// texture that the closing at `period` left apart), each closed at its own period; shortest
  /// first.
  std::vector<double> coarser_periods;
  /// The windows used.
  double position_window = 0, mean_window = 0, variance_window = 0;
  explicit operator bool() const { return status == Texture_segmentation_status::ok; }
};

} // namespace tessera

#include <tessera/resizing/internal/texture_segmentation_impl.h>

namespace tessera {

/// Segments `tm` into regions of like geometric texture and marks the texture: writes each
/// vertex's region id (an index into `result.regions`) to `region` and whether it is texture to
/// `is_texture` (writable vertex maps of `std::size_t` and `bool`).
///
/// Named parameters: `vertex_point_map`, `vertex_index_map`.
template <typename TriangleMesh, typename VertexRegionMap, typename VertexTextureMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Texture_segmentation_result
segment_texture(const TriangleMesh& tm, VertexRegionMap region, VertexTextureMap is_texture,
                const Texture_segmentation_options& options = {},
                const NamedParameters& np = CGAL::parameters::default_values()) {
  return internal::segment_texture_impl(tm, region, is_texture, options, np);
}

} // namespace tessera
