// Lookups in a table of (enum value, name) pairs, the form in which modules publish the names of
// their choices (`cut_method_names`), so that parsing and printing read one table.
#pragma once

#include <array>
#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tessera::internal {

template <typename Enum, std::size_t N>
using Enum_names = std::array<std::pair<Enum, const char*>, N>;

/// The name of `value` in `names`, or "unknown" for a value the table lacks.
template <typename Enum, std::size_t N>
const char* enum_name(const Enum_names<Enum, N>& names, Enum value) {
  for (const auto& [v, name] : names)
    if (v == value)
      return name;
  return "unknown";
}

/// The value called `name` in `names` (exact match), or nothing.
template <typename Enum, std::size_t N>
std::optional<Enum> enum_value(const Enum_names<Enum, N>& names, std::string_view name) {
  for (const auto& [v, n] : names)
    if (name == n)
      return v;
  return std::nullopt;
}

/// The names of `names`, then `more` (a caller's own choices besides the table's), as a reader
/// lists them: "a, b or c".
template <typename Enum, std::size_t N>
std::string enum_name_list(const Enum_names<Enum, N>& names,
                           std::initializer_list<const char*> more = {}) {
  std::vector<const char*> all;
  for (const auto& entry : names)
    all.push_back(entry.second);
  all.insert(all.end(), more);
  std::string out;
  for (std::size_t k = 0; k < all.size(); ++k)
    out += std::string(k == 0 ? "" : k + 1 == all.size() ? " or " : ", ") + all[k];
  return out;
}

} // namespace tessera::internal
