// A coarse mesh made fine enough for a field that tiles follow: a direction field lives on the
// vertices, so on a CAD box of 12 triangles it is interpolated across faces many tiles wide and
// swirls. Faces with edges longer than a few tiles are remeshed
// (CGAL::Polygon_mesh_processing::isotropic_remeshing), and what was read on the coarse mesh —
// per-vertex values, per-face data, feature lines — is carried onto the refined one. With it,
// the other setting of a field at the tiles' scale: where its thin parts are measured.
#pragma once

#include <tessera/fields/feature_lines.h>
#include <tessera/fields/thin_parts.h>
#include <tessera/mosaic/tile.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <optional>
#include <set>
#include <utility>
#include <vector>

namespace tessera {
namespace internal {

// Surface_mesh only marks what the remeshing removed: compact it, so that indices run from 0 to
// the number of elements again (the coarse vertices, never removed, keep theirs).
template <typename Point> void collect_garbage(CGAL::Surface_mesh<Point>& tm) {
  tm.collect_garbage();
}
template <typename TriangleMesh> void collect_garbage(TriangleMesh&) {}

} // namespace internal

/// Which faces `refine_coarse_mesh()` remeshes, and how finely.
struct Coarse_mesh_options {
  /// Faces with an edge longer than this are remeshed...
  double coarse_edge_length = 0;
  /// ... to edges no longer than this (0: `coarse_edge_length`).
  double max_edge_length = 0;
};

/// The options for tiles of `layout`: faces with an edge longer than four tiles' spacing (along
/// the shorter side) remeshed to edges of at most two. (Remeshing every face with an edge over two
/// spacings changes most organic meshes a little, and opened a bare patch of 2.1 tiles on both
/// seeds of CGAL's femur, whose widest had been 1.5-1.8; splitting edges to four spacings leaves
/// the tiles on `beam`, a box of 12 triangles, swirling near its corners.)
inline Coarse_mesh_options coarse_mesh_options(const Mosaic_layout& layout) {
  const double eta = std::sqrt(layout.aspect);
  const double spacing = layout.spacing * std::min(eta, 1 / eta);
  return {4 * spacing, 2 * spacing};
}

/// The layout `tiles` have on the surface's area (`mosaic_layout()`), or none when the tile
/// options give none.
///
/// Named parameters: `vertex_point_map`, `geom_traits`.
template <typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::optional<Mosaic_layout>
surface_layout(const TriangleMesh& tm, const Mosaic_tile_size& tiles,
               const NamedParameters& np = CGAL::parameters::default_values()) {
  Mosaic_layout layout;
  if (mosaic_layout(tiles, CGAL::to_double(CGAL::Polygon_mesh_processing::area(tm, np)), layout))
    return std::nullopt;
  return layout;
}

/// The options for `tiles` on `tm`: `coarse_mesh_options(layout)` for the layout those tiles have
/// on the surface's area (`surface_layout()`). Tile options that give no layout (see
/// `mosaic_layout()`) give options that leave every face as it is; the mosaic then says why.
///
/// Named parameters: `vertex_point_map`, `geom_traits`.
template <typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Coarse_mesh_options
coarse_mesh_options(const TriangleMesh& tm, const Mosaic_tile_size& tiles,
                    const NamedParameters& np = CGAL::parameters::default_values()) {
  const std::optional<Mosaic_layout> layout = surface_layout(tm, tiles, np);
  return layout ? coarse_mesh_options(*layout) : Coarse_mesh_options{};
}

/// The thin-part options for tiles of `layout` (`smoothest_field_with_thin_parts()`): girths
/// measured in their spacing, the rest the defaults.
inline Thin_part_options thin_part_options(const Mosaic_layout& layout) {
  Thin_part_options options;
  options.spacing = layout.spacing;
  return options;
}

/// The thin-part options `tessera mosaic` uses for tiles of `layout` along `lines` (the feature
/// lines the field is aligned to): `thin_part_options(layout)`, and when some line is a crease (a
/// CAD part's edge), curved bands with no short loop around them guided below 8 tiles around
/// (`Thin_part_options::curved_bands_below_tiles_around`; doc/mosaic.md, "Curved bands on CAD
/// parts").
template <typename HalfedgeDescriptor>
Thin_part_options thin_part_options(const Mosaic_layout& layout,
                                    const std::vector<Feature_line<HalfedgeDescriptor>>& lines) {
  Thin_part_options options = thin_part_options(layout);
  for (const auto& line : lines)
    if (line.kind == Feature_kind::crease)
      options.curved_bands_below_tiles_around = 8;
  return options;
}

/// The alignment with feature lines for tiles of `layout`: hard, with bends tighter than four tile
/// spacings left free (`Feature_alignment_options::tightest_radius`: a row beside such an arc
/// opens a wedge of more than a quarter of a tile at each tile; doc/mosaic.md, "Rounded corners
/// and small holes"). On CGAL's 40 meshes at 3000 tiles, seeds 1-3, oblong's lowest coverage went
/// 0.848 -> 0.855 and couplingdown's 0.859 -> 0.855; radii of 2 and 3 spacings gave oblong 0.853
/// and 0.854, and couplingdown 0.853 and 0.850.
inline Feature_alignment_options feature_alignment_options(const Mosaic_layout& layout) {
  Feature_alignment_options options;
  options.tightest_radius = 4 * layout.spacing;
  return options;
}

/// The thin-part options for `tiles` on `tm`: `thin_part_options(layout)` for the layout those
/// tiles have on the surface's area (`surface_layout()`). Tile options that give no layout give a
/// spacing of 0, which the thin-part functions reject with a message.
///
/// Named parameters: `vertex_point_map`, `geom_traits`.
template <typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Thin_part_options
thin_part_options(const TriangleMesh& tm, const Mosaic_tile_size& tiles,
                  const NamedParameters& np = CGAL::parameters::default_values()) {
  const std::optional<Mosaic_layout> layout = surface_layout(tm, tiles, np);
  return layout ? thin_part_options(*layout) : Thin_part_options{};
}

/// Where an element of a mesh refined by `refine_coarse_mesh()` comes from on the coarse mesh.
template <typename TriangleMesh> struct Coarse_mesh_refinement {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;

  /// Whether any face was remeshed (false: the mesh is untouched and the maps below are empty).
  bool refined = false;
  /// True when the faces with long edges are slivers, left as they were: splitting the long
  /// edges would add more than 8 × the area over the longest allowed edge squared, plus 1000,
  /// vertices.
  bool left_coarse = false;
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
  /// The coarse face every face of the refined mesh lies in.
  std::map<face_descriptor, face_descriptor> source_face;

  /// The coarse face `f` lies in (`f` itself when nothing was remeshed).
  face_descriptor coarse_face(face_descriptor f) const {
    const auto it = source_face.find(f);
    return it == source_face.end() ? f : it->second;
  }

  /// Gives each added vertex the value of `map` interpolated linearly in its coarse face. The value
  /// type needs `+` and `* double` (scalars, vectors); `map` must already hold the coarse vertices'
  /// values and accept the added ones (a property map of the refined mesh).
  template <typename VertexMap> void interpolate(VertexMap map) const {
    for (const auto& [v, p] : added)
      put(map, v,
          get(map, p.corners[0]) * p.weights[0] + get(map, p.corners[1]) * p.weights[1] +
              get(map, p.corners[2]) * p.weights[2]);
  }
};

/// Remeshes the faces of `tm` with an edge longer than `options.coarse_edge_length` to edges of
/// about 3/4 of `options.max_edge_length` (CGAL::Polygon_mesh_processing::isotropic_remeshing, new
/// vertices on the coarse surface; its vertices, borders and `lines` kept: their edges split at
/// midpoints, so that the surface's creases stay where they were) and carries `lines`, feature
/// lines of the coarse mesh, onto the refined one: each coarse edge of a line becomes the chain of
/// edges it was split into. Returns where the refined mesh's vertices and faces come from, so that
/// per-vertex values (`interpolate()`) and per-face data (`coarse_face()`) read on the coarse mesh
/// follow. The coarse vertices keep their descriptors (they are never moved or removed; a
/// Surface_mesh is compacted afterwards, which leaves them in place); the remeshed faces are
/// replaced. Numeric: the geometric traits must have inexact constructions (Epick), as CGAL's
/// remeshing requires.
///
/// Named parameters: `vertex_point_map`, `geom_traits`.
template <typename TriangleMesh, typename HalfedgeDescriptor,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Coarse_mesh_refinement<TriangleMesh>
refine_coarse_mesh(TriangleMesh& tm, const Coarse_mesh_options& options,
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
                                    get_property_map(CGAL::vertex_point, tm));

