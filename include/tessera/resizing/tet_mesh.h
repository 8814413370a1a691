// Volume meshes for resizing (Kraevoy et al., "Non-homogeneous resizing of complex models", 2008,
// deform a volume around the model rather than its surface): a TetGen tetrahedralization of a
// closed surface's interior whose first vertices are the surface's own, or, for bordered and open
// input, a regular grid of tetrahedra around the model (Kraevoy's protective grid) in which every
// surface vertex is embedded by barycentric coordinates. Compiled into Tessera::core (TetGen is
// private).
#pragma once

#include <CGAL/Bbox_3.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace tessera {

/// A tetrahedral mesh. Either the surface's vertices are its first `surface_vertices` points
/// (TetGen) or each surface vertex i lies in tetrahedron `embedding_tet[i]` at barycentric
/// coordinates `embedding_weights[i]` (grid); `embedded()` tells which.
struct Tet_mesh {
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 4>> tets;
  std::size_t surface_vertices = 0;
  std::vector<std::size_t> embedding_tet;
  std::vector<std::array<double, 4>> embedding_weights;

  bool embedded() const { return !embedding_tet.empty(); }
  /// Values at the surface vertices of a quantity given per volume vertex (`volume_values[v]`),
  /// interpolated in the embedding tetrahedra when the surface is embedded.
  std::vector<double> surface_values(const double* volume_values) const;
  /// Positions of the surface vertices for volume positions `volume_points`.
  std::vector<std::array<double, 3>>
  surface_positions(const std::vector<std::array<double, 3>>& volume_points) const;
  /// Signed volume of tetrahedron t (positive for the orientation this mesh uses).
  double tet_volume(std::size_t t) const;
};

enum class Tetrahedralize_status {
  ok,
  empty_input,
  /// Not a closed surface: a border, or not every face a triangle.
  not_closed,
  /// Faces intersect; TetGen would fail or crash on them.
  self_intersecting,
  /// TetGen gave up (its error code is in the message).
  tetgen_failed
};

struct Tetrahedralize_options {
  /// TetGen's radius-edge bound (its `q` switch, e.g. 1.414). 0, the default, keeps the
  /// constrained Delaunay tetrahedralization of the surface's own vertices: no Steiner points,
  /// half TetGen's time, and for resizing the better result (a tetrahedron then spans a part
  /// from wall to wall, so a rigid part moves as one).
  double radius_edge_ratio = 0;
  /// Largest tetrahedron volume (TetGen's `a` switch); 0 for no bound.
  double max_volume = 0;
  /// Each point is moved by at most this fraction of the bounding box's diagonal along each axis
  /// (a fixed pseudo-random offset per point) before TetGen sees it, and the volume mesh keeps
  /// the moved points. It breaks the ties of regular surfaces, whose many points on common spheres
  /// make TetGen's exact tests slow; TetGen's mesh optimization then runs one pass of flips.
  /// Smaller perturbations leave thinner slivers, which the resizing solve takes worse (the
  /// measurements are in doc/resizing.md). 0 gives TetGen the points as they are.
  double perturbation = 1e-7;
};

struct Tetrahedralize_result {
  Tetrahedralize_status status = Tetrahedralize_status::ok;
  std::string message;
  Tet_mesh mesh;
  explicit operator bool() const { return status == Tetrahedralize_status::ok; }
};

/// The bounding box of `points` (an empty box for no points).
CGAL::Bbox_3 bounding_box(const std::vector<std::array<double, 3>>& points);

/// Tetrahedralizes the interior of the closed triangle surface (`points`, `triangles`) with TetGen,
/// keeping the surface's triangles (switch `Y`): the result's first `points.size()` vertices are
/// the surface's, in order, moved by `options.perturbation` at most. The caller checks closedness
/// and self-intersections (`tetrahedralize()` in resize.h does); TetGen's own failures come back as
/// `tetgen_failed`, never as a crash.
Tetrahedralize_result
tetrahedralize_surface(const std::vector<std::array<double, 3>>& points,
                       const std::vector<std::array<std::size_t, 3>>& triangles,
                       const Tetrahedralize_options& options = {});

struct Grid_tet_mesh_options {
  /// Cells along the bounding box's longest side; the others get as many as keep cells cubic.
  std::size_t resolution = 24;
  /// Margin around the bounding box, in cells.
  double margin = 0.5;
};

/// Kraevoy's protective grid: a regular grid of cubes around `points`, each split into six
/// tetrahedra (Kuhn's subdivision, conforming across cells), with every point embedded.
Tet_mesh grid_tet_mesh(const std::vector<std::array<double, 3>>& points,
                       const Grid_tet_mesh_options& options = {});

/// Per-volume-vertex values from per-surface-vertex values: surface vertices of a TetGen mesh keep
/// theirs; every other volume vertex takes the value of the nearest surface vertex (CGAL kd-tree),
/// scaled by `max(0, 1 − d/falloff)` at distance d when `falloff` > 0 (so grid vertices far from
/// the model get 0).
std::vector<std::array<double, 3>>
carry_to_volume(const Tet_mesh& mesh, const std::vector<std::array<double, 3>>& surface_points,
                const std::vector<std::array<double, 3>>& surface_values, double falloff = 0);

} // namespace tessera
