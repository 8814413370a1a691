// Umbrella header of Tessera's viewer: self-contained HTML pages showing a result in 3D.
#pragma once

#include <tessera/view/read_view_scene.h>
#include <tessera/view/view_scene.h>
#include <tessera/view/write_view_html.h>
