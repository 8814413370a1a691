// A coarse mesh made fine enough for a field that tiles follow: a direction field lives on the
// vertices, so on a CAD box of 12 triangles it is interpolated across faces many tiles wide and
// swirls. Edges longer than a few tiles are split
// (CGAL::Polygon_mesh_processing::split_long_edges), and what was read on the coarse mesh —
// per-vertex values, per-face data, feature lines — is carried onto the split one.
#pragma once

#include <tessera/fields/feature_lines.h>
#include <tessera/mosaic/tile.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

namespace tessera {

/// The longest edge `refine_coarse_mesh()` leaves in a mesh that tiles of `layout` will cover: two
/// tiles' spacing along the shorter side. (At four the tiles on `beam`, a box of 12 triangles,
/// still swirl near its corners; at one the mosaic is no better than at two, with twice the
/// vertices.)
inline double coarse_mesh_edge_length(const Mosaic_layout& layout) {
  const double eta = std::sqrt(layout.aspect);
  return 2 * layout.spacing * std::min(eta, 1 / eta);
}

/// Where an element of a mesh split by `refine_coarse_mesh()` comes from on the coarse mesh.
template <typename TriangleMesh> struct Coarse_mesh_refinement {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;

  /// Whether any edge was split (false: the mesh is untouched and the maps below are empty).
  bool refined = false;
  std::size_t vertices_before = 0, vertices_added = 0;
  /// The coarse mesh's longest edge, and the longest the refinement left.
  double longest_edge_before = 0, max_edge_length = 0;
  /// Where an added vertex lies in its coarse face: the face's corners and barycentric weights
  /// (one of them 0 on a coarse edge).
  struct Coarse_point {
    std::array<vertex_descriptor, 3> corners;
    std::array<double, 3> weights{{0, 0, 0}};
  };
  std::map<vertex_descriptor, Coarse_point> added;
  /// The coarse face every face of the split mesh lies in.
  std::map<face_descriptor, face_descriptor> source_face;

  /// The coarse face `f` lies in (`f` itself when nothing was split).
  face_descriptor coarse_face(face_descriptor f) const {
    const auto it = source_face.find(f);
    return it == source_face.end() ? f : it->second;
  }

  /// Gives each added vertex the value of `map` interpolated linearly in its coarse face. The value
  /// type needs `+` and `* double` (scalars, vectors); `map` must already hold the coarse vertices'
  /// values and accept the added ones (a property map of the split mesh).
  template <typename VertexMap> void interpolate(VertexMap map) const {
    for (const auto& [v, p] : added)
      put(map, v,
          get(map, p.corners[0]) * p.weights[0] + get(map, p.corners[1]) * p.weights[1] +
              get(map, p.corners[2]) * p.weights[2]);
  }
};

/// Splits every edge of `tm` longer than `max_edge_length` (CGAL::Polygon_mesh_processing::
/// split_long_edges: midpoints, no vertex moves, so the surface and its creases stay exactly where
/// they were) and carries `lines`, feature lines of the coarse mesh, onto the split one: each
/// coarse edge of a line becomes the chain of edges it was split into. Returns where the split
/// mesh's vertices and faces come from, so that per-vertex values (`interpolate()`) and per-face
/// data (`coarse_face()`) read on the coarse mesh follow. Existing vertices and faces keep their
/// descriptors: CGAL::Surface_mesh and CGAL::Polyhedron_3 add new elements on a split.
///
/// Named parameters: `vertex_point_map`, `geom_traits`.
template <typename TriangleMesh, typename HalfedgeDescriptor,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Coarse_mesh_refinement<TriangleMesh>
refine_coarse_mesh(TriangleMesh& tm, double max_edge_length,
                   std::vector<Feature_line<HalfedgeDescriptor>>& lines,
                   const NamedParameters& np = CGAL::parameters::default_values()) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using GT = typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type;
  using Point = typename GT::Point_3;
  using Triangle = typename GT::Triangle_3;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));

  Coarse_mesh_refinement<TriangleMesh> out;
  out.vertices_before = num_vertices(tm);
  auto length = [&](halfedge_descriptor h) {
    return std::sqrt(
        CGAL::to_double(CGAL::squared_distance(get(vpm, source(h, tm)), get(vpm, target(h, tm)))));
  };
  for (auto e : edges(tm))
    out.longest_edge_before = std::max(out.longest_edge_before, length(halfedge(e, tm)));
  out.max_edge_length = out.longest_edge_before;
  if (!(max_edge_length > 0) || !(out.longest_edge_before > max_edge_length))
    return out;

  // The coarse triangles, their corners, and the lines as chains of coarse vertices: the split
  // changes halfedges, not the vertices they join.
  std::vector<Triangle> triangles;
  std::vector<face_descriptor> coarse_faces;
  std::vector<std::array<vertex_descriptor, 3>> corners;
  for (face_descriptor f : faces(tm)) {
    const halfedge_descriptor h = halfedge(f, tm);
    corners.push_back({{source(h, tm), target(h, tm), target(next(h, tm), tm)}});
    triangles.emplace_back(get(vpm, corners.back()[0]), get(vpm, corners.back()[1]),
                           get(vpm, corners.back()[2]));
    coarse_faces.push_back(f);
  }
  std::vector<std::vector<vertex_descriptor>> chains;
  for (const auto& line : lines) {
    std::vector<vertex_descriptor> chain;
    if (!line.halfedges.empty())
      chain.push_back(source(line.halfedges.front(), tm));
    for (halfedge_descriptor h : line.halfedges)
      chain.push_back(target(h, tm));
    chains.push_back(std::move(chain));
  }
  std::map<vertex_descriptor, bool> coarse_vertex;
  for (vertex_descriptor v : vertices(tm))
    coarse_vertex[v] = true;

  // split_long_edges() splits the edges it is given, and the faces beside them with new edges
  // that may be long again (from a corner to a split edge's midpoint): split until none is.
  for (int round = 0; round < 64; ++round) {
    std::vector<typename boost::graph_traits<TriangleMesh>::edge_descriptor> long_edges;
    for (auto e : edges(tm))
      if (length(halfedge(e, tm)) > max_edge_length)
        long_edges.push_back(e);
    if (long_edges.empty())
      break;
    PMP::split_long_edges(long_edges, max_edge_length, tm, np);
  }
  out.refined = true;

  using Primitive = CGAL::AABB_triangle_primitive<GT, typename std::vector<Triangle>::iterator>;
  CGAL::AABB_tree<CGAL::AABB_traits<GT, Primitive>> tree(triangles.begin(), triangles.end());
  // An added vertex lies in its closest coarse triangle: its barycentric weights there, those
  // under 1e-9 (on an edge or at a corner) set to 0.
  for (vertex_descriptor v : vertices(tm)) {
    if (coarse_vertex.count(v))
      continue;
    const Point p = get(vpm, v);
    const std::size_t i =
        std::size_t(tree.closest_point_and_primitive(p).second - triangles.begin());
    const Triangle& t = triangles[i];
    const auto e0 = t.vertex(1) - t.vertex(0), e1 = t.vertex(2) - t.vertex(0), d = p - t.vertex(0);
    const double d00 = CGAL::to_double(e0 * e0), d01 = CGAL::to_double(e0 * e1),
                 d11 = CGAL::to_double(e1 * e1), d20 = CGAL::to_double(d * e0),
                 d21 = CGAL::to_double(d * e1), det = d00 * d11 - d01 * d01;
    std::array<double, 3> w{{1, 0, 0}};
    if (det > 0) {
      w[1] = std::clamp((d11 * d20 - d01 * d21) / det, 0.0, 1.0);
      w[2] = std::clamp((d00 * d21 - d01 * d20) / det, 0.0, 1.0);
      w[0] = std::max(0.0, 1 - w[1] - w[2]);
    }
    double sum = 0;
    for (double& x : w)
      sum += (x = x < 1e-9 ? 0 : x);
    for (double& x : w)
      x /= sum;
    out.added[v] = {corners[i], w};
  }
  out.vertices_added = out.added.size();
  for (face_descriptor f : faces(tm)) {
    const halfedge_descriptor h = halfedge(f, tm);
    const Point c = CGAL::centroid(get(vpm, source(h, tm)), get(vpm, target(h, tm)),
                                   get(vpm, target(next(h, tm), tm)));
    out.source_face[f] =
        coarse_faces[std::size_t(tree.closest_point_and_primitive(c).second - triangles.begin())];
  }
  out.max_edge_length = 0;
  for (auto e : edges(tm))
    out.max_edge_length = std::max(out.max_edge_length, length(halfedge(e, tm)));

  // Each coarse edge (a, b) of a line: from a, the neighbour added on (a, b) farthest towards b,
  // until b. Edges cannot overlap, so the chain's vertices are the only neighbours on (a, b).
  auto towards = [&](vertex_descriptor v, vertex_descriptor a, vertex_descriptor b) {
    if (v == a || v == b)
      return v == a ? 0.0 : 1.0;
    const auto it = out.added.find(v);
    if (it == out.added.end())
      return -1.0;
    double on_a = 0, on_b = 0, off = 0;
    for (int k = 0; k < 3; ++k)
      (it->second.corners[k] == a   ? on_a
       : it->second.corners[k] == b ? on_b
                                    : off) += it->second.weights[k];
    return off == 0 && on_a > 0 && on_b > 0 ? on_b : -1.0;
  };
  for (std::size_t l = 0; l < lines.size(); ++l) {
    std::vector<halfedge_descriptor> carried;
    for (std::size_t k = 0; k + 1 < chains[l].size(); ++k) {
      const vertex_descriptor a = chains[l][k], b = chains[l][k + 1];
      vertex_descriptor at = a;
      while (at != b) {
        halfedge_descriptor step = boost::graph_traits<TriangleMesh>::null_halfedge();
        double reached = towards(at, a, b);
        for (halfedge_descriptor h : CGAL::halfedges_around_source(at, tm)) {
          const double t = towards(target(h, tm), a, b);
          if (t > reached) {
            reached = t;
            step = h;
          }
        }
        if (step == boost::graph_traits<TriangleMesh>::null_halfedge())
          break; // cannot happen on a split of a valid mesh; the line stays as far as it got
        carried.push_back(step);
        at = target(step, tm);
      }
    }
    lines[l].halfedges = std::move(carried);
  }
  return out;
}

} // namespace tessera
