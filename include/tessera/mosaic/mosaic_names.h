// Names of the surface mosaic's choices as the command line, reports and benchmarks spell them
// (`tessera mosaic --start position-field --count about`): one table per enum, read by both the
// parser and the printer, each name the enumerator's with '-' for '_'.
#pragma once

#include <tessera/internal/enum_names.h>
#include <tessera/mosaic/surface_mosaic.h>

#include <optional>
#include <string>
#include <string_view>

namespace tessera {

inline constexpr internal::Enum_names<Mosaic_energy, 2> mosaic_energy_names{
    {{Mosaic_energy::soft_box, "soft-box"},
     {Mosaic_energy::gaussian_manhattan, "gaussian-manhattan"}}};

inline constexpr internal::Enum_names<Mosaic_initialization, 4> mosaic_initialization_names{
    {{Mosaic_initialization::automatic, "automatic"},
     {Mosaic_initialization::position_field, "position-field"},
     {Mosaic_initialization::lattice, "lattice"},
     {Mosaic_initialization::error_diffusion, "error-diffusion"}}};

inline constexpr internal::Enum_names<Mosaic_count, 3> mosaic_count_names{
    {{Mosaic_count::about, "about"},
     {Mosaic_count::exact, "exact"},
     {Mosaic_count::at_most, "at-most"}}};

inline const char* to_string(Mosaic_energy e) {
  return internal::enum_name(mosaic_energy_names, e);
}
inline const char* to_string(Mosaic_initialization i) {
  return internal::enum_name(mosaic_initialization_names, i);
}
inline const char* to_string(Mosaic_count c) {
  return internal::enum_name(mosaic_count_names, c);
}

inline std::optional<Mosaic_energy> parse_mosaic_energy(std::string_view name) {
  return internal::enum_value(mosaic_energy_names, name);
}
inline std::optional<Mosaic_initialization> parse_mosaic_initialization(std::string_view name) {
  return internal::enum_value(mosaic_initialization_names, name);
}
inline std::optional<Mosaic_count> parse_mosaic_count(std::string_view name) {
  return internal::enum_value(mosaic_count_names, name);
}

} // namespace tessera
