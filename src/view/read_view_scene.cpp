// tessera::read_view_scene (see tessera/view/read_view_scene.h).
#include <tessera/view/read_view_scene.h>

#include <tessera/io/image.h>
#include <tessera/io/read_cutting.h>
#include <tessera/io/read_mesh.h>
#include <tessera/io/read_result_directory.h>
#include <tessera/render/scene.h>
#include <tessera/resizing/draw_resize.h>
#include <tessera/resizing/stretch.h>
#include <tessera/types.h>

#include <CGAL/IO/Color.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Surface_mesh/IO/PLY.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <utility>

namespace tessera {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct Read_failure {
  View_status status;
  std::string message;
};

[[noreturn]] void fail_file(const std::string& path, const std::string& why) {
  throw Read_failure{View_status::bad_file, "cannot read " + path + ": " + why};
}

json read_json(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    fail_file(path, "cannot open");
  try {
    return json::parse(in);
  } catch (const json::exception& e) {
    fail_file(path, e.what());
  }
}

/// The mesh layer of `mesh`, faces fan-triangulated, vertex i the mesh's vertex i.
View_mesh_layer mesh_layer(const std::string& name, const Mesh& mesh) {
  View_mesh_layer layer;
  layer.name = name;
  layer.positions.reserve(3 * mesh.number_of_vertices());
  for (const auto v : mesh.vertices())
    for (int k = 0; k < 3; ++k)
      layer.positions.push_back(static_cast<float>(mesh.point(v)[k]));
  for (const auto f : mesh.faces()) {
    std::vector<std::uint32_t> corners;
    for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      corners.push_back(static_cast<std::uint32_t>(v.idx()));
    for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
      layer.triangles.insert(layer.triangles.end(), {corners[0], corners[k], corners[k + 1]});
      layer.element_ids.push_back(static_cast<std::uint32_t>(f.idx()));
    }
  }
  return layer;
}

/// Reads `path` as written (no repair, no triangulation) unless `as_read`: then as the commands
/// read their input, so that ids match their reports.
Mesh read_mesh_file(const std::string& path, bool as_read) {
  Mesh mesh;
  Read_mesh_options options;
  if (!as_read) {
    options.triangulate = false;
    options.repair = Mesh_repair::none;
  }
  if (const Read_mesh_result r = read_mesh(path, mesh, options); !r)
    fail_file(path, r.message);
  return mesh;
}

Mesh read_coloured_ply(const std::string& path) {
  Mesh mesh;
  std::ifstream in(path, std::ios::binary);
  if (!in || !CGAL::IO::read_PLY(in, mesh) || mesh.is_empty())
    fail_file(path, "not a PLY polygon mesh");
  return mesh;
}

void push_point(std::vector<float>& out, const Point_3& p) {
  for (int k = 0; k < 3; ++k)
    out.push_back(static_cast<float>(p[k]));
}

/// Seam edges of a cutting: edges of `mesh` on the border of `opened` (whose vertex i copies
/// vertex opened_to_mesh[i] of `mesh`) but not of `mesh`.
View_segment_layer seam_layer(const std::string& name, const Mesh& mesh, const Mesh& opened,
                              const std::vector<Mesh::Vertex_index>& opened_to_mesh) {
  std::set<std::pair<std::size_t, std::size_t>> seams;
  for (const auto h : opened.halfedges()) {
    if (!opened.is_border(h))
      continue;
    const auto a = opened_to_mesh[opened.source(h).idx()];
    const auto b = opened_to_mesh[opened.target(h).idx()];
    const auto mh = mesh.halfedge(a, b);
    if (mh == Mesh::null_halfedge() || mesh.is_border(mesh.edge(mh)))
      continue;
    seams.insert(std::minmax(std::size_t(a), std::size_t(b)));
  }
  View_segment_layer layer;
  layer.name = name;
  layer.colour = {200, 20, 20};
  for (const auto& [a, b] : seams) {
    push_point(layer.segments, mesh.point(Mesh::Vertex_index(static_cast<Mesh::size_type>(a))));
    push_point(layer.segments, mesh.point(Mesh::Vertex_index(static_cast<Mesh::size_type>(b))));
  }
  return layer;
}

View_segment_layer seam_layer(const std::string& name, const Result_directory& d) {
  return seam_layer(name, d.mesh, d.opened, d.opened_to_mesh);
}

