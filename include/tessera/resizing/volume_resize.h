// Non-homogeneous resizing of a volume mesh (after Kraevoy, Sheffer, Shamir, Cohen-Or,
// "Non-homogeneous resizing of complex models", SIGGRAPH Asia 2008): each tetrahedron is given a
// target deformation gradient, a stretch along the resized axes where the model is free and a
// uniform scale where it is vulnerable, and one Poisson solve per coordinate finds the positions.
// Compiled into Tessera::core.
#pragma once

#include <tessera/progress.h>
#include <tessera/resizing/tet_mesh.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace tessera {

struct Volume_resize_options {
  /// Target extent of the surface's bounding box along x, y, z, as a factor of the current one.
  std::array<double, 3> scale{{1, 1, 1}};
  /// μ: how strongly every tetrahedron of a resized axis is also pulled to the simple scaling's
  /// stretch along it (0: vulnerable parts keep their proportions as far as the rest allows).
  double anchor = 0;
  /// Tetrahedra count 1 + stiffness·max_d w_t,d times in the energy (d over the resized axes), so
  /// the free ones
  /// take up what cannot be met everywhere (the transition between stretched and rigid parts).
  double stiffness = 10;
  /// Alternations of the local step (each tetrahedron's uniform scale from the current solution)
  /// and the global solve; they stop earlier once no scale moves by more than `tolerance`.
  std::size_t iterations = 20;
  double tolerance = 1e-4;
  /// k: each free stretch a_d keeps |log a_d| ≤ k·|log s_d| (s_d the axis' scale), so a 2× resize
  /// stretches free tetrahedra at most 2^2.5 ≈ 5.7 times and a halving squeezes them to no less
  /// than 0.18 (never flat, never inverted). Where the free parts are too small to take a resize
  /// within that (a ring, a knot: curved everywhere), the vulnerabilities along d are weighed down
  /// by λ_d (`Volume_resize_result::vulnerability_weight`) until they can: the rest of the stretch
  /// is spread over the vulnerable parts, as simple scaling does at λ = 0. Must be at least 1.
  double max_free_stretch_exponent = 2.5;
  /// Called after each alternation, "volume iterations" done of at most `iterations`; the last
  /// call has done = total (they stop early).
  Progress_callback progress;
};

enum class Volume_resize_status {
  ok,
  /// The volume has no vertices, no tetrahedra or no surface vertices.
  empty_volume,
  /// The vulnerabilities are not one per volume vertex, or the volume's indices are out of range.
  invalid_input,
  /// A scale factor is not positive and finite, or the stiffness is negative or not finite.
  invalid_options,
  /// The volume's matrix could not be factored.
  solve_failed
};

struct Volume_resize_result {
  Volume_resize_status status = Volume_resize_status::ok;
  std::string message;
  /// New positions of the volume's vertices (the input's when the solve did not run).
  std::vector<std::array<double, 3>> points;
  /// The stretch a_d that free tetrahedra take along each axis so the targets are met.
  std::array<double, 3> free_stretch{{1, 1, 1}};
  /// λ_d: the factor the vulnerabilities along each axis were weighed by so that a_d stays within
  /// `Volume_resize_options::max_free_stretch_exponent` (1: the free parts took the resize alone).
  std::array<double, 3> vulnerability_weight{{1, 1, 1}};
  std::size_t iterations = 0;
  /// Tetrahedra left out of the energy for having no volume.
  std::size_t degenerate_tets = 0;
  std::string solver;
  explicit operator bool() const { return status == Volume_resize_status::ok; }
};

/// Resizes the volume `mesh` so that its surface's bounding box is `options.scale` times the
/// current one, with per-vertex, per-axis vulnerabilities `vulnerability[v][d]` in [0, 1].
///
/// Energy (the sum over tetrahedra t of volume V_t times Σ_{j,d} (F_t,jd − T_t,jd)²), with F_t
/// the deformation gradient and T_t = diag(τ_t,0, τ_t,1, τ_t,2) the target,
/// τ_t,d = ((1 − λ_d·w_t,d)·a_d + λ_d·w_t,d·σ_t + μ·s_d) / (1 + μ): a free tetrahedron (w = 0)
/// stretches by the global a_d, a vulnerable one (w = 1) scales uniformly by σ_t, the
/// vulnerability-weighted mean of its diagonal stretches, recomputed from each solve; μ pulls all
/// towards the simple scaling s_d; λ_d is 1 unless the free parts are too small
/// (`max_free_stretch_exponent`). The matrix (a volume Laplacian, stiffer where vulnerable) is the
/// same for the three coordinates and every iteration: it is factored once. Each a_d (and λ_d) is
/// found after each solve so the surface's extent along d meets its target (the solution is
/// affine in a_d and in λ_d). Targets have no rotation: parts are expected to keep their
/// orientation under a resize. Bad input (see `Volume_resize_status`) is refused before the solve.
Volume_resize_result resize_volume(const Tet_mesh& mesh,
                                   const std::vector<std::array<double, 3>>& vulnerability,
                                   const Volume_resize_options& options = {});

} // namespace tessera
