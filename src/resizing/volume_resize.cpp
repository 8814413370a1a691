// The local/global solve of resize_volume().
#include <tessera/resizing/volume_resize.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#ifdef TESSERA_HAS_CHOLMOD
#include <Eigen/CholmodSupport>
#else
#include <Eigen/SparseCholesky>
#endif

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace tessera {

namespace {

using P3 = std::array<double, 3>;
using Sparse = Eigen::SparseMatrix<double>;
#ifdef TESSERA_HAS_CHOLMOD
using Cholesky = Eigen::CholmodDecomposition<Sparse, Eigen::Lower>;
const char* cholesky_name = "CHOLMOD";
#else
using Cholesky = Eigen::SimplicialLDLT<Sparse, Eigen::Lower>;
const char* cholesky_name = "Eigen SimplicialLDLT";
#endif

// Gradients of the four barycentric functions of a tetrahedron (rows), and its volume times its
// stiffness (0 for a degenerate tetrahedron).
struct Tet_gradients {
  Eigen::Matrix<double, 4, 3> g;
  double volume = 0;
};

// Extent max − min of a·u + v over the surface's values.
struct Extent {
  double value;
  double slope;
};
Extent extent(double a, const std::vector<double>& u, const std::vector<double>& v) {
  std::size_t hi = 0, lo = 0;
  double best_hi = -std::numeric_limits<double>::infinity();
  double best_lo = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < u.size(); ++i) {
    const double x = a * u[i] + v[i];
    if (x > best_hi) {
      best_hi = x;
      hi = i;
    }
    if (x < best_lo) {
      best_lo = x;
      lo = i;
    }
  }
  return {best_hi - best_lo, u[hi] - u[lo]};
}

// The a ≥ 0 at which the (convex, piecewise linear) extent meets `target`, by Newton's method
// from `a`; on a convex function it moves monotonically and stops on a linear piece.
double solve_stretch(double a, double target, const std::vector<double>& u,
                     const std::vector<double>& v) {
  for (int step = 0; step < 100; ++step) {
    const Extent e = extent(a, u, v);
    if (std::abs(e.value - target) <= 1e-12 * std::max(1.0, target) || e.slope <= 0)
      break;
    const double next = std::max(0.0, a + (target - e.value) / e.slope);
    if (next == a)
      break;
    a = next;
  }
  return a;
}

// Why resize_volume() cannot run on these inputs, or ok.
Volume_resize_status check_input(const Tet_mesh& mesh, const std::vector<P3>& vulnerability,
                                 const Volume_resize_options& options, std::string& message) {
  const std::size_t n = mesh.points.size();
  for (double s : options.scale)
    if (!(s > 0) || !std::isfinite(s)) {
      message = "scale factors must be positive and finite";
      return Volume_resize_status::invalid_options;
    }
  if (!(options.stiffness >= 0) || !std::isfinite(options.stiffness)) {
    message = "the stiffness must be finite and not negative";
    return Volume_resize_status::invalid_options;
  }
  if (!(options.max_free_stretch_exponent >= 1) ||
      !std::isfinite(options.max_free_stretch_exponent)) {
    message = "the free stretch exponent must be a number of at least 1";
    return Volume_resize_status::invalid_options;
  }
  if (n == 0 || mesh.tets.empty() || (!mesh.embedded() && mesh.surface_vertices == 0)) {
    message = "the volume has no tetrahedra or no surface";
    return Volume_resize_status::empty_volume;
  }
  if (vulnerability.size() != n) {
    message = "the volume has " + std::to_string(n) + " vertices but " +
              std::to_string(vulnerability.size()) + " vulnerabilities";
    return Volume_resize_status::invalid_input;
  }
  bool in_range = mesh.embedded() ? mesh.embedding_weights.size() == mesh.embedding_tet.size()
                                  : mesh.surface_vertices <= n;
  for (const auto& q : mesh.tets)
    in_range = in_range && q[0] < n && q[1] < n && q[2] < n && q[3] < n;
  for (std::size_t t : mesh.embedding_tet)
    in_range = in_range && t < mesh.tets.size();
  if (!in_range) {
    message = "the volume's indices are out of range";
    return Volume_resize_status::invalid_input;
  }
  return Volume_resize_status::ok;
}

} // namespace

