// Progress of long computations: an options struct's `progress` callback receives what is being
// done and how much of it, so that a caller can show it (the command-line tool prints it on stderr
// once a stage has run for more than a second). The loops that report through it today: the
// quadrangulation's cutting paths (`Quadrangulation_options`), the tiles' parameterization
// (`Tile_parameterization_options`) and the surface mosaic's iterations (`Surface_mosaic_options`);
// other long stages (cut graphs of millions of faces, resizing, texture synthesis) do not report
// yet.
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
