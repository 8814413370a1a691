// Tangent vector, line and cross fields on triangle meshes, stored in vertex property maps:
// smoothest fields with constraints (control vectors, feature lines, principal directions),
// singularities (Lai et al. §3.1, §5), the text specifications of features, drawing.
#pragma once

#include <tessera/fields/color_regions.h>
#include <tessera/fields/control_vectors.h>
#include <tessera/fields/draw_field.h>
#include <tessera/fields/feature_lines.h>
#include <tessera/fields/feature_specs.h>
#include <tessera/fields/lai_iteration.h>
#include <tessera/fields/principal_directions.h>
#include <tessera/fields/singularities.h>
#include <tessera/fields/smoothest_field.h>
#include <tessera/fields/tangent_field.h>
#include <tessera/fields/thin_parts.h>
