// Pictures of resizing and deformation: several states of one mesh side by side in one scene, so
// they are seen from the same view at the same scale, each optionally coloured per vertex; and the
// comparison pictures of a resize: the input, its simple scaling (and non-homogeneous resizing)
// and the result, from a view chosen for them.
#pragma once

#include <tessera/internal/named_parameters.h>
#include <tessera/render/scene.h>
#include <tessera/resizing/resize.h>
#include <tessera/resizing/tet_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
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

/// Adds the states of `tm` to `scene` one after the other along `offset_axis` (0 or 1: the first
/// state lowest, left in the default view; 2: the first state on top), with a gap of 0.4 times the
/// largest extent along it.
template <typename TriangleMesh>
void add_mesh_states(Render_scene& scene, const TriangleMesh& tm,
                     const std::vector<Mesh_state>& states, std::size_t offset_axis);

/// Adds one more state, of a mesh that may differ from the ones already in `scene` (a remeshed
/// result beside its input), after them along `offset_axis` as `add_mesh_states` places its
/// states: further along 0 or 1, lower along 2, with a gap of 0.4 times its extent.
template <typename TriangleMesh>
void append_mesh_state(Render_scene& scene, const TriangleMesh& tm, const Mesh_state& state,
                       std::size_t offset_axis);

/// The state `tm` is in: its points, in the order of `vertices(tm)`, with `vertex_colors`.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Mesh_state mesh_state(const TriangleMesh& tm, std::vector<Color> vertex_colors = {},
                      const NamedParameters& np = CGAL::parameters::default_values()) {
  const auto vpm = internal::vertex_point_map(tm, np);
  Mesh_state state;
  for (auto v : vertices(tm)) {
    const auto& p = get(vpm, v);
    state.positions.push_back(
        {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}});
  }
  state.vertex_colors = std::move(vertex_colors);
  return state;
}

/// A picture of states side by side: the scene and the view it is meant to be drawn from.
struct Comparison_scene {
  Render_scene scene;
  /// The eye and up directions chosen for the scene, the rest at the renderer's defaults (the
  /// caller adds a title).
  Render_options view;
  /// The axis the states follow each other along, as `add_mesh_states` lays them: along 0 or 1
  /// the first is lowest, left in the default view; along 2 it is on top.
  std::size_t offset_axis = 0;
};

/// Lays `states` of `input` (as `add_mesh_states` does) and after them `result`, a mesh with its
/// own connectivity (a texture-preserving resize or deformation of `input`), coloured per vertex
/// by `result_colors` (empty: uncoloured). Seen from the texture's side: the mean normal of the
/// result's vertices where `is_texture` is true, tilted as the default view is; the states
/// stacked upwards on the screen along the axis most across the view that is not the result's
/// longest. The arithmetic of the view is in double.
///
/// Named parameters (of `result`): `vertex_point_map`, `geom_traits`.
template <typename TriangleMesh, typename TextureMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Comparison_scene
texture_comparison_scene(const TriangleMesh& input, const std::vector<Mesh_state>& states,
                         const TriangleMesh& result, TextureMap is_texture,
                         std::vector<Color> result_colors = {},
                         const NamedParameters& np = CGAL::parameters::default_values());

/// Colours of the states of a resize comparison, one per vertex in the order of `vertices()`;
/// empty: uncoloured.
struct Resize_comparison_options {
  /// Of the input, and of the input's simple scaling and non-homogeneous resizing.
  std::vector<Color> input_colors;
  /// Of the result (a vulnerability, a detail height).
  std::vector<Color> result_colors;
};

enum class Resize_comparison_status {
  ok,
  /// A colour list has not one colour per vertex, or `resize_comparison`'s result has not the
  /// input's vertices.
  mismatched_input,
  /// The input's simple scaling failed (the message is `resize`'s).
  simple_scaling_failed
};

/// The states a resize is compared with, and the picture of them beside the input and the result.
template <typename TriangleMesh> struct Resize_comparison {
  Resize_comparison_status status = Resize_comparison_status::ok;
  std::string message;
  /// The input scaled by the same factors.
  TriangleMesh simple_scaling;
  /// With `texture_resize_comparison`: the input resized non-homogeneously, unless that failed
  /// (then it is left out of the picture too).
  std::optional<TriangleMesh> nonhomogeneous;
  Comparison_scene picture;
  explicit operator bool() const { return status == Resize_comparison_status::ok; }
};

/// Scales `input` simply by `options.scale` and lays input, simple scaling and `resized` (`input`
/// resized by `resize()` with `options`: the same vertices) side by side in the default view,
/// along x when z is the most resized axis and from the top down otherwise, so that each shows
/// its full length along the most resized axis.
template <typename TriangleMesh>
Resize_comparison<TriangleMesh>
resize_comparison(const TriangleMesh& input, const TriangleMesh& resized,
                  const Resize_options& options, const Resize_comparison_options& colors = {});

/// Scales `input` simply by `options.scale`, resizes it non-homogeneously as well, and lays
/// input, simple scaling, non-homogeneous resizing (where it succeeds) and `result` (`input`
/// resized by `resize_preserving_texture()`, with its own vertices) as `texture_comparison_scene`
/// does, seen from the side of `result`'s texture (`is_texture`, a vertex map of `result`).
template <typename TriangleMesh, typename TextureMap>
Resize_comparison<TriangleMesh>
texture_resize_comparison(const TriangleMesh& input, const TriangleMesh& result,
                          TextureMap is_texture, const Resize_options& options,
                          const Resize_comparison_options& colors = {});

} // namespace tessera

#include <tessera/resizing/internal/draw_resize_impl.h>