View_point_layer corner_layer(const Result_directory& d) {
  View_point_layer layer;
  layer.name = "corners";
  for (const std::size_t v : d.multipoints) {
    push_point(layer.positions, d.mesh.point(Mesh::Vertex_index(static_cast<Mesh::size_type>(v))));
    layer.labels.push_back("vertex " + std::to_string(v));
  }
  return layer;
}

/// Quad `id`'s colour: the palette of the quadrangulation's PNG picture (draw_quadrangulation.h).
View_colour quad_colour(std::size_t id) {
  const Color c = distinct_color(id);
  const auto byte = [](double t) { return static_cast<std::uint8_t>(std::lround(255 * t)); };
  return {byte(c.r), byte(c.g), byte(c.b)};
}

std::string figures(const json& object, std::initializer_list<const char*> keys) {
  std::ostringstream line;
  for (const char* key : keys)
    if (object.contains(key) && object[key].is_number())
      line << (line.tellp() > 0 ? ", " : "") << key << " " << object[key].get<double>();
  return line.str();
}

Result_directory read_cutting(const std::string& dir) {
  Result_directory d = read_result_directory(dir);
  if (!d)
    throw Read_failure{View_status::bad_file, d.message};
  return d;
}

void read_cut(const std::string& dir, View_scene& scene) {
  const Result_directory d = read_cutting(dir);
  scene.kind = "cut";
  scene.sources = {d.mesh_path, dir + "/opened.off", dir + "/result.json"};
  scene.meshes.push_back(mesh_layer("surface", d.mesh));
  scene.segments.push_back(seam_layer("seams", d));
  scene.points.push_back(corner_layer(d));
}

void read_quadrangulation(const std::string& dir, View_scene& scene) {
  const Result_directory d = read_cutting(dir);
  const json result = read_json(dir + "/result.json");
  scene.kind = "quadrangulate";
  scene.sources = {d.mesh_path, dir + "/opened.off", dir + "/result.json"};
  View_mesh_layer quads = mesh_layer("quads", d.mesh);
  quads.element_kind = "quad";
  const json& tiles = result.value("tiles", json::array());
  if (!tiles.is_array() || tiles.size() != d.mesh.number_of_faces())
    fail_file(dir + "/result.json", "\"tiles\" does not give one quad per face of mesh.off");
  for (std::uint32_t& id : quads.element_ids) {
    id = tiles[id].get<std::uint32_t>();
    const View_colour c = quad_colour(id);
    quads.triangle_colours.insert(quads.triangle_colours.end(), c.begin(), c.end());
  }
  for (const json& quad : result.value("quad_tiles", json::array()))
    quads.element_figures.push_back(
        figures(quad, {"angle_distortion", "area_distortion", "stretch", "flipped"}));
  scene.meshes.push_back(std::move(quads));
  scene.segments.push_back(seam_layer("quad borders", d));
  scene.points.push_back(corner_layer(d));
}

/// The input mesh named by a report's "mesh", else `given`; none when neither reads.
std::optional<Mesh> input_mesh(const json& report, const std::string& given, View_scene& scene) {
  std::string path = given;
  if (path.empty() && report.contains("mesh") && report["mesh"].is_string())
    path = report["mesh"].get<std::string>();
  if (path.empty() || !fs::exists(path))
    return std::nullopt;
  scene.sources.push_back(path);
  return read_mesh_file(path, true);
}

float diagonal(const std::vector<float>& positions) {
  std::array<float, 3> lo{1e30f, 1e30f, 1e30f}, hi{-1e30f, -1e30f, -1e30f};
  for (std::size_t i = 0; i < positions.size(); ++i) {
    lo[i % 3] = std::min(lo[i % 3], positions[i]);
    hi[i % 3] = std::max(hi[i % 3], positions[i]);
  }
  float d = 0;
  for (int k = 0; k < 3; ++k)
    d += (hi[k] - lo[k]) * (hi[k] - lo[k]);
  return std::sqrt(d);
}

