// The pieces of the smoothest-field solve (tessera/fields/smoothest_field.h) that are not its API:
// the sparse Cholesky chosen at build time, the power representation's edge transport, weights and
// energy, and the check that a constraint's vertex is one of the mesh's.
#pragma once

#include <tessera/fields/internal/vertex_frames.h>

#include <Eigen/Sparse>
#ifdef TESSERA_HAS_CHOLMOD
#include <Eigen/CholmodSupport>
#else
#include <Eigen/SparseCholesky>
#endif

#include <algorithm>
#include <complex>
#include <cstddef>
#include <vector>

namespace tessera {

namespace internal {

using Complex_sparse = Eigen::SparseMatrix<std::complex<double>>;
#ifdef TESSERA_HAS_CHOLMOD
using Sparse_cholesky = Eigen::CholmodDecomposition<Complex_sparse, Eigen::Lower>;
inline const char* sparse_cholesky_name() {
  return "CHOLMOD";
}
#else
using Sparse_cholesky = Eigen::SimplicialLDLT<Complex_sparse, Eigen::Lower>;
inline const char* sparse_cholesky_name() {
  return "Eigen SimplicialLDLT";
}
#endif

template <typename TriangleMesh>
std::complex<double> edge_transport(const Vertex_frames<TriangleMesh>& frames,
                                    typename Vertex_frames<TriangleMesh>::halfedge_descriptor h,
                                    int n) {
  return std::polar(1.0, n * frames.transport(h));
}

/// 1 / edge length, guarded against zero-length edges.
template <typename TriangleMesh>
double edge_weight(const Vertex_frames<TriangleMesh>& frames,
                   typename Vertex_frames<TriangleMesh>::halfedge_descriptor h) {
  return 1.0 / std::max(frames.length(h), 1e-300);
}

/// Σ_edges w_ij |u_j − r_ij u_i|² for power vectors u indexed like `frames`, without the edges
/// marked in `left_out` (by the order of edges(tm); empty: none).
template <typename TriangleMesh>
double power_field_energy(const Vertex_frames<TriangleMesh>& frames,
                          const std::vector<std::complex<double>>& u, int n,
                          const std::vector<char>& left_out = {}) {
  const TriangleMesh& tm = frames.mesh();
  double energy = 0;
  std::size_t k = 0;
  for (auto e : edges(tm)) {
    if (!left_out.empty() && left_out[k++])
      continue;
    const auto h = halfedge(e, tm);
    const std::size_t i = frames.index(source(h, tm)), j = frames.index(target(h, tm));
    energy += edge_weight(frames, h) * std::norm(u[j] - edge_transport(frames, h, n) * u[i]);
  }
  return energy;
}

template <typename TriangleMesh, typename VertexFieldMap>
std::vector<std::complex<double>> power_vectors(const Vertex_frames<TriangleMesh>& frames,
                                                const VertexFieldMap& field, int n) {
  std::vector<std::complex<double>> u(frames.size());
  for (std::size_t i = 0; i < frames.size(); ++i)
    u[i] = frames.to_power(i, to_vec3(get(field, frames.vertex(i))), n);
  return u;
}

// Surface_mesh-like descriptors know their index; others are trusted.
template <typename TriangleMesh, typename Descriptor>
auto is_vertex_of(const TriangleMesh& tm, Descriptor v, int) -> decltype(v.idx(), bool()) {
  return v != boost::graph_traits<TriangleMesh>::null_vertex() &&
         std::size_t(v.idx()) < num_vertices(tm);
}
template <typename TriangleMesh, typename Descriptor>
bool is_vertex_of(const TriangleMesh& tm, Descriptor v, long) {
  return v != boost::graph_traits<TriangleMesh>::null_vertex() && num_vertices(tm) > 0;
}

} // namespace internal

} // namespace tessera