Volume_resize_result resize_volume(const Tet_mesh& mesh, const std::vector<P3>& vulnerability,
                                   const Volume_resize_options& options) {
  Volume_resize_result result;
  // Axes with a factor of exactly 1 are not resized: their targets stay 1 (see the header).
  const std::array<bool, 3> resized{options.scale[0] != 1, options.scale[1] != 1,
                                    options.scale[2] != 1};
  result.solver = cholesky_name;
  const std::size_t n = mesh.points.size();
  result.points = mesh.points;
  result.status = check_input(mesh, vulnerability, options, result.message);
  if (!result)
    return result;

  double max_volume = 0;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    max_volume = std::max(max_volume, mesh.tet_volume(t));
  std::vector<Tet_gradients> grads(mesh.tets.size());
  std::vector<P3> weights(mesh.tets.size(), P3{0, 0, 0});
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(16 * mesh.tets.size() + n);
  Eigen::VectorXd mass = Eigen::VectorXd::Zero(Eigen::Index(n));
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const auto& q = mesh.tets[t];
    Eigen::Matrix3d d;
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c)
        d(c, k) =
            mesh.points[q[std::size_t(k) + 1]][std::size_t(c)] - mesh.points[q[0]][std::size_t(c)];
    const double volume = d.determinant() / 6.0;
    if (!(volume > 1e-12 * max_volume)) {
      ++result.degenerate_tets;
      continue;
    }
    const Eigen::Matrix3d inv = d.inverse();
    Tet_gradients& tg = grads[t];
    // A tetrahedron is as vulnerable as its most vulnerable corner: its affine map moves that
    // corner's neighbourhood as a whole.
    for (int k = 0; k < 4; ++k)
      for (int c = 0; c < 3; ++c)
        weights[t][std::size_t(c)] =
            std::max(weights[t][std::size_t(c)],
                     std::clamp(vulnerability[q[std::size_t(k)]][std::size_t(c)], 0.0, 1.0));
    // Tetrahedra vulnerable along a resized axis weigh more, so what cannot be met everywhere (the
    // transition between a stretched part and a rigid one) is taken up by the free side.
    double resisted = 0;
    for (std::size_t c = 0; c < 3; ++c)
      if (resized[c])
        resisted = std::max(resisted, weights[t][c]);
    const double stiffness = 1 + options.stiffness * resisted;
    tg.volume = volume * stiffness;
    tg.g.row(0) = -(inv.row(0) + inv.row(1) + inv.row(2));
    tg.g.block<3, 3>(1, 0) = inv;
    for (int a = 0; a < 4; ++a) {
      mass[Eigen::Index(q[std::size_t(a)])] += volume / 4;
      for (int b = 0; b < 4; ++b)
        triplets.emplace_back(Eigen::Index(q[std::size_t(a)]), Eigen::Index(q[std::size_t(b)]),
                              tg.volume * tg.g.row(a).dot(tg.g.row(b)));
    }
  }
  // A small mass term fixes the translation the Laplacian leaves free; the result is re-centred.
  double trace = 0, total_mass = mass.sum();
  for (const auto& tr : triplets)
    if (tr.row() == tr.col())
      trace += tr.value();
  const double epsilon = 1e-10 * trace / std::max(total_mass, 1e-300);
  for (std::size_t v = 0; v < n; ++v)
    triplets.emplace_back(Eigen::Index(v), Eigen::Index(v), epsilon * mass[Eigen::Index(v)]);
  Sparse laplacian{Eigen::Index(n), Eigen::Index(n)};
  laplacian.setFromTriplets(triplets.begin(), triplets.end());
  triplets = {};
  Cholesky cholesky;
#ifdef TESSERA_HAS_CHOLMOD
  cholesky.cholmod().nmethods = 1;
  cholesky.cholmod().method[0].ordering = CHOLMOD_AMD;
