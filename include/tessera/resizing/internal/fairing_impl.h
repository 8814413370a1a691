// The fairing behind `extract_detail` (texture_detail.h): the published implicit iterations with
// the umbrella operator, and the default one-solve thin-plate low pass with cotangent weights.
#pragma once

#include <tessera/internal/cotangent_laplacian.h>
#include <tessera/internal/index_sets.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <utility>
#include <vector>

namespace tessera::internal {

constexpr std::size_t not_free = std::size_t(-1);

/// Each vertex's position in `free`, `not_free` for the others.
template <typename TriangleMesh>
auto free_slots(
    const TriangleMesh& tm,
    const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& free) {
  auto slot = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  for (auto v : vertices(tm))
    put(slot, v, not_free);
  for (std::size_t i = 0; i < free.size(); ++i)
    put(slot, free[i], i);
  return slot;
}

/// A frame at a surface point with unit normal `normal`: the normal, `axis` projected into the
/// tangent plane (the next coordinate axis where `axis` is almost normal), and their cross
/// product. Texture templates and Laplacian-coordinate details are read in it, so a texture
/// keeps its orientation on a changed base.
inline std::array<Eigen::Vector3d, 3> tangent_frame(const Eigen::Vector3d& normal,
                                                    const std::array<double, 3>& axis) {
  Eigen::Vector3d t(axis[0], axis[1], axis[2]);
  t -= t.dot(normal) * normal;
  for (int k = 0; t.norm() < 0.3 && k < 3; ++k) {
    t = Eigen::Vector3d::Unit(k);
    t -= t.dot(normal) * normal;
  }
  t.normalize();
  return {{normal, t, normal.cross(t)}};
}

/// The published fairing (eq. 4): (I + λdt·K) X^{n+1} = X^n repeated until no texture vertex moves
/// more than `options.tolerance` mean edge lengths, K = −L or L² with the umbrella L. Writes the
/// texture vertices' (`free`) positions to `base` and the iterations and volume ratio to `result`;
/// false if the matrix cannot be factored. `laplacian`: K = −L (mean-curvature flow), else L².
template <typename TriangleMesh, typename VertexPointMap, typename BasePointMap, typename Options,
          typename Result>
bool iterative_fairing(
    const TriangleMesh& tm, VertexPointMap vpm, BasePointMap base,
    const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& free,
    bool laplacian, const Options& options, Result& result) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Point = typename boost::property_traits<BasePointMap>::value_type;
  constexpr std::size_t fixed = not_free;
  const auto index = free_slots(tm, free);
  // Eq. 4 with the umbrella operator L x_i = (1/deg) Σ x_j − x_i over the whole mesh; the rows and
  // columns of the texture vertices make the system, the fixed vertices' columns its right-hand
  // side. For thin-plate fairing the operator is L·L.
  const double lambda = options.lambda_dt;
  const Eigen::Index n = Eigen::Index(free.size());
  auto all = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  std::vector<vertex_descriptor> ordered;
  Eigen::MatrixX3d everything(Eigen::Index(num_vertices(tm)), 3);
  for (vertex_descriptor v : vertices(tm)) {
    put(all, v, ordered.size());
    const Point p = get(vpm, v);
    everything.row(Eigen::Index(ordered.size())) << CGAL::to_double(p.x()), CGAL::to_double(p.y()),
        CGAL::to_double(p.z());
    ordered.push_back(v);
  }
  const Eigen::Index total = Eigen::Index(ordered.size());
  Eigen::SparseMatrix<double> umbrella(total, total);
  {
    std::vector<Eigen::Triplet<double>> entries;
    for (vertex_descriptor v : ordered) {
      const Eigen::Index i = Eigen::Index(get(all, v));
      entries.emplace_back(i, i, -1.0);
      if (halfedge(v, tm) == boost::graph_traits<TriangleMesh>::null_halfedge())
        continue;
      const auto ring = CGAL::vertices_around_target(halfedge(v, tm), tm);
      const double degree = double(std::distance(ring.begin(), ring.end()));
      for (vertex_descriptor w : ring)
        entries.emplace_back(i, Eigen::Index(get(all, w)), 1.0 / degree);
    }
    umbrella.setFromTriplets(entries.begin(), entries.end());
  }
  // The operator K with (I + λdt·K) on the left: −L, or L².
  const Eigen::SparseMatrix<double> op = laplacian
                                             ? Eigen::SparseMatrix<double>(-umbrella)
                                             : Eigen::SparseMatrix<double>(umbrella * umbrella);
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixX3d constant = Eigen::MatrixX3d::Zero(n, 3), x(n, 3);
  {
    Eigen::SparseMatrix<double, Eigen::RowMajor> rows(op);
    for (Eigen::Index i = 0; i < n; ++i) {
      const Eigen::Index r = Eigen::Index(get(all, free[std::size_t(i)]));
      x.row(i) = everything.row(r);
      entries.emplace_back(i, i, 1.0);
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(rows, r); it; ++it) {
        const vertex_descriptor w = ordered[std::size_t(it.col())];
        if (get(index, w) != fixed)
          entries.emplace_back(i, Eigen::Index(get(index, w)), lambda * it.value());
        else
          constant.row(i) -= lambda * it.value() * everything.row(it.col());
      }
    }
  }
  Eigen::SparseMatrix<double> matrix(n, n);
  matrix.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> solver;
  solver.compute(matrix);
  if (solver.info() != Eigen::Success) {
    return false;
  }

  const bool keep_volume = options.preserve_volume && CGAL::is_closed(tm);
  auto write_base = [&](const Eigen::MatrixX3d& positions) {
    for (Eigen::Index i = 0; i < n; ++i)
      put(base, free[std::size_t(i)], Point(positions(i, 0), positions(i, 1), positions(i, 2)));
  };
  auto base_volume = [&] {
    return CGAL::to_double(PMP::volume(tm, CGAL::parameters::vertex_point_map(base)));
  };
  const double volume0 =
      keep_volume ? CGAL::to_double(PMP::volume(tm, CGAL::parameters::vertex_point_map(vpm))) : 0;
  Eigen::RowVector3d centroid = Eigen::RowVector3d::Zero();
  for (vertex_descriptor v : vertices(tm)) {
    const Point p = get(vpm, v);
    centroid +=
        Eigen::RowVector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())) /
        double(num_vertices(tm));
  }
  const double step_tolerance = options.tolerance * result.mean_edge_length;
  for (; result.iterations < options.max_iterations; ++result.iterations) {
    Eigen::MatrixX3d next = solver.solve(x + constant);
    if (keep_volume) {
      // Only the faired vertices scale, so the volume is a cubic in the factor s: a few secant
      // steps on V(s) = V0 from s = 1 and the whole-body guess (V0/V)^(1/3).
      auto volume_at = [&](double s) {
        Eigen::MatrixX3d scaled = (next.rowwise() - centroid) * s;
        scaled.rowwise() += centroid;
        write_base(scaled);
        return base_volume() - volume0;
      };
      double s0 = 1, f0 = volume_at(s0);
      double s1 = std::cbrt(volume0 / (volume0 + f0)), f1 = volume_at(s1);
      for (int k = 0; k < 20 && std::abs(f1) > 1e-12 * std::abs(volume0) && f1 != f0; ++k) {
        const double s2 = s1 - f1 * (s1 - s0) / (f1 - f0);
        s0 = s1, f0 = f1, s1 = s2, f1 = volume_at(s1);
      }
      next = (next.rowwise() - centroid) * s1;
      next.rowwise() += centroid;
    }
    const double moved = (next - x).rowwise().norm().maxCoeff();
    x = next;
    if (moved < step_tolerance) {
      ++result.iterations;
      break;
    }
  }
  write_base(x);
  if (keep_volume)
    result.volume_ratio = base_volume() / volume0;
  return true;
}