void read_field(const std::string& dir, const std::string& mesh_path, View_scene& scene) {
  scene.kind = "field";
  const std::string csv = dir + "/field.csv";
  const json sing = read_json(dir + "/singularities.json");
  scene.sources = {csv, dir + "/singularities.json"};
  std::ifstream in(csv);
  std::string line;
  if (!std::getline(in, line) || line.rfind("vertex,", 0) != 0)
    fail_file(csv, "no header line vertex,x,y,z,...");
  std::vector<float> points, vectors;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::string cell;
    std::vector<float> cells;
    while (std::getline(row, cell, ','))
      cells.push_back(std::stof(cell));
    if (cells.size() != 7)
      fail_file(csv, "a row without 7 numbers");
    points.insert(points.end(), cells.begin() + 1, cells.begin() + 4);
    vectors.insert(vectors.end(), cells.begin() + 4, cells.end());
  }
  const std::optional<Mesh> mesh = input_mesh(json::object(), mesh_path, scene);
  if (mesh)
    scene.meshes.push_back(mesh_layer("surface", *mesh));
  const std::size_t n = points.size() / 3;
  const float length =
      0.35f * diagonal(points) / std::sqrt(static_cast<float>(std::max<std::size_t>(n, 1)));
  const int symmetry = sing.value("symmetry", 4);
  std::vector<Vector_3> normals(n, Vector_3(0, 0, 0));
  if (mesh && mesh->number_of_vertices() == n)
    for (const auto f : mesh->faces()) {
      const auto h = mesh->halfedge(f);
      const Point_3 &a = mesh->point(mesh->source(h)), &b = mesh->point(mesh->target(h)),
                    &c = mesh->point(mesh->target(mesh->next(h)));
      const Vector_3 normal = CGAL::cross_product(b - a, c - a);
      for (const auto v : CGAL::vertices_around_face(h, *mesh))
        normals[v.idx()] = normals[v.idx()] + normal;
    }
  View_segment_layer crosses;
  crosses.name = "field";
  crosses.colour = {30, 60, 200};
  for (std::size_t i = 0; i < n; ++i) {
    const Vector_3 v(vectors[3 * i], vectors[3 * i + 1], vectors[3 * i + 2]);
    std::vector<Vector_3> directions{v};
    if (symmetry >= 2)
      directions.push_back(-v);
    const double nn = std::sqrt(normals[i].squared_length());
    if (symmetry == 4 && nn > 0) {
      const Vector_3 w = CGAL::cross_product(normals[i] / nn, v);
      directions.push_back(w);
      directions.push_back(-w);
    }
    const Point_3 p(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
    for (const Vector_3& d : directions) {
      push_point(crosses.segments, p);
      push_point(crosses.segments, p + length * d);
    }
  }
  scene.segments.push_back(std::move(crosses));
  View_point_layer singularities;
  singularities.name = "singularities";
  singularities.colour = {220, 30, 30};
  for (const json& s : sing.value("singularities", json::array())) {
    for (int k = 0; k < 3; ++k)
      singularities.positions.push_back(s.at("position").at(k).get<float>());
    std::ostringstream label;
    label << "face " << s.value("face", -1) << ", index " << s.value("index", 0.0);
    singularities.labels.push_back(label.str());
  }
  scene.points.push_back(std::move(singularities));
}

void read_mosaic(const std::string& dir, const std::string& mesh_path, View_scene& scene) {
  scene.kind = "mosaic";
  const std::string ply = dir + "/tiles.ply";
  const json report = read_json(dir + "/report.json");
  const json tiles_json = read_json(dir + "/tiles.json");
  scene.sources = {ply, dir + "/tiles.json", dir + "/report.json"};
  const Mesh tiles = read_coloured_ply(ply);
  View_mesh_layer layer = mesh_layer("tiles", tiles);
  layer.element_kind = "tile";
  const auto [colours, coloured] = tiles.property_map<Mesh::Face_index, CGAL::IO::Color>("f:color");
  if (coloured)
    for (const std::uint32_t f : layer.element_ids) {
      const CGAL::IO::Color c = colours[Mesh::Face_index(f)];
      layer.triangle_colours.insert(layer.triangle_colours.end(), {c.red(), c.green(), c.blue()});
    }
  const json& list = tiles_json.value("tiles", json::array());
  if (list.size() == tiles.number_of_faces())
    for (const json& tile : list) {
      std::ostringstream line;
      line << "face " << tile.value("face", -1) << ", region " << tile.value("region", -1);
      if (tile.contains("size") && tile["size"].size() == 2)
        line << ", size " << tile["size"][0].get<double>() << " x "
             << tile["size"][1].get<double>();
      layer.element_figures.push_back(line.str());
    }
  if (const std::optional<Mesh> mesh = input_mesh(report, mesh_path, scene)) {
    View_mesh_layer base = mesh_layer("surface", *mesh);
    base.colour = {90, 90, 90};
    scene.meshes.push_back(std::move(base));
  }
  scene.meshes.push_back(std::move(layer));
}

