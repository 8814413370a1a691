// Resizing a triangle mesh along chosen axes: simple scaling, or non-homogeneous resizing (Kraevoy,
// Sheffer, Shamir, Cohen-Or, SIGGRAPH Asia 2008) that lets straight, axis-parallel parts take the
// stretch and keeps curved parts in proportion. The surface is embedded in a volume (TetGen for
// closed surfaces, the protective grid otherwise), the volume is resized, the surface follows.
#pragma once

#include <tessera/internal/named_parameters.h>
#include <tessera/resizing/tet_mesh.h>
#include <tessera/resizing/volume_resize.h>
#include <tessera/resizing/vulnerability.h>

#include <array>
#include <cstddef>
#include <string>

namespace tessera {

enum class Resize_method {
  /// Coordinates multiplied by the scale factors: round parts become ellipsoids.
  simple,
  /// Kraevoy et al.'s: stretch where the model is free, uniform scale where it is vulnerable.
  nonhomogeneous
};

/// The volume the surface is resized in.
enum class Resize_volume {
  /// TetGen for closed surfaces, the grid otherwise.
  automatic,
  /// The surface's interior by TetGen; needs a closed surface without self-intersections.
  tetgen,
  /// Kraevoy's protective grid around the model; works for any surface.
  grid
};

struct Resize_options {
  /// Target size of the bounding box along x, y, z as a factor of the current one.
  std::array<double, 3> scale{{1, 1, 1}};
  Resize_method method = Resize_method::nonhomogeneous;
  Resize_volume volume = Resize_volume::automatic;
  /// Factor on every vulnerability (0 gives the simple scaling's shape back, through the volume).
  double vulnerability_weight = 1;
  Vulnerability_options vulnerability;
  Tetrahedralize_options tetrahedralize;
  Grid_tet_mesh_options grid;
  /// Anchor μ, iterations and tolerance of the solve (its `scale` is set from `scale`).
  Volume_resize_options solve;
};

enum class Resize_status {
  ok,
  empty_mesh,
  /// A scale factor is not positive and finite.
  invalid_scale,
  /// An option of the vulnerability or of the solve is out of range (the message says which).
  invalid_options,
  /// The TetGen volume was asked for a surface that is not closed.
  not_closed,
  self_intersecting,
  tetgen_failed,
  /// The volume could not be solved: its matrix could not be factored (or it was empty).
  solve_failed
};

struct Resize_result {
  Resize_status status = Resize_status::ok;
  std::string message;
  Resize_volume volume = Resize_volume::automatic;
  std::size_t volume_vertices = 0;
  std::size_t tetrahedra = 0;
  std::size_t iterations = 0;
  std::array<double, 3> free_stretch{{1, 1, 1}};
  /// Per axis, the factor the vulnerabilities were weighed by because the free parts alone could
  /// not take the resize (`Volume_resize_options::max_free_stretch_exponent`); 1 when they could.
  std::array<double, 3> vulnerability_weight{{1, 1, 1}};
  std::array<double, 3> extent_before{{0, 0, 0}};
  std::array<double, 3> target_extent{{0, 0, 0}};
  std::array<double, 3> extent_after{{0, 0, 0}};
  Vulnerability_result vulnerability;
  std::string solver;
  /// Wall-clock seconds: the vulnerability, the volume mesh (its TetGen part overlaps the
  /// vulnerability, on another thread, and is counted from the same start), the solve.
  double vulnerability_seconds = 0, volume_seconds = 0, solve_seconds = 0;
  explicit operator bool() const { return status == Resize_status::ok; }
};

/// Tetrahedralizes the interior of a closed triangle mesh with TetGen, after checking what would
/// make TetGen fail or crash: a border, a face that is not a triangle, a self-intersection
/// (`CGAL::Polygon_mesh_processing::does_self_intersect`). The volume's first vertices are the
/// mesh's, in the order of `vertices(tm)`.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Tetrahedralize_result
tetrahedralize(const TriangleMesh& tm, const Tetrahedralize_options& options = {},
               const NamedParameters& np = CGAL::parameters::default_values());

/// Resizes `tm` in place (its `vertex_point_map`) so its bounding box becomes `options.scale`
/// times the current one, writing each vertex's vulnerability along x, y, z into `vulnerability`
/// (a vertex property map of `std::array<double, 3>`; zeros for the simple method). On failure
/// the mesh is left as it was.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh, typename VulnerabilityMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Resize_result resize(TriangleMesh& tm, VulnerabilityMap vulnerability,
                     const Resize_options& options = {},
                     const NamedParameters& np = CGAL::parameters::default_values());

/// Scale factors for `Resize_options::scale` that give a mesh's bounding box chosen extents.
struct Scale_for_extents_result {
  /// `invalid_scale` when an extent is not positive and finite or the mesh is flat along an axis
  /// given an extent (the message names the axis); `empty_mesh` without vertices.
  Resize_status status = Resize_status::ok;
  std::string message;
  std::array<double, 3> scale{{1, 1, 1}};
  explicit operator bool() const { return status == Resize_status::ok; }
};

/// The factors by which `tm`'s bounding box (`CGAL::Polygon_mesh_processing::bbox`) becomes
/// `extents` along x, y and z: what `tessera resize --size X,Y,Z` resizes by.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Scale_for_extents_result
scale_for_extents(const TriangleMesh& tm, const std::array<double, 3>& extents,
                  const NamedParameters& np = CGAL::parameters::default_values());

/// As above, with the vulnerability in a scratch map.
template <typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Resize_result resize(TriangleMesh& tm, const Resize_options& options = {},
                     const NamedParameters& np = CGAL::parameters::default_values());

} // namespace tessera

#include <tessera/resizing/internal/resize_impl.h>