  Coarse_mesh_refinement<TriangleMesh> out;
  out.vertices_before = num_vertices(tm);
  auto length = [&](halfedge_descriptor h) {
    return std::sqrt(
        CGAL::to_double(CGAL::squared_distance(get(vpm, source(h, tm)), get(vpm, target(h, tm)))));
  };
  for (auto e : edges(tm))
    out.longest_edge_before = std::max(out.longest_edge_before, length(halfedge(e, tm)));
  out.max_edge_length = out.longest_edge_before;
  const double coarse = options.coarse_edge_length,
               max_edge_length = options.max_edge_length > 0 ? options.max_edge_length : coarse;
  if (!(max_edge_length > 0) || !(out.longest_edge_before > coarse))
    return out;
  // Splitting the long edges costs their length over the allowed one in vertices, the faces'
  // interior about their area over its square: far more of the first means slivers (a strip
  // 1e-12 high), which a remeshing would cut into millions of pieces. Those are left coarse.
  double splits = 0;
  for (auto e : edges(tm))
    if (length(halfedge(e, tm)) > coarse)
      splits += length(halfedge(e, tm)) / max_edge_length;
  const double area = CGAL::to_double(PMP::area(tm, np));
  if (splits > 8 * area / (max_edge_length * max_edge_length) + 1000) {
    out.left_coarse = true;
    return out;
  }

