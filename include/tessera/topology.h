// Umbrella header of Tessera's topology module: M-tilings, systems of loops, cut graphs (greedy,
// schema, intermediate), opening along seams and validation (Favreau et al. 2009).
#pragma once

#include <tessera/topology/cut_graph.h>
#include <tessera/topology/draw_cut.h>
#include <tessera/topology/draw_quadrangulation.h>
#include <tessera/topology/edge_cost.h>
#include <tessera/topology/m_tiling.h>
#include <tessera/topology/open_mesh.h>
#include <tessera/topology/parameterize_tiles.h>
#include <tessera/topology/quadrangulate.h>
#include <tessera/topology/system_of_loops.h>
#include <tessera/topology/validate_charts.h>
#include <tessera/topology/validate_cut.h>
#include <tessera/topology/validate_quadrangulation.h>
#include <tessera/topology/validate_refinement.h>
