// Umbrella header of Tessera's mesh I/O: checked reading and writing through CGAL's IO.
#pragma once

#include <tessera/io/read_cutting.h>
#include <tessera/io/read_feature_polylines.h>
#include <tessera/io/read_mesh.h>
#include <tessera/io/read_obj_material.h>
#include <tessera/io/read_vertex_scalars.h>
#include <tessera/io/write_mesh.h>
#include <tessera/io/write_obj_with_uvs.h>
