// Principal curvature directions as an optional guide for the field: a degree-2 jet fitted to each
// vertex's 2-ring by CGAL's Monge_via_jet_fitting (Cazals, Pouget 2005) gives the directions, and
// soft constraints pull the field towards them where the surface is clearly anisotropic.
#pragma once

#include <tessera/fields/smoothest_field.h>

#include <tessera/fields/internal/jet_fitting.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace tessera {

/// Options of `principal_direction_constraints()`.
struct Principal_direction_options {
  /// Follow the direction of largest absolute curvature (true) or smallest (false); absolute values
  /// make the choice independent of the fitted normal's orientation. For a 4-field both give the
  /// same cross.
  bool maximal = true;
  /// Soft weight of the constraint at the most anisotropic vertex; others get weight·a / a_max with
  /// a = |k1 − k2| their anisotropy.
  double weight = 0.1;
  /// Vertices whose anisotropy is below this fraction of the largest get no constraint (umbilics
  /// and flat parts, where the directions are noise).
  double min_relative_anisotropy = 0.1;
};

/// Soft constraints along principal curvature directions (jet fitting over the 2-ring of each
/// vertex).
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<typename Smoothest_field_solver<TriangleMesh>::Constraint>
principal_direction_constraints(const TriangleMesh& tm,
                                const Principal_direction_options& options = {},
                                const NamedParameters& np = CGAL::parameters::default_values()) {
  using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Vector = typename Smoothest_field_solver<TriangleMesh>::Vector_3;
  const internal::Vertex_frames<TriangleMesh> frames(tm, np);
  const std::size_t nv = frames.size();
  std::vector<Vector> direction(nv);
  std::vector<double> anisotropy(nv, 0);
  internal::fit_vertex_jets(
      tm, 2,
      [&](auto w) {
        const internal::Vec3& p = frames.point(frames.index(w));
        return Epick::Point_3(p[0], p[1], p[2]);
      },
      [&](auto v, const auto& form) {
        const std::size_t i = frames.index(v);
        const double k1 = form.principal_curvatures(0), k2 = form.principal_curvatures(1);
        const bool first = (std::abs(k1) >= std::abs(k2)) == options.maximal;
        const auto d =
            first ? form.maximal_principal_direction() : form.minimal_principal_direction();
        const double a = std::abs(k1 - k2);
        if (!std::isfinite(a))
          return;
        direction[i] = Vector(d.x(), d.y(), d.z());
        anisotropy[i] = a;
      });
  const double largest = nv == 0 ? 0 : *std::max_element(anisotropy.begin(), anisotropy.end());
  std::vector<typename Smoothest_field_solver<TriangleMesh>::Constraint> out;
  if (!(largest > 0))
    return out;
  for (std::size_t i = 0; i < nv; ++i)
    if (anisotropy[i] >= options.min_relative_anisotropy * largest)
      out.push_back({frames.vertex(i), direction[i], Constraint_kind::soft,
                     options.weight * anisotropy[i] / largest});
  return out;
}

} // namespace tessera
