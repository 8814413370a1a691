// Progress of long computations: an options struct's `progress` callback receives what is being
// done and how much of it, so that a caller can show it (the command-line tool prints it on stderr
// once a stage has run for more than a second). The loops that report through it: the cut graph's
// stages per component (`Cut_options`), the quadrangulation's cutting paths
// (`Quadrangulation_options`), the tiles' parameterization (`Tile_parameterization_options`), the
// surface mosaic's iterations (`Surface_mosaic_options`), the resizing volume's iterations
// (`Volume_resize_options`, also through `Resize_options::solve`) and the texture synthesis'
// iterations (`Texture_synthesis_options`, also through the texture-preserving pipelines).
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

/// Reports `done` of `total` steps of `stage` through `progress` when it is set. Loops report 0
/// before their first step, so that a caller can time the first one too.
inline void report_progress(const Progress_callback& progress, const char* stage, std::size_t done,
                            std::size_t total) {
  if (progress)
    progress({stage, done, total});
}

} // namespace tessera
