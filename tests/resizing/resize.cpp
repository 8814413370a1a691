// Resizing: TetGen volumes and the protective grid, vulnerability, non-homogeneous resizing against
// simple scaling (capsule caps, a bump on a box), target sizes, self-intersections before and
// after, bordered input, bad input, a second mesh type, deformation by handles, and the generated
// textures with the texel measure, and the comparison pictures of a resize.
#include "corpus.h"

#include <tessera/generators/textures.h>
#include <tessera/io/read_handles.h>
#include <tessera/io/resize_reports.h>
#include <tessera/resizing/deform.h>
#include <tessera/resizing/draw_resize.h>
#include <tessera/resizing/resize.h>
#include <tessera/resizing/stretch.h>
#include <tessera/resizing/texels.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/generators.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace tessera;
using tessera::test::load;

namespace {

// Largest local stretch ratio over the vertices that `select` keeps (by original position).
template <typename Select>
double max_stretch(const Mesh& before, const Mesh& after, Select select) {
  auto ratio = get(CGAL::dynamic_vertex_property_t<double>(), after);
  local_stretch_ratios(after, before.points(), after.points(), ratio);
  double out = 0;
  for (auto v : vertices(after))
    if (select(before.point(v)) && std::isfinite(get(ratio, v)))
      out = std::max(out, get(ratio, v));
  return out;
}

Mesh capsule() {
  Mesh m;
  make_capsule(m, 1.0, 4.0, 32);
  return m;
}

} // namespace

TEST_CASE("TetGen keeps the surface and fills its volume, and the grid embeds every point",
          "[resizing]") {
  const Mesh m = capsule();
  const Tetrahedralize_result r = tetrahedralize(m);
  REQUIRE(r);
  REQUIRE(r.mesh.surface_vertices == num_vertices(m));
  // The surface's vertices come first, in order, each moved by the documented perturbation at
  // most (and moved: TetGen saw the moved points).
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(m);
  const double shift = Tetrahedralize_options{}.perturbation *
                       std::sqrt(CGAL::square(box.x_span()) + CGAL::square(box.y_span()) +
                                 CGAL::square(box.z_span()));
  REQUIRE(shift > 0);
  Mesh seen = m; // the surface as TetGen saw it
  std::size_t i = 0, moved = 0;
  for (auto v : vertices(m)) {
    const auto& p = r.mesh.points[i++];
    for (int c = 0; c < 3; ++c)
      CHECK(std::abs(p[std::size_t(c)] - m.point(v)[c]) <= shift);
    moved += Point_3(p[0], p[1], p[2]) != m.point(v);
    seen.point(v) = Point_3(p[0], p[1], p[2]);
  }
  CHECK(moved == num_vertices(m));
  // Every tetrahedron is positively oriented (exactly) and together they fill the surface.
  double volume = 0;
  for (std::size_t t = 0; t < r.mesh.tets.size(); ++t) {
    std::array<Point_3, 4> c;
    for (std::size_t k = 0; k < 4; ++k) {
      const auto& p = r.mesh.points[r.mesh.tets[t][k]];
      c[k] = Point_3(p[0], p[1], p[2]);
    }
    CHECK(CGAL::orientation(c[0], c[1], c[2], c[3]) == CGAL::POSITIVE);
    volume += r.mesh.tet_volume(t);
  }
  CHECK(volume == Approx(CGAL::Polygon_mesh_processing::volume(seen)).epsilon(1e-12));

  std::vector<std::array<double, 3>> points;
  for (auto v : vertices(m))
    points.push_back({m.point(v).x(), m.point(v).y(), m.point(v).z()});
  const Tet_mesh grid = grid_tet_mesh(points, {10, 0.5});
  REQUIRE(grid.embedded());
  const auto back = grid.surface_positions(grid.points);
  for (std::size_t k = 0; k < points.size(); ++k) {
    for (double w : grid.embedding_weights[k])
      CHECK(w >= -1e-12);
    for (int c = 0; c < 3; ++c)
      CHECK(back[k][std::size_t(c)] == Approx(points[k][std::size_t(c)]).margin(1e-9));
  }
  double grid_volume = 0;
  for (std::size_t t = 0; t < grid.tets.size(); ++t)
    grid_volume += grid.tet_volume(t);
  const auto& a = grid.points.front();
  const auto& b = grid.points.back();
  CHECK(grid_volume == Approx((b[0] - a[0]) * (b[1] - a[1]) * (b[2] - a[2])));
}

TEST_CASE("Vulnerability: a capsule is free along its axis on the cylinder, vulnerable on the caps",
          "[resizing]") {
  const Mesh m = capsule();
  auto w = get(CGAL::dynamic_vertex_property_t<std::array<double, 3>>(), m);
  Vulnerability_options options;
  options.dilation = 0;
  const Vulnerability_result r = compute_vulnerability(m, w, options);
  REQUIRE(r);
  CHECK(r.message.empty());
  CHECK(r.unfitted_vertices == 0);
  CHECK(r.reference_curvature == Approx(1.0).epsilon(0.05)); // 1/radius on the caps
  for (auto v : vertices(m)) {
    const double x = std::abs(m.point(v).x());
    if (x < 1.0) // mid-cylinder: straight along x, curved around it
      CHECK(get(w, v)[0] < 0.05);
    if (x > 2.5) // near the poles
      CHECK(get(w, v)[0] > 0.9);
  }
}

