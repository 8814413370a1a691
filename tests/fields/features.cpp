// Feature lines (boundaries, creases, colour regions), alignment with them, principal directions.
#include "corpus.h"

#include <tessera/fields.h>
#include <tessera/generators/textures.h>

#include <CGAL/IO/OFF.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <map>
#include <sstream>

using namespace tessera;
using halfedge_descriptor = Mesh::Halfedge_index;

namespace {

double angle_degrees(const Vector_3& a, const Vector_3& b) {
  return std::atan2(std::sqrt(CGAL::cross_product(a, b).squared_length()), a * b) * 180 /
         std::acos(-1.0);
}

// Angle between the line of `x` (or of N × x for a cross field) and the line of `t`, in [0, 90].
double line_angle_degrees(const Vector_3& x, const Vector_3& t, const Vector_3& normal, int n) {
  const double a = angle_degrees(x, t);
  double best = std::min(a, 180 - a);
  if (n == 4) {
    const double b = angle_degrees(CGAL::cross_product(normal, x), t);
    best = std::min({best, b, 180 - b});
  }
  return best;
}

} // namespace

TEST_CASE("boundaries are closed feature lines, one per boundary loop", "[fields][features]") {
  for (const auto& e : test::generated_corpus(2, 3)) {
    INFO(e.name);
    const auto lines = feature_lines(e.mesh);
    CHECK(lines.size() == e.boundaries);
    for (const auto& l : lines) {
      CHECK(l.closed);
      CHECK(l.kind == Feature_kind::boundary);
      for (std::size_t k = 0; k < l.halfedges.size(); ++k)
        CHECK(target(l.halfedges[k], e.mesh) ==
              source(l.halfedges[(k + 1) % l.halfedges.size()], e.mesh));
    }
  }
}

TEST_CASE("a cube's creases are twelve open lines between its corners", "[fields][features]") {
  const Mesh cube = test::load("cube-meshed.off");
  Feature_line_options o;
  o.creases = true;
  const auto lines = feature_lines(cube, o);
  CHECK(lines.size() == 12);
  for (const auto& l : lines) {
    CHECK_FALSE(l.closed);
    CHECK(l.kind == Feature_kind::crease);
  }
}

TEST_CASE("with crease alignment the field is parallel or perpendicular to every crease",
          "[fields][features]") {
  for (const char* file : {"cube-meshed.off", "fandisk.off"}) {
    Mesh m = test::load(file);
    Feature_line_options fo;
    fo.creases = true;
    const auto lines = feature_lines(m, fo);
    REQUIRE(!lines.empty());
    std::vector<Tangent_basis<Vector_3>> basis(num_vertices(m));
    vertex_tangent_bases(m, CGAL::make_property_map(basis));
    auto field = m.add_property_map<Mesh::Vertex_index, Vector_3>("v:tessera_field").first;
    for (int n : {1, 2, 4})
      for (Feature_alignment a : {Feature_alignment::parallel, Feature_alignment::perpendicular}) {
        INFO(file << " symmetry " << n
                  << (a == Feature_alignment::parallel ? " parallel" : " perpendicular"));
        Smoothest_field_options so;
        so.symmetry = n;
        REQUIRE(smoothest_field(m, feature_alignment_constraints(m, lines, {a}), field, so));
        double worst = 0;
        for (const auto& l : lines)
          for (std::size_t k = 1; k < l.halfedges.size(); ++k) {
            const auto v = source(l.halfedges[k], m);
            // The crease's tangent (sum of its two unit edge directions), projected to the tangent
            // plane; on the cube it lies in that plane already.
            auto unit = [&](halfedge_descriptor h) {
              const Vector_3 d = m.point(target(h, m)) - m.point(source(h, m));
              return d / std::sqrt(d.squared_length());
            };
            const Vector_3 crease = unit(l.halfedges[k - 1]) + unit(l.halfedges[k]);
            const Vector_3 t = crease - (crease * basis[v].normal) * basis[v].normal;
            if (std::string(file) == "cube-meshed.off")
              CHECK(angle_degrees(t, crease) < 1e-6);
            const double angle = line_angle_degrees(field[v], t, basis[v].normal, n);
            worst =
                std::max(worst, a == Feature_alignment::parallel || n == 4 ? angle : 90 - angle);
          }
        CHECK(worst < 1.0);
      }
  }
}

