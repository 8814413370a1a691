// Umbrella header of Tessera's mosaic module: surface mosaics (Lai, Hu, Martin, "Surface Mosaics",
// 2006) — tile sizes, initialization, Manhattan charts, feature lines, the optimization, cutting
// tiles free of overlap, the quality report and pictures — and planar decorative mosaics of images
// (Hausner, "Simulating decorative mosaics", 2001), compiled into Tessera::core.
#pragma once

#include <tessera/mosaic/cut_tiles.h>
#include <tessera/mosaic/draw_mosaic.h>
#include <tessera/mosaic/draw_planar_mosaic.h>
#include <tessera/mosaic/manhattan_charts.h>
#include <tessera/mosaic/mosaic_names.h>
#include <tessera/mosaic/planar_field.h>
#include <tessera/mosaic/planar_mosaic.h>
#include <tessera/mosaic/planar_quality.h>
#include <tessera/mosaic/planar_voronoi.h>
#include <tessera/mosaic/quality_report.h>
#include <tessera/mosaic/refine_coarse_mesh.h>
#include <tessera/mosaic/surface_mosaic.h>
#include <tessera/mosaic/tile.h>
#include <tessera/mosaic/tile_colors.h>
#include <tessera/mosaic/tile_scale_surface.h>