TEST_CASE("Non-homogeneous resizing keeps a capsule's caps round where simple scaling stretches "
          "them 2x, and meets the target length",
          "[resizing]") {
  const Mesh input = capsule();
  auto on_caps = [](const Mesh::Point& p) { return std::abs(p.x()) > 2.0 + 1e-9; };

  Mesh simple = input;
  Resize_options options;
  options.scale = {2, 1, 1};
  options.method = Resize_method::simple;
  REQUIRE(resize(simple, options));
  const double simple_caps = max_stretch(input, simple, on_caps);
  CHECK(simple_caps > 1.9);

  Mesh resized = input;
  options.method = Resize_method::nonhomogeneous;
  const Resize_result r = resize(resized, options);
  REQUIRE(r);
  CHECK(r.volume == Resize_volume::tetgen);
  CHECK(r.extent_after[0] == Approx(12.0).epsilon(0.01));
  CHECK(r.extent_after[1] == Approx(2.0).epsilon(0.01));
  CHECK(r.extent_after[2] == Approx(2.0).epsilon(0.01));
  const double caps = max_stretch(input, resized, on_caps);
  INFO("caps' largest stretch ratio " << caps << ", simple scaling " << simple_caps);
  CHECK(caps <= 1.1);
  // The cylinder took the stretch: its middle is stretched more than 2x.
  CHECK(max_stretch(input, resized, [](const Mesh::Point& p) { return std::abs(p.x()) < 0.5; }) >
        2.2);
  CHECK_FALSE(CGAL::Polygon_mesh_processing::does_self_intersect(resized));
}

TEST_CASE("A sphere-shaped bump on a box stays round under a 2x stretch", "[resizing]") {
  // A rounded box with a spherical cap raised on the middle of its top.
  Mesh m;
  make_genus_surface(m, 0);
  CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(1));
  CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(m);
  const double cx = 0.5 * (box.xmin() + box.xmax()), cy = 0.5 * (box.ymin() + box.ymax());
  const double radius = 0.3 * std::min(box.xmax() - box.xmin(), box.ymax() - box.ymin());
  std::vector<Mesh::Vertex_index> bump;
  for (auto v : vertices(m)) {
    const auto p = m.point(v);
    const double d = std::hypot(p.x() - cx, p.y() - cy);
    if (p.z() > box.zmax() - 1e-6 && d < radius) {
      m.point(v) = {p.x(), p.y(), p.z() + std::sqrt(radius * radius - d * d)};
      bump.push_back(v);
    }
  }
  REQUIRE(bump.size() > 50);
  // The bump's width along y (the box's long side, which is stretched) over its width along x.
  auto aspect = [&](const Mesh& mesh) {
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for (auto v : bump)
      for (int c = 0; c < 2; ++c) {
        lo[c] = std::min(lo[c], mesh.point(v)[c]);
        hi[c] = std::max(hi[c], mesh.point(v)[c]);
      }
    return (hi[1] - lo[1]) / (hi[0] - lo[0]);
  };
  const double before = aspect(m);
  Resize_options options;
  options.scale = {1, 2, 1};
  Mesh simple = m, resized = m;
  options.method = Resize_method::simple;
  REQUIRE(resize(simple, options));
  options.method = Resize_method::nonhomogeneous;
  const Resize_result r = resize(resized, options);
  REQUIRE(r);
  CHECK(r.extent_after[1] == Approx(2 * r.extent_before[1]).epsilon(0.01));
  INFO("bump aspect before " << before << ", simple " << aspect(simple) << ", resized "
                             << aspect(resized));
  CHECK(aspect(simple) == Approx(2 * before).epsilon(0.01));
  CHECK(aspect(resized) < 1.1 * before);
}

TEST_CASE("Resizing a real model: targets met, no new self-intersection", "[resizing]") {
  for (const char* name : {"elephant.off", "knot1.off"}) {
    Mesh m = load(name);
    REQUIRE_FALSE(CGAL::Polygon_mesh_processing::does_self_intersect(m));
    Resize_options options;
    options.scale = {1, 1.6, 1};
    const Resize_result r = resize(m, options);
    INFO(name << ": " << r.message);
    REQUIRE(r);
    CHECK(r.extent_after[1] == Approx(1.6 * r.extent_before[1]).epsilon(0.01));
    CHECK(r.extent_after[0] == Approx(r.extent_before[0]).epsilon(0.01));
    CHECK_FALSE(CGAL::Polygon_mesh_processing::does_self_intersect(m));
  }
}