/// The picture at `path` as an unlit, unpickable layer: a rectangle [x0, x1] × [y0, y1] of a
/// planar mosaic's pixel frame (y down, drawn as -y so that the picture stands upright seen from
/// +z) at height `z`.
View_mesh_layer picture_layer(const std::string& name, const std::string& path, float x0, float y0,
                              float x1, float y1, float z, Rgb_image picture) {
  View_mesh_layer layer;
  layer.name = name;
  layer.positions = {x0, -y0, z, x1, -y0, z, x1, -y1, z, x0, -y1, z};
  layer.triangles = {0, 3, 2, 0, 2, 1};
  layer.texture_coordinates = {0, 0, 1, 0, 1, 1, 0, 1};
  if (picture.empty())
    fail_file(path, "an empty picture");
  layer.texture = {picture.width, picture.height, std::move(picture.pixels)};
  layer.lit = false;
  layer.pickable = false;
  return layer;
}

Rgb_image read_picture(const std::string& path) {
  Image_read_result r = read_image(path);
  if (!r)
    fail_file(path, r.message);
  return std::move(r.image);
}

/// A tile of a planar mosaic's tiles.json as a rectangle (two triangles) or, for ellipses, a fan
/// of `ellipse_sides` triangles around its centre, at height `z`.
void push_planar_tile(View_mesh_layer& layer, const json& tile, bool ellipse, float z) {
  const double x = tile.at("center").at(0).get<double>(), y = tile.at("center").at(1).get<double>();
  const double angle = tile.at("angle").get<double>(), a = tile.at("width").get<double>() / 2,
               b = tile.at("height").get<double>() / 2;
  const double c = std::cos(angle), s = std::sin(angle);
  // The width side along (c, s), the height side along (-s, c), in the frame with y down.
  const auto corner = [&](double u, double v) {
    layer.positions.insert(layer.positions.end(), {static_cast<float>(x + u * c - v * s),
                                                   static_cast<float>(-(y + u * s + v * c)), z});
  };
  const auto first = static_cast<std::uint32_t>(layer.positions.size() / 3);
  const auto id = static_cast<std::uint32_t>(layer.element_figures.size());
  constexpr int ellipse_sides = 24;
  if (ellipse) {
    corner(0, 0);
    for (int k = 0; k < ellipse_sides; ++k) {
      const double t = 2 * M_PI * k / ellipse_sides;
      corner(a * std::cos(t), b * std::sin(t));
      layer.triangles.insert(layer.triangles.end(),
                             {first, first + 1 + static_cast<std::uint32_t>(k),
                              first + 1 + static_cast<std::uint32_t>((k + 1) % ellipse_sides)});
    }
  } else {
    corner(-a, -b), corner(a, -b), corner(a, b), corner(-a, b);
    layer.triangles.insert(layer.triangles.end(),
                           {first, first + 2, first + 1, first, first + 3, first + 2});
  }
  const auto colour = tile.at("color").get<std::array<std::uint8_t, 3>>();
  for (int t = 0; t < (ellipse ? ellipse_sides : 2); ++t) {
    layer.element_ids.push_back(id);
    layer.triangle_colours.insert(layer.triangle_colours.end(), colour.begin(), colour.end());
  }
  std::ostringstream line;
  line << "colour " << int(colour[0]) << ", " << int(colour[1]) << ", " << int(colour[2])
       << ", size " << 2 * a << " x " << 2 * b << " px, angle " << angle * 180 / M_PI
       << "°, centre (" << x << ", " << y << ") px, region " << tile.value("region", 0);
  layer.element_figures.push_back(line.str());
}

