// Control vectors (read by `read_control_vectors`, tessera/io/read_control_vectors.h) turned into
// the constraints of the smoothest field: a vertex control constrains its vertex, a face control
// the face's corners by its barycentric coordinates (`face_point_constraints`).
#pragma once

#include <tessera/fields/smoothest_field.h>
#include <tessera/io/read_control_vectors.h>

#include <cstddef>
#include <string>
#include <vector>

namespace tessera {

template <typename TriangleMesh> struct Control_constraints_result {
  /// `ok`, or `invalid_constraint` with the control's number in `message`.
  Field_status status = Field_status::ok;
  std::string message;
  std::vector<typename Smoothest_field_solver<TriangleMesh>::Constraint> constraints;
  explicit operator bool() const { return status == Field_status::ok; }
};

/// The constraints of `controls` on `tm`: indices must name a vertex or face of `tm`, barycentric
/// coordinates be non-negative and sum to 1. Nothing is returned unless every control is valid.
template <typename TriangleMesh>
Control_constraints_result<TriangleMesh>
control_vector_constraints(const TriangleMesh& tm, const std::vector<Control_vector>& controls) {
  using Solver = Smoothest_field_solver<TriangleMesh>;
  using Vector = typename Solver::Vector_3;
  Control_constraints_result<TriangleMesh> r;
  const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> vs(
      vertices(tm).begin(), vertices(tm).end());
  const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> fs(
      faces(tm).begin(), faces(tm).end());
  auto fail = [&](std::size_t k, const std::string& what) {
    r.status = Field_status::invalid_constraint;
    r.message = "control " + std::to_string(k) + ": " + what;
    r.constraints.clear();
    return r;
  };
  for (std::size_t k = 0; k < controls.size(); ++k) {
    const Control_vector& c = controls[k];
    const Vector d(c.direction[0], c.direction[1], c.direction[2]);
    const Constraint_kind kind = c.weight ? Constraint_kind::soft : Constraint_kind::hard;
    const double weight = c.weight ? *c.weight : 1.0;
    if (c.location == Control_vector::Location::vertex) {
      if (c.index >= vs.size())
        return fail(k, "\"vertex\" must be an index below " + std::to_string(vs.size()));
      r.constraints.push_back({vs[c.index], d, kind, weight});
    } else {
      if (c.index >= fs.size())
        return fail(k, "\"face\" must be an index below " + std::to_string(fs.size()));
      const auto on_face = face_point_constraints(tm, fs[c.index], c.barycentric, d, kind, weight);
      if (on_face.empty())
        return fail(k, "barycentric coordinates must be non-negative and sum to 1");
      r.constraints.insert(r.constraints.end(), on_face.begin(), on_face.end());
    }
  }
  return r;
}

} // namespace tessera