TEST_CASE("Where little is free (the eight: curved everywhere) the free stretch stays bounded and "
          "the rings are not distorted past simple scaling, and halving never flattens free parts",
          "[resizing]") {
  // The 95th percentile of the local stretch ratios from `before` to `after`.
  auto p95 = [](const Mesh& before, const Mesh& after) {
    auto ratio = get(CGAL::dynamic_vertex_property_t<double>(), after);
    local_stretch_ratios(after, before.points(), after.points(), ratio);
    std::vector<double> values;
    for (auto v : vertices(after))
      if (std::isfinite(get(ratio, v)))
        values.push_back(get(ratio, v));
    std::sort(values.begin(), values.end());
    return values[std::size_t(0.95 * double(values.size() - 1))];
  };
  const Mesh input = load("eight.off");
  for (const double s : {2.0, 0.5}) {
    INFO("scale along x " << s);
    Resize_options options;
    options.scale = {s, 1, 1};
    Mesh resized = input, simple = input;
    const Resize_result r = resize(resized, options);
    REQUIRE(r);
    // Before the bound the free stretch went to 77 (a spike through the ring) for 2x and to 0
    // (free tetrahedra flattened) for 0.5x.
    const double k = options.solve.max_free_stretch_exponent;
    CHECK(std::abs(std::log(r.free_stretch[0])) <= k * std::abs(std::log(s)) + 1e-9);
    CHECK(r.vulnerability_weight[0] < 1);
    CHECK(r.vulnerability_weight[1] == 1);
    CHECK(r.extent_after[0] == Approx(s * r.extent_before[0]).epsilon(1e-6));
    options.method = Resize_method::simple;
    REQUIRE(resize(simple, options));
    // 4.95 against 2.00 before the bound.
    CHECK(p95(input, resized) < 1.25 * p95(input, simple));
  }
  // Where the free parts suffice, the bound does not act.
  Mesh elephant = load("elephant.off");
  Resize_options options;
  options.scale = {2, 1, 1};
  const Resize_result r = resize(elephant, options);
  REQUIRE(r);
  CHECK(r.vulnerability_weight[0] == 1);
  CHECK(r.free_stretch[0] > 2);
}

TEST_CASE("Bordered input goes through the protective grid", "[resizing]") {
  Mesh m = load("pig.off");
  Resize_options options;
  options.scale = {1.5, 1, 1};
  const Resize_result r = resize(m, options);
  REQUIRE(r);
  CHECK(r.volume == Resize_volume::grid);
  CHECK(r.extent_after[0] == Approx(1.5 * r.extent_before[0]).epsilon(0.01));

  Mesh bordered = load("pig.off");
  options.volume = Resize_volume::tetgen;
  const Resize_result refused = resize(bordered, options);
  CHECK(refused.status == Resize_status::not_closed);
  CHECK(bordered.point(*vertices(bordered).begin()) ==
        load("pig.off").point(*vertices(bordered).begin()));
}

TEST_CASE("Self-intersecting input gets a clear error, never a TetGen crash", "[resizing]") {
  Mesh m;
  make_sphere(m, 1.0, 2);
  Mesh other;
  make_sphere(other, 1.0, 2);
  for (auto v : vertices(other))
    other.point(v) = other.point(v) + Kernel::Vector_3(0.8, 0, 0);
  CGAL::copy_face_graph(other, m);
  const Tetrahedralize_result t = tetrahedralize(m);
  CHECK(t.status == Tetrahedralize_status::self_intersecting);
  CHECK_FALSE(t.message.empty());
  const auto before = m.point(*vertices(m).begin());
  const Resize_result r = resize(m, Resize_options{});
  CHECK(r.status == Resize_status::self_intersecting);
  CHECK(m.point(*vertices(m).begin()) == before);

  Mesh empty;
  CHECK(resize(empty, Resize_options{}).status == Resize_status::empty_mesh);
  Resize_options bad;
  bad.scale = {0, 1, 1};
  Mesh c = capsule();
  CHECK(resize(c, bad).status == Resize_status::invalid_scale);
}

TEST_CASE("Vulnerability refuses a mesh without faces and options out of range, and resizing "
          "passes its refusal on",
          "[resizing]") {
  const Mesh empty;
  const Vulnerability_result none = compute_vulnerability(
      empty, get(CGAL::dynamic_vertex_property_t<std::array<double, 3>>(), empty));
  CHECK(!none);
  CHECK(none.status == Vulnerability_status::empty_mesh);
  CHECK(none.message == "the mesh has no faces");

  const Mesh m = capsule();
  auto w = get(CGAL::dynamic_vertex_property_t<std::array<double, 3>>(), m);
  for (auto v : vertices(m))
    put(w, v, std::array<double, 3>{{-1, -1, -1}});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<std::pair<Vulnerability_options, std::string>> bad(4);
  bad[0].first.rings = 0;
  bad[0].second = "ring";
  bad[1].first.reference_curvature = -1;
  bad[1].second = "reference curvature";
  bad[2].first.slippage_weight = nan;
  bad[2].second = "slippage weight";
  bad[3].first.reference_curvature = std::numeric_limits<double>::infinity();
  bad[3].second = "reference curvature";
  for (const auto& [options, named] : bad) {
    const Vulnerability_result r = compute_vulnerability(m, w, options);
    INFO(r.message);
    CHECK(!r);
    CHECK(r.status == Vulnerability_status::invalid_options);
    CHECK(r.message.find(named) != std::string::npos);
  }
  for (auto v : vertices(m)) // the map is left as it was
    CHECK(get(w, v)[0] == -1);

  Resize_options options;
  options.scale = {2, 1, 1};
  options.vulnerability.slippage_weight = nan;
  Mesh resized = m;
  const Resize_result r = resize(resized, options);
  CHECK(!r);
  CHECK(r.status == Resize_status::invalid_options);
  CHECK(r.message == compute_vulnerability(m, w, options.vulnerability).message);
  for (auto v : vertices(m))
    CHECK(resized.point(v) == m.point(v));
}

