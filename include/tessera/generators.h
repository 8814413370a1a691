// Umbrella header of Tessera's surface generators (the test and benchmark corpus).
#pragma once

#include <tessera/generators/surfaces.h>
#include <tessera/generators/uv_layouts.h>
