// The smoothest n-direction field (n = 1, 2, 4) with hard and soft constraints by one sparse
// Cholesky solve: Knöppel, Crane, Pinkall, Schröder, "Globally optimal direction fields" (2013) —
// the power representation u = |X| e^{inψ} and the connection Laplacian — with constraints as in
// Directional's power fields (hard ones eliminated, soft ones as weighted terms). It replaces eq. 1
// of Lai et al.
#pragma once

#include <tessera/fields/internal/power_field.h>
#include <tessera/fields/tangent_field.h>

#include <CGAL/boost/graph/helpers.h>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/Sparse>
#ifdef TESSERA_HAS_CHOLMOD
#include <Eigen/CholmodSupport>
#else
#include <Eigen/SparseCholesky>
#endif

#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <memory>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

namespace tessera {

/// Options of `smoothest_field()` and `Smoothest_field_solver`.
struct Smoothest_field_options {
  /// Symmetry order n: 1, 2 or 4.
  int symmetry = 4;
  /// Write unit vectors (true) or the minimiser's vectors, whose length |u| shrinks where the field
  /// must turn a lot (false; zero where the direction is undefined either way).
  bool normalize = true;
  /// Inverse power iterations for the unconstrained smoothest field (Knöppel et al. Alg. 1), at
  /// most.
  std::size_t eigen_iterations = 50;
  /// They stop once an iteration turns the field by less than this: 1 − |⟨u_k, u_k+1⟩_M| with
  /// unit mass norms, about half the squared (mass-weighted, radian) turn. At 1e-8 the 207k-face
  /// fandisk stops after 19 solves instead of 37 at 1e-12, its energy the same to 7 digits and
  /// its vectors 0.016° apart on average (3.3° at most, next to a singularity, where the
  /// direction is least defined).
  double eigen_tolerance = 1e-8;
  /// With soft constraints that hold nearly every free vertex (a soft weight of at least
  /// `held_weight` at 99 % of them, as `thin_part_constraints_holding()` gives), solve by
  /// conjugate gradients started from the previous solve's field instead of factorizing: the soft
  /// terms bound the system's condition number (about 2 / held_weight), so it converges in some
  /// tens of sparse products. Falls back to the factorization when it does not reach
  /// `iterative_tolerance` within `iterative_iterations`. (The 207k-face fandisk's turn along its
  /// thin parts: 0.5 s by a numeric factorization, 0.1 s this way.)
  bool iterative_when_held = true;
  double held_weight = 0.01;
  /// Relative residual |b − Ax| / |b| at which the conjugate gradients stop, and their cap.
  double iterative_tolerance = 1e-10;
  std::size_t iterative_iterations = 500;
};

/// Summary of a smoothest-field solve.
struct Smoothest_field_result {
  Field_status status = Field_status::ok;
  std::string message;
  /// Smoothness energy Σ_edges w_ij |u_j − r_ij u_i|² of the minimiser (before normalization),
  /// w_ij = 1 / edge length (the weights of Lai et al. eq. 1), r_ij the transport (see
  /// `field_energy`); without the edges left out at line ends (the solver's
  /// `edge_is_constrained_map`).
  double energy = 0;
  std::size_t hard_constraints = 0;
  std::size_t soft_constraints = 0;
  /// True when this solve factorized the matrix; false when it reused the previous factorization.
  bool factorized = false;
  /// True when it factorized on the previous solve's ordering and symbolic analysis (the same
  /// hard-constrained vertices: the matrix kept its sparsity pattern, only soft weights changed).
  bool analysis_reused = false;
  /// Inverse power iterations run (the unconstrained field; 0 with constraints).
  std::size_t eigen_iterations = 0;
  /// Conjugate-gradient iterations run (see `Smoothest_field_options::iterative_when_held`; 0
  /// when the solve did not try them).
  std::size_t iterative_iterations = 0;
  /// "CHOLMOD", "Eigen SimplicialLDLT" or, when the conjugate gradients solved it,
  /// "Eigen ConjugateGradient".
  std::string solver;
  explicit operator bool() const { return status == Field_status::ok; }
};

/// The smoothness energy of `field` (any vertex map of vectors) as a symmetry-n field: the vectors
/// are taken to power vectors |X| e^{inψ} and Σ_edges w_ij |u_j − r_ij u_i|² is returned, w_ij =
/// 1/|e_ij|.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh, typename VertexFieldMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
double field_energy(const TriangleMesh& tm, const VertexFieldMap& field, int symmetry,
                    const NamedParameters& np = CGAL::parameters::default_values()) {
  const internal::Vertex_frames<TriangleMesh> frames(tm, np);
  return internal::power_field_energy(frames, internal::power_vectors(frames, field, symmetry),
                                      symmetry);
}

/// Reusable solver: the connection Laplacian is built once; the Cholesky factorization is redone
/// only when the set of constrained vertices or the soft weights change, so new constraint values
/// (moving a control direction, switching parallel/perpendicular alignment) cost two triangular
/// solves; new soft weights on the same hard vertices cost a numeric factorization on the kept
/// ordering and symbolic analysis, unless soft weights hold nearly every vertex: then conjugate
/// gradients from the previous field solve it (`Smoothest_field_options::iterative_when_held`).
/// Like CGAL's `Surface_mesh_geodesic_distances_3`, the mesh must outlive the solver and not
/// change.
template <typename TriangleMesh> class Smoothest_field_solver {
public:
  using Frames = internal::Vertex_frames<TriangleMesh>;
  using vertex_descriptor = typename Frames::vertex_descriptor;
  using Vector_3 = typename Frames::Vector_3;
  using Constraint = Direction_constraint<vertex_descriptor, Vector_3>;

  /// Named parameters: `vertex_point_map`, and `edge_is_constrained_map`: the edges of feature
  /// lines (a CAD part's creases, borders). Where such lines end or meet (a vertex on one, three
  /// or more of those edges: a box's corner), the vertex's intrinsic frame squeezes or stretches
  /// the corners' angles to a full turn, so the transport through it from one face to another
  /// turns the field by up to a third of a right angle; the field's smoothness then pulls that
  /// into the flat faces around, which the lines' own constraints do not hold (on CGAL's oblong,
  /// 1° median and up to 8° off its flat faces' edges). With the map, the edges from such a vertex
  /// that are not on a line are left out of the energy: each face beside it then takes its field
  /// from its own lines (exactly along a rectangle's edges), as if the mesh were cut along the
  /// lines. The vertex itself keeps its line edges.
  template <typename NamedParameters = CGAL::parameters::Default_named_parameters>
  explicit Smoothest_field_solver(const TriangleMesh& tm,
                                  const Smoothest_field_options& options = {},
                                  const NamedParameters& np = CGAL::parameters::default_values())
      : tm_(tm), options_(options), frames_(tm, np) {
    if constexpr (!CGAL::parameters::is_default_parameter<
                      NamedParameters, CGAL::internal_np::edge_is_constrained_t>::value)
      leave_out_edges_at_line_ends(
          CGAL::parameters::get_parameter(np, CGAL::internal_np::edge_is_constrained));
    if (is_valid_symmetry(options.symmetry))
      build_laplacian();
  }

  /// Solves for the smoothest field meeting `constraints` and writes it into `field` (a writable
  /// vertex property map of `Vector_3`). Without any constraint the result is the globally
  /// smoothest field (the smallest eigenvector of the connection Laplacian, Knöppel et al. Alg. 1).
  template <typename VertexFieldMap>
  Smoothest_field_result solve(const std::vector<Constraint>& constraints, VertexFieldMap field);

  /// Number of Cholesky factorizations done so far.
  std::size_t number_of_factorizations() const { return factorizations_; }

  /// Edges the energy leaves out (see the constructor's `edge_is_constrained_map`).
  std::size_t number_of_edges_left_out() const { return left_out_count_; }

private:
  // Marks, in `left_out_` (by the order of edges(tm_)), the edges not in `is_line` from a vertex
  // on 1 or 3+ edges of `is_line`.
  template <typename EdgeIsConstrainedMap> void leave_out_edges_at_line_ends(EdgeIsConstrainedMap);
  // The connection Laplacian (its lower triangle and diagonal), the lumped masses and the shift.
  void build_laplacian();

  // The system of the free vertices: the free block of the Laplacian plus the soft terms (its
  // lower triangle) and its coupling to the fixed (hard-constrained) vertices.
  struct Free_system {
    std::vector<std::size_t> free, fixed;
    internal::Complex_sparse matrix, coupling;
  };
  // Splits the vertices into free and fixed ones and assembles that system. Free vertices keep
  // their order, so the block's lower triangle is copied column by column.
  Free_system free_system(const std::vector<char>& hard,
                          const std::vector<double>& soft_weight) const;
  // Factorizes the free system of hard_ and soft_weight_. `same_pattern`: the free block has the
  // previous one's pattern; its analysis is reused.
  bool factorize(bool same_pattern);
  // Conjugate gradients on the free system from the previous solution, scaled to fit this one;
  // false when they do not converge (`iterations` says how many ran).
  bool solve_iteratively(const Free_system& system, const Eigen::VectorXcd& rhs,
                         Eigen::VectorXcd& x, std::size_t& iterations) const;

  // Inverse power iteration on (A + εM) u = λ M u, normalized in the mass norm, until one turns
  // the vector by less than the tolerance; `iterations` says how many ran.
  std::vector<std::complex<double>> smallest_eigenvector(std::size_t& iterations) const;
  // The norm of x in the mass matrix M.
  double mass_norm(const Eigen::VectorXcd& x) const;

  const TriangleMesh& tm_;
  Smoothest_field_options options_;
  Frames frames_;
  internal::Complex_sparse laplacian_, coupling_;
  std::vector<double> diagonal_, mass_;
  double shift_ = 0;
  std::vector<char> hard_;
  std::vector<double> soft_weight_;
  bool eigen_mode_ = false;
  std::vector<std::size_t> free_, fixed_;
  std::unique_ptr<internal::Sparse_cholesky> factorization_;
  bool analyzed_ = false; // `factorization_` holds an analysis of the current free block's pattern
  std::size_t factorizations_ = 0;
  std::vector<std::complex<double>> last_; // the previous solve's power vectors (a start for CG)
  std::vector<char> left_out_;             // per edge, in the order of edges(tm_); empty when none
  std::size_t left_out_count_ = 0;
};

/// One-shot smoothest field: builds a `Smoothest_field_solver` and solves once.
///
/// Named parameters: `vertex_point_map`, `edge_is_constrained_map` (see the solver).
template <typename TriangleMesh, typename VertexFieldMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Smoothest_field_result smoothest_field(
    const TriangleMesh& tm,
    const std::vector<typename Smoothest_field_solver<TriangleMesh>::Constraint>& constraints,
    VertexFieldMap field, const Smoothest_field_options& options = {},
    const NamedParameters& np = CGAL::parameters::default_values()) {
  Smoothest_field_solver<TriangleMesh> solver(tm, options, np);
  return solver.solve(constraints, field);
}

/// Constraints for a control direction at a point inside face `f`, given by barycentric coordinates
/// in the order of `vertices_around_face(halfedge(f, tm), tm)`: a hard control goes to the corner
/// with the largest coordinate; a soft one becomes three soft constraints weighted by the
/// coordinates. Empty when the coordinates are not finite, negative, or do not sum to 1.
template <typename TriangleMesh>
std::vector<typename Smoothest_field_solver<TriangleMesh>::Constraint>
face_point_constraints(const TriangleMesh& tm,
                       typename boost::graph_traits<TriangleMesh>::face_descriptor f,
                       const std::array<double, 3>& barycentric,
                       const typename Smoothest_field_solver<TriangleMesh>::Vector_3& direction,
                       Constraint_kind kind, double weight = 1) {
  std::vector<typename Smoothest_field_solver<TriangleMesh>::Constraint> out;
  double sum = 0;
  for (double b : barycentric) {
    if (!std::isfinite(b) || b < -1e-9)
      return out;
    sum += b;
  }
  if (std::abs(sum - 1) > 1e-6)
    return out;
  std::size_t k = 0, best = 0;
  for (auto v : CGAL::vertices_around_face(halfedge(f, tm), tm)) {
    if (k < 3) {
      if (kind == Constraint_kind::soft && barycentric[k] > 0)
        out.push_back({v, direction, kind, weight * barycentric[k]});
      if (kind == Constraint_kind::hard && (k == 0 || barycentric[k] > barycentric[best])) {
        best = k;
        out.assign(1, {v, direction, kind, weight});
      }
    }
    ++k;
  }
  return out;
}

} // namespace tessera

#include <tessera/fields/internal/smoothest_field_impl.h>
