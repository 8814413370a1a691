// What a `tessera view` page shows: a plain scene of triangle, segment and point layers with
// per-element ids and report figures, and the files it came from. Written into one self-contained
// HTML page by write_view_html() (tessera/view/write_view_html.h); built from a command's result
// directory by read_view_scene() (tessera/view/read_view_scene.h).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace tessera {

/// An RGB colour, 0-255 per channel.
using View_colour = std::array<std::uint8_t, 3>;

/// An RGB picture laid on a mesh layer (a planar mosaic's source image).
struct View_texture {
  int width = 0, height = 0;
  /// r, g, b per pixel, row by row from the top row.
  std::vector<std::uint8_t> pixels;
};

/// Triangles drawn as a surface. Vertex i is vertex i of the source file, so hover shows file ids.
struct View_mesh_layer {
  std::string name;
  /// x, y, z per vertex.
  std::vector<float> positions;
  /// Three vertex indices per triangle.
  std::vector<std::uint32_t> triangles;
  /// r, g, b per triangle; empty: every triangle in `colour`.
  std::vector<std::uint8_t> triangle_colours;
  /// r, g, b per vertex (interpolated); used when `triangle_colours` is empty.
  std::vector<std::uint8_t> vertex_colours;
  View_colour colour{200, 200, 200};
  /// What hover calls the element a triangle belongs to ("face", "quad", "tile", "chart").
  std::string element_kind = "face";
  /// Per triangle, the id of its element; empty: the triangle's own index.
  std::vector<std::uint32_t> element_ids;
  /// Per element id, one line of the report's figures for it (may be empty).
  std::vector<std::string> element_figures;
  /// u, v per vertex into `texture`, (0, 0) the top-left corner of its top row and (1, 1) the
  /// bottom-right one; the layer shows the picture when `texture` has pixels.
  std::vector<float> texture_coordinates;
  View_texture texture;
  /// Shaded by the lights; false: drawn in its own colours, as a picture is.
  bool lit = true;
  /// Hover names this layer's elements; false: hover looks through it.
  bool pickable = true;
  /// Hover names the vertex nearest the pointer (false when vertices are not a file's).
  bool hover_vertex = true;
  bool visible = true;
};

/// Line segments (seams, tile borders, field crosses).
struct View_segment_layer {
  std::string name;
  /// Two points (six floats) per segment.
  std::vector<float> segments;
  View_colour colour{20, 20, 20};
  bool visible = true;
};

/// Points (corners, singularities), each with an optional label shown beside it.
struct View_point_layer {
  std::string name;
  /// x, y, z per point.
  std::vector<float> positions;
  /// Empty, or one label per point.
  std::vector<std::string> labels;
  View_colour colour{230, 190, 0};
  bool visible = true;
};

/// A whole page.
struct View_scene {
  /// First line of the page ("cut of genus-2 surface").
  std::string title;
  /// What kind of result this is ("cut", "quadrangulate", "field", "mosaic", "resize", ...).
  std::string kind;
  /// The files the scene was read from, as given.
  std::vector<std::string> sources;
  std::vector<View_mesh_layer> meshes;
  std::vector<View_segment_layer> segments;
  std::vector<View_point_layer> points;
  /// The scene lies in the plane z = 0 (a planar mosaic): the camera starts looking down the z
  /// axis, fitted to the scene's rectangle.
  bool flat = false;
};

} // namespace tessera
