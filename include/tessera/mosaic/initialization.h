// First positions of a mosaic's tiles by error diffusion over faces (Lai, Hu, Martin, "Surface
// Mosaics" §3.2): faces are visited by region growing; each takes its real-valued share N·A_T/A
// plus the error passed to it, places the rounded number of tiles at random points inside it, and
// passes the rounding error on to its neighbours not yet visited, so that the count matches N and
// the density follows the area.
#pragma once

#include <tessera/mosaic/internal/error_diffusion.h>
