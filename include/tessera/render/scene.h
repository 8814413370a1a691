// Headless pictures of meshes: a plain scene (triangles with per-face colours, polylines, points)
// that every module fills, and `render_png()` that draws it offscreen (orthographic view, two-sided
// Lambert shading, a depth buffer; lines by cairo). No window system or GPU is needed.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace tessera {

/// RGB colour with components in [0, 1].
struct Color {
  double r = 0.8, g = 0.8, b = 0.8;
};

/// A well-spread palette: colour `i` differs clearly from colours i-1 and i+1 (golden-ratio hues).
Color distinct_color(std::size_t i);

struct Render_polyline {
  std::vector<std::array<double, 3>> points;
  Color color{0.85, 0.1, 0.1};
  /// Line width in pixels.
  double width = 2.5;
};

struct Render_point {
  std::array<double, 3> position{{0, 0, 0}};
  Color color{0.1, 0.1, 0.9};
  /// Radius in pixels.
  double radius = 5;
};

/// What to draw. Triangles index `positions`; `triangle_colors` is empty (all default grey) or one
/// colour per triangle.
struct Render_scene {
  std::vector<std::array<double, 3>> positions;
  std::vector<std::array<std::size_t, 3>> triangles;
  std::vector<Color> triangle_colors;
  /// Empty, or one distance per triangle by which it counts as nearer to the eye in the depth test
  /// (for things that lie on a surface, such as mosaic tiles over their grout).
  std::vector<double> triangle_depth_bias;
  std::vector<Render_polyline> polylines;
  std::vector<Render_point> points;
};

enum class Edge_drawing { automatic, always, never };

struct Render_options {
  int width = 1200;
  int height = 900;
  /// Direction from the scene's centre towards the eye.
  std::array<double, 3> eye_direction{{0.45, -1.0, 1.1}};
  /// Up direction on screen (projected orthogonally to the view).
  std::array<double, 3> up{{0, 0, 1}};
  Color background{1, 1, 1};
  /// Thin triangle edges: `automatic` draws them when there are few enough triangles to see them.
  Edge_drawing edges = Edge_drawing::automatic;
  /// Title printed in the top-left corner (empty for none).
  std::string title;
};

enum class Render_status { ok, empty_scene, invalid_scene, write_failed };

struct Render_result {
  Render_status status = Render_status::ok;
  std::string message;
  explicit operator bool() const { return status == Render_status::ok; }
};

/// Draws `scene` into the PNG file `path`.
Render_result render_png(const Render_scene& scene, const std::string& path,
                         const Render_options& options = {});

} // namespace tessera