/// The low pass: (M + λ·L M⁻¹ L) X = M X⁰ on the texture vertices (`free`), the others fixed,
/// with L the cotangent Laplacian (CGAL::Weights::cotangent) and M the lumped vertex areas. The
/// matrix is symmetric positive definite (M plus a Gram matrix), so one LDLᵀ factorization solves
/// the three coordinates, and the same smoothing of the region's indicator (1 on the free
/// vertices, 0 on the fixed ones), written to `plateau` in `free`'s order: how much of a constant
/// offset of the region the smoothing keeps at each vertex (1 inside, falling to 0 at its
/// border). Writes `base` on the free vertices; false if the factorization fails.
///
/// Where the region reaches an open border of the mesh, the smoothing also pulls that border
/// in along the surface, as any Laplacian fairing shrinks a free boundary: issue 36's plate came
/// out 5.5 % narrower on each side under its texture (a waist, and 1.81× the texture's area for a
/// 2× stretch). So those border vertices keep only the part of their move along the smoothed
/// surface's normal, and the system is solved again with them held there.
template <typename TriangleMesh, typename VertexPointMap, typename BasePointMap>
bool low_pass_fairing(
    const TriangleMesh& tm, VertexPointMap vpm, BasePointMap base,
    const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& free,
    double lambda, std::vector<double>& plateau) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Point = typename boost::property_traits<BasePointMap>::value_type;
  using Matrix = Eigen::SparseMatrix<double>;
  auto all = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  std::vector<vertex_descriptor> ordered;
  // Each vertex's position and region indicator: the right-hand side of a fixed vertex.
  std::vector<Eigen::RowVector4d> point;
  for (vertex_descriptor v : vertices(tm)) {
    put(all, v, ordered.size());
    ordered.push_back(v);
    const auto& p = get(vpm, v);
    point.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()), 0);
  }
  const Eigen::Index total = Eigen::Index(ordered.size());
  const std::pair<Matrix, Eigen::VectorXd> operators = cotangent_laplacian(
      tm, all, [&](std::size_t i) { return Epick_point_3(point[i][0], point[i][1], point[i][2]); });
  const Matrix& laplacian = operators.first;
  const Eigen::VectorXd& mass = operators.second;
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd inverse_mass(total);
  for (Eigen::Index i = 0; i < total; ++i)
    inverse_mass[i] = mass[i] > 0 ? 1 / mass[i] : 0;
  const Matrix bilaplacian = Matrix(laplacian.transpose() * inverse_mass.asDiagonal() * laplacian);
  // Solves for the vertices of `unknowns` (the others fixed at `point`) and writes their base and
  // plateau; false if the factorization fails.
  constexpr std::size_t fixed = std::size_t(-1);
  std::vector<std::size_t> slot_of(free.size());
  for (std::size_t i = 0; i < free.size(); ++i)
    slot_of[i] = i;
  auto solve = [&](const std::vector<std::size_t>& unknowns) {
    std::vector<std::size_t> unknown(ordered.size(), fixed);
    for (std::size_t i = 0; i < unknowns.size(); ++i)
      unknown[get(all, free[unknowns[i]])] = i;
    const Eigen::Index n = Eigen::Index(unknowns.size());
    Eigen::MatrixX4d rhs(n, 4);
    entries.clear();
    for (Eigen::Index i = 0; i < n; ++i) {
      const std::size_t r = get(all, free[unknowns[std::size_t(i)]]);
      Eigen::RowVector4d p = point[r];
      p[3] = 1;
      rhs.row(i) = mass[Eigen::Index(r)] * p;
      entries.emplace_back(i, i, mass[Eigen::Index(r)]);
    }
    for (Eigen::Index col = 0; col < total; ++col)
      for (Matrix::InnerIterator it(bilaplacian, col); it; ++it) {
        const std::size_t row = unknown[std::size_t(it.row())];
        if (row == fixed)
          continue;
        const std::size_t c = unknown[std::size_t(col)];
        if (c != fixed)
          entries.emplace_back(Eigen::Index(row), Eigen::Index(c), lambda * it.value());
        else
          rhs.row(Eigen::Index(row)) -= lambda * it.value() * point[std::size_t(col)];
      }
    Matrix system(n, n);
    system.setFromTriplets(entries.begin(), entries.end());
    Eigen::SimplicialLDLT<Matrix> solver(system);
    if (solver.info() != Eigen::Success)
      return false;
    const Eigen::MatrixX4d x = solver.solve(rhs);
    if (solver.info() != Eigen::Success || !x.allFinite())
      return false;
    for (Eigen::Index i = 0; i < n; ++i) {
      const std::size_t k = unknowns[std::size_t(i)];
      put(base, free[k], Point(x(i, 0), x(i, 1), x(i, 2)));
      plateau[k] = x(i, 3);
    }
    return true;
  };
  plateau.assign(free.size(), 0);
  if (!solve(slot_of))
    return false;
  // The free vertices on an open border of the mesh: held where their move along the normal
  // takes them (with the indicator the first solve gave them), the others solved again.
  // (Every normal is taken from the first solve's base, before any border vertex moves.)
  std::vector<std::size_t> inner, border;
  std::vector<Eigen::Vector3d> normals;
  for (std::size_t k = 0; k < free.size(); ++k) {
    if (!CGAL::is_border(free[k], tm)) {
      inner.push_back(k);
      continue;
    }
    const auto m =
        PMP::compute_vertex_normal(free[k], tm, CGAL::parameters::vertex_point_map(base));
    border.push_back(k);
    normals.emplace_back(CGAL::to_double(m.x()), CGAL::to_double(m.y()), CGAL::to_double(m.z()));
  }
  for (std::size_t i = 0; i < border.size(); ++i) {
    const std::size_t k = border[i];
    const Eigen::Vector3d& normal = normals[i];
    const std::size_t r = get(all, free[k]);
    const Point b = get(base, free[k]);
    const Eigen::Vector3d p = point[r].head<3>().transpose();
    const Eigen::Vector3d moved =
        p +
        (Eigen::Vector3d(CGAL::to_double(b.x()), CGAL::to_double(b.y()), CGAL::to_double(b.z())) -
         p)
                .dot(normal) *
            normal;
    point[r] << moved.x(), moved.y(), moved.z(), plateau[k];
    put(base, free[k], Point(moved.x(), moved.y(), moved.z()));
  }
  return border.empty() || inner.empty() || solve(inner);
}

