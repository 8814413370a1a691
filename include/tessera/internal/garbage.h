// Compaction of meshes that only mark removed elements (Surface_mesh), shared by the modules that
// remove elements. Not for direct use.
#pragma once

namespace tessera {
namespace internal {

// Surface_mesh only marks removed elements; compact it so that indices are contiguous again
// (which renumbers the elements after the first removed one; its property maps follow).
template <typename Graph>
auto collect_garbage_if_any(Graph& g, int) -> decltype(g.collect_garbage(), void()) {
  g.collect_garbage();
}
template <typename Graph> void collect_garbage_if_any(Graph&, long) {}
template <typename Graph> void collect_garbage_if_any(Graph& g) {
  collect_garbage_if_any(g, 0);
}

} // namespace internal
} // namespace tessera