TEST_CASE("Volume resizing refuses an empty volume, vulnerabilities that do not match it and "
          "options out of range",
          "[resizing]") {
  const Mesh m = capsule();
  std::vector<std::array<double, 3>> points;
  for (auto v : vertices(m))
    points.push_back({m.point(v).x(), m.point(v).y(), m.point(v).z()});
  const Tet_mesh grid = grid_tet_mesh(points, {6, 0.5});
  REQUIRE(grid.points.size() != points.size());
  const std::vector<std::array<double, 3>> free(grid.points.size(), {0, 0, 0});
  Volume_resize_options options;
  options.scale = {2, 1, 1};
  const Volume_resize_result ok = resize_volume(grid, free, options);
  REQUIRE(ok);
  CHECK(ok.message.empty());
  CHECK(ok.iterations > 0);

  auto refused = [&](const Tet_mesh& mesh, const std::vector<std::array<double, 3>>& values,
                     const Volume_resize_options& o, Volume_resize_status status,
                     const std::string& named) {
    const Volume_resize_result r = resize_volume(mesh, values, o);
    INFO(r.message);
    CHECK(!r);
    CHECK(r.status == status);
    CHECK(r.message.find(named) != std::string::npos);
    CHECK(r.iterations == 0);
    CHECK(r.points == mesh.points);
  };
  refused(Tet_mesh{}, {}, options, Volume_resize_status::empty_volume, "no tetrahedra");
  refused(grid, std::vector<std::array<double, 3>>(points.size(), {0, 0, 0}), options,
          Volume_resize_status::invalid_input,
          std::to_string(grid.points.size()) + " vertices but " + std::to_string(points.size()));
  Tet_mesh broken = grid;
  broken.tets.back()[3] = grid.points.size();
  refused(broken, free, options, Volume_resize_status::invalid_input, "out of range");
  Volume_resize_options bad = options;
  bad.scale[1] = -1;
  refused(grid, free, bad, Volume_resize_status::invalid_options, "scale");
  bad = options;
  bad.stiffness = std::numeric_limits<double>::quiet_NaN();
  refused(grid, free, bad, Volume_resize_status::invalid_options, "stiffness");
  bad = options;
  bad.max_free_stretch_exponent = 0.5;
  refused(grid, free, bad, Volume_resize_status::invalid_options, "free stretch exponent");

  // resize() passes the solve's refusal on, the mesh left as it was.
  Resize_options resize_options;
  resize_options.scale = {2, 1, 1};
  resize_options.solve.stiffness = -1;
  Mesh resized = m;
  const Resize_result r = resize(resized, resize_options);
  CHECK(r.status == Resize_status::invalid_options);
  CHECK(r.message.find("stiffness") != std::string::npos);
  for (auto v : vertices(m))
    CHECK(resized.point(v) == m.point(v));
}

TEST_CASE("Resizing works on Polyhedron_3", "[resizing]") {
  CGAL::Polyhedron_3<Kernel> p;
  make_capsule(p, 1.0, 4.0, 16);
  Resize_options options;
  options.scale = {2, 1, 1};
  const Resize_result r = resize(p, options);
  REQUIRE(r);
  CHECK(r.extent_after[0] == Approx(12.0).epsilon(0.01));
}

