// Helpers shared by several modules. A parallel loop over independent indices (the mosaic's
// per-tile forces, projections, neighbour queries and quality samples; per-vertex jet fits; the
// texture synthesis' template matches): the range is cut into one contiguous block per hardware
// thread, each run with std::async. Results go to per-index slots and sums are then taken in index
// order by the caller, so a run's result does not depend on the number of threads.
#pragma once

#include <algorithm>
#include <cstddef>
#include <future>
#include <thread>
#include <vector>

namespace tessera::internal {

/// Calls `body(first, last)` on disjoint blocks covering [0, n), in parallel when n is at least
/// `grain` per thread. `body` must only read shared state and write its own indices.
template <typename Body> void parallel_blocks(std::size_t n, Body&& body, std::size_t grain = 256) {
  const std::size_t hardware = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t threads =
      std::min<std::size_t>({hardware, 16, n / std::max<std::size_t>(grain, 1)});
  if (threads <= 1) {
    body(std::size_t(0), n);
    return;
  }
  std::vector<std::future<void>> others;
  others.reserve(threads - 1);
  const std::size_t block = (n + threads - 1) / threads;
  for (std::size_t t = 1; t < threads; ++t) {
    const std::size_t first = std::min(n, t * block), last = std::min(n, first + block);
    others.push_back(std::async(std::launch::async, [&body, first, last] { body(first, last); }));
  }
  body(std::size_t(0), std::min(n, block));
  for (auto& o : others)
    o.get();
}

} // namespace tessera::internal
