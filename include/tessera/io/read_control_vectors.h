// Reading control vectors for direction fields from JSON (the `--control` file of `tessera field`
// and `tessera mosaic`, documented in doc/fields.md):
//   {"controls": [{"vertex": 12, "direction": [1, 0, 0]},
//                 {"face": 7, "barycentric": [0.2, 0.3, 0.5], "direction": [0, 1, 0], "weight":
//                 2}]}
// A control without "weight" is hard; with one it is soft. The file is read into plain structs
// (compiled into Tessera::core, nlohmann-json stays private); `control_vector_constraints()`
// (tessera/fields/control_vectors.h) checks them against a mesh and makes field constraints.
#pragma once

#include <array>
#include <cstddef>
#include <istream>
#include <optional>
#include <string>
#include <vector>

namespace tessera {

struct Control_vector {
  enum class Location { vertex, face };
  Location location = Location::vertex;
  /// Index of the vertex or face, in the order of `vertices(tm)` / `faces(tm)`.
  std::size_t index = 0;
  /// Where in the face (faces only), in the order of `vertices_around_face(halfedge(f, tm), tm)`.
  std::array<double, 3> barycentric{{1.0 / 3, 1.0 / 3, 1.0 / 3}};
  std::array<double, 3> direction{{0, 0, 0}};
  /// Soft control with this positive weight; hard when none.
  std::optional<double> weight;
};

enum class Control_vectors_read_status {
  ok,
  cannot_open,
  /// Not JSON at all (the message gives the parser's position).
  not_json,
  /// JSON, but not the control format: a missing or ill-typed field (the message names it).
  bad_field
};

struct Control_vectors_read_result {
  Control_vectors_read_status status = Control_vectors_read_status::ok;
  /// What is wrong and where ("control 2: \"weight\" must be a positive number").
  std::string message;
  std::vector<Control_vector> controls;
  explicit operator bool() const { return status == Control_vectors_read_status::ok; }
};

/// Reads control vectors from `in`. Directions and barycentric coordinates must be finite numbers,
/// weights positive. Nothing is kept unless the whole input reads.
Control_vectors_read_result read_control_vectors(std::istream& in);

/// Reads control vectors from the file at `path`.
Control_vectors_read_result read_control_vectors(const std::string& path);

} // namespace tessera
