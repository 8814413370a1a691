// The bodies of extract_laplacian_detail() and reconstruct_from_laplacian_detail()
// (tessera/resizing/laplacian_detail.h). Included by laplacian_detail.h after the types it uses;
// nothing here is meant to be called directly.
#pragma once

#include <tessera/resizing/internal/fairing_impl.h>

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace tessera::internal {

/// The base's operators and frames: the cotangent Laplacian L, the vertex areas M, the points B
/// (rows, in the order of vertices(tm)) and each vertex's frame (tangent_frame of its normal).
template <typename TriangleMesh> struct Laplacian_base {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  typename boost::property_map<TriangleMesh,
                               CGAL::dynamic_vertex_property_t<std::size_t>>::const_type index;
  std::vector<vertex_descriptor> ordered;
  Eigen::MatrixX3d points;
  Eigen::SparseMatrix<double> laplacian;
  Eigen::VectorXd mass;
  std::vector<std::array<Eigen::Vector3d, 3>> frames;

  template <typename BasePointMap>
  Laplacian_base(const TriangleMesh& tm, BasePointMap base, const std::array<double, 3>& axis)
      : index(get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm)),
        points(Eigen::Index(num_vertices(tm)), 3) {
    namespace PMP = CGAL::Polygon_mesh_processing;
    for (vertex_descriptor v : vertices(tm)) {
      const auto& p = get(base, v);
      points.row(Eigen::Index(ordered.size())) << CGAL::to_double(p.x()), CGAL::to_double(p.y()),
          CGAL::to_double(p.z());
      put(index, v, ordered.size());
      ordered.push_back(v);
      const auto n = PMP::compute_vertex_normal(v, tm, CGAL::parameters::vertex_point_map(base));
      frames.push_back(tangent_frame(
          Eigen::Vector3d(CGAL::to_double(n.x()), CGAL::to_double(n.y()), CGAL::to_double(n.z())),
          axis));
    }
    std::pair<Eigen::SparseMatrix<double>, Eigen::VectorXd> operators =
        cotangent_laplacian(tm, index, [&](std::size_t i) {
          return Epick_point_3(points(Eigen::Index(i), 0), points(Eigen::Index(i), 1),
                               points(Eigen::Index(i), 2));
        });
    laplacian = std::move(operators.first);
    mass = std::move(operators.second);
  }
};

template <typename TriangleMesh, typename VertexPointMap, typename BasePointMap, typename DetailMap,
          typename Options>
Laplacian_detail_result extract_laplacian_detail_impl(const TriangleMesh& tm, VertexPointMap vpm,
                                                      BasePointMap base, DetailMap detail,
                                                      const Options& options) {
  Laplacian_detail_result result;
  if (faces(tm).empty()) {
    result.status = Laplacian_detail_status::empty_mesh;
    result.message = "the mesh has no faces";
    return result;
  }
  const Laplacian_base<TriangleMesh> b(tm, base, options.reference_axis);
  Eigen::MatrixX3d offset(b.points.rows(), 3);
  for (std::size_t i = 0; i < b.ordered.size(); ++i) {
    const auto& p = get(vpm, b.ordered[i]);
    offset.row(Eigen::Index(i)) =
        Eigen::RowVector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())) -
        b.points.row(Eigen::Index(i));
  }
  // Eq. 5: L(X) − L(B) = L(X − B) with the base's operator, per unit of area (so a detail read on
  // one mesh means the same on a finer or coarser one); eq. 6: in the vertex's frame.
  const Eigen::MatrixX3d laplacian = b.laplacian * offset;
  for (std::size_t i = 0; i < b.ordered.size(); ++i) {
    const double m = b.mass[Eigen::Index(i)];
    const Eigen::Vector3d delta =
        m > 0 ? Eigen::Vector3d(laplacian.row(Eigen::Index(i)).transpose() / m)
              : Eigen::Vector3d::Zero();
    const auto& frame = b.frames[i];
    put(detail, b.ordered[i],
        std::array<double, 3>{{delta.dot(frame[0]), delta.dot(frame[1]), delta.dot(frame[2])}});
    result.vertices += delta.squaredNorm() > 0 ? 1 : 0;
    result.largest_detail = std::max(result.largest_detail, delta.norm());
  }
  return result;
}

template <typename TriangleMesh, typename FreeMap, typename BasePointMap, typename DetailMap,
          typename OutPointMap, typename Options>
