// Common kernel and mesh aliases used by Tessera's compiled parts, examples and the CLI.
// The algorithms themselves are templates over any FaceGraph model; these are only defaults.
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

namespace tessera {

/// Default kernel: exact predicates, double constructions.
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
/// Kernel with exact constructions, for refinements that must stay exactly on the input surface.
using Exact_kernel = CGAL::Exact_predicates_exact_constructions_kernel;

using Point_3 = Kernel::Point_3;
using Vector_3 = Kernel::Vector_3;
/// The mesh type of the CLI and the explicit instantiations in the compiled library.
using Mesh = CGAL::Surface_mesh<Point_3>;
using Exact_mesh = CGAL::Surface_mesh<Exact_kernel::Point_3>;

} // namespace tessera
