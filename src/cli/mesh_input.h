// The input mesh of a command: one reader for every command, with the --strict and --repair flags,
// and one note on stderr saying what reading changed.
#pragma once

#include "commands.h"

#include <tessera/io/mesh_repair.h>
#include <tessera/types.h>

#include <string>

namespace tessera::cli {

/// Adds the positional `mesh` argument and the --strict / --repair flags to `cmd`.
void add_mesh_input(CLI::App* cmd, std::string& path, Mesh_input_flags& flags);

/// Reads `path` as the flags allow; throws User_error with the reader's message when refused, and
/// prints one note on stderr when reading triangulated or repaired the file. `changes` receives
/// what reading changed, for the command's JSON output.
Mesh read_input_mesh(const std::string& path, const Mesh_input_flags& flags,
                     Mesh_changes* changes = nullptr);

/// `mesh` (read from `path` by read_input_mesh()) with exact coordinates, for `--kernel exact`: the
/// file's own decimal or p/q text read without rounding when `path` is OFF or OBJ text and reading
/// kept its vertices (no merge, no repair); otherwise the exact values of the doubles, with a note
/// on stderr. Vertex and face indices are `mesh`'s.
Exact_mesh exact_input_mesh(const Mesh& mesh, const std::string& path);

} // namespace tessera::cli
