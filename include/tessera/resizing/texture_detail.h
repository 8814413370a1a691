// Splitting a textured surface into a smooth base and a scalar detail (Chen and Meng, SPM 2009 and
// CAD 2010, §3.3): implicit fairing (Desbrun, Meyer, Schröder, Barr 1999), (I − λdt·L)X^{n+1} = X^n
// with λdt on the texture region and 0 elsewhere (eq. 4), smooths the texture away and leaves the
// rest of the surface where it is; by default with the bi-Laplacian in place of L, which keeps a
// curved base's curvature (see Fairing_operator). Optionally the faired vertices of a closed
// surface are rescaled about the centroid to keep its volume (conference eq. 4). The detail is each
// vertex's offset from the base along the base's normal (the conference version's displacement).
#pragma once

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <string>
#include <vector>

namespace tessera {

/// The fairing operator.
enum class Fairing_operator {
  /// Eq. 4 as published, (I − λdt·L)X^{n+1} = X^n with the umbrella operator L: mean-curvature
  /// flow, which also flattens a curved base towards the membrane spanning the region's border (a
  /// bumpy patch of a cylinder of radius 1 loses a tenth of its sagitta per few iterations).
  laplacian,
  /// (I + λdt·L²)X^{n+1} = X^n: thin-plate fairing. A frequency with umbrella eigenvalue μ is
  /// damped by 1/(1 + λdt·μ²) instead of 1/(1 + λdt·μ), so texels (μ ~ 0.5) go as fast while the
  /// base's curvature (μ ~ 0.01) stays: a cylinder keeps its radius, a sphere its roundness.
  bilaplacian
};

struct Detail_extraction_options {
  Fairing_operator fairing = Fairing_operator::bilaplacian;
  /// λ·dt of eq. 4 on texture vertices (0 elsewhere, so untextured vertices stay put).
  double lambda_dt = 10;
  std::size_t max_iterations = 200;
  /// Stop once no vertex moved more than this fraction of the mean edge length in an iteration.
  double tolerance = 1e-3;
  /// On closed surfaces, rescale the faired vertices about the centroid after each iteration so
  /// the enclosed volume stays the input's (conference eq. 4). Off by default: when the texture
  /// covers part of the surface, rescaling that part about the centroid lifts it off the rest
  /// (a step at the region's border), and the detail keeps the texels' volume anyway.
  bool preserve_volume = false;
};

enum class Detail_extraction_status {
  ok,
  empty_mesh,
  /// No vertex is marked as texture.
  no_texture,
  /// The fairing matrix could not be factored.
  solve_failed
};

struct Detail_extraction_result {
  Detail_extraction_status status = Detail_extraction_status::ok;
  std::string message;
  std::size_t iterations = 0;
  std::size_t texture_vertices = 0;
  /// Largest |detail| over the texture vertices, and the mean edge length it is measured against.
  double max_height = 0;
  double mean_edge_length = 0;
  /// Enclosed volume of the base over the input's (1 when kept, or for bordered surfaces).
  double volume_ratio = 1;
  explicit operator bool() const { return status == Detail_extraction_status::ok; }
};

/// Fairs the texture region of `tm` (vertices where `is_texture` is true) into a base surface
/// written to `base` (a writable vertex map of the mesh's point type), and writes each vertex's
/// detail, its offset from the base along the base's vertex normal, to `height` (a writable vertex
/// map of double; 0 off the texture). `tm` itself is not changed; base and input share
/// connectivity.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh, typename VertexTextureMap, typename BasePointMap,
          typename HeightMap, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Detail_extraction_result
extract_detail(const TriangleMesh& tm, VertexTextureMap is_texture, BasePointMap base,
               HeightMap height, const Detail_extraction_options& options = {},
               const NamedParameters& np = CGAL::parameters::default_values()) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Point = typename boost::property_traits<BasePointMap>::value_type;
  const auto vpm = CGAL::parameters::choose_parameter(
      CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
      get_const_property_map(CGAL::vertex_point, tm));
  Detail_extraction_result result;
  if (faces(tm).empty()) {
    result.status = Detail_extraction_status::empty_mesh;
    result.message = "the mesh has no faces";
    return result;
  }
  // Unknowns: the texture vertices, numbered in the order of vertices(tm).
  constexpr std::size_t fixed = std::size_t(-1);
  auto index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  std::vector<vertex_descriptor> free;
  for (vertex_descriptor v : vertices(tm)) {
    put(base, v, get(vpm, v));
    put(height, v, 0.0);
    put(index, v, get(is_texture, v) ? free.size() : fixed);
    if (get(is_texture, v))
      free.push_back(v);
  }
  result.texture_vertices = free.size();
  if (free.empty()) {
    result.status = Detail_extraction_status::no_texture;
    result.message = "no vertex is marked as texture";
    return result;
  }
  double total_length = 0;
  for (auto e : edges(tm))
    total_length += PMP::edge_length(halfedge(e, tm), tm, CGAL::parameters::vertex_point_map(vpm));
  result.mean_edge_length = total_length / double(num_edges(tm));

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
  const Eigen::SparseMatrix<double> op = options.fairing == Fairing_operator::laplacian
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
    result.status = Detail_extraction_status::solve_failed;
    result.message = "the fairing matrix could not be factored";
    return result;
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

  for (vertex_descriptor v : free) {
    const auto normal = PMP::compute_vertex_normal(v, tm, CGAL::parameters::vertex_point_map(base));
    const double h = CGAL::to_double((get(vpm, v) - get(base, v)) * normal);
    put(height, v, h);
    result.max_height = std::max(result.max_height, std::abs(h));
  }
  return result;
}

} // namespace tessera
