// What the JSON writers of the result reports share (internal to Tessera::core, not installed): the
// last step of every writer, and the "repairs" object several reports carry.
#pragma once

#include <tessera/io/mesh_repair.h>

#include <nlohmann/json.hpp>

#include <ostream>

namespace tessera::io_internal {

/// `j` indented by `indent` and a newline into `out`; false when the stream failed.
inline bool dump(std::ostream& out, const nlohmann::json& j, int indent = 1) {
  out << j.dump(indent) << "\n";
  return bool(out);
}

/// What reading changed in a mesh, as the "repairs" object of a report.
inline nlohmann::json repairs_json(const Mesh_changes& changes) {
  return {{"merged_vertices", changes.merged_vertices},
          {"removed_vertices", changes.removed_vertices},
          {"split_faces", changes.split_faces},
          {"removed_faces", changes.removed_faces},
          {"reoriented_faces", changes.reoriented_faces},
          {"pinched_vertices", changes.pinched_vertices},
          {"non_manifold_edges", changes.non_manifold_edges}};
}

} // namespace tessera::io_internal