TEST_CASE("on a box's flat faces the field aligned with its creases runs along the edges",
          "[fields][features]") {
  // Each face of the box is flat and bounded by creases along the axes: the smoothest 4-field
  // aligned with them is the axes there. Read through the crease vertices' tangent planes (45°
  // to both faces) by projection alone, the creases' tangents were up to 5.6° off the angle the
  // transport gives their edges, and that bent the field inside the faces.
  const Mesh box = test::load("cube-meshed.off");
  Feature_line_options fo;
  fo.creases = true;
  const auto lines = feature_lines(box, fo);
  REQUIRE(lines.size() == 12);
  std::map<Mesh::Vertex_index, int> on_lines;
  for (const auto& l : lines)
    for (const auto h : l.halfedges)
      ++on_lines[source(h, box)], ++on_lines[target(h, box)];
  // The largest angle between a face's field (its corners' power vectors averaged in its plane,
  // as the mosaic reads it) and the nearest axis, over the faces away from the box's corners.
  auto worst_off_axes = [&](const auto& field) {
    double worst = 0;
    for (const auto f : faces(box)) {
      bool at_corner = false;
      for (const auto v : vertices_around_face(halfedge(f, box), box))
        at_corner = at_corner || (on_lines.count(v) && on_lines[v] != 2);
      if (at_corner)
        continue;
      const Vector_3 n = CGAL::Polygon_mesh_processing::compute_face_normal(f, box);
      int a = 0;
      for (int k = 1; k < 3; ++k)
        if (std::abs(n[k]) > std::abs(n[a]))
          a = k;
      REQUIRE(std::abs(n[a]) > 1 - 1e-9);
      const int b = (a + 1) % 3, c = (a + 2) % 3;
      std::complex<double> sum = 0;
      for (const auto v : vertices_around_face(halfedge(f, box), box))
        sum += std::polar(1.0, 4 * std::atan2(field[v][c], field[v][b]));
      // arg(sum)/4 is the face's direction against axis b; 0 along an axis.
      worst = std::max(worst, std::abs(std::arg(sum)) / 4 * 180 / CGAL_PI);
    }
    return worst;
  };
  Mesh m = box;
  auto field = m.add_property_map<Mesh::Vertex_index, Vector_3>("v:tessera_field").first;
  const auto constraints = feature_alignment_constraints(m, lines, {Feature_alignment::parallel});
  REQUIRE(smoothest_field(m, constraints, field, Smoothest_field_options{}));
  const double plain = worst_off_axes(field);
  // Not carried through the corners either, where the lines meet: each face keeps its own.
  auto is_line = get(CGAL::dynamic_edge_property_t<bool>(), m);
  mark_feature_edges(m, lines, is_line);
  Smoothest_field_solver<Mesh> solver(m, Smoothest_field_options{},
                                      CGAL::parameters::edge_is_constrained_map(is_line));
  CHECK(solver.number_of_edges_left_out() > 0);
  REQUIRE(solver.solve(constraints, field));
  const double cut = worst_off_axes(field);
  INFO("off the axes: " << plain << "° through the corners, " << cut << "° not through them");
  CHECK(plain < 0.5);
  CHECK(cut < 0.01);
}

TEST_CASE("lines can be aligned one by one", "[fields][features]") {
  Mesh m;
  make_genus_surface(m, 1);
  punch_holes(m, 2, 3);
  const auto lines = feature_lines(m);
  REQUIRE(lines.size() == 2);
  const auto c = feature_alignment_constraints(
      m, lines, {Feature_alignment::parallel, Feature_alignment::perpendicular});
  REQUIRE(c.size() == lines[0].halfedges.size() + lines[1].halfedges.size());
  // At the vertex between a loop's first two halfedges: the sum of their unit directions.
  auto tangent = [&](const Feature_line<halfedge_descriptor>& l) {
    auto unit = [&](halfedge_descriptor h) {
      const Vector_3 d = m.point(target(h, m)) - m.point(source(h, m));
      return d / std::sqrt(d.squared_length());
    };
    return unit(l.halfedges[0]) + unit(l.halfedges[1]);
  };
  CHECK(angle_degrees(c[1].direction, tangent(lines[0])) < 1e-6);
  CHECK(std::abs(angle_degrees(c[lines[0].halfedges.size() + 1].direction, tangent(lines[1])) -
                 90) < 1e-6);
  CHECK(feature_alignment_constraints(m, lines, {}).empty());
}

