// Benchmark inputs shared by the cases: generated genus-g plates and Loop-subdivided test meshes.
#pragma once

#include "harness.h"

#include <tessera/types.h>

#include <tessera/generators.h>
#include <tessera/io.h>

#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>

#include <algorithm>
#include <string>

namespace tessera::bench {

/// A genus-g plate with `n` cells per hole side, Loop-smoothed once (the Topology benchmarks'
/// surface).
inline Mesh genus_plate(std::size_t genus, std::size_t n) {
  Genus_surface_options o;
  o.cell_resolution = n;
  o.wall_resolution = std::max<std::size_t>(1, n / 2);
  o.subdivision_steps = 1;
  Mesh m;
  make_genus_surface(m, genus, o);
  return m;
}

/// A mesh of tests/data after `steps` Loop subdivisions.
inline Mesh loop_subdivided(const std::string& file, int steps) {
  Mesh m;
  read_mesh(bench::data_dir() + "/" + file, m);
  CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(steps));
  return m;
}

} // namespace tessera::bench