  // The coarse triangles, their corners, and the lines as chains of coarse vertices: the remeshing
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
  const std::set<vertex_descriptor> coarse_vertex(vertices(tm).begin(), vertices(tm).end());

  // CGAL's isotropic remeshing of the faces with a long edge, to edges of about 3/4 of the
  // longest allowed: the coarse vertices stay (constrained), and so do the lines and the borders,
  // whose edges are split at their midpoints but neither flipped nor collapsed. (Splitting long
  // edges alone fans out from the corners of long faces: 70000 vertices on a 12-triangle beam at
  // 3000 tiles.)
  auto constrained_edge = get(CGAL::dynamic_edge_property_t<bool>(), tm);
  auto constrained_vertex = get(CGAL::dynamic_vertex_property_t<bool>(), tm);
  for (auto e : edges(tm))
    put(constrained_edge, e, CGAL::is_border(e, tm));
  for (const auto& line : lines)
    for (halfedge_descriptor h : line.halfedges)
      put(constrained_edge, edge(h, tm), true);
  for (vertex_descriptor v : vertices(tm))
    put(constrained_vertex, v, true);
  std::vector<face_descriptor> coarse_patch;
  for (face_descriptor f : faces(tm))
    for (halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm), tm))
      if (length(h) > coarse) {
        coarse_patch.push_back(f);
        break;
      }
  PMP::isotropic_remeshing(coarse_patch, 0.75 * max_edge_length, tm,
                           np.edge_is_constrained_map(constrained_edge)
                               .vertex_is_constrained_map(constrained_vertex)
                               .collapse_constraints(false)
                               .number_of_iterations(3));
  // The relaxation can leave a few edges a little longer than allowed: split those at their
  // midpoints (a line's sub-edge stays on the line), until none is.
  for (int round = 0; round < 16; ++round) {
    std::vector<typename boost::graph_traits<TriangleMesh>::edge_descriptor> long_edges;
    for (auto e : edges(tm))
      if (length(halfedge(e, tm)) > max_edge_length)
        long_edges.push_back(e);
    if (long_edges.empty())
      break;
    PMP::split_long_edges(long_edges, max_edge_length, tm,
                          CGAL::parameters::edge_is_constrained_map(constrained_edge)
                              .vertex_point_map(vpm)
                              .geom_traits(GT()));
  }
  internal::collect_garbage(tm);
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
    std::array<double, 3> w{{1, 0, 0}};
    if (!CGAL::collinear(t.vertex(0), t.vertex(1), t.vertex(2))) {
      const auto b = PMP::barycentric_coordinates(t.vertex(0), t.vertex(1), t.vertex(2), p, GT());
      w[1] = std::clamp(CGAL::to_double(b[1]), 0.0, 1.0);
      w[2] = std::clamp(CGAL::to_double(b[2]), 0.0, 1.0);
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
          break; // cannot happen on a valid mesh; the line stays as far as it got
        carried.push_back(step);
        at = target(step, tm);
      }
    }
    lines[l].halfedges = std::move(carried);
  }
  return out;
}

} // namespace tessera
