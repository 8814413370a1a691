// Tangent fields as property maps: a field is a vertex property map of `Vector_3` plus its symmetry
// order n (1 vector, 2 line, 4 cross field), following the n-direction fields of Knöppel et al.
// 2013 and the 1- and 4-fields of Lai, Hu, Martin, "Surface Mosaics" (§3.1). Shared types live
// here.
#pragma once

#include <tessera/fields/internal/vertex_frames.h>

#include <cstddef>
#include <limits>
#include <string>

namespace tessera {

/// Outcome of the field algorithms.
enum class Field_status {
  ok,
  invalid_symmetry,   ///< symmetry order not 1, 2 or 4
  invalid_constraint, ///< a constraint on no vertex, with a non-finite or normal direction, a bad
                      ///< weight
  conflicting_constraints, ///< two hard constraints at one vertex that disagree
  not_triangle_mesh,
  empty_mesh,
  solver_failed,  ///< the sparse factorization failed (should not happen on a valid mesh)
  invalid_options ///< an options struct's value out of its range (the message names it)
};

/// True for the symmetry orders Tessera supports: 1 (vectors), 2 (lines), 4 (crosses).
inline bool is_valid_symmetry(int n) {
  return n == 1 || n == 2 || n == 4;
}

/// Whether a constraint is met exactly (eliminated from the system) or traded against smoothness.
enum class Constraint_kind { hard, soft };

/// A direction asked for at one vertex. `direction` is projected to the vertex's tangent plane (its
/// length does not matter); for a symmetry-n field any of its n rotations about the normal meets
/// it. `weight` (soft only, > 0) scales the term |u_v − c_v|² against the vertex's own smoothness
/// stiffness: 1 balances them, larger pulls harder.
template <typename VertexDescriptor, typename Vector> struct Direction_constraint {
  VertexDescriptor vertex;
  Vector direction;
  Constraint_kind kind = Constraint_kind::hard;
  double weight = 1;
};

/// The unit vectors (N, e1, e2) of vertex v's tangent frame: N the angle-weighted vertex normal,
/// e1 the projection of the reference outgoing edge (the first border edge on the border), e2 = N ×
/// e1. Field angles are measured from e1 towards e2.
template <typename Vector> struct Tangent_basis { Vector normal, e1, e2; };

/// Writes into `orthogonal` the field N × X of `field` (same lengths): the orthogonal 1- or 2-field
/// of Lai et al.; for a 4-field it is the same cross. Both maps may be the same.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh, typename VertexFieldMap, typename OutputFieldMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
void orthogonal_field(const TriangleMesh& tm, const VertexFieldMap& field,
                      OutputFieldMap orthogonal,
                      const NamedParameters& np = CGAL::parameters::default_values()) {
  const internal::Vertex_frames<TriangleMesh> frames(tm, np);
  using Vector = typename boost::property_traits<OutputFieldMap>::value_type;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const auto v = frames.vertex(i);
    const internal::Vec3 x = internal::to_vec3(get(field, v));
    const internal::Vec3 r = internal::cross(
        frames.normal(i), x - internal::dot(x, frames.normal(i)) * frames.normal(i));
    put(orthogonal, v, Vector(r[0], r[1], r[2]));
  }
}

/// Tangent frames of all vertices, in the convention every field function uses (see
/// `Tangent_basis`).
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh, typename BasisMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
void vertex_tangent_bases(const TriangleMesh& tm, BasisMap bases,
                          const NamedParameters& np = CGAL::parameters::default_values()) {
  using Vector =
      decltype(std::declval<typename boost::property_traits<BasisMap>::value_type>().normal);
  const internal::Vertex_frames<TriangleMesh> frames(tm, np);
  auto vec = [](const internal::Vec3& a) { return Vector(a[0], a[1], a[2]); };
  for (std::size_t i = 0; i < frames.size(); ++i)
    put(bases, frames.vertex(i),
        Tangent_basis<Vector>{vec(frames.normal(i)), vec(frames.e1(i)), vec(frames.e2(i))});
}

} // namespace tessera
