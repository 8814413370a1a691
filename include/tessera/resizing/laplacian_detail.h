// The journal version's detail of a geometric texture (Chen and Meng, CAD 2010, eqs. 5–6 and
// 10–11): the textured surface X over its base B as the difference of their Laplacian coordinates,
// δ = M⁻¹L(X − B) with the base's cotangent Laplacian L and vertex areas M, written in each
// vertex's frame on the base so that it turns with the base; and the surface rebuilt from such a
// detail on another base B' by one Poisson solve, L'X' = L'B' + M'R'δ, the vertices around the
// texture held where they are.
#pragma once

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <tessera/internal/named_parameters.h>

#include <array>
#include <cstddef>
#include <string>

namespace tessera {

/// How texture-preserving resizing carries the detail from the input to the changed base.
enum class Detail_representation {
  /// The conference version's scalar offset along the base's normal (texture_detail.h): the result
  /// is the changed base displaced by the synthesized detail along its normals.
  normal_displacement,
  /// The journal version's Laplacian coordinates in the base's frames (this header): the
  /// synthesis carries the three components of δ along with the scalar detail it matches on, and
  /// the result is the Poisson reconstruction from them.
  laplacian_coordinates
};

struct Laplacian_detail_options {
  /// The frames' first tangent axis: this direction projected into each tangent plane (as the
  /// synthesis' templates take it, `Texture_synthesis_options::reference_axis`).
  std::array<double, 3> reference_axis{{1, 0, 0}};
  /// Soft positional constraints of the reconstruction (model units; 0: none, the Poisson solve
  /// of eqs. 10–11 alone). With a wavelength w, the free vertices minimize
  /// Σ M⁻¹‖L X' − L B − M R δ‖² + μ Σ M ‖X' − A‖², μ = (2π/w)⁴, A the positions `out` holds for
  /// them: a wave of length λ of the result comes 1/(1 + (λ/w)⁴) from δ and the rest from A. A
  /// synthesized δ does not sum to 0 over a texel as a surface's does (the least-squares average
  /// and the fade towards the border break it), and the Poisson solve integrates that error into
  /// broad swells; the anchors take the long waves from elsewhere.
  double anchor_wavelength = 0;
};

enum class Laplacian_detail_status {
  ok,
  empty_mesh,
  /// `reconstruct_from_laplacian_detail`: no vertex is free.
  no_free_vertex,
  /// The Poisson system could not be factored: a connected group of free vertices holds no
  /// neighbour that is not free (a closed surface wholly free has no position to start from).
  solve_failed
};

struct Laplacian_detail_result {
  Laplacian_detail_status status = Laplacian_detail_status::ok;
  std::string message;
  /// Vertices with a nonzero detail (extraction) or solved for (reconstruction).
  std::size_t vertices = 0;
  /// Largest |δ| (extraction), in inverse model units: δ is a mean-curvature vector.
  double largest_detail = 0;
  explicit operator bool() const { return status == Laplacian_detail_status::ok; }
};

} // namespace tessera

#include <tessera/resizing/internal/laplacian_detail_impl.h>

namespace tessera {

/// Writes to `detail` (a writable vertex map of std::array<double, 3>) each vertex's Laplacian-
/// coordinate detail over the base `base` (a vertex map of points, the same connectivity):
/// δ = M⁻¹L(X − B), L the cotangent Laplacian and M the lumped vertex areas of the base, as its
/// components along the base's vertex normal, the reference axis projected into the tangent
/// plane, and their cross product (eqs. 5–6). 0 where the surface and its base agree around the
/// vertex.
///
/// Named parameters: `vertex_point_map` (the textured surface X).
template <typename TriangleMesh, typename BasePointMap, typename DetailMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Laplacian_detail_result
extract_laplacian_detail(const TriangleMesh& tm, BasePointMap base, DetailMap detail,
                         const Laplacian_detail_options& options = {},
                         const NamedParameters& np = CGAL::parameters::default_values()) {
  const auto vpm = internal::vertex_point_map(tm, np);
  return internal::extract_laplacian_detail_impl(tm, vpm, base, detail, options);
}

/// Rebuilds a textured surface over the base `base` from its Laplacian-coordinate detail `detail`
/// (as `extract_laplacian_detail` writes it, in the frames of this base): the vertices where
/// `is_free` is true get the positions X' that solve L X' = L B + M R δ (eqs. 10–11; L, M and the
/// frames R of the base), written to `out` (a read-write vertex map of points); every other vertex
/// keeps the position `out` holds for it, a boundary condition (with `anchor_wavelength`, the
/// positions `out` holds for the free vertices are their soft constraints). On the base a surface
/// was extracted from, with the other vertices at their own positions, this gives the surface
/// back.
template <typename TriangleMesh, typename FreeMap, typename BasePointMap, typename DetailMap,
          typename OutPointMap>
Laplacian_detail_result
reconstruct_from_laplacian_detail(const TriangleMesh& tm, FreeMap is_free, BasePointMap base,
                                  DetailMap detail, OutPointMap out,
                                  const Laplacian_detail_options& options = {}) {
  return internal::reconstruct_from_laplacian_detail_impl(tm, is_free, base, detail, out, options);
}

} // namespace tessera
