// The tokens of a --features / --align specification (tessera/fields/feature_specs.h): its
// separated parts, and an index made only of digits.
#pragma once

#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

namespace tessera::internal {

/// The non-empty parts of `s` between the separators `sep`.
inline std::vector<std::string> split_spec(const std::string& s, char sep) {
  std::vector<std::string> parts;
  std::stringstream in(s);
  std::string part;
  while (std::getline(in, part, sep))
    if (!part.empty())
      parts.push_back(part);
  return parts;
}

/// `entry` made only of digits (at most 18), as a number.
inline bool spec_index(const std::string& entry, std::size_t& out) {
  if (entry.empty() || entry.size() > 18 ||
      entry.find_first_not_of("0123456789") != std::string::npos)
    return false;
  out = std::size_t(std::stoull(entry));
  return true;
}

} // namespace tessera::internal
