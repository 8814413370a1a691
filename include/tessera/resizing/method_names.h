// Names of the resizing module's choices as the command line and reports spell them
// (`tessera resize --volume grid`, `tessera deform --method srarap`): one table per enum, which
// both the parser (`internal::enum_value`) and the printer (`internal::enum_name`) read, so that
// the two cannot drift apart.
#pragma once

#include <tessera/internal/enum_names.h>
#include <tessera/resizing/deform.h>
#include <tessera/resizing/laplacian_detail.h>
#include <tessera/resizing/resize.h>

namespace tessera {

/// Every resize method and its name.
inline constexpr internal::Enum_names<Resize_method, 2> resize_method_names{
    {{Resize_method::nonhomogeneous, "nonhomogeneous"}, {Resize_method::simple, "simple"}}};

/// Every choice of volume and its name.
inline constexpr internal::Enum_names<Resize_volume, 3> resize_volume_names{
    {{Resize_volume::automatic, "auto"},
     {Resize_volume::tetgen, "tetgen"},
     {Resize_volume::grid, "grid"}}};

/// Every deformation method and its short name.
inline constexpr internal::Enum_names<Deformation_method, 3> deformation_method_names{
    {{Deformation_method::arap, "arap"},
     {Deformation_method::smoothed_arap, "srarap"},
     {Deformation_method::spokes_and_rims, "spokes"}}};

/// Every representation of a texture's detail and its name (`--detail`).
inline constexpr internal::Enum_names<Detail_representation, 2> detail_representation_names{
    {{Detail_representation::normal_displacement, "normal"},
     {Detail_representation::laplacian_coordinates, "laplacian"}}};

} // namespace tessera