TEST_CASE("Deformation by handles: handles reach their targets, fixed vertices stay, every CGAL "
          "method",
          "[resizing]") {
  const Mesh input = capsule();
  Deformation_handle fixed, moved;
  fixed.vertices.kind = Vertex_selection::Kind::box;
  fixed.vertices.min = {-4, -2, -2};
  fixed.vertices.max = {-2.5, 2, 2};
  moved.vertices.kind = Vertex_selection::Kind::box;
  moved.vertices.min = {2.5, -2, -2};
  moved.vertices.max = {4, 2, 2};
  moved.transform.axis = {0, 0, 1};
  moved.transform.angle = std::acos(-1.0) / 4;
  moved.transform.translation = {0, 1, 0};
  moved.transform.twist = 0.5;
  for (Deformation_method method : {Deformation_method::arap, Deformation_method::spokes_and_rims,
                                    Deformation_method::smoothed_arap}) {
    Mesh m = input;
    Deformation_options options;
    options.method = method;
    const Deformation_result r = deform_by_handles(m, {fixed, moved}, options);
    INFO("method " << int(method) << ": " << r.message);
    REQUIRE(r);
    CHECK(r.region_vertices == num_vertices(m));
    CHECK(r.handle_vertices > 2 * 32);
    CHECK(r.max_handle_error < 1e-9);
    double middle_moved = 0;
    for (auto v : vertices(m)) {
      const auto p = input.point(v), q = m.point(v);
      REQUIRE(std::isfinite(q.x()));
      if (p.x() < -2.5)
        CHECK(std::sqrt(CGAL::squared_distance(p, q)) < 1e-12);
      if (std::abs(p.x()) < 0.5)
        middle_moved = std::max(middle_moved, std::sqrt(CGAL::squared_distance(p, q)));
    }
    CHECK(middle_moved > 0.2);
  }

  // The handle's target, checked against an independent rotation: a quarter turn about z through
  // the centroid, without twist, maps (c + (1, 0, 0)) to (c + (0, 1, 0)).
  Handle_transform quarter;
  quarter.angle = std::acos(-1.0) / 2;
  const auto q = quarter.apply({3, 2, 5}, {2, 2, 5});
  CHECK(q[0] == Approx(2).margin(1e-12));
  CHECK(q[1] == Approx(3));
  CHECK(q[2] == Approx(5));

  Mesh m = input;
  Deformation_handle nowhere;
  nowhere.vertices.kind = Vertex_selection::Kind::sphere;
  nowhere.vertices.center = {100, 0, 0};
  nowhere.vertices.radius = 1;
  CHECK(deform_by_handles(m, {fixed, nowhere}).status == Deformation_status::empty_handle);
  Deformation_handle out_of_range;
  out_of_range.vertices.indices = {0, 999999};
  CHECK(deform_by_handles(m, {out_of_range}).status == Deformation_status::empty_handle);
}

TEST_CASE("Generated bump textures and the texel measure: count, aspect and size against the "
          "ground truth, and simple scaling's doubled aspect",
          "[resizing][texels]") {
  Mesh plate;
  make_plate(plate, 4.0, 2.0, 40);
  Bump_texture_options options;
  options.min = {0.5, 0.5};
  options.max = {3.5, 1.5};
  const Texture_ground_truth truth = add_bump_lattice(plate, options);
  // 12 x 4 centres fit in the 3 x 1 region at spacing 0.25 with a 0.09 margin.
  REQUIRE(truth.texels.size() == 48);
  for (const Texel& t : truth.texels)
    CHECK(t.vertices.size() >= 30);
  auto height = get(CGAL::dynamic_vertex_property_t<double>(), plate);
  std::size_t i = 0;
  for (auto v : vertices(plate))
    put(height, v, truth.height[i++]);
  const double threshold = 0.2 * options.height;
  // The disc where the cap (1 − (d/r)²)² exceeds 0.2: radius r·√(1 − √0.2).
  const double expected_size = options.radius * std::sqrt(1 - std::sqrt(0.2));
  const Texel_measure before = measure_texels(plate, plate.points(), height, threshold);
  CHECK(before.texels.size() == truth.texels.size());
  CHECK(before.median_aspect == Approx(1).margin(0.1));
  CHECK(before.median_size == Approx(expected_size).epsilon(0.15));

  Mesh simple = plate;
  Resize_options resize_options;
  resize_options.scale = {2, 1, 1};
  resize_options.method = Resize_method::simple;
  REQUIRE(resize(simple, resize_options));
  const Texel_measure stretched = measure_texels(simple, simple.points(), height, threshold);
  CHECK(stretched.texels.size() == truth.texels.size());
  CHECK(stretched.median_aspect == Approx(2).margin(0.15));

  // On a cylinder: the capsule's body, texels around and along it.
  Mesh body;
  make_capsule(body, 1.0, 4.0, 96);
  Bump_texture_options around;
  around.chart = Texture_chart::cylinder_x;
  around.spacing = 0.5;
  around.radius = 0.2;
  around.height = 0.08;
  around.min = {-1.5, -1.5};
  around.max = {1.5, 1.5};
  const Texture_ground_truth on_cylinder = add_bump_lattice(body, around);
  REQUIRE(on_cylinder.texels.size() == 36);
  auto body_height = get(CGAL::dynamic_vertex_property_t<double>(), body);
  i = 0;
  for (auto v : vertices(body))
    put(body_height, v, on_cylinder.height[i++]);
  const Texel_measure round = measure_texels(body, body.points(), body_height, 0.2 * around.height);
  CHECK(round.texels.size() == on_cylinder.texels.size());
  CHECK(round.median_aspect == Approx(1).margin(0.15));
}

