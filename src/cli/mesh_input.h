// The input mesh of a command: one reader for every command, with the --strict and --repair flags,
// and one note on stderr saying what reading changed.
#pragma once

#include "commands.h"

#include <tessera/io/mesh_repair.h>
#include <tessera/types.h>

#include <nlohmann/json.hpp>

#include <string>

namespace tessera::cli {

/// Adds the positional `mesh` argument and the --strict / --repair flags to `cmd`.
void add_mesh_input(CLI::App* cmd, std::string& path, Mesh_input_flags& flags);

/// Reads `path` as the flags allow; throws User_error with the reader's message when refused, and
/// prints one note on stderr when reading triangulated or repaired the file. `changes` receives
/// what reading changed, for the command's JSON output.
Mesh read_input_mesh(const std::string& path, const Mesh_input_flags& flags,
                     Mesh_changes* changes = nullptr);

/// What reading changed, as the "repairs" object of a command's JSON output.
nlohmann::json mesh_changes_json(const Mesh_changes& changes);

} // namespace tessera::cli
