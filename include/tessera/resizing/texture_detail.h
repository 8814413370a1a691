// Splitting a textured surface into a smooth base and a scalar detail (Chen and Meng, SPM 2009 and
// CAD 2010, §3.3): implicit fairing (Desbrun, Meyer, Schröder, Barr 1999), (I − λdt·L)X^{n+1} = X^n
// with λdt on the texture region and 0 elsewhere (eq. 4), smooths the texture away and leaves the
// rest of the surface where it is; by default with the bi-Laplacian in place of L, which keeps a
// curved base's curvature (see Fairing_operator). Optionally the faired vertices of a closed
// surface are rescaled about the centroid to keep its volume (conference eq. 4). The detail is each
// vertex's offset from the base along the base's normal (the conference version's displacement).
#pragma once

#include <tessera/internal/named_parameters.h>
#include <tessera/resizing/internal/fairing_impl.h>
#include <tessera/resizing/texture_segmentation.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <string>
#include <vector>

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
               const NamedParameters& np = CGAL::parameters::default_values()) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  const auto vpm = internal::vertex_point_map(tm, np);
  Detail_extraction_result result;
  if (faces(tm).empty()) {
    result.status = Detail_extraction_status::empty_mesh;
    result.message = "the mesh has no faces";
    return result;
  }
  // Unknowns: the texture vertices, in the order of vertices(tm).
  std::vector<vertex_descriptor> free;
  for (vertex_descriptor v : vertices(tm)) {
    put(base, v, get(vpm, v));
    put(height, v, 0.0);
    if (get(is_texture, v))
      free.push_back(v);
  }
  result.texture_vertices = free.size();
  if (free.empty()) {
    result.status = Detail_extraction_status::no_texture;
    result.message = "no vertex is marked as texture";
    return result;
  }
  double total_length = 0;
  for (auto e : edges(tm))
    total_length += PMP::edge_length(halfedge(e, tm), tm, CGAL::parameters::vertex_point_map(vpm));
  result.mean_edge_length = total_length / double(num_edges(tm));

  if (options.fairing == Fairing_operator::low_pass) {
    double period = options.texel_period;
    if (!(period > 0))
      period = estimate_texel_period(tm, np).period;
    if (!(period > 0)) {
      result.status = Detail_extraction_status::solve_failed;
      result.message = "no texel period could be found on the surface; give one "
                       "(Detail_extraction_options::texel_period)";
      return result;
    }
    result.texel_period = period;
    std::vector<double> plateau;
    if (!internal::low_pass_fairing(tm, vpm, base, free,
                                    options.low_pass_strength * std::pow(period / (2 * CGAL_PI), 4),
                                    plateau)) {
      result.status = Detail_extraction_status::solve_failed;
      result.message = "the fairing matrix could not be factored";
      return result;
    }
    result.iterations = 1;
    // A low pass keeps the texture's mean height: bumps on a plate leave the base raised by
    // their mean over the region, a plateau that falls to the plate at the region's border
    // (whose bend the resize's vulnerability then protects). The base is moved along its normal
    // so the median detail of each connected texture region's interior (where the plateau is
    // over 0.9) is 0: the base runs along the ground between bumps, or the top between grooves.
    internal::ground_base(tm, vpm, base, free, plateau);
  } else if (!internal::iterative_fairing(tm, vpm, base, free,
                                          options.fairing == Fairing_operator::laplacian, options,
                                          result)) {
    result.status = Detail_extraction_status::solve_failed;
    result.message = "the fairing matrix could not be factored";
    return result;
  }
  for (vertex_descriptor v : free) {
    const auto normal = PMP::compute_vertex_normal(v, tm, CGAL::parameters::vertex_point_map(base));
    const double h = CGAL::to_double((get(vpm, v) - get(base, v)) * normal);
    put(height, v, h);
    result.max_height = std::max(result.max_height, std::abs(h));
  }
  return result;
}

} // namespace tessera
