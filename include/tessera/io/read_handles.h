// Reading deformation handles from JSON (the `--handles` file of `tessera deform`, documented in
// doc/resizing.md): a non-empty "handles" array, each handle a vertex selection ("vertices",
// "sphere" or "box") with a transform ("translate", "rotate", "twist", "scale", "center"), and an
// optional "region" of interest. Compiled into Tessera::core (nlohmann-json stays private).
#pragma once

#include <tessera/resizing/deform.h>

#include <istream>
#include <optional>
#include <string>
#include <vector>

namespace tessera {

enum class Handles_read_status {
  ok,
  cannot_open,
  /// Not JSON at all (the message gives the parser's position).
  not_json,
  /// JSON, but not the handles format: a missing or ill-typed field (the message names it).
  bad_field
};

struct Handles_read_result {
  Handles_read_status status = Handles_read_status::ok;
  /// What is wrong and where ("handle 2: sphere radius must be a finite number").
  std::string message;
  std::vector<Deformation_handle> handles;
  /// The file's "region", when given: the vertices that may move.
  std::optional<Vertex_selection> region;
  explicit operator bool() const { return status == Handles_read_status::ok; }
};

/// Reads handles from `in`. Angles are read in degrees and returned in radians. Nothing is kept
/// unless the whole input reads: on failure `handles` is empty and `region` unset.
Handles_read_result read_deformation_handles(std::istream& in);

/// Reads handles from the file at `path`.
Handles_read_result read_deformation_handles(const std::string& path);

} // namespace tessera