/// A planar mosaic (`tessera planar-mosaic`), flat in the plane z = 0 with y up (pixel rows down):
/// the source image report.json names (or `image_path`) when it opens, field.png (the direction
/// field and the edges over the faded image, hidden at first) and the tiles of tiles.json in their
/// colours and shapes, a little above.
void read_planar_mosaic(const std::string& dir, const std::string& image_path, View_scene& scene) {
  scene.kind = "planar-mosaic";
  scene.flat = true;
  const std::string tiles_path = dir + "/tiles.json", report_path = dir + "/report.json";
  const json report = read_json(report_path);
  const json tiles = read_json(tiles_path);
  scene.sources = {tiles_path, report_path};
  if (!tiles.is_object() || !tiles.contains("tiles") || !tiles["tiles"].is_array() ||
      tiles.value("units", "").rfind("pixels", 0) != 0)
    fail_file(tiles_path,
              "not the tiles of a planar mosaic (no \"units\" in pixels and \"tiles\")");
  int width = 0, height = 0;
  std::string shape, image;
  try {
    width = report.at("image").at("width").get<int>();
    height = report.at("image").at("height").get<int>();
    image = image_path.empty() ? report.at("image").value("path", "") : image_path;
    shape = report.at("options").value("shape", "square");
  } catch (const json::exception& e) {
    fail_file(report_path, e.what());
  }
  const float lift = 1e-3f * std::hypot(float(width), float(height));
  if (!image.empty() && fs::exists(image)) {
    Rgb_image picture = read_picture(image);
    if (picture.width != width || picture.height != height)
      fail_file(image, "the image is " + std::to_string(picture.width) + " x " +
                           std::to_string(picture.height) + " pixels but the mosaic's " +
                           std::to_string(width) + " x " + std::to_string(height));
    // Pixel (x, y) is the square around the point (x, y).
    scene.meshes.push_back(picture_layer("image", image, -0.5f, -0.5f, width - 0.5f, height - 0.5f,
                                         0, std::move(picture)));
    scene.sources.push_back(image);
  }
  if (const std::string field = dir + "/field.png"; fs::exists(field)) {
    Rgb_image picture = read_picture(field);
    // Drawn at the scale s of mosaic.png: the point (x, y) at (s·x, s·y) (doc/formats.md).
    const float s = float(picture.width) / float(std::max(width, 1));
    View_mesh_layer layer =
        picture_layer("field.png (field, edges red)", field, 0, 0, float(picture.width) / s,
                      float(picture.height) / s, lift, std::move(picture));
    layer.visible = false;
    scene.meshes.push_back(std::move(layer));
    scene.sources.push_back(field);
  }
  View_mesh_layer layer;
  layer.name = "tiles";
  layer.element_kind = "tile";
  layer.lit = false;
  layer.hover_vertex = false;
  try {
    for (const json& tile : tiles["tiles"])
      push_planar_tile(layer, tile, shape == "ellipse", 2 * lift);
  } catch (const json::exception& e) {
    fail_file(tiles_path, std::string("a tile without center, angle, width, height or color (") +
                              e.what() + ")");
  }
  scene.meshes.push_back(std::move(layer));
}

/// Shifts `layer` along x so that it stands beside `positions` (before/after side by side).
void place_beside(View_mesh_layer& layer, const std::vector<float>& before) {
  float max_before = -1e30f, min_after = 1e30f;
  for (std::size_t i = 0; i < before.size(); i += 3)
    max_before = std::max(max_before, before[i]);
  for (std::size_t i = 0; i < layer.positions.size(); i += 3)
    min_after = std::min(min_after, layer.positions[i]);
  const float shift = max_before - min_after + 0.15f * diagonal(before);
  for (std::size_t i = 0; i < layer.positions.size(); i += 3)
    layer.positions[i] += shift;
}

/// Colours `after` (the layer of `deformed`) by each vertex's local stretch ratio σ1/σ2 from
/// `input` (local_stretch_ratios(), the figures of the report's "stretch_ratio"): white at 1 to
/// red at the largest, the resize pictures' ramp; hover gives a face the ratios at its corners.
void colour_by_stretch(View_mesh_layer& after, Mesh& input, const Mesh& deformed) {
  if (input.number_of_vertices() != deformed.number_of_vertices() ||
      input.number_of_faces() != deformed.number_of_faces())
    return;
  auto ratio = input.add_property_map<Mesh::Vertex_index, double>("v:tessera_view_stretch").first;
  local_stretch_ratios(input, input.points(), deformed.points(), ratio);
  double largest = 1;
  for (const auto v : input.vertices())
    if (std::isfinite(ratio[v]))
      largest = std::max(largest, ratio[v]);
  for (const auto v : input.vertices()) {
    const Color c = std::isfinite(ratio[v])
                        ? diverging_color(0.5 + 0.5 * (ratio[v] - 1) / std::max(largest - 1, 1e-12))
                        : Color{0.6, 0.6, 0.6};
    for (const double channel : {c.r, c.g, c.b})
      after.vertex_colours.push_back(static_cast<std::uint8_t>(std::lround(255 * channel)));
  }
  for (const auto f : deformed.faces()) {
    std::ostringstream line;
    line << "stretch σ1/σ2 at its corners";
    const char* separator = " ";
    for (const auto v : CGAL::vertices_around_face(deformed.halfedge(f), deformed)) {
      line << separator << ratio[Mesh::Vertex_index(v.idx())];
      separator = ", ";
    }
    after.element_figures.push_back(line.str());
  }
  std::ostringstream name;
  name << "after (stretch σ1/σ2: white 1 to red " << largest << ")";
  after.name = name.str();
}

