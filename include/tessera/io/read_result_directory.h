// Reading a result directory of `tessera cut` or `tessera quadrangulate` back as a cutting, for
// tessera::validate_charts (and validate_refinement): mesh.off and opened.off as the files hold
// them, so that vertex ids keep their meaning, which vertex of mesh.off each vertex of opened.off
// copies, the marked multipoints, and what result.json says the charts form. The files are
// doc/formats.md's. Compiled into Tessera::core (nlohmann-json stays private).
#pragma once

#include <tessera/topology/validate_charts.h>
#include <tessera/types.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace tessera {

enum class Result_directory_status {
  ok,
  /// result.json, mesh.off or opened.off is missing (the message names the first missing one).
  not_a_result_directory,
  /// result.json is not JSON (the message gives the parser's).
  malformed_json,
  /// mesh.off is not a valid polygon mesh as written (the message is `read_mesh`'s).
  bad_mesh,
  /// opened.off is not a valid OFF polygon mesh with finite coordinates.
  bad_opened_mesh,
  /// result.json has no opened_to_mesh_vertex array, or it names a vertex mesh.off lacks.
  bad_vertex_map,
  /// result.json's "method" is not a string, where it decides what the charts form (the message is
  /// the JSON library's).
  bad_method
};

struct Result_directory_options {
  /// What the charts are expected to form. Unset: what result.json says, `quads` for a
  /// quadrangulation (it lists "quad_tiles"), `schema` for a cut whose "method" is "schema", else
  /// `disks`; "method" is then read (and must be a string when present).
  std::optional<Expected_cutting> expect;
};

/// A result directory read back: the surface, its charts (the opened mesh) and what they form, as
/// `validate_charts(mesh, opened, opened_to_mesh, {expect, multipoints})` takes them.
struct Result_directory {
  Result_directory_status status = Result_directory_status::ok;
  /// One line naming the directory or the file at fault; empty when ok.
  std::string message;
  /// The surface's file: the directory's mesh.off.
  std::string mesh_path;
  /// The surface's exact coordinates, mesh.exact.off beside mesh.off, when it exists (a run with
  /// `--kernel exact` writes it).
  std::optional<std::string> exact_mesh_path;
  /// mesh.off as written: vertex i is the file's i-th vertex, nothing repaired or triangulated.
  Mesh mesh;
  /// opened.off as written: the points of seam vertices repeated, each copy its own vertex.
  Mesh opened;
  /// The vertex of `mesh` each vertex of `opened` copies, in vertex order.
  std::vector<Mesh::Vertex_index> opened_to_mesh;
  /// The marked corners (vertices of `mesh`): the non-negative integers of result.json's
  /// "multipoints", in its order.
  std::vector<std::size_t> multipoints;
  /// What the charts are expected to form (see `Result_directory_options::expect`).
  Expected_cutting expect = Expected_cutting::disks;
  explicit operator bool() const { return status == Result_directory_status::ok; }
};

/// Reads the result directory `dir` (a path; messages name it as given). Checks, in this order,
/// that result.json, mesh.off and opened.off exist, that result.json is JSON, reads mesh.off and
/// opened.off, then opened_to_mesh_vertex (every id a vertex of mesh.off), the multipoints and,
/// unless `options.expect` is set, what the charts form. The first failure is the status; the
/// meshes are left as far as they were read.
Result_directory read_result_directory(const std::string& dir,
                                       const Result_directory_options& options = {});

} // namespace tessera
