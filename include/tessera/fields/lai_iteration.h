// The reference iteration of Lai, Hu, Martin, "Surface Mosaics" (2006), eq. 1: start from zero
// vectors except at the controls and repeat X' = X + t Σ_i W_i (X̂_i − X). Kept to compare against
// `smoothest_field()`, which reaches the optimum of the same smoothness in one solve.
#pragma once

#include <tessera/fields/smoothest_field.h>

#include <cstddef>
#include <string>
#include <vector>

namespace tessera {

/// Options of `lai_iteration_field()`.
struct Lai_iteration_options {
  /// Step t of eq. 1 (the paper uses 0.1).
  double step = 0.1;
  std::size_t max_iterations = 100000;
  /// Stop when no vector moves by more than this in one step.
  double tolerance = 1e-10;
  /// Stop after this many seconds (0: no limit), to compare methods in a fixed budget.
  double time_budget_seconds = 0;
};

/// Summary of `lai_iteration_field()`.
struct Lai_iteration_result {
  Field_status status = Field_status::ok;
  std::string message;
  std::size_t iterations = 0;
  /// True when the tolerance was reached.
  bool converged = false;
  double seconds = 0;
  explicit operator bool() const { return status == Field_status::ok; }
};

/// Eq. 1 of Lai et al. for a 1-vector field: the control vertices keep their (unit, tangential)
/// directions; every other vertex moves towards the 1/edge-length-weighted mean of its neighbours'
/// vectors projected into its tangent plane. Only hard constraints are accepted. `field` receives
/// the vectors as they are when the iteration stops (not normalized).
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh, typename VertexFieldMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Lai_iteration_result lai_iteration_field(
    const TriangleMesh& tm,
    const std::vector<typename Smoothest_field_solver<TriangleMesh>::Constraint>& constraints,
    VertexFieldMap field, const Lai_iteration_options& options = {},
    const NamedParameters& np = CGAL::parameters::default_values());

} // namespace tessera

#include <tessera/fields/internal/lai_iteration_impl.h>
