// The indices of a range of Surface_mesh-style descriptors, as the reports write them.
#pragma once

#include <cstddef>
#include <vector>

namespace tessera {

namespace internal {

/// The indices of a range of Surface_mesh-style descriptors.
template <typename Range> std::vector<std::size_t> index_list(const Range& descriptors) {
  std::vector<std::size_t> ids;
  for (const auto& d : descriptors)
    ids.push_back(std::size_t(d));
  return ids;
}

} // namespace internal

} // namespace tessera
