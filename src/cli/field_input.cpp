// The inputs of a direction field: control file, feature lines and their alignment (see
// field_input.h).
#include "field_input.h"

#include <tessera/fields/color_regions.h>
#include <tessera/fields/control_vectors.h>
#include <tessera/fields/feature_specs.h>
#include <tessera/fields/principal_directions.h>
#include <tessera/io/read_feature_polylines.h>

#include <iostream>

namespace tessera::cli {
namespace {

using Constraint = Smoothest_field_solver<Mesh>::Constraint;

std::vector<Constraint> read_controls(const std::string& path, const Mesh& mesh) {
  const Control_vectors_read_result r = read_control_vectors(path);
  if (!r)
    throw User_error(path + ": " + r.message);
  const Control_constraints_result<Mesh> c = control_vector_constraints(mesh, r.controls);
  if (!c)
    throw User_error(path + ": " + c.message);
  return c.constraints;
}

} // namespace

void add_field_input(CLI::App* cmd, Field_input_arguments& a) {
  cmd->add_option("--control", a.control, "JSON file of control vectors");
  cmd->add_option("--features", a.features, "Comma-separated: boundary, crease:ANGLE, color");
  cmd->add_option("--feature-file", a.feature_file,
                  "Feature lines drawn by hand: one polyline of vertex ids per line, each two "
                  "consecutive ids joined by an edge (closed when it ends where it starts)");
  cmd->add_option("--align", a.align,
                  "parallel, perpendicular, or a default plus LINE=ALIGNMENT entries (e.g. "
                  "parallel,2=perpendicular)")
      ->capture_default_str();
  cmd->add_flag("--principal", a.principal,
                "Guide the field by principal curvature directions where the surface is clearly "
                "anisotropic (tubes: legs, horns, tails get rows along and around them)");
}

Field_input read_field_input(const std::string& mesh_path, const Mesh& mesh,
                             const Field_input_arguments& a) {
  Field_input in;
  if (!a.control.empty())
    in.constraints = read_controls(a.control, mesh);
  const Feature_spec_result features = parse_feature_spec(a.features);
  if (!features)
    throw User_error("--features: " + features.message);
  const Feature_line_options& fo = features.options;
  auto region = get(CGAL::dynamic_face_property_t<int>(), mesh);
  for (auto f : faces(mesh))
    put(region, f, 0);
  if (fo.color_boundaries) {
    const Color_regions_result cr = read_color_regions(mesh_path, mesh, region);
    if (!cr)
      throw User_error(cr.message);
    in.color_regions = cr.regions;
    std::cout << "colour regions: " << cr.regions << " (" << (cr.face_colors ? "face" : "vertex")
              << " colours)\n";
  }
  in.lines = feature_lines(mesh, fo, [&](Mesh::Face_index f) { return get(region, f); });
  if (!a.feature_file.empty()) {
    const auto drawn = read_feature_polylines_file(a.feature_file, mesh);
    if (!drawn)
      throw User_error(drawn.message + " (--feature-file)");
    in.lines.insert(in.lines.end(), drawn.lines.begin(), drawn.lines.end());
    std::cout << "feature lines from " << a.feature_file << ": " << drawn.lines.size() << "\n";
  }
  const Alignment_spec_result alignment = parse_alignment_spec(a.align, in.lines.size());
  if (!alignment)
    throw User_error("--align: " + alignment.message);
  in.alignment = alignment.alignment;
  in.principal = a.principal;
  return in;
}

std::vector<std::string> field_input_files(const Field_input_arguments& arguments) {
  std::vector<std::string> files;
  for (const std::string* f : {&arguments.control, &arguments.feature_file})
    if (!f->empty())
      files.push_back(*f);
  return files;
}

std::vector<Constraint> field_constraints(const Mesh& mesh, const Field_input& in,
                                          const Feature_alignment_options& alignment) {
  std::vector<Constraint> constraints = in.constraints;
  const auto aligned = feature_alignment_constraints(mesh, in.lines, in.alignment, alignment);
  constraints.insert(constraints.end(), aligned.begin(), aligned.end());
  if (in.principal) {
    const auto guide = principal_direction_constraints(mesh);
    constraints.insert(constraints.end(), guide.begin(), guide.end());
  }
  return constraints;
}

Smoothest_field_result solve_field(const Mesh& mesh, const Field_input& in, int symmetry,
                                   Field_map field) {
  Smoothest_field_options so;
  so.symmetry = symmetry;
  // Not carried through where feature lines end or meet (as `tessera mosaic` solves it).
  auto is_line = get(CGAL::dynamic_edge_property_t<bool>(), mesh); // false everywhere
  mark_feature_edges(mesh, in.lines, is_line);
  const Smoothest_field_result r =
      smoothest_field(mesh, field_constraints(mesh, in), field, so,
                      CGAL::parameters::edge_is_constrained_map(is_line));
  if (!r)
    throw User_error(r.message);
  return r;
}

} // namespace tessera::cli
