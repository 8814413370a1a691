// The inputs of a direction field shared by `tessera field` and `tessera mosaic`: control vectors
// from a JSON file (--control), feature lines (--features) and how the field meets them (--align),
// turned into the constraints of the smoothest field.
#pragma once

#include "commands.h"

#include <tessera/fields/feature_lines.h>
#include <tessera/fields/smoothest_field.h>
#include <tessera/types.h>

#include <cstddef>
#include <string>
#include <vector>

namespace tessera::cli {

/// Adds --control, --features, --feature-file, --align and --principal to `cmd`.
void add_field_input(CLI::App* cmd, Field_input_arguments& arguments);

/// What the field arguments make of a mesh. The constraints along the lines and by principal
/// directions are made by `solve_field()`, on the mesh the field is solved on (the lines may have
/// been carried onto a refined one).
struct Field_input {
  /// The control vectors (at vertices of the mesh they were read on).
  std::vector<Smoothest_field_solver<Mesh>::Constraint> constraints;
  std::vector<Feature_line<Mesh::Halfedge_index>> lines;
  /// The alignment of each line.
  std::vector<Feature_alignment> alignment;
  /// Colour regions read from the mesh file (0 unless --features has `color`).
  std::size_t color_regions = 0;
  /// --principal: guide the field by principal curvature directions.
  bool principal = false;
};

/// Reads the control file and finds the feature lines of `mesh`, which was read from `mesh_path`
/// (colour regions come from that file); prints the number of colour regions on stdout when
/// --features has `color`. Throws User_error on a bad argument or file.
Field_input read_field_input(const std::string& mesh_path, const Mesh& mesh,
                             const Field_input_arguments& arguments);

/// The files the field arguments name (--control, --feature-file), which an output directory
/// must not overwrite.
std::vector<std::string> field_input_files(const Field_input_arguments& arguments);

using Field_map = Mesh::Property_map<Mesh::Vertex_index, Vector_3>;

/// The constraints `in` puts on the field: its control vectors, the alignment with its lines (as
/// `alignment` says), and principal directions with --principal.
std::vector<Smoothest_field_solver<Mesh>::Constraint>
field_constraints(const Mesh& mesh, const Field_input& in,
                  const Feature_alignment_options& alignment = {});

/// The smoothest field of `symmetry` into `field` under `field_constraints(mesh, in)`; throws
/// User_error with the solver's message when it fails.
Smoothest_field_result solve_field(const Mesh& mesh, const Field_input& in, int symmetry,
                                   Field_map field);

} // namespace tessera::cli
