// Umbrella header of Tessera's resizing module: non-homogeneous resizing (Kraevoy, Sheffer, Shamir,
// Cohen-Or, 2008) of a surface through a volume mesh (TetGen, or a protective grid for open
// surfaces), the vulnerability that steers it, the local stretch that measures it, deformation
// by handles through CGAL's Surface_mesh_deformation, and both preserving a geometric texture
// (Chen and Meng 2010: segmentation, base and detail, synthesis; texels to measure it).
#pragma once

#include <tessera/resizing/deform.h>
#include <tessera/resizing/draw_resize.h>
#include <tessera/resizing/laplacian_detail.h>
#include <tessera/resizing/method_names.h>
#include <tessera/resizing/resize.h>
#include <tessera/resizing/stretch.h>
#include <tessera/resizing/tet_mesh.h>
#include <tessera/resizing/texel_period.h>
#include <tessera/resizing/texels.h>
#include <tessera/resizing/texture_detail.h>
#include <tessera/resizing/texture_resize.h>
#include <tessera/resizing/texture_segmentation.h>
#include <tessera/resizing/texture_synthesis.h>
#include <tessera/resizing/volume_resize.h>
#include <tessera/resizing/vulnerability.h>