#endif
  cholesky.compute(laplacian);
  if (cholesky.info() != Eigen::Success) {
    result.status = Volume_resize_status::solve_failed;
    result.message = "the volume's matrix could not be factored";
    return result;
  }

  const double mu = std::max(0.0, options.anchor);
  // Original extents and centre of the surface.
  const CGAL::Bbox_3 box = bounding_box(mesh.surface_positions(mesh.points));
  auto surface_values = [&](const Eigen::VectorXd& x) { return mesh.surface_values(x.data()); };
  // Σ_t V_t·τ_t,j·∇φ_k,j for each vertex k: the right-hand side of coordinate j for targets
  // τ_t,j = target(t).
  auto right_hand_side = [&](std::size_t j, auto&& target) {
    Eigen::VectorXd b = Eigen::VectorXd::Zero(Eigen::Index(n));
    for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
      if (grads[t].volume <= 0)
        continue;
      const double c = grads[t].volume * target(t);
      for (std::size_t k = 0; k < 4; ++k)
        b[Eigen::Index(mesh.tets[t][k])] += c * grads[t].g(Eigen::Index(k), Eigen::Index(j));
    }
    return b;
  };
  // Along a resized axis j the solution is affine in the free stretch a and in the weight λ of
  // the vulnerabilities: with targets τ_t = ((1 − λw_t)·a + λw_t·σ_t + μ·s)/(1 + μ),
  // x = (a·(P − λQ) + λV + μ·s·P)/(1 + μ), P solved for targets 1 (the coordinate itself), Q for
  // w_t, V for w_t·σ_t. P and Q are solved once; V after each update of σ.
  std::array<Eigen::VectorXd, 3> whole, vulnerable_part;
  std::array<std::vector<double>, 3> whole_surface, vulnerable_surface;
  for (std::size_t j = 0; j < 3; ++j) {
    whole[j] = cholesky.solve(right_hand_side(j, [](std::size_t) { return 1.0; }));
    whole_surface[j] = surface_values(whole[j]);
    if (!resized[j])
      continue;
    vulnerable_part[j] =
        cholesky.solve(right_hand_side(j, [&](std::size_t t) { return weights[t][j]; }));
    vulnerable_surface[j] = surface_values(vulnerable_part[j]);
  }
  // The free stretch along j for weight λ and the surface values of V, and whether it keeps
  // |log a| ≤ k·|log s|.
  const double exponent = options.max_free_stretch_exponent;
  auto stretch_for = [&](std::size_t j, double lambda, double a0, const std::vector<double>& vs) {
    const std::size_t m = vs.size();
    std::vector<double> u(m), rest(m);
    for (std::size_t i = 0; i < m; ++i) {
      u[i] = (whole_surface[j][i] - lambda * vulnerable_surface[j][i]) / (1 + mu);
      rest[i] = (lambda * vs[i] + mu * options.scale[j] * whole_surface[j][i]) / (1 + mu);
    }
    return solve_stretch(a0, options.scale[j] * (box.max(int(j)) - box.min(int(j))), u, rest);
  };
  auto within_bound = [&](std::size_t j, double a) {
    return a > 0 && std::abs(std::log(a)) <= exponent * std::abs(std::log(options.scale[j])) + 1e-9;
  };

  // σ_t, the vulnerability-weighted mean of the tetrahedron's stretches stretch(j) along the axes
  // (1 where it is vulnerable along none); first from the simple scaling.
  auto uniform_scale = [&](std::size_t t, auto&& stretch) {
    double sw = 0, s = 0;
    for (std::size_t j = 0; j < 3; ++j) {
      sw += weights[t][j];
      s += weights[t][j] * stretch(j);
    }
    return sw > 1e-12 ? s / sw : 1.0;
  };
  std::vector<double> sigma(mesh.tets.size());
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    sigma[t] = uniform_scale(t, [&](std::size_t j) { return options.scale[j]; });
  std::array<Eigen::VectorXd, 3> x;
  P3 a = options.scale;
  const std::size_t most = std::max<std::size_t>(options.iterations, 1);
  report_progress(options.progress, "volume iterations", 0, most);
  P3 lambda{1, 1, 1};
  for (std::size_t it = 0; it < most; ++it) {
    for (std::size_t j = 0; j < 3; ++j) {
      if (!resized[j]) {
        x[j] = whole[j];
        continue;
      }
      const Eigen::VectorXd v = cholesky.solve(
          right_hand_side(j, [&](std::size_t t) { return weights[t][j] * sigma[t]; }));
      const std::vector<double> vs = surface_values(v);
      a[j] = stretch_for(j, lambda[j], a[j], vs);
      if (!within_bound(j, a[j])) {
        // The free parts cannot take the resize alone: the largest λ (no larger than the last)
        // whose stretch keeps the bound, by bisection; at λ = 0 the stretch is s itself.
        double lo = 0, hi = lambda[j];
        for (int step = 0; step < 40; ++step) {
          const double mid = 0.5 * (lo + hi);
          (within_bound(j, stretch_for(j, mid, options.scale[j], vs)) ? lo : hi) = mid;
        }
        lambda[j] = lo;
        a[j] = stretch_for(j, lo, options.scale[j], vs);
      }
      x[j] = (a[j] * (whole[j] - lambda[j] * vulnerable_part[j]) + lambda[j] * v +
              mu * options.scale[j] * whole[j]) /
             (1 + mu);
    }
    ++result.iterations;
    report_progress(options.progress, "volume iterations", result.iterations, most);
    double change = 0;
    for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
      if (grads[t].volume <= 0)
        continue;
      // Axes that are not resized count with their target, which keeps vulnerable parts from
      // drifting to any uniform scale (they are free to, as far as compatibility goes).
      const double next = uniform_scale(t, [&](std::size_t j) {
        if (!resized[j])
          return options.scale[j];
        double fjj = 0;
        for (std::size_t k = 0; k < 4; ++k)
          fjj += x[j][Eigen::Index(mesh.tets[t][k])] * grads[t].g(Eigen::Index(k), Eigen::Index(j));
        return fjj;
      });
      change = std::max(change, std::abs(next - sigma[t]));
      sigma[t] = next;
    }
    if (change <= options.tolerance)
      break;
  }
  report_progress(options.progress, "volume iterations", most, most);
  result.free_stretch = a;
  result.vulnerability_weight = lambda;
  // Re-centre: the surface's bounding-box centre stays where it was.
  for (std::size_t j = 0; j < 3; ++j) {
    const std::vector<double> s = surface_values(x[j]);
    const auto [mn, mx] = std::minmax_element(s.begin(), s.end());
    const double shift = 0.5 * (box.min(int(j)) + box.max(int(j))) - 0.5 * (*mn + *mx);
    for (std::size_t v = 0; v < n; ++v)
      result.points[v][j] = x[j][Eigen::Index(v)] + shift;
  }
  return result;
}

} // namespace tessera