TEST_CASE("colour regions read from OFF face and vertex colours bound feature lines",
          "[fields][features]") {
  Mesh sphere;
  make_sphere(sphere, 1.0, 3);
  // Upper and lower hemispheres in two colours, written with face colours and with vertex colours.
  auto fcolor = sphere.add_property_map<Mesh::Face_index, CGAL::IO::Color>("f:color").first;
  auto vcolor = sphere.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
  const std::string faces_file = test::output_path("hemispheres-faces.off");
  const std::string vertices_file = test::output_path("hemispheres-vertices.off");
  for (auto f : faces(sphere)) {
    double z = 0;
    for (auto v : vertices_around_face(halfedge(f, sphere), sphere))
      z += sphere.point(v).z();
    fcolor[f] = z > 0 ? CGAL::IO::Color(200, 30, 30) : CGAL::IO::Color(30, 30, 200);
  }
  for (auto v : vertices(sphere))
    vcolor[v] =
        sphere.point(v).z() > 1e-9 ? CGAL::IO::Color(200, 30, 30) : CGAL::IO::Color(30, 30, 200);
  // Surface_mesh writes its "v:color" and "f:color" maps by itself: one map per copy.
  Mesh face_colored = sphere, vertex_colored = sphere;
  auto drop_v = face_colored.property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
  face_colored.remove_property_map(drop_v);
  auto drop_f = vertex_colored.property_map<Mesh::Face_index, CGAL::IO::Color>("f:color").first;
  vertex_colored.remove_property_map(drop_f);
  REQUIRE(CGAL::IO::write_OFF(
      faces_file, face_colored,
      CGAL::parameters::face_color_map(
          face_colored.property_map<Mesh::Face_index, CGAL::IO::Color>("f:color").first)));
  REQUIRE(CGAL::IO::write_OFF(
      vertices_file, vertex_colored,
      CGAL::parameters::vertex_color_map(
          vertex_colored.property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first)));
  for (const std::string& file : {faces_file, vertices_file}) {
    INFO(file);
    Mesh m;
    REQUIRE(read_mesh(file, m));
    auto region = m.add_property_map<Mesh::Face_index, int>("f:tessera_region", -1).first;
    const auto r = read_color_regions(file, m, region);
    REQUIRE(r);
    CHECK(r.regions == 2);
    CHECK(r.face_colors == (file == faces_file));
    const auto lines = feature_lines(m, {}, [&](Mesh::Face_index f) { return region[f]; });
    REQUIRE(lines.size() == 1);
    CHECK(lines[0].closed);
    CHECK(lines[0].kind == Feature_kind::color_boundary);
    for (auto h : lines[0].halfedges)
      CHECK(std::abs(m.point(target(h, m)).z()) < 0.35);
    // The faces' own colours, or the mean of their corners' colours.
    auto color = m.add_property_map<Mesh::Face_index, CGAL::IO::Color>("f:tessera_color").first;
    REQUIRE(read_face_colors(file, m, color));
    for (auto f : faces(m)) {
      int red = 0;
      for (auto v : vertices_around_face(halfedge(f, m), m))
        red += m.point(v).z() > 1e-9 ? 200 : 30;
      CHECK(int(color[f].red()) ==
            (file == faces_file ? (region[f] == 0 ? 30 : 200) : (red + 1) / 3));
      CHECK(int(color[f].red()) + int(color[f].blue()) == 230);
    }
  }
  Mesh plain;
  REQUIRE(read_mesh(test::data_path("eight.off"), plain));
  auto region = plain.add_property_map<Mesh::Face_index, int>("f:tessera_region", -1).first;
  CHECK(read_color_regions(test::data_path("eight.off"), plain, region).status ==
        Color_regions_status::no_colors);
  auto color = plain.add_property_map<Mesh::Face_index, CGAL::IO::Color>("f:tessera_color").first;
  CHECK(read_face_colors(test::data_path("eight.off"), plain, color).status ==
        Color_regions_status::no_colors);
}

