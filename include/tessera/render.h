// Umbrella header of Tessera's headless rendering (link Tessera::core).
#pragma once

#include <tessera/render/mesh_scene.h>
#include <tessera/render/scene.h>
