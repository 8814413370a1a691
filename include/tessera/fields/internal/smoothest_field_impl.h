// The bodies of Smoothest_field_solver's members (tessera/fields/smoothest_field.h): the solve
// with hard and soft constraints, the connection Laplacian, the free block's factorization or, for
// systems that soft weights hold, its conjugate gradients, and the inverse power iteration.
// Included at the end of the public header.
#pragma once

#include <tessera/fields/smoothest_field.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace tessera {

template <typename TriangleMesh>
template <typename VertexFieldMap>
Smoothest_field_result
Smoothest_field_solver<TriangleMesh>::solve(const std::vector<Constraint>& constraints,
                                            VertexFieldMap field) {
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
  // The hard constraints' own directions (unit, tangential), written back as they are: the angle
  // map through the fan (`Vertex_frames::to_power`) is not a rotation, so another of the n
  // representatives of the power vector, taken back, would not be the constraint's direction.
  std::vector<internal::Vec3> hard_direction(nv);
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
      const internal::Vec3& nrm = frames_.normal(i);
      const internal::Vec3 t = d - internal::dot(d, nrm) * nrm;
      hard_direction[i] = (1 / internal::norm(t)) * t;
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
  std::vector<std::complex<double>> u(nv);
  // The right-hand side of the free system: the soft targets, less the coupling to the fixed
  // vertices' values.
  auto right_hand_side = [&](const std::vector<std::size_t>& free,
                             const std::vector<std::size_t>& fixed,
                             const internal::Complex_sparse& coupling) {
    Eigen::VectorXcd rhs = Eigen::VectorXcd::Zero(Eigen::Index(free.size()));
    for (std::size_t f = 0; f < free.size(); ++f)
      rhs[Eigen::Index(f)] = soft_target[free[f]] * diagonal_[free[f]];
    Eigen::VectorXcd values(Eigen::Index(fixed.size()));
    for (std::size_t c = 0; c < fixed.size(); ++c)
      values[Eigen::Index(c)] = hard_value[fixed[c]];
    if (values.size() > 0)
      rhs -= coupling * values;
    return rhs;
  };
  bool solved = false;
  if (!eigen_mode && options_.iterative_when_held && !last_.empty()) {
    std::size_t free = 0, held = 0;
    for (std::size_t i = 0; i < nv; ++i)
      if (!hard[i]) {
        ++free;
        held += soft_weight[i] >= options_.held_weight;
      }
    if (free > 0 && double(held) >= 0.99 * double(free)) {
      const Free_system system = free_system(hard, soft_weight);
      Eigen::VectorXcd x;
      solved =
          solve_iteratively(system, right_hand_side(system.free, system.fixed, system.coupling), x,
                            result.iterative_iterations);
      if (solved) {
        for (std::size_t f = 0; f < system.free.size(); ++f)
          u[system.free[f]] = x[Eigen::Index(f)];
        for (const std::size_t i : system.fixed)
          u[i] = hard_value[i];
        result.solver = "Eigen ConjugateGradient";
      }
    }
  }
  if (!solved) {
    if (!factorization_ || hard != hard_ || soft_weight != soft_weight_ ||
        eigen_mode != eigen_mode_) {
      // The same hard vertices keep the free block's sparsity pattern: only new soft weights (or
      // the switch from the eigenvector), so the ordering and symbolic analysis are kept.
      const bool same_pattern = analyzed_ && hard == hard_;
      hard_ = hard;
      soft_weight_ = soft_weight;
      eigen_mode_ = eigen_mode;
      if (!factorize(same_pattern))
        return fail(Field_status::solver_failed, "the sparse Cholesky factorization failed");
      result.factorized = true;
      result.analysis_reused = same_pattern;
    }
    if (eigen_mode) {
      u = smallest_eigenvector(result.eigen_iterations);
    } else {
      const Eigen::VectorXcd rhs = right_hand_side(free_, fixed_, coupling_);
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
  }
  // Faces of zero area, or coordinates whose squared lengths overflow, leave nothing to solve
  // for: say so rather than write a field of NaNs.
  for (const std::complex<double>& x : u)
    if (!std::isfinite(x.real()) || !std::isfinite(x.imag()))
      return fail(Field_status::solver_failed,
                  "the solution is not finite (the surface's geometry is degenerate: faces of "
                  "zero area, or coordinates too large or too small for double precision)");
  last_ = u;
  result.energy = internal::power_field_energy(frames_, u, n, left_out_);
  for (std::size_t i = 0; i < nv; ++i) {
    const internal::Vec3 x =
        hard[i] ? hard_direction[i] : frames_.from_power(i, u[i], n, options_.normalize);
    put(field, frames_.vertex(i), Vector_3(x[0], x[1], x[2]));
  }
  return result;
}

template <typename TriangleMesh>
template <typename EdgeIsConstrainedMap>
void Smoothest_field_solver<TriangleMesh>::leave_out_edges_at_line_ends(
    EdgeIsConstrainedMap is_line) {
  std::vector<std::size_t> on_lines(frames_.size(), 0);
  for (auto e : edges(tm_))
    if (get(is_line, e)) {
      const auto h = halfedge(e, tm_);
      ++on_lines[frames_.index(source(h, tm_))];
      ++on_lines[frames_.index(target(h, tm_))];
    }
  auto line_end = [&](std::size_t i) { return on_lines[i] == 1 || on_lines[i] > 2; };
  left_out_.clear();
  left_out_count_ = 0;
  for (auto e : edges(tm_)) {
    const auto h = halfedge(e, tm_);
    const bool out = !get(is_line, e) && (line_end(frames_.index(source(h, tm_))) ||
                                          line_end(frames_.index(target(h, tm_))));
    left_out_.push_back(out ? 1 : 0);
    left_out_count_ += out ? 1 : 0;
  }
  if (left_out_count_ == 0)
    left_out_.clear();
}

template <typename TriangleMesh> void Smoothest_field_solver<TriangleMesh>::build_laplacian() {
  const std::size_t nv = frames_.size();
  const int n = options_.symmetry;
  diagonal_.assign(nv, 0);
  mass_.assign(nv, 0);
  std::vector<Eigen::Triplet<std::complex<double>>> triplets;
  std::size_t k = 0;
  for (auto e : edges(tm_)) {
    if (!left_out_.empty() && left_out_[k++])
      continue;
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

template <typename TriangleMesh>
typename Smoothest_field_solver<TriangleMesh>::Free_system
Smoothest_field_solver<TriangleMesh>::free_system(const std::vector<char>& hard,
                                                  const std::vector<double>& soft_weight) const {
  const std::size_t nv = frames_.size();
  Free_system out;
  std::vector<Eigen::Index> position(nv);
  for (std::size_t i = 0; i < nv; ++i) {
    position[i] = Eigen::Index(hard[i] ? out.fixed.size() : out.free.size());
    (hard[i] ? out.fixed : out.free).push_back(i);
  }
  out.matrix.resize(Eigen::Index(out.free.size()), Eigen::Index(out.free.size()));
  out.matrix.reserve(laplacian_.nonZeros());
  std::vector<Eigen::Triplet<std::complex<double>>> coupling;
  for (Eigen::Index col = 0; col < laplacian_.outerSize(); ++col) {
    const std::size_t c = std::size_t(col);
    if (!hard[c])
      out.matrix.startVec(position[c]);
    for (internal::Complex_sparse::InnerIterator it(laplacian_, col); it; ++it) {
      const std::size_t r = std::size_t(it.row());
      if (!hard[r] && !hard[c]) {
        const double extra = r == c ? soft_weight[c] * diagonal_[c] + shift_ * mass_[c] : 0.0;
        out.matrix.insertBack(position[r], position[c]) = it.value() + extra;
      } else if (!hard[r]) {
        coupling.emplace_back(position[r], position[c], it.value());
      } else if (!hard[c]) {
        coupling.emplace_back(position[c], position[r], std::conj(it.value()));
      }
    }
  }
  out.matrix.finalize();
  out.coupling.resize(Eigen::Index(out.free.size()), Eigen::Index(out.fixed.size()));
  out.coupling.setFromTriplets(coupling.begin(), coupling.end());
  return out;
}

template <typename TriangleMesh>
bool Smoothest_field_solver<TriangleMesh>::solve_iteratively(const Free_system& system,
                                                             const Eigen::VectorXcd& rhs,
                                                             Eigen::VectorXcd& x,
                                                             std::size_t& iterations) const {
  // The previous field, scaled by the complex factor that fits it best (an eigenvector has unit
  // mass norm, the solution of soft targets unit vectors): min over α of the energy of α x0.
  Eigen::VectorXcd start(Eigen::Index(system.free.size()));
  for (std::size_t f = 0; f < system.free.size(); ++f)
    start[Eigen::Index(f)] = last_[system.free[f]];
  const Eigen::VectorXcd product = system.matrix.template selfadjointView<Eigen::Lower>() * start;
  const std::complex<double> curvature = start.dot(product);
  if (std::abs(curvature) > 0 && std::isfinite(std::abs(curvature)))
    start *= start.dot(rhs) / curvature;
  Eigen::ConjugateGradient<internal::Complex_sparse, Eigen::Lower> cg;
  cg.setTolerance(options_.iterative_tolerance);
  cg.setMaxIterations(Eigen::Index(options_.iterative_iterations));
  cg.compute(system.matrix);
  x = cg.solveWithGuess(rhs, start);
  iterations = std::size_t(cg.iterations());
  return cg.info() == Eigen::Success && x.allFinite();
}

template <typename TriangleMesh>
bool Smoothest_field_solver<TriangleMesh>::factorize(bool same_pattern) {
  Free_system system = free_system(hard_, soft_weight_);
  free_ = std::move(system.free);
  fixed_ = std::move(system.fixed);
  coupling_ = std::move(system.coupling);
  const internal::Complex_sparse& matrix = system.matrix;
  ++factorizations_;
  if (same_pattern) {
    factorization_->factorize(matrix); // numeric only, on the kept analysis
    return factorization_->info() == Eigen::Success;
  }
  analyzed_ = false;
  factorization_ = std::make_unique<internal::Sparse_cholesky>();
#ifdef TESSERA_HAS_CHOLMOD
  // AMD alone: on mesh Laplacians METIS saves some fill but its analysis costs more than it
  // saves.
  factorization_->cholmod().nmethods = 1;
  factorization_->cholmod().method[0].ordering = CHOLMOD_AMD;
#endif
  if (free_.empty())
    return true;
  factorization_->compute(matrix);
  analyzed_ = factorization_->info() == Eigen::Success;
  return analyzed_;
}

template <typename TriangleMesh>
std::vector<std::complex<double>>
Smoothest_field_solver<TriangleMesh>::smallest_eigenvector(std::size_t& iterations) const {
  Eigen::VectorXcd u(static_cast<Eigen::Index>(frames_.size()));
  std::mt19937 rng(1);
  std::normal_distribution<double> normal;
  for (Eigen::Index i = 0; i < u.size(); ++i)
    u[i] = {normal(rng), normal(rng)};
  u /= mass_norm(u);
  iterations = 0;
  for (std::size_t it = 0; it < options_.eigen_iterations; ++it) {
    ++iterations;
    Eigen::VectorXcd mu = u;
    for (Eigen::Index i = 0; i < u.size(); ++i)
      mu[i] *= mass_[std::size_t(i)];
    Eigen::VectorXcd next = factorization_->solve(mu);
    next /= mass_norm(next);
    std::complex<double> overlap = 0;
    for (Eigen::Index i = 0; i < u.size(); ++i)
      overlap += mass_[std::size_t(i)] * std::conj(u[i]) * next[i];
    u = next;
    if (1 - std::abs(overlap) < options_.eigen_tolerance)
      break;
  }
  return std::vector<std::complex<double>>(u.data(), u.data() + u.size());
}

template <typename TriangleMesh>
double Smoothest_field_solver<TriangleMesh>::mass_norm(const Eigen::VectorXcd& x) const {
  double s = 0;
  for (Eigen::Index i = 0; i < x.size(); ++i)
    s += mass_[std::size_t(i)] * std::norm(x[i]);
  return std::sqrt(s);
}

} // namespace tessera
