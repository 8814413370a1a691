// Implementation of tessera::add_field_strokes (see tessera/fields/draw_field.h).
#pragma once

#include <tessera/fields/draw_field.h>

#include <tessera/fields/feature_lines.h>
#include <tessera/fields/singularities.h>
#include <tessera/fields/tangent_field.h>
#include <tessera/internal/named_parameters.h>
#include <tessera/render/mesh_scene.h>
#include <CGAL/boost/graph/iterator.h>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace tessera {

template <typename TriangleMesh, typename VertexFieldMap, typename NamedParameters>
void add_field_strokes(Render_scene& scene, const TriangleMesh& tm, const VertexFieldMap& field,
                       int symmetry, const Field_drawing_options& options,
                       const NamedParameters& np) {
  using internal::Vec3;
  using Vector = typename boost::property_traits<VertexFieldMap>::value_type;
  if (!is_valid_symmetry(symmetry) || num_vertices(tm) == 0)
    return;
  const auto vpm = internal::vertex_point_map(tm, np);
  double edge = 0;
  for (auto e : edges(tm))
    edge += internal::norm(internal::to_vec3(get(vpm, target(halfedge(e, tm), tm))) -
                           internal::to_vec3(get(vpm, source(halfedge(e, tm), tm))));
  edge /= double(std::max<std::size_t>(1, num_edges(tm)));
  const std::size_t stride =
      std::max<std::size_t>(1, num_vertices(tm) / std::max<std::size_t>(1, options.strokes));
  const double length = options.stroke_length * edge * std::sqrt(double(stride));

  auto bases = get(CGAL::dynamic_vertex_property_t<Tangent_basis<Vector>>(), tm);
  vertex_tangent_bases(tm, bases, np);
  auto segment = [&](const Vec3& a, const Vec3& b) {
    scene.polylines.push_back({{a, b}, options.ink, options.stroke_width});
  };
  std::size_t i = 0;
  for (auto v : vertices(tm)) {
    if (i++ % stride != 0)
      continue;
    const Vec3 x = internal::to_vec3(get(field, v));
    const double magnitude = internal::norm(x);
    if (magnitude == 0)
      continue;
    const Vec3 n = internal::to_vec3(get(bases, v).normal);
    const Vec3 d = (length / magnitude) * x;
    const Vec3 p = internal::to_vec3(get(vpm, v)) + (options.lift * length) * n;
    if (symmetry == 1) {
      segment(p, p + d);
      scene.points.push_back({p, options.ink, options.stroke_width});
      continue;
    }
    segment(p - 0.5 * d, p + 0.5 * d);
    if (symmetry == 4) {
      const Vec3 q = internal::cross(n, d);
      segment(p - 0.5 * q, p + 0.5 * q);
    }
  }
}

template <typename TriangleMesh, typename NamedParameters>
void add_field_singularities(Render_scene& scene, const TriangleMesh& tm,
                             const Field_singularities<TriangleMesh>& singularities,
                             const Field_drawing_options& options, const NamedParameters& np) {
  const auto vpm = internal::vertex_point_map(tm, np);
  for (const auto& s : singularities.singularities) {
    internal::Vec3 c{{0, 0, 0}};
    for (auto v : CGAL::vertices_around_face(halfedge(s.face, tm), tm))
      c = c + (1.0 / 3) * internal::to_vec3(get(vpm, v));
    scene.points.push_back(
        {c, s.numerator > 0 ? options.positive_singularity : options.negative_singularity,
         options.singularity_radius});
  }
}

template <typename TriangleMesh, typename VertexFieldMap, typename NamedParameters>
void add_field(Render_scene& scene, const TriangleMesh& tm, const VertexFieldMap& field,
               const Field_singularities<TriangleMesh>& singularities,
               const Field_drawing_options& options, const NamedParameters& np) {
  add_field_strokes(scene, tm, field, singularities.symmetry, options, np);
  add_field_singularities(scene, tm, singularities, options, np);
}

template <typename TriangleMesh, typename HalfedgeDescriptor, typename NamedParameters>
void add_feature_lines(Render_scene& scene, const TriangleMesh& tm,
                       const std::vector<Feature_line<HalfedgeDescriptor>>& lines,
                       const Field_drawing_options& options, const NamedParameters& np) {
  const auto vpm = internal::vertex_point_map(tm, np);
  for (const auto& line : lines) {
    if (line.halfedges.empty())
      continue;
    Render_polyline polyline{{}, options.feature_line, options.feature_line_width};
    polyline.points.push_back(internal::to_vec3(get(vpm, source(line.halfedges.front(), tm))));
    for (auto h : line.halfedges)
      polyline.points.push_back(internal::to_vec3(get(vpm, target(h, tm))));
    scene.polylines.push_back(std::move(polyline));
  }
}

} // namespace tessera
