// Implementation of tessera::mesh_info (see tessera/validation/mesh_info.h).
#pragma once

#include <tessera/validation/mesh_info.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/boost/graph/helpers.h>
#include <array>
#include <cstddef>
#include <vector>

namespace tessera {

template <typename PolygonMesh>
Mesh_info mesh_info(const PolygonMesh& tm, const Mesh_info_options& options) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using GT = boost::graph_traits<PolygonMesh>;
  using face_descriptor = typename GT::face_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;

  Mesh_info info;
  info.vertices = num_vertices(tm);
  info.edges = num_edges(tm);
  info.faces = num_faces(tm);
  info.euler_characteristic = long(info.vertices) - long(info.edges) + long(info.faces);
  info.is_valid_polygon_mesh = CGAL::is_valid_polygon_mesh(tm);
  info.is_triangle_mesh = CGAL::is_triangle_mesh(tm);
  info.is_closed = CGAL::is_closed(tm);

  auto fcc = get(CGAL::dynamic_face_property_t<std::size_t>(), tm);
  const std::size_t ncc = PMP::connected_components(tm, fcc);
  info.components.resize(ncc);

  // Vertices, edges and boundary loops per component, through their faces' halfedges.
  auto vcc = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  auto hseen = get(CGAL::dynamic_halfedge_property_t<bool>(), tm);
  for (auto v : vertices(tm))
    put(vcc, v, std::size_t(-1));
  for (halfedge_descriptor h : halfedges(tm))
    put(hseen, h, false);
  for (face_descriptor f : faces(tm)) {
    Component_info& c = info.components[get(fcc, f)];
    ++c.faces;
    for (halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      if (get(vcc, target(h, tm)) == std::size_t(-1)) {
        put(vcc, target(h, tm), get(fcc, f));
        ++c.vertices;
      }
      const halfedge_descriptor o = opposite(h, tm);
      if (is_border(o, tm) || !get(hseen, o))
        ++c.edges;
      put(hseen, h, true);
    }
  }
  std::vector<halfedge_descriptor> cycles;
  PMP::extract_boundary_cycles(tm, std::back_inserter(cycles));
  info.boundary_loops = cycles.size();
  for (halfedge_descriptor h : cycles)
    ++info.components[get(fcc, face(opposite(h, tm), tm))].boundary_loops;

  for (Component_info& c : info.components) {
    c.euler_characteristic = long(c.vertices) - long(c.edges) + long(c.faces);
    c.genus = (2 - c.euler_characteristic - long(c.boundary_loops)) / 2;
  }

  if (info.is_triangle_mesh && info.faces > 0) {
    for (face_descriptor f : faces(tm)) {
      const double a = CGAL::to_double(PMP::face_area(f, tm));
      info.area += a;
      info.components[get(fcc, f)].area += a;
    }
    if (options.check_self_intersection) {
      info.self_intersects = PMP::does_self_intersect(tm);
      info.self_intersection_checked = true;
    }
  }
  if (info.vertices > 0) {
    const CGAL::Bbox_3 b = PMP::bbox(tm);
    info.bbox_min = {{b.xmin(), b.ymin(), b.zmin()}};
    info.bbox_max = {{b.xmax(), b.ymax(), b.zmax()}};
  }
  return info;
}

} // namespace tessera
