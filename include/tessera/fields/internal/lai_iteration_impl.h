// Implementation of tessera::lai_iteration_field (see tessera/fields/lai_iteration.h).
#pragma once

#include <tessera/fields/lai_iteration.h>

#include <tessera/fields/smoothest_field.h>
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <string>
#include <vector>

namespace tessera {

template <typename TriangleMesh, typename VertexFieldMap, typename NamedParameters>
Lai_iteration_result lai_iteration_field(
    const TriangleMesh& tm,
    const std::vector<typename Smoothest_field_solver<TriangleMesh>::Constraint>& constraints,
    VertexFieldMap field, const Lai_iteration_options& options, const NamedParameters& np) {
  using Clock = std::chrono::steady_clock;
  using internal::Vec3;
  using Vector = typename Smoothest_field_solver<TriangleMesh>::Vector_3;
  const auto start = Clock::now();
  Lai_iteration_result result;
  const internal::Vertex_frames<TriangleMesh> frames(tm, np);
  const std::size_t nv = frames.size();
  std::vector<Vec3> x(nv, Vec3{{0, 0, 0}});
  std::vector<char> fixed(nv, 0);
  for (std::size_t k = 0; k < constraints.size(); ++k) {
    const auto& c = constraints[k];
    if (c.kind != Constraint_kind::hard || !internal::is_vertex_of(tm, c.vertex, 0)) {
      result.status = Field_status::invalid_constraint;
      result.message = "constraint " + std::to_string(k) + " is not a hard constraint on a vertex";
      return result;
    }
    const std::size_t i = frames.index(c.vertex);
    const std::complex<double> p = frames.to_power(i, internal::to_vec3(c.direction), 1);
    if (!(std::abs(p) > 0) || !std::isfinite(std::abs(p))) {
      result.status = Field_status::invalid_constraint;
      result.message = "constraint " + std::to_string(k) + " has no finite tangential direction";
      return result;
    }
    x[i] = frames.from_power(i, p, 1, true);
    fixed[i] = 1;
  }
  // Neighbours and normalized weights W_i ∝ 1 / edge length, in compressed rows.
  std::vector<std::size_t> offset(nv + 1, 0), neighbour;
  std::vector<double> weight;
  for (std::size_t i = 0; i < nv; ++i) {
    const auto v = frames.vertex(i);
    double total = 0;
    const std::size_t first = neighbour.size();
    if (halfedge(v, tm) != boost::graph_traits<TriangleMesh>::null_halfedge())
      for (auto h : CGAL::halfedges_around_source(v, tm)) {
        neighbour.push_back(frames.index(target(h, tm)));
        weight.push_back(internal::edge_weight(frames, h));
        total += weight.back();
      }
    for (std::size_t k = first; k < weight.size(); ++k)
      weight[k] /= total;
    offset[i + 1] = neighbour.size();
  }
  std::vector<Vec3> next = x;
  for (; result.iterations < options.max_iterations; ++result.iterations) {
    double largest_move = 0;
    for (std::size_t i = 0; i < nv; ++i) {
      if (fixed[i])
        continue;
      const Vec3& n = frames.normal(i);
      Vec3 pull{{0, 0, 0}};
      for (std::size_t k = offset[i]; k < offset[i + 1]; ++k) {
        const Vec3& xj = x[neighbour[k]];
        const Vec3 projected = xj - internal::dot(xj, n) * n; // X̂_i of eq. 1
        pull = pull + weight[k] * (projected - x[i]);
      }
      next[i] = x[i] + options.step * pull;
      largest_move = std::max(largest_move, options.step * internal::norm(pull));
    }
    x.swap(next);
    if (largest_move <= options.tolerance) {
      result.converged = true;
      ++result.iterations;
      break;
    }
    if (options.time_budget_seconds > 0 && (result.iterations & 15) == 0 &&
        std::chrono::duration<double>(Clock::now() - start).count() > options.time_budget_seconds) {
      ++result.iterations;
      break;
    }
  }
  for (std::size_t i = 0; i < nv; ++i)
    put(field, frames.vertex(i), Vector(x[i][0], x[i][1], x[i][2]));
  result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

} // namespace tessera
