// The cotangent Laplacian and lumped vertex areas of a triangle mesh, shared by the fairing of
// resizing/ and the tile-scale smoothing of mosaic/.
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Weights/utils.h>
#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Sparse>

#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace tessera::internal {

using Epick_point_3 = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;

/// The cotangent Laplacian L of `tm` and its lumped vertex areas M, with the vertices numbered
/// by `index` (0 to num_vertices − 1) and vertex i at `position(i)` (an Epick point):
/// L_ij = (cot α + cot β)/2 summed over the faces at edge ij (CGAL::Weights::cotangent),
/// L_ii = −Σ_j L_ij; M_ii a third of the areas of i's triangles.
template <typename TriangleMesh, typename IndexMap, typename Position>
std::pair<Eigen::SparseMatrix<double>, Eigen::VectorXd>
cotangent_laplacian(const TriangleMesh& tm, const IndexMap& index, Position position) {
  const Eigen::Index total = Eigen::Index(num_vertices(tm));
  // Two off-diagonal entries per corner; the diagonal summed apart, one entry per vertex (twelve
  // triplets per face, unreserved, took twice as long at 200k faces).
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(6 * std::size_t(num_faces(tm)) + std::size_t(total));
  Eigen::VectorXd diagonal = Eigen::VectorXd::Zero(total);
  Eigen::VectorXd mass = Eigen::VectorXd::Zero(total);
  for (auto f : faces(tm)) {
    std::array<std::size_t, 3> c;
    std::size_t k = 0;
    for (auto v : CGAL::vertices_around_face(halfedge(f, tm), tm))
      c[k++] = get(index, v);
    std::array<Epick_point_3, 3> q;
    for (std::size_t a = 0; a < 3; ++a)
      q[a] = position(c[a]);
    const double area = std::sqrt(CGAL::squared_area(q[0], q[1], q[2]));
    for (std::size_t a = 0; a < 3; ++a) {
      const std::size_t i = c[a], j = c[(a + 1) % 3];
      const double w = 0.5 * CGAL::Weights::cotangent(q[a], q[(a + 2) % 3], q[(a + 1) % 3]);
      entries.emplace_back(Eigen::Index(i), Eigen::Index(j), w);
      entries.emplace_back(Eigen::Index(j), Eigen::Index(i), w);
      diagonal[Eigen::Index(i)] -= w;
      diagonal[Eigen::Index(j)] -= w;
      mass[Eigen::Index(i)] += area / 3;
    }
  }
  for (Eigen::Index i = 0; i < total; ++i)
    entries.emplace_back(i, i, diagonal[i]);
  Eigen::SparseMatrix<double> laplacian(total, total);
  laplacian.setFromTriplets(entries.begin(), entries.end());
  return {std::move(laplacian), std::move(mass)};
}

} // namespace tessera::internal
