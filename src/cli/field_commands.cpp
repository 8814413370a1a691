// tessera field: the smoothest direction field of a mesh under control vectors, feature-line
// alignment and principal directions, written as CSV, singularities.json and a picture.
#include "commands.h"
#include "field_input.h"
#include "mesh_input.h"
#include "output_dir.h"

#include <tessera/fields.h>
#include <tessera/io.h>
#include <tessera/io/field_reports.h>
#include <tessera/render.h>
#include <tessera/types.h>

#include <fstream>
#include <iostream>

namespace tessera::cli {
namespace {

void render_field(const Mesh& mesh, Field_map field,
                  const std::vector<Feature_line<Mesh::Halfedge_index>>& lines,
                  const Field_singularities<Mesh>& sing, const std::string& path,
                  const std::string& title) {
  Render_scene scene;
  add_mesh(scene, mesh);
  add_feature_lines(scene, mesh, lines);
  add_field(scene, mesh, field, sing);
  Render_options options;
  options.title = title;
  options.edges = Edge_drawing::never;
  write_checked(path, [&](const std::string& tmp) { return render_png(scene, tmp, options); });
}

} // namespace

int run_field(const Field_arguments& a) {
  if (!is_valid_symmetry(a.symmetry))
    throw User_error("--symmetry must be 1, 2 or 4 (got " + std::to_string(a.symmetry) + ")");
  std::vector<std::string> inputs{a.mesh};
  for (const std::string& f : field_input_files(a.field))
    inputs.push_back(f);
  Mesh mesh = read_input_mesh(a.mesh, a.input);
  Field_input in = read_field_input(a.mesh, mesh, a.field);

  const Output_directory dir(a.out, a.force, inputs);
  const Field_map field =
      mesh.add_property_map<Mesh::Vertex_index, Vector_3>("v:tessera_field").first;
  const Smoothest_field_result r = solve_field(mesh, in, a.symmetry, field);
  const Field_singularities<Mesh> sing = field_singularities(mesh, field, a.symmetry);
  std::cout << "field: symmetry " << a.symmetry << ", " << r.hard_constraints << " hard and "
            << r.soft_constraints << " soft constraints, " << in.lines.size()
            << " feature lines, energy " << r.energy << " (" << r.solver << ")\n"
            << "singularities: " << sing.singularities.size() << ", index sum "
            << sing.face_index_sum << "/" << a.symmetry << " + boundary " << sing.boundary_index_sum
            << "/" << a.symmetry << " = Euler characteristic " << sing.euler_characteristic
            << (sing.poincare_hopf_holds() ? " (Poincaré–Hopf holds)" : " (Poincaré–Hopf FAILS)")
            << "\n";

  write_checked_stream(dir.file("field.csv"),
                       [&](std::ostream& out) { return write_field_csv(out, mesh, field); });
  write_checked_stream(dir.file("singularities.json"), [&](std::ostream& out) {
    return write_singularities_report(out, make_singularities_report(mesh, sing));
  });
  write_checked_stream(dir.file("feature_lines.json"), [&](std::ostream& out) {
    return write_feature_lines_report(out, make_feature_lines_report(mesh, in.lines, in.alignment));
  });
  render_field(mesh, field, in.lines, sing, dir.file("field.png"),
               a.mesh + ": " + std::to_string(a.symmetry) + "-field, " +
                   std::to_string(sing.singularities.size()) + " singularities");
  print_written(with_view({dir.file("field.csv"), dir.file("singularities.json"),
                           dir.file("feature_lines.json"), dir.file("field.png")},
                          dir, a.view, a.mesh));
  return int(exit_ok);
}

void register_field_commands(CLI::App& app, std::function<int()>& run) {
  auto args = std::make_shared<Field_arguments>();
  auto* cmd =
      app.add_subcommand("field", "Smoothest direction field with controls and feature alignment");
  add_mesh_input(cmd, args->mesh, args->input);
  add_field_input(cmd, args->field);
  cmd->add_option("--symmetry", args->symmetry, "Symmetry order: 1, 2 or 4")->capture_default_str();
  cmd->add_option("--out", args->out, "Output directory")->required();
  cmd->add_flag("--force", args->force, "Write into a non-empty directory Tessera did not create");
  add_view_flag(cmd, args->view);
  cmd->callback([&run, args] { run = [args] { return run_field(*args); }; });
}

} // namespace tessera::cli