/// Moves the low-passed base of the free vertices along its normals by m·plateau, m the median
/// detail over the interior (plateau ≥ 0.9) of each connected group of free vertices, so that
/// median becomes 0 (see `extract_detail`).
template <typename TriangleMesh, typename VertexPointMap, typename BasePointMap>
void ground_base(
    const TriangleMesh& tm, VertexPointMap vpm, BasePointMap base,
    const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& free,
    const std::vector<double>& plateau) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using Point = typename boost::property_traits<BasePointMap>::value_type;
  constexpr std::size_t none = not_free;
  const auto slot = free_slots(tm, free);
  // Connected groups of free vertices (union-find over the edges between them).
  internal::Index_sets sets(free.size());
  for (auto e : edges(tm)) {
    const std::size_t a = get(slot, source(halfedge(e, tm), tm)),
                      b = get(slot, target(halfedge(e, tm), tm));
    if (a != none && b != none)
      sets.unite(a, b);
  }
  std::vector<Eigen::Vector3d> normal(free.size());
  std::vector<double> detail(free.size());
  std::vector<std::vector<double>> interior(free.size());
  for (std::size_t i = 0; i < free.size(); ++i) {
    const auto m =
        PMP::compute_vertex_normal(free[i], tm, CGAL::parameters::vertex_point_map(base));
    normal[i] =
        Eigen::Vector3d(CGAL::to_double(m.x()), CGAL::to_double(m.y()), CGAL::to_double(m.z()));
    const auto d = get(vpm, free[i]) - get(base, free[i]);
    detail[i] = CGAL::to_double(d.x()) * normal[i].x() + CGAL::to_double(d.y()) * normal[i].y() +
                CGAL::to_double(d.z()) * normal[i].z();
    if (plateau[i] >= 0.9)
      interior[sets.find(i)].push_back(detail[i]);
  }
  std::vector<double> median(free.size(), 0);
  for (std::size_t i = 0; i < free.size(); ++i)
    if (!interior[i].empty()) {
      auto middle = interior[i].begin() + std::ptrdiff_t(interior[i].size() / 2);
      std::nth_element(interior[i].begin(), middle, interior[i].end());
      median[i] = *middle;
    }
  for (std::size_t i = 0; i < free.size(); ++i) {
    const Eigen::Vector3d shift = median[sets.find(i)] * plateau[i] * normal[i];
    const Point b = get(base, free[i]);
    put(base, free[i], Point(b.x() + shift.x(), b.y() + shift.y(), b.z() + shift.z()));
  }
}

} // namespace tessera::internal
