// Turning FaceGraph data into a `Render_scene`: a triangle mesh with optional per-face colours, and
// edge paths (cuts, tile borders) as polylines.
#pragma once

#include <tessera/render/scene.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <vector>

namespace tessera {

/// Appends the triangles of `tm` (faces of more than three sides are fanned) to `scene`, coloured
/// by `face_color(f)` (any callable or property-map-like lookup returning `Color`).
template <typename FaceGraph, typename FaceColor>
void add_mesh(Render_scene& scene, const FaceGraph& tm, FaceColor face_color) {
  const auto vpm = get(CGAL::vertex_point, tm);
  const std::size_t first = scene.positions.size();
  auto vindex = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  std::size_t i = first;
  for (auto v : vertices(tm)) {
    const auto& p = get(vpm, v);
    scene.positions.push_back(
        {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}});
    put(vindex, v, i++);
  }
  if (scene.triangle_colors.size() < scene.triangles.size())
    scene.triangle_colors.resize(scene.triangles.size(), Color{});
  for (auto f : faces(tm)) {
    std::vector<std::size_t> ids;
    for (auto v : CGAL::vertices_around_face(halfedge(f, tm), tm))
      ids.push_back(get(vindex, v));
    const Color c = face_color(f);
    for (std::size_t k = 1; k + 1 < ids.size(); ++k) {
      scene.triangles.push_back({{ids[0], ids[k], ids[k + 1]}});
      scene.triangle_colors.push_back(c);
    }
  }
}

/// Appends the triangles of `tm`, all in `color`.
template <typename FaceGraph>
void add_mesh(Render_scene& scene, const FaceGraph& tm, Color color = Color{0.78, 0.8, 0.85}) {
  add_mesh(scene, tm, [color](auto) { return color; });
}

/// Appends a polyline through the sources and targets of consecutive `halfedges` of `tm`.
template <typename FaceGraph, typename HalfedgeRange>
void add_halfedge_path(Render_scene& scene, const FaceGraph& tm, const HalfedgeRange& halfedges,
                       Color color, double width = 2.5) {
  const auto vpm = get(CGAL::vertex_point, tm);
  auto xyz = [&](auto v) {
    const auto& p = get(vpm, v);
    return std::array<double, 3>{
        {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
  };
  Render_polyline line;
  line.color = color;
  line.width = width;
  bool first = true;
  for (auto h : halfedges) {
    if (first)
      line.points.push_back(xyz(source(h, tm)));
    first = false;
    line.points.push_back(xyz(target(h, tm)));
  }
  if (line.points.size() > 1)
    scene.polylines.push_back(std::move(line));
}

} // namespace tessera
