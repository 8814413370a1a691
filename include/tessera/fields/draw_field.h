// Pictures of direction fields: a short stroke per sampled vertex (a vector with a dot at its foot,
// a line, or a cross, by the symmetry order), singular faces as dots (red positive, blue negative)
// and feature lines as polylines, for `render_png()`.
#pragma once

#include <tessera/fields/feature_lines.h>
#include <tessera/fields/singularities.h>
#include <tessera/fields/tangent_field.h>
#include <tessera/internal/named_parameters.h>
#include <tessera/render/mesh_scene.h>

#include <cstddef>

namespace tessera {

/// How a field is drawn.
struct Field_drawing_options {
  /// About this many strokes whatever the mesh size: every k-th vertex gets one, k = max(1,
  /// ⌊V / strokes⌋).
  std::size_t strokes = 3000;
  /// Stroke length in mean edge lengths, times √k, so that a stroke is about as long as the spacing
  /// between strokes.
  double stroke_length = 0.8;
  /// Strokes float this far off the surface along the vertex normal, in stroke lengths, so that no
  /// half of a stroke sinks behind a face.
  double lift = 0.1;
  Color ink{0.1, 0.15, 0.45};
  /// Stroke width in pixels, also the radius of the dot at a vector's foot (symmetry 1).
  double stroke_width = 1.5;
  Color positive_singularity{0.9, 0.1, 0.1};
  Color negative_singularity{0.1, 0.4, 0.95};
  /// Radius of a singular face's dot in pixels.
  double singularity_radius = 6;
  Color feature_line{0.95, 0.55, 0.1};
  /// Feature line width in pixels.
  double feature_line_width = 3;
};

/// Adds strokes along `field` (a vertex map of vectors read as a symmetry-n field, n = 1, 2 or 4;
/// another n draws nothing) to `scene`: for n = 1 a segment from the vertex with a dot at its foot,
/// for n = 2 a segment centred on it, for n = 4 a cross whose second arm is N × X. Vertices with a
/// zero vector get no stroke.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh, typename VertexFieldMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
void add_field_strokes(Render_scene& scene, const TriangleMesh& tm, const VertexFieldMap& field,
                       int symmetry, const Field_drawing_options& options = {},
                       const NamedParameters& np = CGAL::parameters::default_values());

/// Adds a dot at the centroid of every singular face of `singularities` (a result of
/// `field_singularities()` on `tm`) to `scene`: positive indices in
/// `options.positive_singularity`, negative ones in `options.negative_singularity`.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
void add_field_singularities(Render_scene& scene, const TriangleMesh& tm,
                             const Field_singularities<TriangleMesh>& singularities,
                             const Field_drawing_options& options = {},
                             const NamedParameters& np = CGAL::parameters::default_values());

/// Adds the strokes of `field` and the dots of its `singularities` (a result of
/// `field_singularities(tm, field, n)`, whose symmetry order the strokes follow) to `scene`.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh, typename VertexFieldMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
void add_field(Render_scene& scene, const TriangleMesh& tm, const VertexFieldMap& field,
               const Field_singularities<TriangleMesh>& singularities,
               const Field_drawing_options& options = {},
               const NamedParameters& np = CGAL::parameters::default_values());

/// Adds every line of `lines` (from `feature_lines(tm, …)`) to `scene` as a polyline in
/// `options.feature_line`.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh, typename HalfedgeDescriptor,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
void add_feature_lines(Render_scene& scene, const TriangleMesh& tm,
                       const std::vector<Feature_line<HalfedgeDescriptor>>& lines,
                       const Field_drawing_options& options = {},
                       const NamedParameters& np = CGAL::parameters::default_values());

} // namespace tessera

#include <tessera/fields/internal/draw_field_impl.h>
