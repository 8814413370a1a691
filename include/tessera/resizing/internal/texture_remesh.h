// Remeshing the texture region of a resized base (texture_resize.h): the resize stretched its
// triangles, so they are remeshed to the input's edge length (CGAL's isotropic remeshing of the
// region's faces, its border kept as a constrained polyline) before the texture is synthesized on
// them; the rest of the surface keeps its vertices and triangles.
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace tessera::internal {

using Texture_work_mesh =
    CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;

struct Texture_region_remeshing {
  std::size_t region_faces = 0;
  /// Vertices inside the region after remeshing (all their faces in it): the synthesis' unknowns.
  std::size_t free_vertices = 0;
  /// Vertices the remeshing added on the region's border.
  std::size_t border_vertices_added = 0;
};

/// Remeshes the faces of `m` whose three corners are texture (`texture`) to `edge_length`, in
/// `iterations` rounds, then marks in `free` the vertices inside the remeshed region and gives the
/// vertices added on its border the detail (`height`) interpolated along the border from the
/// vertices that were there before; `texture` then marks the remeshed region with its border.
/// `part` holds each texture vertex's texture (`separate_textures`; the corners of a face share
/// one) and is given to the vertices the remeshing makes, from the faces around them.
/// Collects the garbage of `m`.
inline Texture_region_remeshing remesh_texture_region(
    Texture_work_mesh& m,
    Texture_work_mesh::Property_map<Texture_work_mesh::Vertex_index, bool> texture,
    Texture_work_mesh::Property_map<Texture_work_mesh::Vertex_index, double> height,
    Texture_work_mesh::Property_map<Texture_work_mesh::Vertex_index, bool> free,
    Texture_work_mesh::Property_map<Texture_work_mesh::Vertex_index, std::size_t> part,
    double edge_length, unsigned iterations) {
  using M = Texture_work_mesh;
  Texture_region_remeshing out;
  auto patch = m.add_property_map<M::Face_index, int>("f:tessera_texture_patch", 0).first;
  auto constrained =
      m.add_property_map<M::Edge_index, bool>("e:tessera_texture_border", false).first;
  auto old = m.add_property_map<M::Vertex_index, bool>("v:tessera_texture_old", false).first;
  // A region face's patch is 1 + its texture; the remeshing's new faces inherit it (vertex
  // properties would not do: the remeshing recycles removed vertices with their old values).
  std::vector<M::Face_index> region;
  for (M::Face_index f : m.faces()) {
    bool inside = true;
    for (M::Vertex_index v : CGAL::vertices_around_face(m.halfedge(f), m))
      inside = inside && texture[v];
    if (inside) {
      const std::size_t id = part[m.target(m.halfedge(f))];
      patch[f] = 1 + int(id == std::size_t(-1) ? 0 : id);
      region.push_back(f);
    }
  }
  out.region_faces = region.size();
  for (M::Vertex_index v : m.vertices())
    old[v] = true;
  auto patch_of = [&](M::Halfedge_index h) {
    const M::Face_index f = m.face(h);
    return f == M::null_face() ? -1 : patch[f];
  };
  for (M::Edge_index e : m.edges()) {
    const M::Halfedge_index h = m.halfedge(e);
    constrained[e] = patch_of(h) != patch_of(m.opposite(h));
  }
  if (!region.empty())
    // The border may be split (the resize stretched it too) but neither collapsed nor moved, so
    // the surface outside the region keeps its shape; new faces inherit their patch.
    CGAL::Polygon_mesh_processing::isotropic_remeshing(
        region, edge_length, m,
        CGAL::parameters::edge_is_constrained_map(constrained)
            .protect_constraints(false)
            .collapse_constraints(false)
            .face_patch_map(patch)
            .number_of_iterations(iterations));
  m.collect_garbage();

  // Vertices added on the border: the detail interpolated by arc length between the old
  // vertices at either end of their run of new ones.
  auto length = [&](M::Halfedge_index h) {
    return std::sqrt(CGAL::squared_distance(m.point(m.source(h)), m.point(m.target(h))));
  };
  for (M::Vertex_index v : m.vertices()) {
    bool inside = !m.is_border(v);
    for (M::Face_index f : CGAL::faces_around_target(m.halfedge(v), m)) {
      inside = inside && f != M::null_face() && patch[f] >= 1;
      if (f != M::null_face() && patch[f] >= 1)
        part[v] = std::size_t(patch[f] - 1);
    }
    free[v] = inside;
    if (inside)
      texture[v] = true;
    out.free_vertices += inside ? 1 : 0;
    if (old[v] || inside)
      continue;
    std::vector<M::Halfedge_index> along;
    for (M::Halfedge_index h : CGAL::halfedges_around_source(v, m))
      if (constrained[m.edge(h)])
        along.push_back(h);
    if (along.size() != 2)
      continue;
    ++out.border_vertices_added;
    texture[v] = true;
    double value[2] = {0, 0}, distance[2] = {0, 0};
    for (std::size_t side = 0; side < 2; ++side) {
      M::Halfedge_index h = along[side];
      distance[side] = length(h);
      for (std::size_t steps = 0; !old[m.target(h)] && steps < m.number_of_vertices(); ++steps) {
        M::Halfedge_index next = M::null_halfedge();
        for (M::Halfedge_index g : CGAL::halfedges_around_source(m.target(h), m))
          if (constrained[m.edge(g)] && g != m.opposite(h))
            next = g;
        if (next == M::null_halfedge())
          break;
        h = next;
        distance[side] += length(h);
      }
      value[side] = height[m.target(h)];
    }
    const double total = distance[0] + distance[1];
    height[v] = total > 0 ? (value[0] * distance[1] + value[1] * distance[0]) / total : value[0];
  }
  m.remove_property_map(patch);
  m.remove_property_map(constrained);
  m.remove_property_map(old);
  return out;
}

} // namespace tessera::internal
