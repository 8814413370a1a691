// The inputs of a direction field: control file, feature lines and their alignment (see
// field_input.h).
#include "field_input.h"

#include <tessera/fields/color_regions.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <fstream>
#include <iostream>
#include <sstream>

namespace tessera::cli {
namespace {

using Constraint = Smoothest_field_solver<Mesh>::Constraint;

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
  if (!in)
    throw User_error(path + ": cannot open control file");
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
    if (!c.is_object() || !c.contains("direction"))
      throw User_error(where + " needs a \"direction\"");
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
      if (!c[key].is_number_integer() || c[key].get<long long>() < 0 ||
          std::size_t(c[key].get<long long>()) >= count)
        throw User_error(where + ": \"" + key + "\" must be an index below " +
                         std::to_string(count));
      return std::size_t(c[key].get<long long>());
    };
    if (c.contains("vertex")) {
      out.push_back({Mesh::Vertex_index(Mesh::size_type(index("vertex", num_vertices(mesh)))), d,
                     kind, weight});
    } else if (c.contains("face")) {
      const Mesh::Face_index f(Mesh::size_type(index("face", num_faces(mesh))));
      std::array<double, 3> b{{1.0 / 3, 1.0 / 3, 1.0 / 3}};
      if (c.contains("barycentric")) {
        const auto& j = c["barycentric"];
        if (!j.is_array() || j.size() != 3 || !j[0].is_number() || !j[1].is_number() ||
            !j[2].is_number())
          throw User_error(where + ": \"barycentric\" must be three numbers");
        b = {{j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}};
      }
      const auto on_face = face_point_constraints(mesh, f, b, d, kind, weight);
      if (on_face.empty())
        throw User_error(where + ": barycentric coordinates must be non-negative and sum to 1");
      out.insert(out.end(), on_face.begin(), on_face.end());
    } else {
      throw User_error(where + " needs a \"vertex\" or a \"face\"");
    }
  }
  return out;
}

Feature_alignment parse_alignment(const std::string& s) {
  if (s == "parallel")
    return Feature_alignment::parallel;
  if (s == "perpendicular")
    return Feature_alignment::perpendicular;
  throw User_error("--align: '" + s + "' is neither parallel nor perpendicular");
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> parts;
  std::stringstream in(s);
  std::string part;
  while (std::getline(in, part, sep))
    if (!part.empty())
      parts.push_back(part);
  return parts;
}

// "parallel", "perpendicular", or a default followed by LINE=ALIGNMENT entries:
// "parallel,3=perpendicular".
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
      throw User_error("--align: line " + std::to_string(line) + " does not exist (" +
                       std::to_string(lines) + " feature lines, see feature_lines.json)");
    out[line] = parse_alignment(entry.substr(eq + 1));
  }
  return out;
}

// "boundary,crease:ANGLE,color": which feature lines to find.
Feature_line_options parse_features(const std::string& spec) {
  Feature_line_options fo;
  fo.boundary = false;
  fo.color_boundaries = false;
  for (const std::string& f : split(spec, ',')) {
    if (f == "boundary") {
      fo.boundary = true;
    } else if (f == "color") {
      fo.color_boundaries = true;
    } else if (f.rfind("crease", 0) == 0) {
      fo.creases = true;
      if (f.size() > 6) {
        if (f[6] != ':')
          throw User_error("--features: write crease:ANGLE (degrees)");
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
  return fo;
}

} // namespace

void add_field_input(CLI::App* cmd, Field_input_arguments& a) {
  cmd->add_option("--control", a.control, "JSON file of control vectors");
  cmd->add_option("--features", a.features, "Comma-separated: boundary, crease:ANGLE, color");
  cmd->add_option("--align", a.align,
                  "parallel, perpendicular, or a default plus LINE=ALIGNMENT entries (e.g. "
                  "parallel,2=perpendicular)")
      ->capture_default_str();
}

Field_input read_field_input(const std::string& mesh_path, const Mesh& mesh,
                             const Field_input_arguments& a) {
  Field_input in;
  if (!a.control.empty())
    in.constraints = read_controls(a.control, mesh);
  const Feature_line_options fo = parse_features(a.features);
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
  in.alignment = alignment_per_line(a.align, in.lines.size());
  const auto aligned = feature_alignment_constraints(mesh, in.lines, in.alignment);
  in.constraints.insert(in.constraints.end(), aligned.begin(), aligned.end());
  return in;
}

} // namespace tessera::cli