TEST_CASE("principal directions guide the field along a cylinder's circles", "[fields][features]") {
  Mesh torus;
  make_torus(torus, 4, 1, 60, 24);
  Principal_direction_options po;
  po.maximal = true;
  const auto c = principal_direction_constraints(torus, po);
  REQUIRE(c.size() > num_vertices(torus) / 2);
  // On a torus of revolution the maximal curvature runs around the tube (1/r > curvature of the
  // axis circle).
  std::size_t around_tube = 0;
  for (const auto& k : c) {
    const Point_3 p = torus.point(k.vertex);
    const Vector_3 axis_dir(-p.y(), p.x(), 0); // direction around the z axis
    if (std::abs(angle_degrees(k.direction, axis_dir) - 90) < 5)
      ++around_tube;
  }
  CHECK(around_tube > 0.9 * c.size());
  auto field = torus.add_property_map<Mesh::Vertex_index, Vector_3>("v:tessera_field").first;
  Smoothest_field_options so;
  so.symmetry = 2;
  REQUIRE(smoothest_field(torus, c, field, so));
  const auto s = field_singularities(torus, field, 2);
  CHECK(s.singularities.empty());
}

TEST_CASE("control vectors and feature specifications are read, bad ones named", "[fields][io]") {
  Mesh m = test::load("eight.off");
  const Control_vectors_read_result read =
      read_control_vectors(test::data_path("../fields/controls.json"));
  INFO(read.message);
  REQUIRE(read);
  REQUIRE(read.controls.size() == 3);
  CHECK(read.controls[1].index == 120);
  CHECK(read.controls[2].location == Control_vector::Location::face);
  CHECK(read.controls[2].weight == 2.0);
  const auto c = control_vector_constraints(m, read.controls);
  REQUIRE(c);
  REQUIRE(c.constraints.size() == 5); // two vertices, then the face's three corners
  CHECK(c.constraints[0].vertex == *std::next(vertices(m).begin(), 5));
  CHECK(c.constraints[0].kind == Constraint_kind::hard);
  CHECK(c.constraints[4].kind == Constraint_kind::soft);
  CHECK(c.constraints[2].weight + c.constraints[3].weight + c.constraints[4].weight == Approx(2.0));

  auto controls = [](const std::string& text) {
    std::istringstream in(text);
    return read_control_vectors(in);
  };
  const std::pair<std::string, std::string> bad[] = {
      {"{\"controls\": [", "malformed JSON"},
      {R"({"controls": 3})", "\"controls\" array"},
      {R"({"controls": [{"vertex": 1}]})", "control 0 needs a \"direction\""},
      {R"({"controls": [{"vertex": -1, "direction": [1, 0, 0]}]})", "control 0: \"vertex\""},
      {R"({"controls": [{"vertex": 1, "direction": [1, 0]}]})", "three numbers"},
      {R"({"controls": [{"vertex": 1, "direction": [1, 0, 0], "weight": 0}]})",
       "\"weight\" must be a positive number"},
      {R"({"controls": [{"direction": [1, 0, 0]}]})", "needs a \"vertex\" or a \"face\""}};
  for (const auto& [text, expected] : bad) {
    const auto r = controls(text);
    INFO(text << " -> " << r.message);
    CHECK(!r);
    CHECK(r.controls.empty());
    CHECK(r.message.find(expected) != std::string::npos);
  }
  const auto far = controls(R"({"controls": [{"vertex": 100000, "direction": [1, 0, 0]}]})");
  REQUIRE(far);
  const auto out_of_range = control_vector_constraints(m, far.controls);
  CHECK(!out_of_range);
  CHECK(out_of_range.message ==
        "control 0: \"vertex\" must be an index below " + std::to_string(num_vertices(m)));
  const auto off_face = controls(
      R"({"controls": [{"face": 1, "barycentric": [0.5, 0.6, -0.1], "direction": [1, 0, 0]}]})");
  REQUIRE(off_face);
  CHECK(!control_vector_constraints(m, off_face.controls));

  const Feature_spec_result f = parse_feature_spec("boundary,crease:40,color");
  REQUIRE(f);
  CHECK(f.options.boundary);
  CHECK(f.options.creases);
  CHECK(f.options.color_boundaries);
  CHECK(f.options.crease_angle_degrees == 40);
  const Feature_spec_result only = parse_feature_spec("crease");
  REQUIRE(only);
  CHECK(!only.options.boundary);
  CHECK(only.options.crease_angle_degrees == Feature_line_options{}.crease_angle_degrees);
  for (const char* spec :
       {"crease:0", "crease:180", "crease:abc", "crease:40x", "crease40", "edges"})
    CHECK(!parse_feature_spec(spec));

  const Alignment_spec_result a = parse_alignment_spec("parallel,3=perpendicular", 5);
  REQUIRE(a);
  CHECK(a.alignment == std::vector<Feature_alignment>{
                           Feature_alignment::parallel, Feature_alignment::parallel,
                           Feature_alignment::parallel, Feature_alignment::perpendicular,
                           Feature_alignment::parallel});
  CHECK(parse_alignment_spec("perpendicular", 2).alignment ==
        std::vector<Feature_alignment>(2, Feature_alignment::perpendicular));
  const Alignment_spec_result missing = parse_alignment_spec("9=parallel", 5);
  CHECK(!missing);
  CHECK(missing.message.find("line 9 does not exist") != std::string::npos);
  CHECK(!parse_alignment_spec("2=sideways", 5));
  CHECK(!parse_alignment_spec("x=parallel", 5));
  CHECK(!parse_alignment_spec("skew", 5));
}

