// Umbrella header of Tessera's checks on meshes and on the results of its algorithms.
#pragma once

#include <tessera/validation/mesh_info.h>
