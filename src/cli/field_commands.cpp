// tessera field: the smoothest direction field of a mesh under control vectors, feature-line
// alignment and principal directions, written as CSV, singularities.json and a picture.
#include "commands.h"
#include "mesh_input.h"
#include "output_dir.h"

#include <tessera/fields.h>
#include <tessera/io.h>
#include <tessera/render.h>
#include <tessera/types.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

namespace tessera::cli {
namespace {

using Constraint = Smoothest_field_solver<Mesh>::Constraint;
using Field_map = Mesh::Property_map<Mesh::Vertex_index, Vector_3>;

Vector_3 json_vector(const nlohmann::json& j, const std::string& where) {
  if (!j.is_array() || j.size() != 3 || !j[0].is_number() || !j[1].is_number() || !j[2].is_number())
    throw User_error(where + ": \"direction\" must be an array of three numbers");
  return Vector_3(j[0].get<double>(), j[1].get<double>(), j[2].get<double>());
}

// {"controls": [{"vertex": 12, "direction": [1, 0, 0]},
//               {"face": 7, "barycentric": [0.2, 0.3, 0.5], "direction": [0, 1, 0], "weight": 2}]}
// A control without "weight" is hard; with one it is soft.
std::vector<Constraint> read_controls(const std::string& path, const Mesh& mesh) {
  std::ifstream in(path);
  if (!in) throw User_error(path + ": cannot open control file");
  nlohmann::json doc;
  try {
    in >> doc;
  } catch (const nlohmann::json::exception& e) {
    throw User_error(path + ": malformed JSON (" + std::string(e.what()) + ")");
  }
  if (!doc.is_object() || !doc.contains("controls") || !doc["controls"].is_array())
    throw User_error(path + ": expected an object with a \"controls\" array");
  std::vector<Constraint> out;
  for (std::size_t k = 0; k < doc["controls"].size(); ++k) {
    const auto& c = doc["controls"][k];
    const std::string where = path + ": control " + std::to_string(k);
    if (!c.is_object() || !c.contains("direction")) throw User_error(where + " needs a \"direction\"");
    const Vector_3 d = json_vector(c["direction"], where);
    Constraint_kind kind = Constraint_kind::hard;
    double weight = 1;
    if (c.contains("weight")) {
      if (!c["weight"].is_number() || !(c["weight"].get<double>() > 0))
        throw User_error(where + ": \"weight\" must be a positive number");
      kind = Constraint_kind::soft;
      weight = c["weight"].get<double>();
    }
    auto index = [&](const char* key, std::size_t count) {
      if (!c[key].is_number_integer() || c[key].get<long long>() < 0 || std::size_t(c[key].get<long long>()) >= count)
        throw User_error(where + ": \"" + key + "\" must be an index below " + std::to_string(count));
      return std::size_t(c[key].get<long long>());
    };
    if (c.contains("vertex")) {
      out.push_back({Mesh::Vertex_index(Mesh::size_type(index("vertex", num_vertices(mesh)))), d, kind, weight});
    } else if (c.contains("face")) {
      const Mesh::Face_index f(Mesh::size_type(index("face", num_faces(mesh))));
      std::array<double, 3> b{{1.0 / 3, 1.0 / 3, 1.0 / 3}};
      if (c.contains("barycentric")) {
        const auto& j = c["barycentric"];
        if (!j.is_array() || j.size() != 3 || !j[0].is_number() || !j[1].is_number() || !j[2].is_number())
          throw User_error(where + ": \"barycentric\" must be three numbers");
        b = {{j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}};
      }
      const auto on_face = face_point_constraints(mesh, f, b, d, kind, weight);
      if (on_face.empty()) throw User_error(where + ": barycentric coordinates must be non-negative and sum to 1");
      out.insert(out.end(), on_face.begin(), on_face.end());
    } else {
      throw User_error(where + " needs a \"vertex\" or a \"face\"");
    }
  }
  return out;
}

Feature_alignment parse_alignment(const std::string& s) {
  if (s == "parallel") return Feature_alignment::parallel;
  if (s == "perpendicular") return Feature_alignment::perpendicular;
  throw User_error("--align: '" + s + "' is neither parallel nor perpendicular");
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> parts;
  std::stringstream in(s);
  std::string part;
  while (std::getline(in, part, sep))
    if (!part.empty()) parts.push_back(part);
  return parts;
}

// "parallel", "perpendicular", or a default followed by LINE=ALIGNMENT entries: "parallel,3=perpendicular".
std::vector<Feature_alignment> alignment_per_line(const std::string& spec, std::size_t lines) {
  std::vector<Feature_alignment> out(lines, Feature_alignment::parallel);
  for (const std::string& entry : split(spec, ',')) {
    const auto eq = entry.find('=');
    if (eq == std::string::npos) {
      std::fill(out.begin(), out.end(), parse_alignment(entry));
      continue;
    }
    std::size_t line = 0;
    try {
      line = std::stoul(entry.substr(0, eq));
    } catch (const std::exception&) {
      throw User_error("--align: '" + entry + "' does not start with a line number");
    }
    if (line >= lines)
      throw User_error("--align: line " + std::to_string(line) + " does not exist (" + std::to_string(lines) +
                       " feature lines, see feature_lines.json)");
    out[line] = parse_alignment(entry.substr(eq + 1));
  }
  return out;
}

const char* kind_name(Feature_kind k) {
  return k == Feature_kind::boundary ? "boundary" : k == Feature_kind::crease ? "crease" : "color";
}

void render_field(const Mesh& mesh, Field_map field, int symmetry,
                  const std::vector<Feature_line<Mesh::Halfedge_index>>& lines,
                  const Field_singularities<Mesh>& sing, const std::string& path, const std::string& title) {
  Render_scene scene;
  add_mesh(scene, mesh);
  for (const auto& l : lines) add_halfedge_path(scene, mesh, l.halfedges, Color{0.95, 0.55, 0.1}, 3);
  double edge = 0;
  for (auto e : edges(mesh)) edge += std::sqrt(CGAL::squared_distance(mesh.point(source(halfedge(e, mesh), mesh)),
                                                                        mesh.point(target(halfedge(e, mesh), mesh))));
  edge /= double(std::max<std::size_t>(1, num_edges(mesh)));
  // About 3000 strokes whatever the mesh size, each as long as the spacing between them.
  const std::size_t stride = std::max<std::size_t>(1, num_vertices(mesh) / 3000);
  const double len = 0.8 * edge * std::sqrt(double(stride));
  std::vector<Tangent_basis<Vector_3>> basis(num_vertices(mesh));
  vertex_tangent_bases(mesh, CGAL::make_property_map(basis));
  auto xyz = [](const Point_3& p) { return std::array<double, 3>{{p.x(), p.y(), p.z()}}; };
  for (auto v : vertices(mesh)) {
    if (std::size_t(v) % stride != 0 || field[v] == CGAL::NULL_VECTOR) continue;
    const Vector_3 d = field[v] / std::sqrt(field[v].squared_length()) * len;
    // Lifted a little off the surface so that no half of a stroke sinks behind a face.
    const Point_3 p = mesh.point(v) + 0.1 * len * basis[v].normal;
    const Color ink{0.1, 0.15, 0.45};
    if (symmetry == 1) {
      scene.polylines.push_back({{xyz(p), xyz(p + d)}, ink, 1.5});
      scene.points.push_back({xyz(p), ink, 1.5});
    } else {
      scene.polylines.push_back({{xyz(p - d / 2), xyz(p + d / 2)}, ink, 1.5});
      if (symmetry == 4) {
        const Vector_3 q = CGAL::cross_product(basis[v].normal, d);
        scene.polylines.push_back({{xyz(p - q / 2), xyz(p + q / 2)}, ink, 1.5});
      }
    }
  }
  for (const auto& s : sing.singularities) {
    Vector_3 c = CGAL::NULL_VECTOR;
    for (auto v : vertices_around_face(halfedge(s.face, mesh), mesh)) c = c + (mesh.point(v) - CGAL::ORIGIN) / 3;
    scene.points.push_back({{{c.x(), c.y(), c.z()}}, s.numerator > 0 ? Color{0.9, 0.1, 0.1} : Color{0.1, 0.4, 0.95}, 6});
  }
  Render_options options;
  options.title = title;
  options.edges = Edge_drawing::never;
  const Render_result r = render_png(scene, path, options);
  if (!r) throw User_error(r.message);
}

} // namespace

void register_field_commands(CLI::App& app, std::function<int()>& run) {
  auto* cmd = app.add_subcommand("field", "Smoothest direction field with controls and feature alignment");
  struct Args {
    std::string mesh, control, features, align = "parallel", out;
    int symmetry = 4;
    bool principal = false, force = false;
    Mesh_input_flags input;
  };
  auto a = std::make_shared<Args>();
  add_mesh_input(cmd, a->mesh, a->input);
  cmd->add_option("--control", a->control, "JSON file of control vectors");
  cmd->add_option("--features", a->features, "Comma-separated: boundary, crease:ANGLE, color");
  cmd->add_option("--align", a->align,
                  "parallel, perpendicular, or a default plus LINE=ALIGNMENT entries (e.g. parallel,2=perpendicular)")
      ->capture_default_str();
  cmd->add_option("--symmetry", a->symmetry, "Symmetry order: 1, 2 or 4")->capture_default_str();
  cmd->add_flag("--principal", a->principal, "Guide the field by principal curvature directions");
  cmd->add_option("--out", a->out, "Output directory")->required();
  cmd->add_flag("--force", a->force, "Write into a non-empty directory Tessera did not create");
  cmd->callback([&run, a] {
    run = [a] {
      if (!is_valid_symmetry(a->symmetry))
        throw User_error("--symmetry must be 1, 2 or 4 (got " + std::to_string(a->symmetry) + ")");
      std::vector<std::string> inputs{a->mesh};
      if (!a->control.empty()) inputs.push_back(a->control);
      Mesh mesh = read_input_mesh(a->mesh, a->input);
      std::vector<Constraint> constraints;
      if (!a->control.empty()) constraints = read_controls(a->control, mesh);

      Feature_line_options fo;
      fo.boundary = false;
      fo.color_boundaries = false;
      for (const std::string& f : split(a->features, ',')) {
        if (f == "boundary") fo.boundary = true;
        else if (f == "color") fo.color_boundaries = true;
        else if (f.rfind("crease", 0) == 0) {
          fo.creases = true;
          if (f.size() > 6) {
            if (f[6] != ':') throw User_error("--features: write crease:ANGLE (degrees)");
            try {
              fo.crease_angle_degrees = std::stod(f.substr(7));
            } catch (const std::exception&) {
              throw User_error("--features: '" + f.substr(7) + "' is not an angle in degrees");
            }
            if (!(fo.crease_angle_degrees > 0 && fo.crease_angle_degrees < 180))
              throw User_error("--features: the crease angle must be between 0 and 180 degrees");
          }
        } else {
          throw User_error("--features: unknown feature '" + f + "' (boundary, crease:ANGLE, color)");
        }
      }
      auto region = mesh.add_property_map<Mesh::Face_index, int>("f:tessera_region", 0).first;
      if (fo.color_boundaries) {
        const Color_regions_result cr = read_color_regions(a->mesh, mesh, region);
        if (!cr) throw User_error(cr.message);
        std::cout << "colour regions: " << cr.regions << " (" << (cr.face_colors ? "face" : "vertex") << " colours)\n";
      }
      const auto lines = feature_lines(mesh, fo, [&](Mesh::Face_index f) { return region[f]; });
      const auto alignment = alignment_per_line(a->align, lines.size());
      const auto aligned = feature_alignment_constraints(mesh, lines, alignment);
      constraints.insert(constraints.end(), aligned.begin(), aligned.end());
      if (a->principal) {
        const auto guide = principal_direction_constraints(mesh);
        constraints.insert(constraints.end(), guide.begin(), guide.end());
      }

      const Output_directory dir(a->out, a->force, inputs);
      auto field = mesh.add_property_map<Mesh::Vertex_index, Vector_3>("v:tessera_field").first;
      Smoothest_field_options so;
      so.symmetry = a->symmetry;
      const Smoothest_field_result r = smoothest_field(mesh, constraints, field, so);
      if (!r) throw User_error(r.message);
      const Field_singularities<Mesh> sing = field_singularities(mesh, field, a->symmetry);
      std::cout << "field: symmetry " << a->symmetry << ", " << r.hard_constraints << " hard and " << r.soft_constraints
                << " soft constraints, " << lines.size() << " feature lines, energy " << r.energy << " (" << r.solver
                << ")\n"
                << "singularities: " << sing.singularities.size() << ", index sum " << sing.face_index_sum << "/"
                << a->symmetry << " + boundary " << sing.boundary_index_sum << "/" << a->symmetry
                << " = Euler characteristic " << sing.euler_characteristic
                << (sing.poincare_hopf_holds() ? " (Poincaré–Hopf holds)" : " (Poincaré–Hopf FAILS)") << "\n";

      std::ofstream csv(dir.file("field.csv"));
      csv << "vertex,x,y,z,field_x,field_y,field_z\n";
      csv.precision(17);
      for (auto v : vertices(mesh)) {
        const Point_3& p = mesh.point(v);
        csv << std::size_t(v) << "," << p.x() << "," << p.y() << "," << p.z() << "," << field[v].x() << ","
            << field[v].y() << "," << field[v].z() << "\n";
      }
      nlohmann::json sj;
      sj["symmetry"] = a->symmetry;
      sj["euler_characteristic"] = sing.euler_characteristic;
      sj["face_index_sum"] = double(sing.face_index_sum) / a->symmetry;
      sj["boundary_index_sum"] = double(sing.boundary_index_sum) / a->symmetry;
      sj["poincare_hopf_holds"] = sing.poincare_hopf_holds();
      sj["singularities"] = nlohmann::json::array();
      for (const auto& s : sing.singularities) {
        Vector_3 c = CGAL::NULL_VECTOR;
        for (auto v : vertices_around_face(halfedge(s.face, mesh), mesh)) c = c + (mesh.point(v) - CGAL::ORIGIN) / 3;
        sj["singularities"].push_back({{"face", std::size_t(s.face)},
                                       {"index", double(s.numerator) / a->symmetry},
                                       {"position", {c.x(), c.y(), c.z()}}});
      }
      sj["boundary_loops"] = nlohmann::json::array();
      for (const auto& b : sing.boundary_loops)
        sj["boundary_loops"].push_back({{"halfedge", std::size_t(b.halfedge)}, {"index", double(b.numerator) / a->symmetry}});
      std::ofstream(dir.file("singularities.json")) << sj.dump(2) << "\n";
      nlohmann::json lj = nlohmann::json::array();
      for (std::size_t l = 0; l < lines.size(); ++l) {
        nlohmann::json vs = nlohmann::json::array();
        vs.push_back(std::size_t(source(lines[l].halfedges.front(), mesh)));
        for (auto h : lines[l].halfedges) vs.push_back(std::size_t(target(h, mesh)));
        lj.push_back({{"line", l}, {"kind", kind_name(lines[l].kind)}, {"closed", lines[l].closed},
                      {"alignment", alignment[l] == Feature_alignment::parallel ? "parallel" : "perpendicular"},
                      {"vertices", vs}});
      }
      std::ofstream(dir.file("feature_lines.json")) << lj.dump(1) << "\n";
      render_field(mesh, field, a->symmetry, lines, sing, dir.file("field.png"),
                   a->mesh + ": " + std::to_string(a->symmetry) + "-field, " +
                       std::to_string(sing.singularities.size()) + " singularities");
      std::cout << "wrote " << dir.file("field.csv") << ", " << dir.file("singularities.json") << ", "
                << dir.file("feature_lines.json") << ", " << dir.file("field.png") << "\n";
      return int(exit_ok);
    };
  });
}

} // namespace tessera::cli
