// Topological and geometric summary of a surface mesh: counts, connected components, boundary
// loops, Euler characteristic and genus per component, triangle-ness, self-intersection, area,
// bounding box. This is what `tessera info` prints and what the tests use to check generated and
// cut surfaces.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace tessera {

/// Invariants of one connected component.
struct Component_info {
  std::size_t vertices = 0;
  std::size_t edges = 0;
  std::size_t faces = 0;
  std::size_t boundary_loops = 0;
  /// V - E + F.
  long euler_characteristic = 0;
  /// (2 - chi - b) / 2 of an orientable surface with b boundary loops.
  long genus = 0;
  double area = 0;
};

/// Options of `mesh_info()`.
struct Mesh_info_options {
  /// Self-intersection test (an AABB-tree query; the costliest part on large meshes).
  bool check_self_intersection = true;
};

/// Result of `mesh_info()`.
struct Mesh_info {
  std::size_t vertices = 0;
  std::size_t edges = 0;
  std::size_t faces = 0;
  std::size_t boundary_loops = 0;
  long euler_characteristic = 0;
  std::vector<Component_info> components;
  bool is_valid_polygon_mesh = false;
  bool is_triangle_mesh = false;
  bool is_closed = false;
  /// Meaningful only when the self-intersection test was run.
  bool self_intersects = false;
  bool self_intersection_checked = false;
  double area = 0;
  std::array<double, 3> bbox_min{{0, 0, 0}};
  std::array<double, 3> bbox_max{{0, 0, 0}};
};

/// Computes the summary of `tm`, a valid polygon mesh (triangulated or not; area and
/// self-intersection are computed only for triangle meshes).
template <typename PolygonMesh>
Mesh_info mesh_info(const PolygonMesh& tm, const Mesh_info_options& options = {});

} // namespace tessera

#include <tessera/validation/internal/mesh_info_impl.h>