Laplacian_detail_result
reconstruct_from_laplacian_detail_impl(const TriangleMesh& tm, FreeMap is_free, BasePointMap base,
                                       DetailMap detail, OutPointMap out, const Options& options) {
  using Point = typename boost::property_traits<OutPointMap>::value_type;
  using Matrix = Eigen::SparseMatrix<double>;
  Laplacian_detail_result result;
  auto fail = [&](Laplacian_detail_status status, std::string message) {
    result.status = status;
    result.message = std::move(message);
    return result;
  };
  if (faces(tm).empty())
    return fail(Laplacian_detail_status::empty_mesh, "the mesh has no faces");
  const Laplacian_base<TriangleMesh> b(tm, base, options.reference_axis);
  constexpr std::size_t fixed = not_free;
  std::vector<std::size_t> unknown(b.ordered.size(), fixed), owners;
  for (std::size_t i = 0; i < b.ordered.size(); ++i)
    if (get(is_free, b.ordered[i])) {
      unknown[i] = owners.size();
      owners.push_back(i);
    }
  if (owners.empty())
    return fail(Laplacian_detail_status::no_free_vertex, "no vertex is free");
  if (!(options.anchor_wavelength > 0)) {
    // Without soft constraints each connected group of free vertices needs a held neighbour,
    // or L on it is singular (a translation costs nothing): the groups reached from the held
    // vertices along edges must be all of them.
    std::vector<char> reached(b.ordered.size(), 0);
    std::vector<std::size_t> stack;
    for (std::size_t i = 0; i < b.ordered.size(); ++i)
      if (unknown[i] == fixed) {
        reached[i] = 1;
        stack.push_back(i);
      }
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      for (auto w : CGAL::vertices_around_target(halfedge(b.ordered[i], tm), tm))
        if (!reached[get(b.index, w)]) {
          reached[get(b.index, w)] = 1;
          stack.push_back(get(b.index, w));
        }
    }
    if (std::find(reached.begin(), reached.end(), 0) != reached.end())
      return fail(Laplacian_detail_status::solve_failed,
                  "a group of free vertices has no held neighbour: the Poisson solve does not "
                  "fix its position (hold a vertex of it, or give anchor_wavelength)");
  }
  // Eqs. 10–11: L X' = L B + M R δ on the free rows, the held vertices' columns moved to the
  // right-hand side. −L restricted to the free vertices is positive definite when every group of
  // them touches a held vertex, so one LDLᵀ factorization solves the three coordinates.
  Eigen::MatrixX3d held(b.points.rows(), 3);
  for (std::size_t i = 0; i < b.ordered.size(); ++i) {
    const Point p = get(out, b.ordered[i]);
    held.row(Eigen::Index(i)) << CGAL::to_double(p.x()), CGAL::to_double(p.y()),
        CGAL::to_double(p.z());
  }
  const Eigen::MatrixX3d base_laplacian = b.laplacian * b.points;
  const Eigen::Index n = Eigen::Index(owners.size());
  Eigen::MatrixX3d rhs(n, 3);
  for (Eigen::Index k = 0; k < n; ++k) {
    const std::size_t i = owners[std::size_t(k)];
    const std::array<double, 3> d = get(detail, b.ordered[i]);
    const auto& frame = b.frames[i];
    const Eigen::Vector3d rotated = d[0] * frame[0] + d[1] * frame[1] + d[2] * frame[2];
    rhs.row(k) =
        -(base_laplacian.row(Eigen::Index(i)) + b.mass[Eigen::Index(i)] * rotated.transpose());
  }
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index col = 0; col < b.laplacian.outerSize(); ++col)
    for (Matrix::InnerIterator it(b.laplacian, col); it; ++it) {
      const std::size_t row = unknown[std::size_t(it.row())];
      if (row == fixed)
        continue;
      const std::size_t c = unknown[std::size_t(col)];
      if (c != fixed)
        entries.emplace_back(Eigen::Index(row), Eigen::Index(c), -it.value());
      else
        rhs.row(Eigen::Index(row)) += it.value() * held.row(col);
    }
  Matrix system(n, n);
  system.setFromTriplets(entries.begin(), entries.end());
  if (options.anchor_wavelength > 0) {
    // The soft constraints: the normal equations of the weighted least squares,
    // (Kᵀ M⁻¹ K + μ M) X = Kᵀ M⁻¹ r + μ M A with K = −L on the free vertices and r the
    // right-hand side above.
    const double mu = std::pow(2 * CGAL_PI / options.anchor_wavelength, 4);
    Eigen::VectorXd inverse_mass(n), mass(n);
    Eigen::MatrixX3d anchors(n, 3);
    for (Eigen::Index k = 0; k < n; ++k) {
      const std::size_t i = owners[std::size_t(k)];
      mass[k] = b.mass[Eigen::Index(i)];
      inverse_mass[k] = mass[k] > 0 ? 1 / mass[k] : 0;
      anchors.row(k) = held.row(Eigen::Index(i));
    }
    rhs = Eigen::MatrixX3d(system.transpose() * (inverse_mass.asDiagonal() * rhs)) +
          mu * (mass.asDiagonal() * anchors);
    system = Matrix(system.transpose() * inverse_mass.asDiagonal() * system);
    system += Matrix(Eigen::VectorXd(mu * mass).asDiagonal());
  }
  const Eigen::SimplicialLDLT<Matrix> solver(system);
  if (solver.info() != Eigen::Success)
    return fail(Laplacian_detail_status::solve_failed,
                "the Poisson system could not be factored (a group of free vertices has no held "
                "neighbour)");
  const Eigen::MatrixX3d x = solver.solve(rhs);
  if (solver.info() != Eigen::Success || !x.allFinite())
    return fail(Laplacian_detail_status::solve_failed,
                "the Poisson system could not be solved (a group of free vertices has no held "
                "neighbour)");
  for (Eigen::Index k = 0; k < n; ++k)
    put(out, b.ordered[owners[std::size_t(k)]], Point(x(k, 0), x(k, 1), x(k, 2)));
  result.vertices = owners.size();
  return result;
}

} // namespace tessera::internal