/// Before and after of resize or deform, side by side; for deform the after mesh coloured by
/// stretch.
void read_resizing(const std::string& dir, const std::string& result_name,
                   const std::string& mesh_path, View_scene& scene) {
  const json report = read_json(dir + "/report.json");
  const std::string result_path = dir + "/" + result_name;
  scene.sources = {result_path, dir + "/report.json"};
  View_mesh_layer before;
  for (const char* coloured : {"vulnerability.ply", "regions.ply"})
    if (fs::exists(dir + "/" + coloured)) {
      const std::string ply = dir + "/" + coloured;
      const Mesh input = read_coloured_ply(ply);
      before = mesh_layer(std::string("before (") + coloured + ")", input);
      const auto [colours, coloured] =
          input.property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color");
      for (const auto v : input.vertices())
        if (coloured)
          before.vertex_colours.insert(before.vertex_colours.end(),
                                       {colours[v].red(), colours[v].green(), colours[v].blue()});
      scene.sources.push_back(ply);
      break;
    }
  const Mesh deformed = read_mesh_file(result_path, false);
  View_mesh_layer after = mesh_layer("after", deformed);
  after.colour = {120, 170, 220};
  if (before.positions.empty())
    if (std::optional<Mesh> input = input_mesh(report, mesh_path, scene)) {
      before = mesh_layer("before", *input);
      if (scene.kind == "deform")
        colour_by_stretch(after, *input, deformed);
    }
  if (!before.positions.empty()) {
    place_beside(after, before.positions);
    scene.meshes.push_back(std::move(before));
  }
  scene.meshes.push_back(std::move(after));
}

/// A point per vertex and per face (its centroid) that a check report's problems or notes name,
/// labelled with the problem's kind.
View_point_layer problem_layer(const std::string& name, const json& problems, const Mesh& mesh,
                               const std::string& path) {
  View_point_layer layer;
  layer.name = name;
  layer.colour = name == "problems" ? View_colour{220, 20, 20} : View_colour{240, 150, 0};
  for (const json& p : problems) {
    const std::string kind = p.value("kind", std::string("problem"));
    for (const std::size_t v : p.value("vertices", std::vector<std::size_t>())) {
      if (v >= mesh.number_of_vertices())
        fail_file(path, "a problem names vertex " + std::to_string(v) + " of a smaller surface");
      push_point(layer.positions, mesh.point(Mesh::Vertex_index(static_cast<Mesh::size_type>(v))));
      layer.labels.push_back(kind + ": vertex " + std::to_string(v));
    }
    for (const std::size_t f : p.value("faces", std::vector<std::size_t>())) {
      if (f >= mesh.number_of_faces())
        fail_file(path, "a problem names face " + std::to_string(f) + " of a smaller surface");
      const Mesh::Face_index face(static_cast<Mesh::size_type>(f));
      Vector_3 sum(0, 0, 0);
      int n = 0;
      for (const auto v : CGAL::vertices_around_face(mesh.halfedge(face), mesh)) {
        sum = sum + (mesh.point(v) - CGAL::ORIGIN);
        ++n;
      }
      push_point(layer.positions, CGAL::ORIGIN + sum / std::max(n, 1));
      layer.labels.push_back(kind + ": face " + std::to_string(f));
    }
  }
  return layer;
}

