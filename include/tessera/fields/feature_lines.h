// Feature lines that a field should follow (Lai, Hu, Martin, "Surface Mosaics", §5): open
// boundaries, sharp creases (CGAL::Polygon_mesh_processing::detect_sharp_edges) and borders between
// colour regions, chained into polylines addressed by index, and the parallel / perpendicular
// constraints they impose.
#pragma once

#include <tessera/fields/smoothest_field.h>

#include <vector>

namespace tessera {

/// What a feature line is: an open boundary, a sharp crease, a border between colour regions, or a
/// line the user drew (`read_feature_polylines()`).
enum class Feature_kind { boundary, crease, color_boundary, user };

/// Which features `feature_lines()` extracts.
struct Feature_line_options {
  bool boundary = true;
  bool creases = false;
  /// Dihedral angle (degrees, between face normals) above which an edge is a crease.
  double crease_angle_degrees = 60;
  /// Borders between faces of different regions (only when a region map is given).
  bool color_boundaries = true;
};

/// A feature polyline: consecutive halfedges (target of one = source of the next). Open lines end
/// at vertices where the number of feature edges is not 2 or the kind changes; closed lines are
/// loops.
template <typename HalfedgeDescriptor> struct Feature_line {
  Feature_kind kind = Feature_kind::boundary;
  std::vector<HalfedgeDescriptor> halfedges;
  bool closed = false;
};

/// How a field meets a feature line: along it or across it.
enum class Feature_alignment { parallel, perpendicular };

/// Feature lines of `tm`; `face_region(f)` returns an integer region id (a colour class) of face f.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh, typename FaceRegion,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<Feature_line<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>>
feature_lines(const TriangleMesh& tm, const Feature_line_options& options, FaceRegion face_region,
              const NamedParameters& np = CGAL::parameters::default_values());

/// Feature lines of `tm` without colour regions.
template <typename TriangleMesh>
std::vector<Feature_line<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>>
feature_lines(const TriangleMesh& tm, const Feature_line_options& options = {});

/// Sets `is_line` (a writable edge property map of `bool`) to true on every edge of `lines`, as the
/// `edge_is_constrained_map` of `Smoothest_field_solver` and of CGAL's functions takes it.
template <typename TriangleMesh, typename HalfedgeDescriptor, typename EdgeIsConstrainedMap>
void mark_feature_edges(const TriangleMesh& tm,
                        const std::vector<Feature_line<HalfedgeDescriptor>>& lines,
                        EdgeIsConstrainedMap is_line) {
  for (const auto& line : lines)
    for (const HalfedgeDescriptor h : line.halfedges)
      put(is_line, edge(h, tm), true);
}

/// How `feature_alignment_constraints()` holds a field to the lines.
struct Feature_alignment_options {
  Constraint_kind kind = Constraint_kind::hard;
  double weight = 1;
  /// Bends of a line tighter than this radius leave the field free (0: every vertex inside a line
  /// is constrained). A vertex is in such a bend when the line turns, over the stretch of this
  /// length centred on it, by more than one radian: along an arc of radius r it turns by this
  /// length over r, so arcs of a smaller radius, and a stretch this long around a sharp corner,
  /// are left out. Rows of tiles cannot follow an arc much tighter than a few tiles (each tile of
  /// the row beside it opens a wedge of its side squared over r), nor a corner's bisector; there
  /// the field takes the direction of the straight parts around and the tiles are cut to the arc.
  double tightest_radius = 0;
};

/// Constraints aligning a field with feature lines: at every vertex inside a line (all vertices of
/// a closed one; never the end points, where lines meet at angles no field can follow), except
/// in bends tighter than `options.tightest_radius`, the direction is the line's tangent (parallel)
/// or the normal times it (perpendicular). `alignment` holds one entry per line, or a single entry
/// for all. For a 4-field both alignments give the same cross.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh, typename HalfedgeDescriptor,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<typename Smoothest_field_solver<TriangleMesh>::Constraint>
feature_alignment_constraints(const TriangleMesh& tm,
                              const std::vector<Feature_line<HalfedgeDescriptor>>& lines,
                              const std::vector<Feature_alignment>& alignment,
                              const Feature_alignment_options& options,
                              const NamedParameters& np = CGAL::parameters::default_values());

/// As above with `kind` and `weight` and no bend left free.
template <typename TriangleMesh, typename HalfedgeDescriptor,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<typename Smoothest_field_solver<TriangleMesh>::Constraint>
feature_alignment_constraints(const TriangleMesh& tm,
                              const std::vector<Feature_line<HalfedgeDescriptor>>& lines,
                              const std::vector<Feature_alignment>& alignment,
                              Constraint_kind kind = Constraint_kind::hard, double weight = 1,
                              const NamedParameters& np = CGAL::parameters::default_values()) {
  Feature_alignment_options options;
  options.kind = kind;
  options.weight = weight;
  return feature_alignment_constraints(tm, lines, alignment, options, np);
}

} // namespace tessera

#include <tessera/fields/internal/feature_lines_impl.h>
