// Names of the planar mosaic's choices as the command line and report.json spell them
// (`tessera planar-mosaic --shape rect --colors area --fit none`): one table per enum, which both
// the parser (`internal::enum_value`) and the printer (`internal::enum_name`) read, so that the
// two cannot drift apart.
#pragma once

#include <tessera/internal/enum_names.h>
#include <tessera/mosaic/planar_mosaic.h>

namespace tessera {

inline constexpr internal::Enum_names<Planar_tile_shape, 3> planar_tile_shape_names{
    {{Planar_tile_shape::square, "square"},
     {Planar_tile_shape::rectangle, "rect"},
     {Planar_tile_shape::ellipse, "ellipse"}}};

inline constexpr internal::Enum_names<Planar_tile_coloring, 2> planar_tile_coloring_names{
    {{Planar_tile_coloring::point, "point"}, {Planar_tile_coloring::area, "area"}}};

inline constexpr internal::Enum_names<Planar_tile_fitting, 2> planar_tile_fitting_names{
    {{Planar_tile_fitting::shrink, "shrink"}, {Planar_tile_fitting::none, "none"}}};

} // namespace tessera
