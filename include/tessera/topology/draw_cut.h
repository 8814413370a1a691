// Pictures of cuts: the polygon sides of a cut as polylines on the mesh, a side and its reversed
// partner in the same colour (sides along the mesh's own boundary in black), multipoints as dots.
#pragma once

#include <tessera/render/mesh_scene.h>
#include <tessera/topology/cut_graph.h>

#include <map>

namespace tessera {

/// Adds `multipoints` (vertices of `tm`) to `scene` as yellow dots of `radius` pixels.
template <typename TriangleMesh, typename VertexRange>
void add_multipoints(Render_scene& scene, const TriangleMesh& tm, const VertexRange& multipoints,
                     double radius) {
  const auto vpm = get(CGAL::vertex_point, tm);
  for (auto v : multipoints) {
    const auto& p = get(vpm, v);
    Render_point rp;
    rp.position = {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
    rp.color = Color{1.0, 0.85, 0.0};
    rp.radius = radius;
    scene.points.push_back(rp);
  }
}

/// Adds the sides and multipoints of `result` (a cut of `tm`) to `scene`.
template <typename TriangleMesh>
void add_cut(Render_scene& scene, const TriangleMesh& tm, const Cut_result<TriangleMesh>& result,
             double line_width = 4.5) {
  using edge_descriptor = typename boost::graph_traits<TriangleMesh>::edge_descriptor;
  std::map<edge_descriptor, std::size_t> pair_of_first_edge;
  std::size_t pairs = 0;
  for (const auto& poly : result.polygons)
    for (const auto& side : poly.sides) {
      if (is_border(opposite(side.front(), tm), tm)) {
        add_halfedge_path(scene, tm, side, Color{0.05, 0.05, 0.05}, line_width);
        continue;
      }
      // A side and its partner share their edge set; key the pair by the smaller end edge.
      const edge_descriptor a = edge(side.front(), tm), b = edge(side.back(), tm);
      const edge_descriptor key = a < b ? a : b;
      auto it = pair_of_first_edge.find(key);
      if (it == pair_of_first_edge.end())
        it = pair_of_first_edge.emplace(key, pairs++).first;
      add_halfedge_path(scene, tm, side, distinct_color(it->second), line_width);
    }
  add_multipoints(scene, tm, result.multipoints, 5);
}

} // namespace tessera
