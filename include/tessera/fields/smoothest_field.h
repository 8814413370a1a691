// The smoothest n-direction field (n = 1, 2, 4) with hard and soft constraints by one sparse
// Cholesky solve: Knöppel, Crane, Pinkall, Schröder, "Globally optimal direction fields" (2013) —
// the power representation u = |X| e^{inψ} and the connection Laplacian — with constraints as in
// Directional's power fields (hard ones eliminated, soft ones as weighted terms). It replaces eq. 1
// of Lai et al.
#pragma once

#include <tessera/fields/internal/power_field.h>
#include <tessera/fields/tangent_field.h>

#include <CGAL/boost/graph/helpers.h>

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
  /// Inverse power iterations for the unconstrained smoothest field (Knöppel et al. Alg. 1).
  std::size_t eigen_iterations = 50;
};

/// Summary of a smoothest-field solve.
struct Smoothest_field_result {
  Field_status status = Field_status::ok;
  std::string message;
  /// Smoothness energy Σ_edges w_ij |u_j − r_ij u_i|² of the minimiser (before normalization),
  /// w_ij = 1 / edge length (the weights of Lai et al. eq. 1), r_ij the transport (see
  /// `field_energy`).
  double energy = 0;
  std::size_t hard_constraints = 0;
  std::size_t soft_constraints = 0;
  /// True when this solve factorized the matrix; false when it reused the previous factorization.
  bool factorized = false;
  /// "CHOLMOD" or "Eigen SimplicialLDLT".
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
/// solves. Like CGAL's `Surface_mesh_geodesic_distances_3`, the mesh must outlive the solver and
/// not change.
template <typename TriangleMesh> class Smoothest_field_solver {
public:
  using Frames = internal::Vertex_frames<TriangleMesh>;
  using vertex_descriptor = typename Frames::vertex_descriptor;
  using Vector_3 = typename Frames::Vector_3;
  using Constraint = Direction_constraint<vertex_descriptor, Vector_3>;

  /// Named parameters: `vertex_point_map`.
  template <typename NamedParameters = CGAL::parameters::Default_named_parameters>
  explicit Smoothest_field_solver(const TriangleMesh& tm,
                                  const Smoothest_field_options& options = {},
                                  const NamedParameters& np = CGAL::parameters::default_values())
      : tm_(tm), options_(options), frames_(tm, np) {
    if (is_valid_symmetry(options.symmetry))
      build_laplacian();
  }

  /// Solves for the smoothest field meeting `constraints` and writes it into `field` (a writable
  /// vertex property map of `Vector_3`). Without any constraint the result is the globally
  /// smoothest field (the smallest eigenvector of the connection Laplacian, Knöppel et al. Alg. 1).
  template <typename VertexFieldMap>
  Smoothest_field_result solve(const std::vector<Constraint>& constraints, VertexFieldMap field) {
    Smoothest_field_result result;
    result.solver = internal::sparse_cholesky_name();
    auto fail = [&](Field_status s, std::string m) {
      result.status = s;
      result.message = std::move(m);
      return result;
    };
    if (!is_valid_symmetry(options_.symmetry))
      return fail(Field_status::invalid_symmetry,
                  "symmetry must be 1, 2 or 4 (got " + std::to_string(options_.symmetry) + ")");
    if (frames_.size() == 0 || faces(tm_).empty())
      return fail(Field_status::empty_mesh, "the mesh has no faces");
    if (!CGAL::is_triangle_mesh(tm_))
      return fail(Field_status::not_triangle_mesh, "the mesh is not a triangle mesh");

    const std::size_t nv = frames_.size();
    const int n = options_.symmetry;
    std::vector<char> hard(nv, 0);
    std::vector<std::complex<double>> hard_value(nv), soft_target(nv);
    std::vector<double> soft_weight(nv, 0);
    for (std::size_t k = 0; k < constraints.size(); ++k) {
      const Constraint& c = constraints[k];
      const std::string which = "constraint " + std::to_string(k);
      if (!internal::is_vertex_of(tm_, c.vertex, 0))
        return fail(Field_status::invalid_constraint, which + " is on no vertex of the mesh");
      const internal::Vec3 d = internal::to_vec3(c.direction);
      if (!std::isfinite(d[0]) || !std::isfinite(d[1]) || !std::isfinite(d[2]))
        return fail(Field_status::invalid_constraint, which + " has a non-finite direction");
      const std::size_t i = frames_.index(c.vertex);
      const std::complex<double> p = frames_.to_power(i, d, n);
      if (!(std::abs(p) > 1e-9 * internal::norm(d)))
        return fail(Field_status::invalid_constraint, which + " has no tangential component");
      const std::complex<double> unit = p / std::abs(p);
      if (c.kind == Constraint_kind::hard) {
        if (hard[i] && std::abs(hard_value[i] - unit) > 1e-9)
          return fail(Field_status::conflicting_constraints,
                      which + " contradicts an earlier hard constraint at the same vertex");
        hard[i] = 1;
        hard_value[i] = unit;
        ++result.hard_constraints;
      } else {
        if (!(c.weight > 0) || !std::isfinite(c.weight))
          return fail(Field_status::invalid_constraint,
                      which + " has a soft weight that is not positive");
        soft_weight[i] += c.weight;
        soft_target[i] += c.weight * unit;
        ++result.soft_constraints;
      }
    }
    for (std::size_t i = 0; i < nv; ++i)
      if (hard[i])
        soft_weight[i] = 0; // a hard constraint overrides soft ones at its vertex

    const bool eigen_mode = constraints.empty();
    if (!factorization_ || hard != hard_ || soft_weight != soft_weight_ ||
        eigen_mode != eigen_mode_) {
      hard_ = hard;
      soft_weight_ = soft_weight;
      eigen_mode_ = eigen_mode;
      if (!factorize())
        return fail(Field_status::solver_failed, "the sparse Cholesky factorization failed");
      result.factorized = true;
    }

    std::vector<std::complex<double>> u(nv);
    if (eigen_mode) {
      u = smallest_eigenvector();
    } else {
      Eigen::VectorXcd rhs = Eigen::VectorXcd::Zero(Eigen::Index(free_.size()));
      for (std::size_t f = 0; f < free_.size(); ++f) {
        const std::size_t i = free_[f];
        rhs[Eigen::Index(f)] = soft_target[i] * diagonal_[i];
      }
      Eigen::VectorXcd fixed(Eigen::Index(nv - free_.size()));
      for (std::size_t c = 0; c < fixed_.size(); ++c)
        fixed[Eigen::Index(c)] = hard_value[fixed_[c]];
      if (fixed.size() > 0)
        rhs -= coupling_ * fixed;
      // Every vertex constrained: nothing to solve (the factorization of an empty block is not
      // computed).
      const Eigen::VectorXcd x =
          free_.empty() ? Eigen::VectorXcd() : Eigen::VectorXcd(factorization_->solve(rhs));
      if ((!free_.empty() && factorization_->info() != Eigen::Success) || !x.allFinite())
        return fail(Field_status::solver_failed, "the sparse solve failed");
      for (std::size_t f = 0; f < free_.size(); ++f)
        u[free_[f]] = x[Eigen::Index(f)];
      for (std::size_t c = 0; c < fixed_.size(); ++c)
        u[fixed_[c]] = hard_value[fixed_[c]];
    }
    // Faces of zero area, or coordinates whose squared lengths overflow, leave nothing to solve
    // for: say so rather than write a field of NaNs.
    for (const std::complex<double>& x : u)
      if (!std::isfinite(x.real()) || !std::isfinite(x.imag()))
        return fail(Field_status::solver_failed,
                    "the solution is not finite (the surface's geometry is degenerate: faces of "
                    "zero area, or coordinates too large or too small for double precision)");
    result.energy = internal::power_field_energy(frames_, u, n);
    for (std::size_t i = 0; i < nv; ++i) {
      const internal::Vec3 x = frames_.from_power(i, u[i], n, options_.normalize);
      put(field, frames_.vertex(i), Vector_3(x[0], x[1], x[2]));
    }
    return result;
  }

  /// Number of Cholesky factorizations done so far.
  std::size_t number_of_factorizations() const { return factorizations_; }

private:
  void build_laplacian() {
    const std::size_t nv = frames_.size();
    const int n = options_.symmetry;
    diagonal_.assign(nv, 0);
    mass_.assign(nv, 0);
    std::vector<Eigen::Triplet<std::complex<double>>> triplets;
    for (auto e : edges(tm_)) {
      const auto h = halfedge(e, tm_);
      const std::size_t i = frames_.index(source(h, tm_)), j = frames_.index(target(h, tm_));
      const double w = internal::edge_weight(frames_, h);
      const std::complex<double> r = internal::edge_transport(frames_, h, n);
      diagonal_[i] += w;
      diagonal_[j] += w;
      // Only the lower triangle is stored: row j, column i holds −w r_ij when j > i.
      if (j > i)
        triplets.emplace_back(Eigen::Index(j), Eigen::Index(i), -w * r);
      else
        triplets.emplace_back(Eigen::Index(i), Eigen::Index(j), -w * std::conj(r));
    }
    for (auto f : faces(tm_)) {
      std::array<std::size_t, 3> ids{};
      std::size_t k = 0;
      for (auto v : CGAL::vertices_around_face(halfedge(f, tm_), tm_))
        if (k < 3)
          ids[k++] = frames_.index(v);
      const double area =
          internal::norm(internal::cross(frames_.point(ids[1]) - frames_.point(ids[0]),
                                         frames_.point(ids[2]) - frames_.point(ids[0]))) /
          2;
      for (std::size_t id : ids)
        mass_[id] += area / 3;
    }
    double ratio = 0;
    for (std::size_t i = 0; i < nv; ++i)
      if (mass_[i] > 0)
        ratio += diagonal_[i] / mass_[i];
    // A vanishing shift keeps the matrix definite on parts without constraints and a parallel
    // field.
    shift_ = 1e-10 * ratio / double(std::max<std::size_t>(1, nv));
    for (std::size_t i = 0; i < nv; ++i)
      triplets.emplace_back(Eigen::Index(i), Eigen::Index(i), diagonal_[i]);
    laplacian_.resize(Eigen::Index(nv), Eigen::Index(nv));
    laplacian_.setFromTriplets(triplets.begin(), triplets.end());
  }

  // Splits the vertices into free and fixed ones and factorizes the free block plus the soft terms.
  // Free vertices keep their order, so the block's lower triangle is copied column by column.
  bool factorize() {
    const std::size_t nv = frames_.size();
    free_.clear();
    fixed_.clear();
    std::vector<Eigen::Index> position(nv);
    for (std::size_t i = 0; i < nv; ++i) {
      position[i] = Eigen::Index(hard_[i] ? fixed_.size() : free_.size());
      (hard_[i] ? fixed_ : free_).push_back(i);
    }
    internal::Complex_sparse matrix(Eigen::Index(free_.size()), Eigen::Index(free_.size()));
    matrix.reserve(laplacian_.nonZeros());
    std::vector<Eigen::Triplet<std::complex<double>>> coupling;
    for (Eigen::Index col = 0; col < laplacian_.outerSize(); ++col) {
      const std::size_t c = std::size_t(col);
      if (!hard_[c])
        matrix.startVec(position[c]);
      for (internal::Complex_sparse::InnerIterator it(laplacian_, col); it; ++it) {
        const std::size_t r = std::size_t(it.row());
        if (!hard_[r] && !hard_[c]) {
          const double extra = r == c ? soft_weight_[c] * diagonal_[c] + shift_ * mass_[c] : 0.0;
          matrix.insertBack(position[r], position[c]) = it.value() + extra;
        } else if (!hard_[r]) {
          coupling.emplace_back(position[r], position[c], it.value());
        } else if (!hard_[c]) {
          coupling.emplace_back(position[c], position[r], std::conj(it.value()));
        }
      }
    }
    matrix.finalize();
    coupling_.resize(Eigen::Index(free_.size()), Eigen::Index(fixed_.size()));
    coupling_.setFromTriplets(coupling.begin(), coupling.end());
    factorization_ = std::make_unique<internal::Sparse_cholesky>();
#ifdef TESSERA_HAS_CHOLMOD
    // AMD alone: on mesh Laplacians METIS saves some fill but its analysis costs more than it
    // saves.
    factorization_->cholmod().nmethods = 1;
    factorization_->cholmod().method[0].ordering = CHOLMOD_AMD;
#endif
    ++factorizations_;
    if (free_.empty())
      return true;
    factorization_->compute(matrix);
    return factorization_->info() == Eigen::Success;
  }

  // Inverse power iteration on (A + εM) u = λ M u, normalized in the mass norm.
  std::vector<std::complex<double>> smallest_eigenvector() const {
    Eigen::VectorXcd u(static_cast<Eigen::Index>(frames_.size()));
    std::mt19937 rng(1);
    std::normal_distribution<double> normal;
    for (Eigen::Index i = 0; i < u.size(); ++i)
      u[i] = {normal(rng), normal(rng)};
    auto mass_norm = [&](const Eigen::VectorXcd& x) {
      double s = 0;
      for (Eigen::Index i = 0; i < x.size(); ++i)
        s += mass_[std::size_t(i)] * std::norm(x[i]);
      return std::sqrt(s);
    };
    u /= mass_norm(u);
    for (std::size_t it = 0; it < options_.eigen_iterations; ++it) {
      Eigen::VectorXcd mu = u;
      for (Eigen::Index i = 0; i < u.size(); ++i)
        mu[i] *= mass_[std::size_t(i)];
      Eigen::VectorXcd next = factorization_->solve(mu);
      next /= mass_norm(next);
      std::complex<double> overlap = 0;
      for (Eigen::Index i = 0; i < u.size(); ++i)
        overlap += mass_[std::size_t(i)] * std::conj(u[i]) * next[i];
      u = next;
      if (1 - std::abs(overlap) < 1e-12)
        break;
    }
    return std::vector<std::complex<double>>(u.data(), u.data() + u.size());
  }

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
  std::size_t factorizations_ = 0;
};

/// One-shot smoothest field: builds a `Smoothest_field_solver` and solves once.
///
/// Named parameters: `vertex_point_map`.
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