TEST_CASE("thin parts: a tube's girth in tiles and its axis are found at the tile's scale",
          "[fields][features]") {
  const double pi = std::acos(-1.0);
  Mesh capsule;
  make_capsule(capsule, 1.0, 20.0, 48);
  Thin_part_options to;
  to.spacing = 2 * pi / 6; // six tiles around the tube
  const Thin_part_result<Mesh> thin = thin_part_constraints(capsule, to);
  INFO(thin.message);
  REQUIRE(thin);
  // The sliced girth is the loop around the tube: 2π over the spacing (the 48-gon's perimeter is
  // 0.07 % shorter), read from the normals' spread it was 6 ± 0.9.
  CHECK(thin.median_guided_tiles_around == Approx(6).margin(0.15));
  CHECK(thin.fewest_tiles_around <= thin.median_guided_tiles_around);
  CHECK(thin.guided_area_fraction > 0.75); // the tube is 20 of its 24 units of length
  std::size_t on_tube = 0, along_axis = 0;
  for (const auto& c : thin.constraints) {
    if (std::abs(capsule.point(c.vertex).x()) > 8)
      continue;
    ++on_tube;
    CHECK(c.kind == Constraint_kind::soft);
    if (std::abs(angle_degrees(c.direction, Vector_3(1, 0, 0)) - 90) > 85)
      ++along_axis;
  }
  CHECK(on_tube > num_vertices(capsule) / 2);
  CHECK(along_axis == on_tube);
  // The field solved with them runs along the tube (a 4-field: along or around).
  auto field = capsule.add_property_map<Mesh::Vertex_index, Vector_3>("v:tessera_field").first;
  REQUIRE(smoothest_field(capsule, thin.constraints, field));
  for (auto v : vertices(capsule))
    if (std::abs(capsule.point(v).x()) < 8) {
      const double a = angle_degrees(field[v], Vector_3(1, 0, 0));
      CHECK(std::min(std::abs(a - 90), 90 - std::abs(a - 90)) < 5);
    }

  // Two tiles around: the normals' spread cannot tell girths below 3.1 tiles apart (a patch of
  // 1.25 spacings wraps the tube), the slice can.
  to.spacing = 2 * pi / 2;
  const auto thinner = thin_part_constraints(capsule, to);
  CHECK(thinner.median_guided_tiles_around == Approx(2).margin(0.1));
  to.girth = Thin_part_girth::normal_spread;
  CHECK(thin_part_constraints(capsule, to).median_guided_tiles_around ==
        Approx(2 * pi * to.patch_radius / 2.5).margin(0.1));
  to.girth = Thin_part_girth::sliced;

  // Twenty-four tiles around the same tube, or a sphere at any scale: nothing to guide.
  to.spacing = 2 * pi / 24;
  const auto wide = thin_part_constraints(capsule, to);
  CHECK(wide.fewest_tiles_around > 15);
  CHECK(wide.guided_area_fraction < 0.05);
  Mesh sphere;
  make_sphere(sphere, 1.0, 4);
  for (double around : {8.0, 16.0, 32.0}) {
    to.spacing = 2 * pi / around;
    const auto round = thin_part_constraints(sphere, to);
    INFO(around << " tiles around the sphere: thinnest " << round.fewest_tiles_around);
    CHECK(round.guided_area_fraction < 0.02);
  }

  to.spacing = 0;
  CHECK(thin_part_constraints(sphere, to).status == Field_status::invalid_options);
}