TEST_CASE("The ridge, rivet and screw-thread generators follow their definitions",
          "[resizing][texels]") {
  // Ridges along x every 0.25 over [0.5, 3.5] x [0.5, 1.5]: lines at y = 1 + 0.25 k, |k| <= 2.
  Mesh plate;
  make_plate(plate, 4.0, 2.0, 40);
  const Mesh flat = plate;
  Ridge_texture_options ridges;
  ridges.min = {0.5, 0.5};
  ridges.max = {3.5, 1.5};
  const Texture_ground_truth lines = add_ridges(plate, ridges);
  REQUIRE(lines.texels.size() == 5);
  std::size_t i = 0;
  for (auto v : vertices(plate)) {
    const Point_3& p = flat.point(v);
    const double d = std::abs(p.y() - 1 - 0.25 * std::round((p.y() - 1) / 0.25));
    const bool inside = p.x() >= 0.5 && p.x() <= 3.5 && p.y() >= 0.5 && p.y() <= 1.5;
    CHECK(lines.height[i] >= 0);
    CHECK(lines.height[i] <= ridges.height);
    if (!inside || d >= ridges.half_width)
      CHECK(lines.height[i] == 0);
    else
      CHECK(plate.point(v).z() == Approx(lines.height[i]).margin(1e-12)); // raised along +z
    ++i;
  }
  for (const Texel& t : lines.texels) {
    CHECK(t.vertices.size() >= 100);
    CHECK(std::abs(t.center[1] - 1 - 0.25 * std::round((t.center[1] - 1) / 0.25)) < 1e-9);
  }
  // Rivets: the same lattice as caps, with round heads (√ profile: higher near the rim).
  Mesh capped, riveted;
  make_plate(capped, 4.0, 2.0, 40);
  make_plate(riveted, 4.0, 2.0, 40);
  Bump_texture_options bumps;
  bumps.min = {0.5, 0.5};
  bumps.max = {3.5, 1.5};
  const Texture_ground_truth caps = add_bump_lattice(capped, bumps);
  bumps.profile = Bump_profile::rivet;
  const Texture_ground_truth rivets = add_bump_lattice(riveted, bumps);
  REQUIRE(rivets.texels.size() == caps.texels.size());
  for (std::size_t k = 0; k < caps.height.size(); ++k) {
    CHECK(rivets.height[k] >= caps.height[k]);
    CHECK(rivets.height[k] <= bumps.height);
  }
  // A screw thread of pitch 0.4 on the capsule's body over x in [-1.5, 1.5]: the crest at angle θ
  // sits at x = -1.5 + 0.4 (k + θ/2π); one texel per turn; nothing raised on the caps.
  Mesh capsule;
  make_capsule(capsule, 1.0, 4.0, 96);
  const Mesh smooth = capsule;
  Screw_thread_options thread;
  thread.pitch = 0.4;
  thread.min_x = -1.5;
  thread.max_x = 1.5;
  const Texture_ground_truth turns = add_screw_thread(capsule, thread);
  CHECK(turns.texels.size() >= 7);
  CHECK(turns.texels.size() <= 9);
  const double two_pi = 2 * std::acos(-1.0);
  i = 0;
  for (auto v : vertices(capsule)) {
    const Point_3& p = smooth.point(v);
    if (std::abs(p.x()) > 1.5 || std::hypot(p.y(), p.z()) < 1 - 1e-9) {
      CHECK(turns.height[i] == 0);
    } else {
      const double phase = (p.x() + 1.5) / thread.pitch - std::atan2(p.z(), p.y()) / two_pi;
      const double d = std::abs(phase - std::round(phase)) * thread.pitch;
      CHECK((turns.height[i] > 0) == (d < thread.half_width));
      // Raised radially: the body's normals point away from the axis.
      CHECK(std::hypot(capsule.point(v).y(), capsule.point(v).z()) ==
            Approx(1 + turns.height[i]).margin(1e-9));
    }
    ++i;
  }
  CHECK_THROWS_AS(add_screw_thread(capsule, Screw_thread_options{1, 0.1, 0.2, 0.05, -1, 1}),
                  std::invalid_argument);
}

