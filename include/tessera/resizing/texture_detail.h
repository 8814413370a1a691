// Splitting a textured surface into a smooth base and a scalar detail (Chen and Meng, SPM 2009 and
// CAD 2010, §3.3): implicit fairing (Desbrun, Meyer, Schröder, Barr 1999), (I − λdt·L)X^{n+1} = X^n
// with λdt on the texture region and 0 elsewhere (eq. 4), smooths the texture away and leaves the
// rest of the surface where it is; by default with the bi-Laplacian in place of L, which keeps a
// curved base's curvature (see Fairing_operator). Optionally the faired vertices of a closed
// surface are rescaled about the centroid to keep its volume (conference eq. 4). The detail is each
// vertex's offset from the base along the base's normal (the conference version's displacement).
#pragma once

#include <tessera/internal/named_parameters.h>

#include <CGAL/Named_function_parameters.h>

#include <cstddef>
#include <string>

namespace tessera {

/// The fairing operator.
enum class Fairing_operator {
  /// Eq. 4 as published, (I − λdt·L)X^{n+1} = X^n with the umbrella operator L: mean-curvature
  /// flow, which also flattens a curved base towards the membrane spanning the region's border (a
  /// bumpy patch of a cylinder of radius 1 loses a tenth of its sagitta per few iterations).
  laplacian,
  /// (I + λdt·L²)X^{n+1} = X^n: thin-plate fairing. A frequency with umbrella eigenvalue μ is
  /// damped by 1/(1 + λdt·μ²) instead of 1/(1 + λdt·μ), so texels (μ ~ 0.5) go as fast while the
  /// base's curvature (μ ~ 0.01) stays: a cylinder keeps its radius, a sphere its roundness.
  /// The umbrella weights make it follow the sampling: on a grid with cells twice as long in y as
  /// in x it fairs y twice as far, and round bumps come out of it as ellipses (aspect 1.4).
  /// It stops on `tolerance` long before its limit, so a broad region keeps a dome.
  bilaplacian,
  /// One solve of (M + λ·L M⁻¹ L) X = M X⁰: thin-plate smoothing with the cotangent Laplacian L
  /// and the vertices' areas M, which measure the surface itself, not its sampling. A wave of
  /// length w is damped by 1/(1 + c·(P/w)⁴) with λ = c·(P/2π)⁴ from the texel period P: the
  /// texels (w ≤ P) to at most 1/(1 + c), a base curved over 8P by under 2.5 % (c = 100).
  low_pass
};

struct Detail_extraction_options {
  Fairing_operator fairing = Fairing_operator::low_pass;
  /// `low_pass`: the texels' period P in model units (0: found on the surface by
  /// `estimate_texel_period`) and c, how strongly a wave of length P is damped (1/(1 + c)).
  double texel_period = 0;
  double low_pass_strength = 300;
  /// λ·dt of eq. 4 on texture vertices (0 elsewhere, so untextured vertices stay put).
  double lambda_dt = 10;
  std::size_t max_iterations = 200;
  /// Stop once no vertex moved more than this fraction of the mean edge length in an iteration.
  double tolerance = 1e-3;
  /// On closed surfaces, rescale the faired vertices about the centroid after each iteration so
  /// the enclosed volume stays the input's (conference eq. 4). Off by default: when the texture
  /// covers part of the surface, rescaling that part about the centroid lifts it off the rest
  /// (a step at the region's border), and the detail keeps the texels' volume anyway.
  bool preserve_volume = false;
};

enum class Detail_extraction_status {
  ok,
  empty_mesh,
  /// No vertex is marked as texture.
  no_texture,
  /// The fairing matrix could not be factored.
  solve_failed
};

struct Detail_extraction_result {
  Detail_extraction_status status = Detail_extraction_status::ok;
  std::string message;
  std::size_t iterations = 0;
  std::size_t texture_vertices = 0;
  /// Largest |detail| over the texture vertices, and the mean edge length it is measured against.
  double max_height = 0;
  double mean_edge_length = 0;
  /// `low_pass`: the texel period used (given or found).
  double texel_period = 0;
  /// Enclosed volume of the base over the input's (1 when kept, or for bordered surfaces).
  double volume_ratio = 1;
  explicit operator bool() const { return status == Detail_extraction_status::ok; }
};

/// Fairs the texture region of `tm` (vertices where `is_texture` is true) into a base surface
/// written to `base` (a writable vertex map of the mesh's point type), and writes each vertex's
/// detail, its offset from the base along the base's vertex normal, to `height` (a writable vertex
/// map of double; 0 off the texture). `tm` itself is not changed; base and input share
/// connectivity.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh, typename VertexTextureMap, typename BasePointMap,
          typename HeightMap, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Detail_extraction_result
extract_detail(const TriangleMesh& tm, VertexTextureMap is_texture, BasePointMap base,
               HeightMap height, const Detail_extraction_options& options = {},
               const NamedParameters& np = CGAL::parameters::default_values());

} // namespace tessera

#include <tessera/resizing/internal/texture_detail_impl.h>
