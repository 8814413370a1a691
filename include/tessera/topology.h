// Umbrella header of Tessera's topology module (Favreau, Marzais, Gérard, Barra, "Tiling surfaces
// with M-tiles", 2009): M-tilings; systems of loops and edge costs; cut graphs (greedy, schema,
// intermediate) opening each component into one disk, with the polygonal schema (a 4g-gon at one
// basepoint, its loops unstuck by local refinement); opening along seams; quadrangulation of the
// tiles into M-tiles with four corners (quads); validation of cuts, quadrangulations, refinements
// and any cutting given as charts, seams or texture coordinates (what `tessera check` runs);
// per-tile parameterization (quads onto the unit square) with distortion figures; drawing of cuts
// and quadrangulations.
#pragma once

#include <tessera/topology/cut_graph.h>
#include <tessera/topology/draw_cut.h>
#include <tessera/topology/draw_quadrangulation.h>
#include <tessera/topology/edge_cost.h>
#include <tessera/topology/m_tiling.h>
#include <tessera/topology/method_names.h>
#include <tessera/topology/open_mesh.h>
#include <tessera/topology/parameterize_tiles.h>
#include <tessera/topology/quadrangulate.h>
#include <tessera/topology/system_of_loops.h>
#include <tessera/topology/validate_charts.h>
#include <tessera/topology/validate_cut.h>
#include <tessera/topology/validate_quadrangulation.h>
#include <tessera/topology/validate_refinement.h>