TEST_CASE("thin parts: a rounded edge of a broad slab is not a thin part, a tube is",
          "[fields][features]") {
  // A capsule 20 long squashed into a slab 12 wide and 2 thick: its long edges curve as tightly as
  // a tube of radius 1/6, so the normals over a patch there spread as a thin tube's do, but the
  // plane across the axis cuts the whole slab's outline, 24.9 long (82 spacings).
  Mesh slab;
  make_capsule(slab, 1.0, 20.0, 96);
  for (auto v : vertices(slab)) {
    const Point_3 p = slab.point(v);
    slab.point(v) = Point_3(p.x(), 6 * p.y(), p.z());
  }
  Thin_part_options to;
  to.spacing = 0.3;
  to.girth = Thin_part_girth::normal_spread;
  const auto spread = thin_part_constraints(slab, to);
  INFO("read from the normals' spread: " << spread.guided_area_fraction << " of the area guided, "
                                         << spread.median_guided_tiles_around << " tiles around");
  CHECK(spread.guided_area_fraction > 0.03);
  to.girth = Thin_part_girth::sliced;
  const auto sliced = thin_part_constraints(slab, to);
  INFO("sliced: " << sliced.guided_area_fraction << " of the area guided");
  // What is left guided lies on the round ends, where the slab narrows to its tips.
  double on_body = 0;
  for (const auto& c : sliced.constraints)
    on_body += std::abs(slab.point(c.vertex).x()) < 9;
  CHECK(on_body == 0);
  CHECK(sliced.guided_area_fraction < 0.25 * spread.guided_area_fraction);
  CHECK(sliced.curved_band_vertices == 0);
  // Asked to (on a CAD part), curved bands with no loop around them are guided along their axis.
  to.curved_bands_below_tiles_around = 8;
  const auto bands = thin_part_constraints(slab, to);
  INFO("curved bands: " << bands.curved_band_vertices << " vertices, " << bands.guided_area_fraction
                        << " of the area guided");
  CHECK(bands.curved_band_vertices > 0);
  CHECK(bands.guided_area_fraction > 0.5 * spread.guided_area_fraction);
  std::size_t along = 0, on_edges = 0;
  for (const auto& c : bands.constraints)
    if (std::abs(slab.point(c.vertex).x()) < 9) {
      ++on_edges;
      along += std::abs(angle_degrees(c.direction, Vector_3(1, 0, 0)) - 90) > 80;
    }
  CHECK(on_edges > 0);
  CHECK(along == on_edges);
  to.curved_bands_below_tiles_around = 0;

  // An open half pipe (a trough): its normals spread as a tube's, but no loop closes around it.
  Mesh pipe;
  make_capsule(pipe, 1.0, 20.0, 48);
  std::vector<Mesh::Face_index> lower;
  for (auto f : faces(pipe)) {
    double z = 0;
    for (auto v : vertices_around_face(halfedge(f, pipe), pipe))
      z += pipe.point(v).z();
    if (z < 0)
      lower.push_back(f);
  }
  for (auto f : lower)
    CGAL::Euler::remove_face(halfedge(f, pipe), pipe);
  pipe.collect_garbage();
  to.spacing = 2 * std::acos(-1.0) / 6; // six tiles around the whole tube
  CHECK(thin_part_constraints(pipe, to).guided_vertices == 0);
  to.girth = Thin_part_girth::normal_spread;
  CHECK(thin_part_constraints(pipe, to).guided_area_fraction > 0.5);
}

