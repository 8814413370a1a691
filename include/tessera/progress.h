// Progress of long computations: an options struct's `progress` callback receives what is being
// done and how much of it, so that a caller can show it (the command-line tool prints it on stderr
// once a stage has run for more than a second). Every module's long loops report through this.
#pragma once

#include <cstddef>
#include <functional>

namespace tessera {

/// One report: `done` of `total` steps of `stage` (a short lower-case noun phrase, e.g.
/// "cutting paths"); `total` is 0 when not known in advance.
struct Progress {
  const char* stage = "";
  std::size_t done = 0;
  std::size_t total = 0;
};

/// Called after each step of a long loop; empty (the default) costs one test per step.
using Progress_callback = std::function<void(const Progress&)>;

} // namespace tessera
