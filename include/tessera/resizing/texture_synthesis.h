// Re-synthesizing a scalar geometric texture on a new base surface from a sample (Chen and Meng
// 2010 §3.4–3.5): neighbourhood templates after Wei and Levoy, each vertex's nearby triangles
// projected into its tangent frame and the detail resampled on a square grid of spacing d = √(2A);
// synthesis by expectation–maximization as in texture optimization (Kwatra et al. 2005, Han et al.
// 2006): from random details, alternate the nearest sample template of every target template
// (CGAL's kd-tree on principal components of the templates) and the least-squares details that
// best agree with all of them (eq. 8), the untextured neighbours held at their details.
#pragma once

#include <tessera/progress.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace tessera {

struct Texture_synthesis_options {
  /// Grid spacing d of the templates; 0: √(2A), A the sample region's mean triangle area (§3.4).
  double grid_spacing = 0;
  /// Template half width in grid steps (a template has (2r + 1)² samples); 0: enough to span
  /// 1.2 texel periods.
  std::size_t template_radius = 0;
  /// The texels' period in model units (`estimate_texel_period`). The templates span 1.2 times
  /// the longer of it and √(area / texels) of the sample's texture region (its texels counted
  /// above a quarter of its largest detail).
  double texel_period = 0;
  /// E–M iterations per level (the papers use 25–30 in all); a level stops earlier once at most
  /// 2 % of the templates change their match.
  std::size_t iterations = 30;
  /// Levels of the coarse-to-fine synthesis: level k samples its templates at spacing 2^k·d.
  std::size_t levels = 2;
  /// Called after each E–M iteration, "synthesis iterations" done of at most levels · iterations;
  /// the last call has done = total (levels stop early).
  Progress_callback progress;
  /// Principal components the templates are reduced to for the nearest-neighbour search.
  std::size_t search_dimensions = 12;
  /// The templates' first axis: this direction projected into each tangent plane (the next
  /// coordinate axis where it is almost normal to the surface). Sample and target share it, so
  /// the texture keeps its orientation.
  std::array<double, 3> reference_axis{{1, 0, 0}};
  unsigned random_seed = 1;
  /// Width (model units) over which the synthesized details fade to 0 towards the region's
  /// border, so texels the border cuts leave no fragments; 0: none.
  double border_fade = 0;
  /// After each level, give the synthesized details the sample's distribution of details
  /// (histogram matching, Kopf et al. 2007), which the least-squares averaging flattens; the
  /// distribution is read over the sample region but its outermost `border_fade`.
  bool match_histogram = true;
  /// Weight of the region's outline in the match, relative to the sample's largest detail. Each
  /// template also carries, per grid sample, whether it lies in the texture region, so a target
  /// template that reaches past the region's border is matched with a sample template that meets
  /// its border alike, and the texels keep the sample's phase against the border (a guidance
  /// channel, as in Hertzmann et al. 2001's texture by numbers). 0: only templates wholly inside
  /// the region are sampled, and the synthesis does not see the border.
  double border_guidance = 1;
};

enum class Texture_synthesis_status {
  ok,
  /// The sample has no texture vertex with a complete template.
  empty_sample,
  /// The target has no texture vertex.
  empty_target,
  solve_failed
};

struct Texture_synthesis_result {
  Texture_synthesis_status status = Texture_synthesis_status::ok;
  std::string message;
  double grid_spacing = 0;
  std::size_t template_radius = 0;
  std::size_t sample_templates = 0;
  std::size_t target_vertices = 0;
  std::size_t iterations = 0;
  /// Root-mean-square difference between the target's templates and their matches at the end, per
  /// grid sample, in the detail's units.
  double rms_mismatch = 0;
  explicit operator bool() const { return status == Texture_synthesis_status::ok; }
};

} // namespace tessera

#include <tessera/resizing/internal/texture_synthesis_impl.h>

namespace tessera {

/// Synthesizes on the texture vertices of `target` (where `target_region` is true; their details
/// are written to `target_height`, the other vertices' details read from it and held) a detail that
/// looks everywhere like the detail `sample_height` of `sample` on its texture vertices
/// (`sample_region`). Both meshes are base surfaces: the detail is a displacement along their
/// normals. Templates measure in the meshes' own units, so the texture keeps its size on a resized
/// target.
///
/// Named parameters (`np_sample`, `np_target`): `vertex_point_map`.
template <typename SampleMesh, typename SampleRegionMap, typename SampleHeightMap,
          typename TargetMesh, typename TargetRegionMap, typename TargetHeightMap,
          typename SampleNamedParameters = CGAL::parameters::Default_named_parameters,
          typename TargetNamedParameters = CGAL::parameters::Default_named_parameters>
Texture_synthesis_result
synthesize_texture(const SampleMesh& sample, SampleRegionMap sample_region,
                   SampleHeightMap sample_height, const TargetMesh& target,
                   TargetRegionMap target_region, TargetHeightMap target_height,
                   const Texture_synthesis_options& options = {},
                   const SampleNamedParameters& np_sample = CGAL::parameters::default_values(),
                   const TargetNamedParameters& np_target = CGAL::parameters::default_values()) {
  return internal::synthesize_texture_impl(sample, sample_region, sample_height, target,
                                           target_region, target_height, options, np_sample,
                                           np_target);
}

/// As `synthesize_texture`, and carries a vector detail along (three numbers per vertex, such as
/// the Laplacian coordinates of laplacian_detail.h): the target's texture vertices get the
/// vectors `target_vectors` that agree best with those of the sample templates the finest level
/// matched last (matched on the scalar detail), averaged as eq. 8 averages the scalar detail and
/// faded towards the region's border alike; the other vertices' vectors are read from
/// `target_vectors` and held. The vector maps are vertex maps of std::array<double, 3>.
///
/// Named parameters (`np_sample`, `np_target`): `vertex_point_map`.
template <typename SampleMesh, typename SampleRegionMap, typename SampleHeightMap,
          typename SampleVectorMap, typename TargetMesh, typename TargetRegionMap,
          typename TargetHeightMap, typename TargetVectorMap,
          typename SampleNamedParameters = CGAL::parameters::Default_named_parameters,
          typename TargetNamedParameters = CGAL::parameters::Default_named_parameters>
Texture_synthesis_result synthesize_texture_with_vectors(
    const SampleMesh& sample, SampleRegionMap sample_region, SampleHeightMap sample_height,
    SampleVectorMap sample_vectors, const TargetMesh& target, TargetRegionMap target_region,
    TargetHeightMap target_height, TargetVectorMap target_vectors,
    const Texture_synthesis_options& options = {},
    const SampleNamedParameters& np_sample = CGAL::parameters::default_values(),
    const TargetNamedParameters& np_target = CGAL::parameters::default_values()) {
  std::vector<std::array<double, 3>> from, to;
  for (auto v : vertices(sample))
    from.push_back(get(sample_vectors, v));
  for (auto v : vertices(target))
    to.push_back(get(target_vectors, v));
  const Texture_synthesis_result result =
      internal::synthesize_texture_impl(sample, sample_region, sample_height, target, target_region,
                                        target_height, options, np_sample, np_target, &from, &to);
  if (result) {
    std::size_t i = 0;
    for (auto v : vertices(target))
      put(target_vectors, v, to[i++]);
  }
  return result;
}

} // namespace tessera
