// Singularities of a vertex-based n-direction field: the index of every face from the field's
// turning along its edges plus n times its holonomy (Knöppel et al. 2013, §5.2; Ray et al. 2008),
// and the index of every boundary loop, so that Σ face indices + Σ boundary indices = χ
// (Poincaré–Hopf).
#pragma once

#include <tessera/fields/smoothest_field.h>

#include <string>
#include <vector>

namespace tessera {

/// A face around which the field turns: its index is `numerator / symmetry` (±1/4 for a cross
/// field's valence-3 and valence-5 points, ±1/2, ±1, …).
template <typename FaceDescriptor> struct Face_singularity {
  FaceDescriptor face;
  int numerator = 0;
};

/// Index of the field along one boundary loop (`halfedge` is a border halfedge of it): how much
/// less the field turns than the boundary, in turns times n. It is 0 when the field is tangent (or
/// normal) to the boundary all along the loop.
template <typename HalfedgeDescriptor> struct Boundary_index {
  HalfedgeDescriptor halfedge;
  int numerator = 0;
};

/// Result of `field_singularities()`.
template <typename TriangleMesh> struct Field_singularities {
  using GT = boost::graph_traits<TriangleMesh>;
  Field_status status = Field_status::ok;
  std::string message;
  int symmetry = 1;
  /// Faces with a non-zero index.
  std::vector<Face_singularity<typename GT::face_descriptor>> singularities;
  std::vector<Boundary_index<typename GT::halfedge_descriptor>> boundary_loops;
  /// Σ of the face numerators and of the boundary numerators (indices times n).
  long face_index_sum = 0;
  long boundary_index_sum = 0;
  /// V − E + F of the mesh (all components).
  long euler_characteristic = 0;
  /// Largest distance of an index numerator from the nearest integer before rounding: round-off
  /// only, a check that the discrete theory holds.
  double integrality_defect = 0;
  /// (Σ face + Σ boundary numerators) == n χ.
  bool poincare_hopf_holds() const {
    return face_index_sum + boundary_index_sum == long(symmetry) * euler_characteristic;
  }
  explicit operator bool() const { return status == Field_status::ok; }
};

/// Index of every face and boundary loop of `field`, read as a symmetry-n field (a vertex map of
/// vectors; zero vectors count as pointing along e1). Works on closed and bordered triangle meshes.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh, typename VertexFieldMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Field_singularities<TriangleMesh>
field_singularities(const TriangleMesh& tm, const VertexFieldMap& field, int symmetry,
                    const NamedParameters& np = CGAL::parameters::default_values());

} // namespace tessera

#include <tessera/fields/internal/singularities_impl.h>
