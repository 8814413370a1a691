// Implementation of tessera::field_singularities (see tessera/fields/singularities.h).
#pragma once

#include <tessera/fields/singularities.h>

#include <tessera/fields/smoothest_field.h>
#include <CGAL/boost/graph/helpers.h>
#include <cmath>
#include <complex>
#include <cstddef>
#include <string>
#include <vector>

namespace tessera {

template <typename TriangleMesh, typename VertexFieldMap, typename NamedParameters>
Field_singularities<TriangleMesh> field_singularities(const TriangleMesh& tm,
                                                      const VertexFieldMap& field, int symmetry,
                                                      const NamedParameters& np) {
  using GT = boost::graph_traits<TriangleMesh>;
  Field_singularities<TriangleMesh> result;
  result.symmetry = symmetry;
  if (!is_valid_symmetry(symmetry)) {
    result.status = Field_status::invalid_symmetry;
    result.message = "symmetry must be 1, 2 or 4 (got " + std::to_string(symmetry) + ")";
    return result;
  }
  if (!CGAL::is_triangle_mesh(tm)) {
    result.status = Field_status::not_triangle_mesh;
    result.message = "the mesh is not a triangle mesh";
    return result;
  }
  const internal::Vertex_frames<TriangleMesh> frames(tm, np);
  const std::vector<std::complex<double>> u = internal::power_vectors(frames, field, symmetry);
  const double two_pi = 2 * frames.pi();
  // Turning of the power vector along h beyond the transport, in (−π, π].
  auto turning = [&](typename GT::halfedge_descriptor h) {
    const std::size_t i = frames.index(source(h, tm)), j = frames.index(target(h, tm));
    const std::complex<double> ui = u[i] == 0.0 ? 1.0 : u[i], uj = u[j] == 0.0 ? 1.0 : u[j];
    return std::arg(uj * std::conj(internal::edge_transport(frames, h, symmetry) * ui));
  };
  auto round_numerator = [&](double x) {
    const double r = std::round(x);
    result.integrality_defect = std::max(result.integrality_defect, std::abs(x - r));
    return int(r);
  };
  for (auto f : faces(tm)) {
    double sum = symmetry * frames.holonomy(f);
    for (auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm))
      sum += turning(h);
    const int k = round_numerator(sum / two_pi);
    result.face_index_sum += k;
    if (k != 0)
      result.singularities.push_back({f, k});
  }
  // Boundary loops: the faces' turning terms along the border do not cancel, and the border
  // vertices' angle deficits π − Θ_v are missing from the holonomies; together they make the loop's
  // index.
  auto visited = get(CGAL::dynamic_halfedge_property_t<bool>(), tm);
  for (auto h : halfedges(tm))
    put(visited, h, false);
  for (auto h : halfedges(tm)) {
    if (!is_border(h, tm) || get(visited, h))
      continue;
    double sum = 0;
    for (auto b : CGAL::halfedges_around_face(h, tm)) {
      put(visited, b, true);
      sum -= turning(opposite(b, tm));
      sum += symmetry * (frames.pi() - frames.angle_sum(frames.index(target(b, tm))));
    }
    const int k = round_numerator(sum / two_pi);
    result.boundary_index_sum += k;
    result.boundary_loops.push_back({h, k});
  }
  result.euler_characteristic =
      long(vertices(tm).size()) - long(edges(tm).size()) + long(faces(tm).size());
  return result;
}

} // namespace tessera