TEST_CASE("thin parts: the field turns along the elephant's legs and trunk and is held elsewhere",
          "[fields][features]") {
  Mesh m = test::load("elephant.off");
  auto held = m.add_property_map<Mesh::Vertex_index, Vector_3>("v:held").first;
  auto field = m.add_property_map<Mesh::Vertex_index, Vector_3>("v:field").first;
  REQUIRE(smoothest_field(m, {}, held)); // the smoothest field: an eigenvector, its angle free
  Thin_part_options to;
  to.spacing = std::sqrt(CGAL::Polygon_mesh_processing::area(m) / 1500); // 1500 tiles
  const Thin_part_result<Mesh> thin = thin_part_constraints_holding(m, to, held);
  INFO(thin.message);
  REQUIRE(thin);
  INFO(thin.guided_vertices << " guided, " << thin.held_vertices << " held, "
                            << thin.guided_area_fraction << " of the area guided");
  REQUIRE(thin.guided_vertices > 0);
  CHECK(thin.guided_vertices + thin.held_vertices == thin.constraints.size());
  CHECK(thin.guided_area_fraction < 0.5);
  // Every vertex gets a guide, a hold or both (where the guide ramps in).
  std::vector<int> count(num_vertices(m), 0);
  for (const auto& c : thin.constraints)
    ++count[std::size_t(c.vertex)];
  CHECK(std::count(count.begin(), count.end(), 0) == 0);

  // Where the guide takes most of the weight (the part fewer than about 8 tiles around), the field
  // runs along the part's axis; where the hold alone acts, it stays the held field. A hold's
  // direction is the held vector itself.
  REQUIRE(smoothest_field(m, thin.constraints, field));
  auto angle = [&](Mesh::Vertex_index v, const Vector_3& t) {
    return line_angle_degrees(field[v], t,
                              CGAL::Polygon_mesh_processing::compute_vertex_normal(v, m), 4);
  };
  std::vector<double> along, kept;
  for (const auto& c : thin.constraints) {
    const bool hold = c.direction == held[c.vertex];
    if (!hold && c.weight >= 0.75 * to.weight)
      along.push_back(angle(c.vertex, c.direction));
    else if (hold && count[std::size_t(c.vertex)] == 1)
      kept.push_back(angle(c.vertex, c.direction));
  }
  auto median = [](std::vector<double> x) {
    std::nth_element(x.begin(), x.begin() + std::ptrdiff_t(x.size() / 2), x.end());
    return x[x.size() / 2];
  };
  REQUIRE(along.size() > 50);
  REQUIRE(kept.size() > num_vertices(m) / 2);
  INFO("along the axis: median " << median(along) << "; held: median " << median(kept));
  CHECK(median(along) < 12); // 6.6° measured
  CHECK(median(kept) < 3);   // 0.96°

  // smoothest_field_with_thin_parts() does the same two solves in one solver: the same field. The
  // guides and holds weigh on every vertex, so the second solve is by conjugate gradients from the
  // first field, without a factorization; told not to, by a numeric factorization on the first
  // solve's analysis.
  auto both = m.add_property_map<Mesh::Vertex_index, Vector_3>("v:both").first;
  const auto r = smoothest_field_with_thin_parts(m, {}, both, to);
  INFO(r.message());
  REQUIRE(r);
  CHECK(r.guided);
  CHECK(r.unguided.eigen_iterations > 0);
  CHECK(r.field.solver == "Eigen ConjugateGradient");
  CHECK_FALSE(r.field.factorized);
  INFO(r.field.iterative_iterations << " conjugate-gradient iterations");
  CHECK(r.field.iterative_iterations > 0);
  CHECK(r.field.iterative_iterations < 150); // 42–44 on fandisk at 3k–200k faces
  CHECK(r.thin_parts.constraints.size() == thin.constraints.size());
  double worst = 0;
  for (auto v : vertices(m))
    worst = std::max(worst, (both[v] - field[v]).squared_length());
  CHECK(worst < 1e-16);
  Smoothest_field_options factorized;
  factorized.iterative_when_held = false;
  const auto rf = smoothest_field_with_thin_parts(m, {}, both, to, factorized);
  REQUIRE(rf);
  CHECK(rf.field.analysis_reused);
  CHECK(rf.field.iterative_iterations == 0);
  worst = 0;
  for (auto v : vertices(m))
    worst = std::max(worst, (both[v] - field[v]).squared_length());
  CHECK(worst < 1e-16);

  // The guides alone (no hold) decide the field everywhere: away from them it turns from the
  // smoothest field.
  REQUIRE(smoothest_field(m, thin_part_constraints(m, to).constraints, field));
  std::vector<double> turned;
  for (const auto& c : thin.constraints)
    if (count[std::size_t(c.vertex)] == 1 && c.direction == held[c.vertex])
      turned.push_back(angle(c.vertex, held[c.vertex]));
  INFO("guides alone, away from them: median " << median(turned));
  CHECK(median(turned) > 8); // 19.6°
}

