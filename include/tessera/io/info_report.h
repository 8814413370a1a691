// What `tessera info --json` prints (and `tessera demo` writes to info.json), for library users: a
// plain report of `mesh_info()` and of what reading repaired, and its JSON writer compiled into
// Tessera::core (nlohmann-json stays private). The keys and their meanings are doc/formats.md's;
// the CLI writes through this and nothing else.
#pragma once

#include <tessera/io/mesh_repair.h>
#include <tessera/validation/mesh_info.h>

#include <ostream>

namespace tessera {

/// The JSON of `tessera info`: the figures of `mesh_info()` ("connected_components" is the
/// number of its components) and the repairs of `read_mesh()`.
struct Info_report {
  Mesh_info info;
  Mesh_changes repairs;
};

/// Writes `report` as JSON (indented by 2); false when the stream failed.
bool write_info_report(std::ostream& out, const Info_report& report);

} // namespace tessera