TEST_CASE("Deformation handles read from JSON, bad files named by field", "[resizing][io]") {
  const Handles_read_result good =
      read_deformation_handles(test::data_path("../resizing/handles.json"));
  INFO(good.message);
  REQUIRE(good);
  REQUIRE(good.handles.size() == 2);
  CHECK(!good.region);
  CHECK(good.handles[0].vertices.kind == Vertex_selection::Kind::box);
  CHECK(good.handles[0].vertices.max[2] == -0.4);
  const Handle_transform& t = good.handles[1].transform;
  const double pi = std::acos(-1.0);
  CHECK(t.angle == Approx(pi / 6)); // 30 degrees
  CHECK(t.twist == Approx(pi / 2)); // 90 degrees per unit
  CHECK(t.axis == std::array<double, 3>{{0, 0, 1}});
  CHECK(t.translation == std::array<double, 3>{{0.1, 0, 0}});

  auto read = [](const std::string& text) {
    std::istringstream in(text);
    return read_deformation_handles(in);
  };
  const auto with_region = read(R"({"region": {"sphere": {"center": [0, 0, 0], "radius": 2}},
               "handles": [{"vertices": [3, 1], "scale": 2}]})");
  REQUIRE(with_region);
  REQUIRE(with_region.region);
  CHECK(with_region.region->radius == 2);
  CHECK(with_region.handles[0].vertices.indices == std::vector<std::size_t>{3, 1});
  CHECK(with_region.handles[0].transform.scale == 2);

  const std::pair<std::string, std::string> bad[] = {
      {"{\"handles\": [", "not valid JSON"},
      {"[1, 2]", "non-empty \"handles\" array"},
      {R"({"handles": []})", "non-empty \"handles\" array"},
      {R"({"handles": [{"sphere": {"center": [0, 0, 0]}}]})",
       "handle 0: sphere radius must be a finite number"},
      {R"({"handles": [{"vertices": [0]}, {"vertices": [-1]}]})", "handle 1: \"vertices\""},
      {R"({"handles": [{"vertices": [0], "scale": -1}]})", "handle 0: scale must be positive"},
      {R"({"handles": [{"box": {"min": [0, 0], "max": [1, 1, 1]}}]})", "handle 0: box min"},
      {R"({"handles": [{"vertices": [0], "rotate": 5}]})", "handle 0: rotate axis"},
      {R"({"region": 3, "handles": [{"vertices": [0]}]})", "region must be an object"}};
  for (const auto& [text, expected] : bad) {
    const auto r = read(text);
    INFO(text << " -> " << r.message);
    CHECK(!r);
    CHECK(r.handles.empty());
    CHECK(r.message.find(expected) != std::string::npos);
  }
  CHECK(read_deformation_handles(std::string("/nonexistent/handles.json")).status ==
        Handles_read_status::cannot_open);
}

TEST_CASE("stretch statistics split a resize between the vertices that resisted it and the others",
          "[resizing][stretch]") {
  // A plate whose left half is held (vulnerability 1 along x) and keeps its shape, and whose right
  // half is free (0) and stretched 2x along x: ratio 1 on the left, 2 on the right, away from the
  // seam between them.
  Mesh before;
  make_plate(before, 2.0, 1.0, 20.0); // [0, 2] x [0, 1]
  Mesh after = before;
  auto w = before.add_property_map<Mesh::Vertex_index, std::array<double, 3>>("v:w").first;
  for (auto v : vertices(before)) {
    const double x = before.point(v).x();
    w[v] = {{x < 1 ? 1.0 : 0.0, 0.3, 0.3}};
    if (x > 1)
      after.point(v) = Point_3(1 + 2 * (x - 1), before.point(v).y(), before.point(v).z());
  }
  const Stretch_by_vulnerability s =
      stretch_by_vulnerability(before, before.points(), after.points(), w, {{2, 1, 1}});
  REQUIRE(s.resisted.size() == num_vertices(before));
  const Stretch_stats held = make_stretch_stats(s.vulnerable), free = make_stretch_stats(s.free);
  INFO("held " << held.vertices << " median " << held.median << ", free " << free.vertices
               << " median " << free.median);
  CHECK(held.vertices + free.vertices <= num_vertices(before));
  CHECK(held.vertices > 0.4 * double(num_vertices(before)));
  CHECK(held.median == Approx(1).margin(1e-9));
  CHECK(free.median == Approx(2).margin(1e-9));
  // Only the resized axis counts: along y and z (scale 1) a vulnerability of 0.3 is no resistance.
  CHECK(resisted_vulnerability(std::array<double, 3>{{0.0, 0.9, 0.9}}, {{2, 1, 1}}) == 0);
  CHECK(resisted_vulnerability(std::array<double, 3>{{0.2, 0.9, 0.9}}, {{2, 1, 1.5}}) == 0.9);
  // With the threshold above every vulnerability, every vertex is free.
  CHECK(stretch_by_vulnerability(before, before.points(), after.points(), w, {{2, 1, 1}}, 1.5)
            .vulnerable.empty());
}

