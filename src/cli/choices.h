// Options whose value is one of a few names: parsed with the library's table of an enum's names
// (`cut_method_names`, …; see tessera/internal/enum_names.h), whose names are also those of the
// help text, of the error for any other value and of the reports.
#pragma once

#include "commands.h"

#include <tessera/internal/enum_names.h>

#include <cstddef>
#include <initializer_list>
#include <string>

namespace tessera::cli {

/// The value called `name` in `names`; any other name is a User_error "unknown WHAT 'NAME'WHERE
/// (a, b or c)" listing the table's names and then `more`, the command's own choices besides them.
template <typename Enum, std::size_t N>
Enum parse_choice(const internal::Enum_names<Enum, N>& names, const std::string& name,
                  const std::string& what, const std::string& where = "",
                  std::initializer_list<const char*> more = {}) {
  if (const auto value = internal::enum_value(names, name))
    return *value;
  throw User_error("unknown " + what + " '" + name + "'" + where + " (" +
                   internal::enum_name_list(names, more) + ")");
}

/// The coordinates `cut` and `quadrangulate` work on (--kernel): doubles, or exact rationals
/// (CGAL::Epeck).
enum class Coordinates { double_precision, exact_rational };

inline constexpr internal::Enum_names<Coordinates, 2> coordinates_names{
    {{Coordinates::double_precision, "double"}, {Coordinates::exact_rational, "exact"}}};

/// "double" or "exact".
inline const char* to_string(Coordinates coordinates) {
  return internal::enum_name(coordinates_names, coordinates);
}

/// Where `tessera mosaic` takes its tiles' colours from (--colors): one colour per region between
/// feature lines, the mesh file's face or vertex colours, or an OBJ's texture image.
enum class Tile_color_source { region, mesh, texture };

inline constexpr internal::Enum_names<Tile_color_source, 3> tile_color_source_names{
    {{Tile_color_source::region, "region"},
     {Tile_color_source::mesh, "mesh"},
     {Tile_color_source::texture, "texture"}}};

} // namespace tessera::cli
