// A field-aligned position field for the surface mosaic's first layout (after Jakob, Tarini,
// Panozzo, Sorkine-Hornung, "Instant Field-Aligned Meshes", SIGGRAPH Asia 2015, §4-§5): every
// vertex carries a point of a lattice of the tile spacing, oriented by the direction field at that
// vertex, and the lattices of neighbouring vertices are made to agree up to integer translations,
// from a coarse hierarchy of merged vertices down to the mesh. The lattice points that fall in
// each face are the tile centres: rows follow the field and meet only at defects. Arrays in, arrays
// out: compiled into Tessera::core.
#pragma once

#include <tessera/fields/internal/vertex_frames.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace tessera::internal {

/// The surface as the position field reads it: per vertex its point, normal and field direction
/// (any representative of the cross or line field, in the vertex's tangent plane or not); faces as
/// corner triples with their unit normals and regions (faces of different regions never share a
/// tile); and the edges tiles may not cross (feature lines and open borders) as vertex pairs.
struct Position_field_surface {
  std::vector<Vec3> points, normals, directions;
  std::vector<std::array<std::uint32_t, 3>> faces;
  std::vector<Vec3> face_normals;
  std::vector<std::uint32_t> face_regions;
  std::vector<std::array<std::uint32_t, 2>> feature_edges;
};

struct Position_field_options {
  /// Lattice spacings along the field direction and across it.
  double spacing_x = 1, spacing_y = 1;
  /// Symmetry of the direction field (4: cross field, 2: line field).
  int symmetry = 4;
  /// Edges longer than this are split first (a face's corners must agree on the lattice inside
  /// it), unless the surface would exceed `most_vertices`; 0 takes the smaller spacing. (At 0.7 of
  /// the spacing the 207k-triangle fandisk under 40k tiles was split into 217k vertices from 104k,
  /// and its start took 1.2 s longer; on the eight organic meshes at 3000 tiles a whole spacing
  /// gave coverage within ±0.006.) A solve with both spacings scaled (`rescale`) keeps this.
  double split_length = 0;
  std::size_t most_vertices = 4000000;
  /// Gauss-Seidel sweeps at each level of the hierarchy (coarsest first) and on the mesh itself.
  /// (With a hierarchy down to a few nodes, 4 sweeps on the mesh gave the eight organic meshes of
  /// doc/mosaic.md the coverage of 10 within ±0.003.)
  int sweeps_per_level = 5, sweeps_finest = 4;
  /// Seed of the coarsest level's random start: the lattice's phase.
  unsigned seed = 1;
  /// Called by `position_field_points` with the number of lattice points found: a factor other
  /// than 1 (and positive) solves the lattice again with both spacings times it, on the same
  /// refined surface and hierarchy, and returns that lattice's points instead (a count aimed at).
  std::function<double(std::size_t)> rescale;
};

struct Position_field_stats {
  /// Vertices after the long edges were split, and levels of the hierarchy above them.
  std::size_t vertices = 0, levels = 0;
  /// Lattice points found in the faces, and how many were dropped as duplicates of another one
  /// (where two faces or two lattices meet).
  std::size_t extracted = 0, merged = 0;
  double seconds_refine = 0, seconds_solve = 0, seconds_extract = 0;
  /// The factor `Position_field_options::rescale` returned (1 when none).
  double rescaled = 1;
};

/// One lattice point per vertex: the point of that vertex's lattice nearest to it.
std::vector<Vec3> solve_position_field(const Position_field_surface& surface,
                                       const Position_field_options& options,
                                       Position_field_stats* stats = nullptr);

/// A tile centre found by `position_field_points`: the input face it lies in and the point.
struct Lattice_point {
  std::uint32_t face = 0;
  Vec3 at;
};

/// Solves the position field and returns the lattice points inside the faces, one per lattice cell:
/// points of one region closer than half a cell to each other (seen in either's lattice) are
/// merged into the first.
std::vector<Lattice_point> position_field_points(const Position_field_surface& surface,
                                                 const Position_field_options& options,
                                                 Position_field_stats* stats = nullptr);

} // namespace tessera::internal