/// A `tessera check --report` file: the checked surface with its charts coloured (connected
/// components of the surface opened along the seams), the seams, and the problems and notes.
void read_check_report(const std::string& path, View_scene& scene) {
  const json report = read_json(path);
  if (!report.contains("form") || !report.contains("input") || !report["input"].is_string())
    fail_file(path, "not a report of tessera check (no \"form\" and \"input\")");
  const std::string input = report["input"].get<std::string>(), form = report.value("form", "");
  scene.kind = "check";
  scene.sources = {path, input};
  Mesh mesh, charts;
  std::vector<Mesh::Vertex_index> chart_to_mesh;
  if (form == "result directory") {
    Result_directory d = read_cutting(input);
    mesh = std::move(d.mesh);
    charts = std::move(d.opened);
    chart_to_mesh = std::move(d.opened_to_mesh);
  } else if (form == "texture coordinates") {
    Uv_layout<Mesh> layout;
    if (const Cutting_read_result r = read_obj_with_uvs(input, layout); !r)
      fail_file(input, r.message);
    mesh = std::move(layout.mesh);
    charts = std::move(layout.charts);
    chart_to_mesh = std::move(layout.chart_to_mesh);
  } else {
    mesh = read_mesh_file(input, false);
  }
  View_mesh_layer layer = mesh_layer("charts", mesh);
  if (charts.number_of_faces() == mesh.number_of_faces()) {
    auto chart = charts.add_property_map<Mesh::Face_index, std::size_t>("f:tessera_chart").first;
    const std::size_t count = CGAL::Polygon_mesh_processing::connected_components(charts, chart);
    const json& summaries = report.contains("charts") ? report["charts"] : json::array();
    std::vector<std::size_t> faces(count, 0);
    for (const auto f : charts.faces())
      ++faces[chart[f]];
    for (std::size_t c = 0; c < count; ++c) {
      std::ostringstream line;
      line << "chart " << c << " of " << count << ", " << faces[c] << " faces";
      // The report's figures when its chart c is this one (same number of faces).
      if (summaries.is_array() && summaries.size() == count && summaries[c].is_object() &&
          summaries[c].value("faces", std::size_t(0)) == faces[c])
        line << ", " << summaries[c].value("sides", 0) << " sides"
             << (summaries[c].contains("word") ? ", word " + summaries[c].value("word", "") : "");
      layer.element_figures.push_back(line.str());
    }
    for (std::uint32_t& id : layer.element_ids) {
      const std::size_t c = chart[Mesh::Face_index(id)];
      const View_colour colour = quad_colour(c);
      layer.triangle_colours.insert(layer.triangle_colours.end(), colour.begin(), colour.end());
      id = static_cast<std::uint32_t>(c);
    }
    layer.element_kind = "chart";
  }
  scene.meshes.push_back(std::move(layer));
  if (charts.number_of_faces() > 0)
    scene.segments.push_back(seam_layer("seams", mesh, charts, chart_to_mesh));
  scene.points.push_back(
      problem_layer("problems", report.value("problems", json::array()), mesh, path));
  scene.points.push_back(problem_layer("notes", report.value("notes", json::array()), mesh, path));
}

} // namespace

View_scene_result read_view_scene(const std::string& dir, const std::string& mesh) {
  View_scene_result result;
  const auto has = [&](const char* name) { return fs::exists(fs::path(dir) / name); };
  try {
    if (fs::is_regular_file(dir))
      read_check_report(dir, result.scene);
    else if (!fs::is_directory(dir))
      throw Read_failure{View_status::not_found, "no result directory " + dir};
    else if (has("quads.obj"))
      read_quadrangulation(dir, result.scene);
    else if (has("opened.off"))
      read_cut(dir, result.scene);
    else if (has("field.csv"))
      read_field(dir, mesh, result.scene);
    else if (has("tiles.ply"))
      read_mosaic(dir, mesh, result.scene);
    else if (has("tiles.json"))
      read_planar_mosaic(dir, mesh, result.scene);
    else if (has("resized.off")) {
      result.scene.kind = "resize";
      read_resizing(dir, "resized.off", mesh, result.scene);
    } else if (has("deformed.off")) {
      result.scene.kind = "deform";
      read_resizing(dir, "deformed.off", mesh, result.scene);
    } else
      throw Read_failure{
          View_status::unknown_result_kind,
          dir + " holds no result of cut, quadrangulate, field, mosaic, planar-mosaic, resize or "
                "deform"};
  } catch (const Read_failure& f) {
    result.status = f.status;
    result.message = f.message;
    result.scene = {};
    return result;
  } catch (const std::exception& e) {
    result.status = View_status::bad_file;
    result.message = "cannot read " + dir + ": " + e.what();
    result.scene = {};
    return result;
  }
  result.scene.title = result.scene.kind + " of " + fs::path(dir).lexically_normal().string();
  return result;
}

} // namespace tessera
