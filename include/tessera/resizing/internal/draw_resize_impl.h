// The drawing behind add_mesh_states(), texture_comparison_scene() and the resize comparisons
// (tessera/resizing/draw_resize.h): the states' triangles, the view from the texture's side, and
// the simple scaling both comparisons start with. Included at the end of draw_resize.h.
#pragma once

#include <tessera/resizing/draw_resize.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace tessera {

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

// `options`'s colour lists against the input's and the result's vertices; empty when they fit.
template <typename TriangleMesh>
std::string mismatched_colors(const TriangleMesh& input, const TriangleMesh& result,
                              const Resize_comparison_options& options) {
  auto fits = [](const std::vector<Color>& colors, const TriangleMesh& tm) {
    return colors.empty() || colors.size() == std::size_t(num_vertices(tm));
  };
  if (!fits(options.input_colors, input))
    return "input_colors: " + std::to_string(options.input_colors.size()) + " colours for " +
           std::to_string(num_vertices(input)) + " vertices";
  if (!fits(options.result_colors, result))
    return "result_colors: " + std::to_string(options.result_colors.size()) + " colours for " +
           std::to_string(num_vertices(result)) + " vertices";
  return {};
}

// `input` resized by `method` with `options`'s factors, into `out`.
template <typename TriangleMesh>
Resize_result resize_copy(const TriangleMesh& input, Resize_options options, Resize_method method,
                          TriangleMesh& out) {
  out = input;
  options.method = method;
  return resize(out, options);
}

// What both comparisons start with: the colours checked against the meshes, the input's simple
// scaling into `out.simple_scaling`; false, with `out`'s status and message, on failure.
template <typename TriangleMesh>
bool compare_with_simple_scaling(const TriangleMesh& input, const TriangleMesh& result,
                                 const Resize_options& options,
                                 const Resize_comparison_options& colors,
                                 Resize_comparison<TriangleMesh>& out) {
  out.message = mismatched_colors(input, result, colors);
  if (!out.message.empty()) {
    out.status = Resize_comparison_status::mismatched_input;
    return false;
  }
  const Resize_result simple =
      resize_copy(input, options, Resize_method::simple, out.simple_scaling);
  if (!simple) {
    out.status = Resize_comparison_status::simple_scaling_failed;
    out.message = simple.message;
    return false;
  }
  return true;
}

} // namespace internal

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

template <typename TriangleMesh, typename TextureMap, typename NamedParameters>
Comparison_scene
texture_comparison_scene(const TriangleMesh& input, const std::vector<Mesh_state>& states,
                         const TriangleMesh& result, TextureMap is_texture,
                         std::vector<Color> result_colors, const NamedParameters& np) {
  using Vector = CGAL::Simple_cartesian<double>::Vector_3;
  Vector facing(0, 0, 0);
  for (auto v : vertices(result))
    if (get(is_texture, v)) {
      const auto n = CGAL::Polygon_mesh_processing::compute_vertex_normal(v, result, np);
      facing =
          facing + Vector(CGAL::to_double(n.x()), CGAL::to_double(n.y()), CGAL::to_double(n.z()));
    }
  const Vector tilt(0.45, -1.0, 1.1);
  const Vector eye = facing.squared_length() > 0
                         ? facing / std::sqrt(facing.squared_length()) +
                               0.35 * tilt / std::sqrt(tilt.squared_length())
                         : tilt;
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(result, np);
  std::size_t longest = 0, axis = 0;
  for (int c = 1; c < 3; ++c)
    if (box.max(c) - box.min(c) > box.max(int(longest)) - box.min(int(longest)))
      longest = std::size_t(c);
  double across = 2;
  for (std::size_t c = 0; c < 3; ++c)
    if (c != longest && std::abs(eye[int(c)]) / std::sqrt(eye.squared_length()) < across) {
      across = std::abs(eye[int(c)]) / std::sqrt(eye.squared_length());
      axis = c;
    }
  Comparison_scene picture;
  picture.view.eye_direction = {{eye.x(), eye.y(), eye.z()}};
  picture.view.up = {{0, 0, 0}}; // upwards on the screen: add_mesh_states puts its first on top
  picture.view.up[axis] = 1;
  picture.offset_axis = axis;
  add_mesh_states(picture.scene, input, states, axis);
  append_mesh_state(picture.scene, result, mesh_state(result, std::move(result_colors), np), axis);
  return picture;
}

template <typename TriangleMesh>
Resize_comparison<TriangleMesh>
resize_comparison(const TriangleMesh& input, const TriangleMesh& resized,
                  const Resize_options& options, const Resize_comparison_options& colors) {
  Resize_comparison<TriangleMesh> out;
  if (num_vertices(resized) != num_vertices(input)) {
    out.status = Resize_comparison_status::mismatched_input;
    out.message = "the result has " + std::to_string(num_vertices(resized)) +
                  " vertices, the input " + std::to_string(num_vertices(input));
    return out;
  }
  if (!internal::compare_with_simple_scaling(input, resized, options, colors, out))
    return out;
  std::size_t most = 0;
  for (std::size_t c = 1; c < 3; ++c)
    if (std::abs(std::log(options.scale[c])) > std::abs(std::log(options.scale[most])))
      most = c;
  out.picture.offset_axis = most == 2 ? 0 : 2;
  add_mesh_states(out.picture.scene, resized,
                  {mesh_state(input, colors.input_colors),
                   mesh_state(out.simple_scaling, colors.input_colors),
                   mesh_state(resized, colors.result_colors)},
                  out.picture.offset_axis);
  return out;
}

template <typename TriangleMesh, typename TextureMap>
Resize_comparison<TriangleMesh>
texture_resize_comparison(const TriangleMesh& input, const TriangleMesh& result,
                          TextureMap is_texture, const Resize_options& options,
                          const Resize_comparison_options& colors) {
  Resize_comparison<TriangleMesh> out;
  if (!internal::compare_with_simple_scaling(input, result, options, colors, out))
    return out;
  std::vector<Mesh_state> states{mesh_state(input, colors.input_colors),
                                 mesh_state(out.simple_scaling, colors.input_colors)};
  TriangleMesh nonhomogeneous;
  if (internal::resize_copy(input, options, Resize_method::nonhomogeneous, nonhomogeneous)) {
    states.push_back(mesh_state(nonhomogeneous, colors.input_colors));
    out.nonhomogeneous = std::move(nonhomogeneous);
  }
  out.picture = texture_comparison_scene(input, states, result, is_texture, colors.result_colors);
  return out;
}

} // namespace tessera
