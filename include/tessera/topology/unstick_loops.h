// Unsticking a system of loops (Favreau et al. 2009, "Tiling surfaces with M-tiles", §3.3.1 and
// §4.2): refines the mesh around loops that share tree segments until they are simple, pairwise
// disjoint except at the basepoint and each homotopic to its original. New points are exact under
// Epeck.
#pragma once

#include <tessera/internal/named_parameters.h>
#include <tessera/topology/system_of_loops.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace tessera {

enum class Unstick_status {
  ok,
  /// The loops are not tree paths from the basepoint joined by generators, the mesh is not
  /// triangulated or not manifold at a vertex of the loops, or `outer_offset` is not in (0, 1/2).
  invalid_input,
  /// The refinement went wrong on valid input (a bug: the message says where).
  failed
};

/// Where a vertex added by `unstick_loops()` lies on the original surface.
template <typename TriangleMesh> struct Vertex_origin {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  vertex_descriptor vertex;
  /// Corners of the original triangle holding the vertex; for a point on an original edge, its two
  /// ends and `support[2] == null_vertex()`.
  std::array<vertex_descriptor, 3> support;
};

template <typename TriangleMesh> struct Unstick_result {
  using GT = boost::graph_traits<TriangleMesh>;
  Unstick_status status = Unstick_status::ok;
  std::string message;
  /// The refined loops, closed halfedge paths at the basepoint, in the order of the input loops.
  std::vector<std::vector<typename GT::halfedge_descriptor>> loops;
  std::vector<Vertex_origin<TriangleMesh>> new_vertices;
  /// Faces added to the mesh (its face count grew by this much).
  std::size_t new_faces = 0;
  explicit operator bool() const { return status == Unstick_status::ok; }
};

struct Unstick_options {
  /// Offset of the outermost strand from each path vertex it turns around, as a fraction of every
  /// edge it crosses there; the other strands are spread evenly between it and the vertex. The
  /// construction needs it in (0, 1/2); smaller keeps the loops closer to the originals.
  double outer_offset = 0.25;
};

/// Makes the loops of `sys` (tree paths joined by generators, as `greedy_system_of_loops()`
/// computes them on `tm`) simple and pairwise disjoint except at the basepoint, by refining `tm` in
/// place: it only adds vertices, splits edges and faces, so existing descriptors stay valid. Every
/// loop of the result is homotopic, as a loop at the basepoint, to the input loop of the same
/// index. Each new vertex is built from original points by the kernel's constructions (a centroid
/// of an original face, or p + λ (q − p) with a rational λ), so with exact constructions it lies
/// exactly on the original surface. Strands turn around path vertices on the side away from the
/// border, so bordered surfaces are handled. `invalid_input`, with `tm` untouched, when the loops
/// are not of that form (not closed at the basepoint, not tree paths from it: such loops may cross)
/// or `tm` is not triangulated, or not manifold at a vertex of the loops. The refinement may split
/// the edges of the input loops: use the result's loops afterwards.
///
/// Named parameters: `vertex_point_map` (written to for new vertices).
template <typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Unstick_result<TriangleMesh>
unstick_loops(TriangleMesh& tm, const System_of_loops<TriangleMesh>& sys,
              const Unstick_options& options = {},
              const NamedParameters& np = CGAL::parameters::default_values());

} // namespace tessera

#include <tessera/topology/internal/unstick_loops_impl.h>