TEST_CASE("bends tighter than the tightest radius leave the field free", "[fields][features]") {
  // A 20 × 20 plate sampled every 0.5: one closed border with four sharp corners.
  Mesh plate;
  make_plate(plate, 20, 20, 2);
  const auto lines = feature_lines(plate);
  REQUIRE(lines.size() == 1);
  REQUIRE(lines[0].halfedges.size() == 160);
  Feature_alignment_options options;
  CHECK(
      feature_alignment_constraints(plate, lines, {Feature_alignment::parallel}, options).size() ==
      160);
  // With 4.2: the border turns by π/2 within 2.1 of each corner (along it), so the corner and
  // the four vertices on each side of it are left free; 31 vertices of each side stay.
  options.tightest_radius = 4.2;
  const auto held =
      feature_alignment_constraints(plate, lines, {Feature_alignment::parallel}, options);
  CHECK(held.size() == 4 * 31);
  for (const auto& c : held) {
    const Point_3& p = plate.point(c.vertex);
    // On a side, the distance to the nearer corner along the border is the smaller coordinate
    // offset that is not 0.
    const double to_corner = std::max(std::min(p.x(), 20 - p.x()), std::min(p.y(), 20 - p.y()));
    INFO("held vertex at " << p);
    CHECK(to_corner > 2.1);
    // Along a side, never the corner's bisector.
    CHECK(line_angle_degrees(c.direction, Vector_3(1, 0, 0), Vector_3(0, 0, 1), 4) < 1e-9);
  }
  // The field at the freed corners takes the sides' direction: the axes everywhere.
  auto field = plate.add_property_map<Mesh::Vertex_index, Vector_3>("v:tessera_field").first;
  REQUIRE(smoothest_field(plate, held, field, Smoothest_field_options{}));
  double worst = 0;
  for (const auto v : vertices(plate))
    worst = std::max(worst, line_angle_degrees(field[v], Vector_3(1, 0, 0), Vector_3(0, 0, 1), 4));
  CHECK(worst < 0.5);

  // An open tube of radius 2: its rims are circles, held below a radius of 2 and free above it.
  Mesh tube;
  make_tube(tube, 2, 10, 32);
  const auto rims = feature_lines(tube);
  REQUIRE(rims.size() == 2);
  options.tightest_radius = 1.5;
  CHECK(feature_alignment_constraints(tube, rims, {Feature_alignment::parallel}, options).size() ==
        64);
  options.tightest_radius = 3;
  CHECK(feature_alignment_constraints(tube, rims, {Feature_alignment::parallel}, options).empty());
}
