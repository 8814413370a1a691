// Pictures of resizing and deformation: several states of one mesh side by side in one scene, so
// they are seen from the same view at the same scale, each optionally coloured per vertex.
#pragma once

#include <tessera/render/scene.h>
#include <tessera/resizing/tet_mesh.h>

#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace tessera {

/// One state of the mesh: a position per vertex (in the order of `vertices(tm)`) and, optionally,
/// a colour per vertex (faces take their corners' mean).
struct Mesh_state {
  std::vector<std::array<double, 3>> positions;
  std::vector<Color> vertex_colors;
};

/// Blue (0) to red (1) through white, for values such as vulnerabilities.
inline Color diverging_color(double t) {
  t = std::clamp(t, 0.0, 1.0);
  const Color blue{0.23, 0.3, 0.75}, white{0.95, 0.95, 0.95}, red{0.75, 0.1, 0.1};
  const Color& a = t < 0.5 ? blue : white;
  const Color& b = t < 0.5 ? white : red;
  const double s = t < 0.5 ? 2 * t : 2 * t - 1;
  return {a.r + s * (b.r - a.r), a.g + s * (b.g - a.g), a.b + s * (b.b - a.b)};
}

namespace internal {

// The triangles of `tm` over the positions from `first` on, coloured by the corners' mean.
template <typename TriangleMesh, typename IndexMap>
void add_state_triangles(Render_scene& scene, const TriangleMesh& tm, IndexMap index,
                         const Mesh_state& s, std::size_t first) {
  for (auto f : faces(tm)) {
    std::array<std::size_t, 3> t{};
    std::size_t k = 0;
    Color c{0, 0, 0};
    for (auto v : CGAL::vertices_around_face(halfedge(f, tm), tm)) {
      if (k == 3)
        break;
      t[k++] = first + get(index, v);
      if (!s.vertex_colors.empty()) {
        const Color& vc = s.vertex_colors[get(index, v)];
        c.r += vc.r / 3;
        c.g += vc.g / 3;
        c.b += vc.b / 3;
      }
    }
    scene.triangles.push_back(t);
    scene.triangle_colors.push_back(s.vertex_colors.empty() ? Color{} : c);
  }
}

} // namespace internal

/// Adds the states of `tm` to `scene` one after the other along `offset_axis` (0 or 1: the first
/// state lowest, left in the default view; 2: the first state on top), with a gap of 0.4 times the
/// largest extent along it.
template <typename TriangleMesh>
void add_mesh_states(Render_scene& scene, const TriangleMesh& tm,
                     const std::vector<Mesh_state>& states, std::size_t offset_axis) {
  auto index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  std::size_t n = 0;
  for (auto v : vertices(tm))
    put(index, v, n++);
  std::vector<CGAL::Bbox_3> boxes;
  double largest = 0;
  for (const Mesh_state& s : states) {
    boxes.push_back(bounding_box(s.positions));
    largest =
        std::max(largest, boxes.back().max(int(offset_axis)) - boxes.back().min(int(offset_axis)));
  }
  double shift = 0;
  for (std::size_t state = 0; state < states.size(); ++state) {
    const Mesh_state& s = states[state];
    const std::size_t first = scene.positions.size();
    const double lo = boxes[state].min(int(offset_axis)), hi = boxes[state].max(int(offset_axis));
    const bool downwards = offset_axis == 2;
    for (auto p : s.positions) {
      p[offset_axis] += downwards ? shift - hi : shift - lo;
      scene.positions.push_back(p);
    }
    shift += (downwards ? -1 : 1) * ((hi - lo) + 0.4 * largest);
    internal::add_state_triangles(scene, tm, index, s, first);
  }
}

/// Adds one more state, of a mesh that may differ from the ones already in `scene` (a remeshed
/// result beside its input), after them along `offset_axis` as `add_mesh_states` places its
/// states: further along 0 or 1, lower along 2, with a gap of 0.4 times its extent.
template <typename TriangleMesh>
void append_mesh_state(Render_scene& scene, const TriangleMesh& tm, const Mesh_state& state,
                       std::size_t offset_axis) {
  const CGAL::Bbox_3 box = bounding_box(state.positions);
  const int axis = int(offset_axis);
  double lo = box.min(axis), hi = box.max(axis), shift = 0;
  if (!scene.positions.empty()) {
    const CGAL::Bbox_3 existing = bounding_box(scene.positions);
    const double gap = 0.4 * (hi - lo);
    shift = offset_axis == 2 ? existing.min(axis) - gap - hi : existing.max(axis) + gap - lo;
  }
  auto index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  std::size_t n = 0;
  for (auto v : vertices(tm))
    put(index, v, n++);
  const std::size_t first = scene.positions.size();
  for (auto p : state.positions) {
    p[offset_axis] += shift;
    scene.positions.push_back(p);
  }
  internal::add_state_triangles(scene, tm, index, state, first);
}

} // namespace tessera