TEST_CASE("A resize comparison scales the input simply and lays input, simple scaling and result "
          "apart across the most resized axis",
          "[resizing]") {
  const Mesh input = capsule(); // 6 x 2 x 2, along x
  const std::size_t n = num_vertices(input), f = num_faces(input);
  Resize_options options;
  options.scale = {1, 1, 2};
  Mesh resized = input;
  REQUIRE(resize(resized, options));
  const std::vector<Color> red(n, Color{1, 0, 0});
  const Resize_comparison<Mesh> c = resize_comparison(input, resized, options, {{}, red});
  REQUIRE(c);
  const CGAL::Bbox_3 simple = CGAL::Polygon_mesh_processing::bbox(c.simple_scaling);
  CHECK(simple.zmax() - simple.zmin() == Approx(4.0));
  CHECK(simple.xmax() - simple.xmin() == Approx(6.0));
  CHECK_FALSE(c.nonhomogeneous);
  // z is the most resized axis: the three states follow each other along x, apart, in order.
  CHECK(c.picture.offset_axis == 0);
  const Render_scene& scene = c.picture.scene;
  REQUIRE(scene.positions.size() == 3 * n);
  REQUIRE(scene.triangles.size() == 3 * f);
  std::vector<CGAL::Bbox_3> boxes;
  for (std::size_t k = 0; k < 3; ++k)
    boxes.push_back(bounding_box(
        std::vector<std::array<double, 3>>(scene.positions.begin() + std::ptrdiff_t(k * n),
                                           scene.positions.begin() + std::ptrdiff_t((k + 1) * n))));
  INFO("x ranges " << boxes[0].xmin() << ".." << boxes[0].xmax() << ", " << boxes[1].xmin() << ".."
                   << boxes[1].xmax() << ", " << boxes[2].xmin() << ".." << boxes[2].xmax());
  CHECK(boxes[0].xmax() < boxes[1].xmin());
  CHECK(boxes[1].xmax() < boxes[2].xmin());
  CHECK(boxes[1].zmax() - boxes[1].zmin() == Approx(4.0));
  CHECK(scene.triangle_colors[0].r == Approx(Color{}.r));
  CHECK(scene.triangle_colors[3 * f - 1].r == Approx(1.0));
  CHECK(scene.triangle_colors[3 * f - 1].g == Approx(0.0));

  // Colours that do not match the vertices are refused.
  const Resize_comparison<Mesh> wrong =
      resize_comparison(input, resized, options, {{}, std::vector<Color>(n - 1)});
  CHECK(wrong.status == Resize_comparison_status::mismatched_input);
  CHECK(wrong.message.find("result_colors") != std::string::npos);

  // On Polyhedron_3, stretched along x: the states are stacked along z.
  CGAL::Polyhedron_3<Kernel> p;
  make_capsule(p, 1.0, 4.0, 16);
  options.scale = {2, 1, 1};
  const Resize_comparison<CGAL::Polyhedron_3<Kernel>> pc = resize_comparison(p, p, options);
  REQUIRE(pc);
  CHECK(pc.picture.offset_axis == 2);
  const CGAL::Bbox_3 stretched = CGAL::Polygon_mesh_processing::bbox(pc.simple_scaling);
  CHECK(stretched.xmax() - stretched.xmin() == Approx(12.0));
}

TEST_CASE("A texture comparison is seen from the texture's side", "[resizing]") {
  Mesh plate; // 4 x 2 in the plane z = 0, facing +z
  make_plate(plate, 4.0, 2.0, 10);
  auto all = get(CGAL::dynamic_vertex_property_t<bool>(), plate);
  for (auto v : vertices(plate))
    put(all, v, true);
  const Comparison_scene up = texture_comparison_scene(plate, {mesh_state(plate)}, plate, all);
  INFO("eye " << up.view.eye_direction[0] << " " << up.view.eye_direction[1] << " "
              << up.view.eye_direction[2]);
  CHECK(up.view.eye_direction[2] > 0.9);
  // Stacked along y, the axis most across the view that is not the plate's longest (x).
  CHECK(up.offset_axis == 1);
  CHECK(up.view.up == std::array<double, 3>{{0, 1, 0}});
  CHECK(up.scene.positions.size() == 2 * num_vertices(plate));

  Mesh flipped = plate;
  CGAL::Polygon_mesh_processing::reverse_face_orientations(flipped);
  auto texture = get(CGAL::dynamic_vertex_property_t<bool>(), flipped);
  for (auto v : vertices(flipped))
    put(texture, v, true);
  const Comparison_scene down =
      texture_comparison_scene(plate, {mesh_state(plate)}, flipped, texture);
  CHECK(down.view.eye_direction[2] < -0.5);
}

TEST_CASE("scale_for_extents gives the bounding box the asked extents", "[resizing]") {
  // The capsule's box is 6 x 2 x 2 (a cylinder of length 4 and radius 1 between two caps, up to
  // the polygon's flattening); asked 9 x 1 x 3, the resized box measures that.
  Mesh m = capsule();
  const CGAL::Bbox_3 before = CGAL::Polygon_mesh_processing::bbox(m);
  const std::array<double, 3> wanted{{9, 1, 3}};
  const Scale_for_extents_result r = scale_for_extents(m, wanted);
  REQUIRE(r);
  Resize_options o;
  o.method = Resize_method::simple;
  o.scale = r.scale;
  REQUIRE(resize(m, o));
  const CGAL::Bbox_3 after = CGAL::Polygon_mesh_processing::bbox(m);
  for (int c = 0; c < 3; ++c) {
    CHECK(r.scale[std::size_t(c)] ==
          Approx(wanted[std::size_t(c)] / (before.max(c) - before.min(c))));
    CHECK(after.max(c) - after.min(c) == Approx(wanted[std::size_t(c)]).epsilon(1e-9));
  }
  // A flat mesh has no factor along its normal, nor does a non-positive extent.
  Mesh plate;
  CGAL::make_grid(3, 3, plate);
  const Scale_for_extents_result flat = scale_for_extents(plate, {{1, 1, 1}});
  CHECK(flat.status == Resize_status::invalid_scale);
  CHECK(flat.message.find("axis 2") != std::string::npos);
  CHECK(scale_for_extents(m, {{1, 0, 1}}).status == Resize_status::invalid_scale);
  CHECK(scale_for_extents(Mesh(), {{1, 1, 1}}).status == Resize_status::empty_mesh);
}
