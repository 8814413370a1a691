// Surface mosaics (Lai, Hu, Martin 2006): layouts on a plane, a creased cube, bordered and genus-2
// meshes and a second FaceGraph model; the Manhattan charts against the analytic distance; the
// quality report and tile cutting against what they must measure; the field and mosaic reports
// (tessera/io) against the results they are built from.
#include "corpus.h"

#include <tessera/fields.h>
#include <tessera/generators.h>
#include <tessera/generators/textures.h>
#include <tessera/io.h>
#include <tessera/io/field_reports.h>
#include <tessera/io/read_vertex_scalars.h>
#include <tessera/io/mosaic_reports.h>
#include <tessera/mosaic.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

using namespace tessera;
using Constraint = Smoothest_field_solver<Mesh>::Constraint;
using Field_map = Mesh::Property_map<Mesh::Vertex_index, Vector_3>;
using Lines = std::vector<Feature_line<Mesh::Halfedge_index>>;

namespace {

// Two triangles per cell of a grid of points numbered row by row, `columns` cells wide.
std::vector<std::array<std::size_t, 3>> grid_triangles(int columns, int rows) {
  std::vector<std::array<std::size_t, 3>> triangles;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      const std::size_t a = std::size_t(j * (columns + 1) + i), b = a + 1,
                        c = a + std::size_t(columns) + 2, d = a + std::size_t(columns) + 1;
      triangles.push_back({{a, b, c}});
      triangles.push_back({{a, c, d}});
    }
  return triangles;
}

// The unit square in z = 0 as an n x n grid of slightly irregular triangles.
Mesh unit_square(int n) {
  std::vector<std::array<double, 3>> points;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const bool inner = i > 0 && j > 0 && i < n && j < n;
      const double dx = inner ? 0.15 * std::sin(3.0 * i + 7.0 * j) : 0,
                   dy = inner ? 0.15 * std::cos(5.0 * i + j) : 0;
      points.push_back({{(i + dx) / n, (j + dy) / n, 0}});
    }
  Mesh m;
  internal::soup_to_mesh(points, grid_triangles(n, n), m);
  return m;
}

Field_map constant_field(Mesh& m, const Vector_3& d) {
  auto field = m.add_property_map<Mesh::Vertex_index, Vector_3>("v:tessera_field").first;
  for (auto v : vertices(m))
    field[v] = d;
  return field;
}

// The smoothest cross field aligned with `lines` (parallel).
Field_map aligned_field(Mesh& m, const Lines& lines, int symmetry = 4) {
  auto field = m.add_property_map<Mesh::Vertex_index, Vector_3>("v:tessera_field").first;
  const auto constraints = feature_alignment_constraints(m, lines, {Feature_alignment::parallel});
  Smoothest_field_options o;
  o.symmetry = symmetry;
  REQUIRE(smoothest_field(m, constraints, field, o));
  return field;
}

// The creases of `m` sharper than 60°.
Lines creases_of(const Mesh& m) {
  Feature_line_options fo;
  fo.creases = true;
  fo.crease_angle_degrees = 60;
  return feature_lines(m, fo);
}

// The angle (degrees) between a unit vector and the coordinate axis nearest to it.
double degrees_off_axes(const std::array<double, 3>& d) {
  const double nearest = std::max({std::abs(d[0]), std::abs(d[1]), std::abs(d[2])});
  return std::acos(std::min(1.0, nearest)) * 180 / std::acos(-1.0);
}

Surface_mosaic_options count_options(std::size_t n, double aspect = 1) {
  Surface_mosaic_options o;
  o.tiles.tile_count = n;
  o.tiles.aspect = aspect;
  return o;
}

} // namespace

TEST_CASE("on a square with a constant field the tiles settle into a grid", "[mosaic]") {
  Mesh m = unit_square(60);
  auto field = constant_field(m, Vector_3(1, 0, 0));
  Feature_line_options fo;
  const Lines border = feature_lines(m, fo);
  REQUIRE(border.size() == 1);
  // 20 x 20 cells of side 1/20: the tile size divides the side.
  Surface_mosaic_options o;
  o.tiles.tile_size = {{0.05 * std::sqrt(0.9), 0}};
  o.teleport_every = 10;
  o.count = Mosaic_count::exact;
  const auto r = surface_mosaic(m, field, border, o);
  REQUIRE(r);
  CHECK(r.tiles.size() == 400);
  const Mosaic_quality q = mosaic_quality(m, r.tiles, field, border);
  INFO("coverage " << q.coverage << ", overlap " << q.overlap << ", rows " << q.row_alignment_median
                   << "/" << q.row_alignment_p95 << ", iterations " << r.stats.iterations);
  // Random positions of the same tiles cover about 0.35 with 0.30 overlap and rows off by 15°.
  CHECK(q.coverage >= 0.85);
  // Issue 13's target; from Lai et al.'s random start the layout kept crowded rows where grains
  // of different phase met (overlap 0.02-0.05).
  CHECK(q.overlap <= 0.01);
  CHECK(q.orientation_error_p95 <= 1.0);
  CHECK(q.row_alignment_median <= 3.0);
  CHECK(q.tiles_crossing_features == 0);
}

TEST_CASE("the Manhattan distance in one chart of a plane is the analytic one",
          "[mosaic][charts]") {
  Mesh m = unit_square(30);
  const double angle = 0.5;
  const Vector_3 x(std::cos(angle), std::sin(angle), 0), y(-std::sin(angle), std::cos(angle), 0);
  auto field = constant_field(m, x);
  const internal::Surface_arrays<Mesh> s(m, get(CGAL::vertex_point, m), {});
  const internal::Face_field<Mesh> ff(s, field, 4);
  Manhattan_chart_options co;
  co.radius = 10;
  co.core_radius = 1;
  Manhattan_chart_atlas<Mesh> atlas(s, ff, co);
  const std::uint32_t seed = 500;
  const Manhattan_chart& chart = atlas.chart(atlas.chart_index_of(seed));
  REQUIRE(chart.faces.size() == s.number_of_faces()); // a plane: nothing stops the chart
  // The chart's u runs along one of the cross's four directions: find which.
  const internal::Surface_point a{seed, {{0.2, 0.3, 0.5}}};
  for (const std::uint32_t f : {std::uint32_t(3), std::uint32_t(977), std::uint32_t(1500)}) {
    const internal::Surface_point b{f, {{0.6, 0.1, 0.3}}};
    const auto ua = chart.uv_at(chart.slot(a.face), a.bary),
               ub = chart.uv_at(chart.slot(b.face), b.bary);
    const internal::Vec3 d = s.position(b) - s.position(a);
    const internal::Vec3 u = chart.frame[chart.slot(seed)][0], v = chart.frame[chart.slot(seed)][1];
    CHECK(ub[0] - ua[0] == Approx(internal::dot(d, u)).margin(1e-9));
    CHECK(ub[1] - ua[1] == Approx(internal::dot(d, v)).margin(1e-9));
    // (u, v) are the field's frame: the analytic distance along x and y of the field.
    const double dx = d[0] * x.x() + d[1] * x.y(), dy = d[0] * y.x() + d[1] * y.y();
    const double analytic = std::sqrt(2.0) * std::max(std::abs(dx), std::abs(dy));
    CHECK(manhattan_distance(ub[0] - ua[0], ub[1] - ua[1]) == Approx(analytic).epsilon(1e-9));
    // Measured along the directions at 45°: the L1 norm there is the same number.
    const double p = (dx + dy) / std::sqrt(2.0), q = (dx - dy) / std::sqrt(2.0);
    CHECK(std::abs(p) + std::abs(q) == Approx(analytic).epsilon(1e-9));
  }
}

TEST_CASE("a chart stops where it would close around a tube thinner than it", "[mosaic][charts]") {
  // An open tube of radius 0.2 (girth 1.25), the field along its axis, charts of radius 0.6:
  // the ball holds whole rings of the tube. A chart that closed around it would be a band whose
  // least-squares (u, v) cannot run the girth around the loop and squeezes the distances around
  // it; cut open where its fronts meet, it unfolds the tube (a prism: developable) exactly.
  Mesh m;
  const std::size_t segments = 40;
  const double r = 0.2, pi = std::acos(-1.0);
  make_tube(m, r, 2.0, segments);
  auto field = constant_field(m, Vector_3(1, 0, 0));
  const internal::Surface_arrays<Mesh> s(m, get(CGAL::vertex_point, m), {});
  const internal::Face_field<Mesh> ff(s, field, 4);
  // Unfolded place of a face's centroid: (x, i·chord) from its corners' indices around the tube.
  const double chord = 2 * r * std::sin(pi / double(segments)), girth = chord * double(segments);
  auto unfolded = [&](std::uint32_t f) {
    std::array<double, 2> c{{0, 0}};
    double first = -1;
    for (int k = 0; k < 3; ++k) {
      const internal::Vec3& p = s.point(f, k);
      double i = std::round(std::atan2(p[2], p[1]) / (2 * pi) * double(segments));
      if (i < 0)
        i += double(segments);
      if (first < 0)
        first = i;
      if (i - first > double(segments) / 2)
        i -= double(segments);
      if (first - i > double(segments) / 2)
        i += double(segments);
      c[0] += p[0] / 3, c[1] += i * chord / 3;
    }
    return c;
  };
  for (const double tolerance : {0.0, 0.2}) {
    Manhattan_chart_options co;
    co.radius = 0.6;
    co.core_radius = 0.1;
    co.seam_tolerance = tolerance;
    Manhattan_chart_atlas<Mesh> atlas(s, ff, co);
    const std::uint32_t seed = std::uint32_t(s.number_of_faces() / 2);
    const Manhattan_chart& chart = atlas.chart(atlas.chart_index_of(seed));
    const auto a = chart.uv_at(chart.slot(seed), {{1.0 / 3, 1.0 / 3, 1.0 / 3}});
    const auto pa = unfolded(seed);
    // Each face's distance in the chart against the unfolded tube's, the short or the long way
    // around (where the fronts met is not quite opposite the seed); near the seed the short one.
    double worst = 0, worst_near = 0;
    for (std::uint32_t slot = 0; slot < chart.faces.size(); ++slot) {
      const auto b = chart.uv_at(slot, {{1.0 / 3, 1.0 / 3, 1.0 / 3}});
      const auto pb = unfolded(chart.faces[slot]);
      const double around = std::abs(pb[1] - pa[1]), along = pb[0] - pa[0];
      const double shorter = std::hypot(along, std::min(around, girth - around)),
                   longer = std::hypot(along, std::max(around, girth - around));
      const double in_chart = std::hypot(b[0] - a[0], b[1] - a[1]);
      worst = std::max(worst, std::min(std::abs(in_chart - shorter), std::abs(in_chart - longer)));
      if (shorter < girth / 4)
        worst_near = std::max(worst_near, std::abs(in_chart - shorter));
    }
    INFO("seam tolerance " << tolerance << ": " << chart.faces.size()
                           << " faces, worst distance error " << worst
                           << ", within a quarter girth " << worst_near << " (girth " << girth
                           << ")");
    if (tolerance > 0) {
      CHECK(worst < 1e-6);
      CHECK(worst_near < 1e-6);
    } else {
      CHECK(worst > 0.05 * girth); // the closed band: squeezed
    }
  }
}

TEST_CASE("on a creased cube every tile lies on one side, along its edges", "[mosaic][features]") {
  Mesh m = test::load("cube-meshed.off");
  const Lines creases = creases_of(m);
  REQUIRE(creases.size() == 12);
  auto field = aligned_field(m, creases);
  Surface_mosaic_options o = count_options(600);
  o.teleport_every = 10;
  const auto r = surface_mosaic(m, field, creases, o);
  REQUIRE(r);
  CHECK(r.stats.regions == 6);
  const Mosaic_quality q = mosaic_quality(m, r.tiles, field, creases);
  INFO("coverage " << q.coverage << ", overlap " << q.overlap);
  CHECK(q.tiles_crossing_features == 0);
  CHECK(q.coverage >= 0.8);
  std::vector<double> angles;
  for (const auto& t : r.tiles) {
    // The cube's sides are axis-aligned: a tile's normal is an axis, its x axis another.
    const double nmax =
        std::max({std::abs(t.normal[0]), std::abs(t.normal[1]), std::abs(t.normal[2])});
    CHECK(nmax > 1 - 1e-9);
    angles.push_back(degrees_off_axes(t.x_axis));
    // All four corners on the cube, [-1, 1]^3.
    for (const auto& c : tile_polygon(t))
      for (int k = 0; k < 3; ++k)
        CHECK(std::abs(c[k]) <= 1 + 1e-9);
  }
  // Tiles follow the field, which runs along the edges inside the sides and turns only next to the
  // corners (its eight +1/4 singularities). (Before the fields module read angles through the
  // vertices' fans, a crease vertex measured the constraint's angle in its averaged tangent plane,
  // tilted 45° from both sides: a median 1.6° and at most 5.9° off the edges here; now 0.002° and
  // 0.23°.)
  std::sort(angles.begin(), angles.end());
  INFO("angle to the cube's edges: median " << angles[angles.size() / 2] << "°, 95th percentile "
                                            << angles[angles.size() * 95 / 100] << "°, largest "
                                            << angles.back() << "°");
  CHECK(angles[angles.size() / 2] < 0.1);
  CHECK(angles[angles.size() * 95 / 100] < 0.5);
  CHECK(angles.back() < 2.0);
}

TEST_CASE("clearing the cube's creases lays no tile over another", "[mosaic][features]") {
  // Tiles moved off a crease by as much as the line asked (up to twice their reach) landed on
  // their neighbours, and the walls kept tiles trimmed beside a crease a whole cell from it,
  // pushing them back over the next tile at every pass: the command's cube at 1000 tiles kept
  // 0.8 % of its area under two tiles, oblong 1 %. Now a move is taken only where the tile fits,
  // and trimmed tiles are walled at their own size.
  Mesh m = test::load("cube-meshed.off");
  const Lines creases = creases_of(m);
  auto field = aligned_field(m, creases);
  for (const unsigned seed : {1u, 2u}) {
    Surface_mosaic_options o = count_options(1000);
    o.seed = seed;
    const auto r = surface_mosaic(m, field, creases, o);
    REQUIRE(r);
    const Mosaic_quality q = mosaic_quality(m, r.tiles, field, creases);
    INFO("seed " << seed << ": " << r.tiles.size() << " tiles, coverage " << q.coverage
                 << ", overlap " << q.overlap << "; moved " << r.stats.moved_off_features
                 << ", cut " << r.stats.cut_at_features << ", left out "
                 << r.stats.removed_at_features);
    CHECK(q.tiles_crossing_features == 0);
    CHECK(q.overlap <= 0.001);
    CHECK(q.coverage >= 0.88);
    CHECK(std::abs(double(r.tiles.size()) - 1000.0) <= 100.0);
  }
}

// A box of 12 triangles, outward, centred at the origin: a square bottom of half side `bottom` at
// z = -half_height, a square top of half side `top` at z = half_height.
Mesh box_of_triangles(double bottom, double top, double half_height) {
  std::vector<std::array<double, 3>> points;
  for (int i = 0; i < 8; ++i) {
    const double r = i & 4 ? top : bottom;
    points.push_back({{i & 1 ? r : -r, i & 2 ? r : -r, i & 4 ? half_height : -half_height}});
  }
  Mesh m;
  internal::soup_to_mesh(points,
                         {{{0, 2, 3}},
                          {{0, 3, 1}},
                          {{4, 5, 7}},
                          {{4, 7, 6}},
                          {{0, 1, 5}},
                          {{0, 5, 4}},
                          {{2, 6, 7}},
                          {{2, 7, 3}},
                          {{0, 4, 6}},
                          {{0, 6, 2}},
                          {{1, 3, 7}},
                          {{1, 7, 5}}},
                         m);
  return m;
}

// The cube [-1, 1]^3 as 12 triangles.
Mesh coarse_cube() {
  return box_of_triangles(1, 1, 1);
}

TEST_CASE("a coarse cube is split for the field, its creases and values carried",
          "[mosaic][refine]") {
  Mesh m = coarse_cube();
  Lines creases = creases_of(m);
  REQUIRE(creases.size() == 12);
  std::vector<std::pair<Mesh::Vertex_index, Mesh::Vertex_index>> ends;
  for (const auto& l : creases)
    ends.push_back({source(l.halfedges.front(), m), target(l.halfedges.back(), m)});
  std::map<Mesh::Face_index, Kernel::Triangle_3> coarse;
  for (auto f : faces(m)) {
    const auto h = halfedge(f, m);
    coarse[f] = {m.point(source(h, m)), m.point(target(h, m)), m.point(target(next(h, m), m))};
  }
  auto value = m.add_property_map<Mesh::Vertex_index, double>("v:value").first;
  auto linear = [](const Point_3& p) { return p.x() + 2 * p.y() - 3 * p.z(); };
  for (auto v : vertices(m))
    value[v] = linear(m.point(v));

  const auto r = refine_coarse_mesh(m, Coarse_mesh_options{0.6, 0.3}, creases);
  REQUIRE(r.refined);
  CHECK(r.vertices_before == 8);
  CHECK(num_vertices(m) == 8 + r.vertices_added);
  CHECK(r.longest_edge_before == Approx(std::sqrt(8.0)));
  CHECK(r.max_edge_length <= 0.3);
  CHECK(CGAL::is_valid_polygon_mesh(m));
  CHECK(int(num_vertices(m)) - int(num_edges(m)) + int(num_faces(m)) == 2);
  CHECK(CGAL::Polygon_mesh_processing::area(m) == Approx(24).epsilon(1e-12));
  for (auto e : edges(m))
    CHECK(std::sqrt(CGAL::squared_distance(m.point(source(e, m)), m.point(target(e, m)))) <= 0.3);
  // Every face lies in the coarse face it names.
  for (auto f : faces(m)) {
    const auto h = halfedge(f, m);
    const Point_3 c = CGAL::centroid(m.point(source(h, m)), m.point(target(h, m)),
                                     m.point(target(next(h, m), m)));
    CHECK(CGAL::squared_distance(c, coarse.at(r.coarse_face(f))) < 1e-20);
  }
  // Values interpolated linearly: a linear function is kept exactly.
  r.interpolate(value);
  for (auto v : vertices(m))
    CHECK(value[v] == Approx(linear(m.point(v))).margin(1e-12));
  // Each crease is a chain from the same corner to the same corner, two long, along 90° edges, and
  // the carried lines hold every crease edge of the split mesh.
  std::size_t carried = 0;
  for (std::size_t l = 0; l < creases.size(); ++l) {
    const auto& hs = creases[l].halfedges;
    REQUIRE(hs.size() >= 7);
    CHECK(source(hs.front(), m) == ends[l].first);
    CHECK(target(hs.back(), m) == ends[l].second);
    double length = 0;
    for (std::size_t k = 0; k < hs.size(); ++k) {
      if (k > 0)
        CHECK(source(hs[k], m) == target(hs[k - 1], m));
      length +=
          std::sqrt(CGAL::squared_distance(m.point(source(hs[k], m)), m.point(target(hs[k], m))));
      const Vector_3 a = CGAL::Polygon_mesh_processing::compute_face_normal(face(hs[k], m), m),
                     b = CGAL::Polygon_mesh_processing::compute_face_normal(
                         face(opposite(hs[k], m), m), m);
      CHECK(std::abs(a * b) < 1e-12);
    }
    CHECK(length == Approx(2).epsilon(1e-12));
    carried += hs.size();
  }
  std::size_t found = 0;
  for (const auto& l : creases_of(m))
    found += l.halfedges.size();
  CHECK(carried == found);

  // The same on Polyhedron_3: the surface and the lines come through alike.
  using Polyhedron = CGAL::Polyhedron_3<Kernel, CGAL::Polyhedron_items_with_id_3>;
  Polyhedron poly;
  CGAL::copy_face_graph(coarse_cube(), poly);
  Feature_line_options fo;
  fo.creases = true;
  auto poly_lines = feature_lines(poly, fo);
  REQUIRE(poly_lines.size() == 12);
  const auto pr = refine_coarse_mesh(poly, Coarse_mesh_options{0.6, 0.3}, poly_lines);
  REQUIRE(pr.refined);
  CHECK(pr.max_edge_length <= 0.3);
  CHECK(CGAL::is_valid_polygon_mesh(poly));
  CHECK(CGAL::Polygon_mesh_processing::area(poly) == Approx(24).epsilon(1e-12));
  for (const auto& l : poly_lines) {
    double length = 0;
    for (auto h : l.halfedges)
      length +=
          std::sqrt(CGAL::squared_distance(source(h, poly)->point(), target(h, poly)->point()));
    CHECK(length == Approx(2).epsilon(1e-12));
  }

  // The field on the split cube follows its edges, and so do the tiles.
  auto field = aligned_field(m, creases);
  const auto mosaic = surface_mosaic(m, field, creases, count_options(600));
  REQUIRE(mosaic);
  const Mosaic_quality q = mosaic_quality(m, mosaic.tiles, field, creases);
  INFO("coverage " << q.coverage << ", course drift median " << q.course_drift_median);
  CHECK(q.tiles_crossing_features == 0);
  CHECK(q.coverage >= 0.85);
  std::vector<double> angles;
  for (const auto& t : mosaic.tiles)
    angles.push_back(degrees_off_axes(t.x_axis));
  std::sort(angles.begin(), angles.end());
  INFO("angle to the cube's edges: median " << angles[angles.size() / 2] << "°");
  CHECK(angles[angles.size() / 2] < 2.0);
}

TEST_CASE("coarse-mesh options follow the tiles' spacing on the surface, or leave it as read",
          "[mosaic][refine]") {
  Mesh m = coarse_cube(); // 2 x 2 x 2: area 24
  Mosaic_tile_size tiles;
  tiles.tile_count = 600; // a spacing of sqrt(24 / 600) = 0.2
  const Coarse_mesh_options o = coarse_mesh_options(m, tiles);
  CHECK(o.coarse_edge_length == Approx(4 * 0.2));
  CHECK(o.max_edge_length == Approx(2 * 0.2));
  // Rectangles: the spacing along the shorter side, sqrt(A / N) / sqrt(aspect).
  tiles.aspect = 4;
  CHECK(coarse_mesh_options(m, tiles).max_edge_length == Approx(2 * 0.2 / 2));
  // No layout (neither a count nor a size): nothing is remeshed, the lines stay as they were.
  tiles = Mosaic_tile_size{};
  Lines creases = creases_of(m);
  const Lines as_read = creases;
  const std::size_t faces_before = num_faces(m);
  const auto r = refine_coarse_mesh(m, coarse_mesh_options(m, tiles), creases);
  CHECK_FALSE(r.refined);
  CHECK(num_faces(m) == faces_before);
  // Each line keeps its halfedges, in order (a refinement would split them into more).
  REQUIRE(creases.size() == as_read.size());
  for (std::size_t i = 0; i < creases.size(); ++i)
    CHECK(creases[i].halfedges == as_read[i].halfedges);
}

TEST_CASE("after the optimization no tile crosses fandisk's creases", "[mosaic][features]") {
  Mesh m = test::load("fandisk.off");
  const Lines creases = creases_of(m);
  auto field = aligned_field(m, creases);
  Surface_mosaic<Mesh> mosaic(m, field, creases, count_options(1000));
  REQUIRE(mosaic.status() == Mosaic_status::ok);
  mosaic.iterate(20);
  // The walls keep tile centres off the creases; corners still reach over where the field turns
  // and at the free ends of creases inside a region.
  const std::size_t before =
      mosaic_quality(m, mosaic.tiles(), field, creases).tiles_crossing_features;
  REQUIRE(before > 0);
  const std::size_t tiles = mosaic.number_of_tiles();
  const std::size_t filled = mosaic.stats().filled_patches;
  mosaic.clear_features();
  const auto& st = mosaic.stats();
  INFO(before << " crossing; moved " << st.moved_off_features << ", cut " << st.cut_at_features
              << ", removed " << st.removed_at_features);
  CHECK(mosaic_quality(m, mosaic.tiles(), field, creases).tiles_crossing_features == 0);
  CHECK(st.moved_off_features + st.cut_at_features + st.removed_at_features >= before);
  // Tiles left out, and bare patches filled after (off the lines too).
  CHECK(mosaic.number_of_tiles() == tiles - st.removed_at_features + (st.filled_patches - filled));
  CHECK(st.removed_at_features <= before);
}

TEST_CASE("energy falls as the layout settles, and every tile stays on the surface", "[mosaic]") {
  Mesh m = test::load("eight.off");
  auto field = aligned_field(m, {});
  // From Lai et al.'s random start (error diffusion), the descent halves the energy at least.
  // Both starts hold exactly N tiles: the energy sums over pairs, so it is compared at one count
  // (the default count lets the lattice aim a little over N).
  Surface_mosaic_options o = count_options(800);
  o.count = Mosaic_count::exact;
  o.initialization = Mosaic_initialization::error_diffusion;
  Surface_mosaic<Mesh> random_start(m, field, {}, o);
  REQUIRE(random_start.status() == Mosaic_status::ok);
  random_start.iterate(60);
  const auto& r = random_start.stats().energy;
  REQUIRE(r.size() >= 10);
  CHECK(r.back() < 0.5 * r.front());
  // The lattice start begins below where the random start ends, and falls from there.
  o.initialization = Mosaic_initialization::lattice;
  Surface_mosaic<Mesh> mosaic(m, field, {}, o);
  REQUIRE(mosaic.status() == Mosaic_status::ok);
  mosaic.iterate(60);
  const auto& e = mosaic.stats().energy;
  REQUIRE(e.size() >= 2);
  INFO("random start " << r.front() << " -> " << r.back() << ", lattice " << e.front() << " -> "
                       << e.back());
  CHECK(e.back() < e.front());
  CHECK(e.back() < r.back());
  std::size_t rises = 0;
  for (std::size_t k = 1; k < r.size(); ++k)
    rises += r[k] > r[k - 1] * 1.02;
  CHECK(rises == 0);
  using Tree =
      CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;
  Tree tree(faces(m).first, faces(m).second, m);
  for (const auto& t : mosaic.tiles()) {
    const Point_3 c(t.center[0], t.center[1], t.center[2]);
    CHECK(tree.squared_distance(c) < 1e-20);
    CHECK(t.barycentric[0] >= 0);
    CHECK(std::abs(t.barycentric[0] + t.barycentric[1] + t.barycentric[2] - 1) < 1e-12);
  }
}

TEST_CASE("the optimization stops at the first iteration or window of 5 below the tolerance",
          "[mosaic]") {
  // Each window's net move per iteration is at most the mean of its iterations' displacements (a
  // chord is no longer than the steps it spans; no size field, no teleports), and the run stops
  // at the first iteration where either figure falls below the tolerance.
  Mesh m = test::load("eight.off");
  auto field = aligned_field(m, {});
  const Surface_mosaic_options o = count_options(800);
  Surface_mosaic<Mesh> mosaic(m, field, {}, o);
  REQUIRE(mosaic.status() == Mosaic_status::ok);
  mosaic.iterate(o.max_iterations);
  const auto& st = mosaic.stats();
  const auto& d = st.mean_displacement;
  const auto& net = st.net_displacement;
  REQUIRE(st.converged);
  REQUIRE(d.size() == st.iterations);
  REQUIRE(net.size() == st.iterations / 5);
  for (std::size_t w = 0; w < net.size(); ++w) {
    double mean = 0;
    for (std::size_t k = 5 * w; k < 5 * w + 5; ++k)
      mean += d[k] / 5;
    CHECK(net[w] <= mean * (1 + 1e-9));
  }
  for (std::size_t k = 0; k + 1 < d.size(); ++k)
    CHECK(d[k] >= o.tolerance);
  for (std::size_t w = 0; w + 1 < net.size() || (w < net.size() && d.size() % 5 != 0); ++w)
    CHECK(net[w] >= o.tolerance);
  const bool window_ended = d.size() % 5 == 0;
  CHECK((d.back() < o.tolerance || (window_ended && net.back() < o.tolerance)));
}

TEST_CASE("with at most N tiles, the eight's mosaic overlaps by less than 1 percent", "[mosaic]") {
  // The paper's figure: the genus-2 eight with 3000 tiles.
  Mesh m = test::load("eight.off");
  auto field = aligned_field(m, {});
  const std::size_t n = 3000;
  Surface_mosaic_options o = count_options(n);
  o.teleport_every = 10;
  o.count = Mosaic_count::at_most;
  const auto r = surface_mosaic(m, field, {}, o);
  REQUIRE(r);
  const Mosaic_quality q = mosaic_quality(m, r.tiles, field, {});
  INFO(r.tiles.size() << " tiles, coverage " << q.coverage << ", overlap " << q.overlap);
  CHECK(r.tiles.size() <= n);
  CHECK(r.tiles.size() >= 0.85 * double(n));
  CHECK(q.overlap <= 0.01);
  CHECK(q.coverage >= 0.8);
  // With exactly N, the same surface holds the extra tiles by crowding them.
  o.count = Mosaic_count::exact;
  const auto exact = surface_mosaic(m, field, {}, o);
  REQUIRE(exact.tiles.size() == n);
  CHECK(mosaic_quality(m, exact.tiles, field, {}).overlap > q.overlap);
}

namespace {
// Fandisk with its creases as feature lines and a field aligned with them (built in place: the
// field is a property of `m`).
struct Creased_fandisk {
  Mesh m = test::load("fandisk.off");
  Lines creases = creases_of(m);
  Field_map field = aligned_field(m, creases);
};
} // namespace

TEST_CASE("the tiles filled into bare patches keep the count within N or the allowed margin",
          "[mosaic][features]") {
  // Fandisk's bands between creases leave partial cells along every crease, and the filling puts
  // a smaller tile in each: unbounded, it lays more tiles than N. The filling takes the widest
  // patches first and stops at N with at_most, at most_over_count over N with about.
  Creased_fandisk f;
  const std::size_t n = 1000;
  Surface_mosaic_options o = count_options(n);
  o.most_over_count = 1; // no limit within reach
  const auto free = surface_mosaic(f.m, f.field, f.creases, o);
  REQUIRE(free);
  INFO("unbounded: " << free.tiles.size() << " tiles, " << free.stats.filled_patches
                     << " filled in");
  REQUIRE(free.tiles.size() > n + 10);
  REQUIRE(free.stats.filled_patches > 0);
  o.most_over_count = 0.01;
  const auto about = surface_mosaic(f.m, f.field, f.creases, o);
  REQUIRE(about);
  INFO("about N, 1 % over at most: " << about.tiles.size() << " tiles, "
                                     << about.stats.filled_patches << " filled in");
  CHECK(about.tiles.size() <= std::size_t(1.01 * double(n)));
  CHECK(about.stats.filled_patches < free.stats.filled_patches);
  o.count = Mosaic_count::at_most;
  const auto most = surface_mosaic(f.m, f.field, f.creases, o);
  REQUIRE(most);
  INFO("at most N: " << most.tiles.size() << " tiles, " << most.stats.filled_patches
                     << " filled in");
  CHECK(most.tiles.size() <= n);
  CHECK(mosaic_quality(f.m, most.tiles, f.field, f.creases).coverage >= 0.8);
  o.count = Mosaic_count::about;
  o.most_over_count = -0.5;
  CHECK(surface_mosaic(f.m, f.field, f.creases, o).status == Mosaic_status::invalid_options);
}

TEST_CASE("with at most N tiles, overlaps go into the grout and crowded tiles are left out",
          "[mosaic][features]") {
  // Fandisk's narrow bands between creases do not take whole rows: after the optimization tiles
  // overlap their neighbours there, and laying exactly N leaves no room to undo it.
  Creased_fandisk fandisk;
  Mesh& m = fandisk.m;
  const Lines& creases = fandisk.creases;
  const Field_map field = fandisk.field;
  const std::size_t n = 1000;
  Surface_mosaic_options o = count_options(n);
  o.count = Mosaic_count::at_most;
  // The rows grown from one seed per region meet out of phase: overlaps to undo.
  o.initialization = Mosaic_initialization::lattice;
  Surface_mosaic<Mesh> mosaic(m, field, creases, o);
  REQUIRE(mosaic.status() == Mosaic_status::ok);
  mosaic.iterate(o.max_iterations);
  const std::size_t laid = mosaic.number_of_tiles();
  const Mosaic_quality before = mosaic_quality(m, mosaic.tiles(), field, creases);
  REQUIRE(before.overlap > 0.015);
  CHECK(mosaic.separate_tiles() > 0);
  mosaic.clear_features();
  const auto& st = mosaic.stats();
  const Mosaic_quality after = mosaic_quality(m, mosaic.tiles(), field, creases);
  INFO("overlap " << before.overlap << " -> " << after.overlap << ", coverage " << before.coverage
                  << " -> " << after.coverage << ", " << st.left_out_crowded << " left out, "
                  << st.close_pairs << " close pairs");
  CHECK(after.overlap <= 0.01);
  CHECK(after.coverage >= 0.8);
  CHECK(after.tiles_crossing_features == 0);
  CHECK(st.left_out_crowded > 0);
  CHECK(mosaic.number_of_tiles() ==
        laid - st.left_out_crowded - st.removed_at_features + st.filled_patches);
  CHECK(double(mosaic.number_of_tiles()) >= 0.85 * double(n));
  // The separation renumbers the neighbour lists as it leaves tiles out, rather than querying
  // them again: an optimization stopped early (crowded, so tiles are left out) goes on from them
  // with every pair energy still counted (each tile has neighbours within its reach, so the
  // energy cannot fall to nothing) and every tile on the surface.
  Surface_mosaic<Mesh> early(m, field, creases, o);
  early.iterate(5);
  early.separate_tiles();
  REQUIRE(early.stats().left_out_crowded > 0);
  const std::size_t kept = early.number_of_tiles();
  const double settled = early.stats().energy.back();
  REQUIRE(early.iterate(2) == 2);
  CHECK(early.number_of_tiles() == kept);
  CHECK(std::isfinite(early.stats().energy.back()));
  CHECK(early.stats().energy.back() > 0.5 * settled);
  for (const auto& t : early.tiles())
    CHECK(std::abs(t.barycentric[0] + t.barycentric[1] + t.barycentric[2] - 1) < 1e-12);
  // With exactly N tiles nothing is pushed or left out.
  o.count = Mosaic_count::exact;
  Surface_mosaic<Mesh> exact(m, field, creases, o);
  exact.iterate(5);
  CHECK(exact.separate_tiles() == 0);
  CHECK(exact.number_of_tiles() == n);
}

TEST_CASE("the position field puts the tiles of a square on one lattice along the field",
          "[mosaic][position_field]") {
  Mesh m = unit_square(60);
  // Turned against the border, so that the border cuts the lattice at an angle.
  const double angle = 0.3;
  auto field = constant_field(m, Vector_3(std::cos(angle), std::sin(angle), 0));
  Feature_line_options fo;
  const Lines border = feature_lines(m, fo);
  const std::size_t n = 400;
  Surface_mosaic_options o = count_options(n);
  o.initialization = Mosaic_initialization::position_field;
  o.max_iterations = 0; // the lattice as laid
  Surface_mosaic<Mesh> mosaic(m, field, border, o);
  REQUIRE(mosaic.status() == Mosaic_status::ok);
  CHECK(mosaic.stats().lattice_points > 0);
  const auto tiles = mosaic.tiles();
  const Mosaic_quality q = mosaic_quality(m, tiles, field, border);
  INFO(tiles.size() << " tiles (" << mosaic.stats().lattice_points << " lattice points), coverage "
                    << q.coverage << ", overlap " << q.overlap << ", rows "
                    << q.row_alignment_median << "/" << q.row_alignment_p95 << ", drift "
                    << q.course_drift_median << ", gap " << q.largest_gap);
  // Every lattice point of the square is a tile: as many as cells, but for the border's cut.
  CHECK(std::abs(double(tiles.size()) - double(n)) <= 0.1 * double(n));
  // A plane loses no rows: laid first at 0.965 of the spacing (1/0.965² = 1.07 N), it is solved
  // again with its rows apart to aim at 1.02 N.
  CHECK(double(mosaic.stats().lattice_points) <= 1.04 * double(n));
  // One lattice: every tile's nearest neighbour along an axis, all axes parallel.
  CHECK(q.row_alignment_p95 <= 1.0);
  CHECK(q.course_drift_p95 <= 0.5);
  CHECK(q.overlap <= 0.005);
  CHECK(q.coverage >= 0.85);
  CHECK(q.largest_gap <= 1.5);
  // Neighbours one cell apart (√(A/N)) along the field: count pairs at that distance.
  const double cell = std::sqrt(1.0 / double(n));
  std::size_t one_cell = 0;
  for (const auto& a : tiles)
    for (const auto& b : tiles) {
      const double dx = b.center[0] - a.center[0], dy = b.center[1] - a.center[1];
      const double along = dx * std::cos(angle) + dy * std::sin(angle),
                   across = -dx * std::sin(angle) + dy * std::cos(angle);
      one_cell += std::abs(along - cell) < 0.02 * cell && std::abs(across) < 0.02 * cell;
    }
  // A tile's neighbour one cell along the field exists for all tiles but those along the border
  // (about 6 % of them at this angle), those in holes filled after the lattice, and those along
  // the defect where the coarse levels' phases met (a column or two).
  CHECK(double(one_cell) >= 0.75 * double(tiles.size()));
  // The seed moves the lattice (its phase), and equal seeds give equal layouts.
  o.seed = 2;
  Surface_mosaic<Mesh> other(m, field, border, o);
  CHECK(other.tiles()[0].center != tiles[0].center);
  o.seed = 1;
  CHECK(Surface_mosaic<Mesh>(m, field, border, o).tiles()[0].center == tiles[0].center);
}

TEST_CASE("a position field short of the count is solved again with its rows closer",
          "[mosaic][position_field]") {
  // The eight's lattice loses rows where lattices meet (genus 2, its field's singularities).
  Mesh m = test::load("eight.off");
  auto field = aligned_field(m, {});
  const std::size_t n = 1500;
  Surface_mosaic_options o = count_options(n);
  o.initialization = Mosaic_initialization::position_field;
  o.max_iterations = 0; // the lattice as laid
  o.separation_passes = 0;
  o.count = Mosaic_count::at_most; // never solved again
  Surface_mosaic<Mesh> once(m, field, {}, o);
  o.count = Mosaic_count::about;
  Surface_mosaic<Mesh> again(m, field, {}, o);
  REQUIRE(once.status() == Mosaic_status::ok);
  REQUIRE(again.status() == Mosaic_status::ok);
  const double first = double(once.stats().lattice_points),
               second = double(again.stats().lattice_points);
  INFO("lattice points: " << first << " at the spacing, " << second << " aimed at 1.02 N");
  // Short of N at the spacing, so laid at 0.965 of it (the closest allowed) and kept: about
  // 1/0.965² = 1.074 times the points, and still within 10 % of N.
  REQUIRE(first < 1.02 * double(n));
  CHECK(second >= 1.05 * first);
  CHECK(second <= 1.1 * double(n));
  // Equal seeds, equal lattices: the second solve starts from the same phase.
  Surface_mosaic<Mesh> same(m, field, {}, o);
  CHECK(same.tiles()[0].center == again.tiles()[0].center);
}

TEST_CASE("with the defaults a torus's mosaic keeps its count and its rows",
          "[mosaic][position_field]") {
  Mesh m;
  make_torus(m, 1.0, 0.4, 120, 48);
  auto field = aligned_field(m, {});
  const std::size_t n = 800;
  const auto r = surface_mosaic(m, field, {}, count_options(n));
  REQUIRE(r);
  const Mosaic_quality q = mosaic_quality(m, r.tiles, field, {});
  INFO(r.tiles.size() << " tiles (" << r.stats.lattice_points << " on the lattice), coverage "
                      << q.coverage << ", overlap " << q.overlap << ", drift "
                      << q.course_drift_median << ", rows " << q.row_alignment_median << ", gap "
                      << q.largest_gap);
  // Issue 35's figures for any mesh.
  CHECK(std::abs(double(r.tiles.size()) - double(n)) <= 0.1 * double(n));
  CHECK(q.coverage >= 0.85);
  CHECK(q.overlap <= 0.01);
  CHECK(q.course_drift_median <= 3.0);
  CHECK(q.largest_gap <= 2.0);
  CHECK(q.row_alignment_median <= 5.0);
  // Lai et al.'s random start on the same surface leaves the tiles out of rows.
  Surface_mosaic_options random = count_options(n);
  random.initialization = Mosaic_initialization::error_diffusion;
  random.count = Mosaic_count::exact;
  const auto rr = surface_mosaic(m, field, {}, random);
  CHECK(mosaic_quality(m, rr.tiles, field, {}).row_alignment_median > q.row_alignment_median);
}

TEST_CASE("on a tube five and a half tiles around the defaults still cover it", "[mosaic]") {
  // A thin torus (tube radius 0.2 on a circle of radius 2) with 5.5 tiles around its girth: rows
  // around it do not close, the charts hold whole rings of it and each tile covers more of the
  // curved surface than its side. Issue 35's figures for thin parts, but the count within 10 %.
  Mesh m;
  make_torus(m, 2.0, 0.2, 400, 32);
  auto field = aligned_field(m, {});
  const double pi = std::acos(-1.0), girth = 2 * pi * 0.2, spacing = girth / 5.5;
  const std::size_t n = std::size_t(std::lround(4 * pi * pi * 2.0 * 0.2 / (spacing * spacing)));
  const auto r = surface_mosaic(m, field, {}, count_options(n));
  REQUIRE(r);
  const Mosaic_quality q = mosaic_quality(m, r.tiles, field, {});
  INFO(r.tiles.size() << " of " << n << " tiles, coverage " << q.coverage << ", overlap "
                      << q.overlap << ", drift " << q.course_drift_median << ", gap "
                      << q.largest_gap);
  CHECK(std::abs(double(r.tiles.size()) - double(n)) <= 0.1 * double(n));
  CHECK(q.coverage >= 0.82);
  CHECK(q.overlap <= 0.01);
  CHECK(q.largest_gap <= 2.0);
}

TEST_CASE("tiles that no move clears of a line are cut to it, one side kept",
          "[mosaic][features]") {
  // A strip 0.7 spacings wide between its two long borders (feature lines): no tile fits across
  // it, so every tile's rectangle crosses a border and no move along its axes clears both; they
  // were all left out before (no tile at all). Cut to the strip, each keeps its length along it
  // and loses the least across it that leaves half a grout to both borders.
  const int columns = 40, rows = 3;
  const double length = 1.0, width = 0.07;
  std::vector<std::array<double, 3>> points;
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i <= columns; ++i)
      points.push_back({{length * i / columns, width * j / rows, 0}});
  Mesh m;
  internal::soup_to_mesh(points, grid_triangles(columns, rows), m);
  const Lines borders = feature_lines(m, Feature_line_options{});
  REQUIRE(!borders.empty());
  auto field = constant_field(m, Vector_3(1, 0, 0));
  const auto r = surface_mosaic(m, field, borders, count_options(7)); // spacing 0.1
  REQUIRE(r);
  const double spacing = r.layout.spacing, side = r.layout.tile_size[1];
  REQUIRE(spacing == Approx(0.1).epsilon(0.01));
  const double margin = 0.5 * (spacing - side);
  INFO(r.tiles.size() << " tiles, " << r.stats.cut_at_features << " cut, "
                      << r.stats.removed_at_features << " left out");
  CHECK(r.stats.cut_at_features >= 5);
  CHECK(r.tiles.size() >= 7);
  std::size_t whole_length = 0;
  for (const auto& t : r.tiles) {
    // Across the strip: within it less half a grout on each side, and no thinner than
    // min_tile_scale of the size; along it the whole side.
    const bool along_x = std::abs(t.x_axis[0]) > 0.99;
    const double across = along_x ? t.size[1] : t.size[0], along = along_x ? t.size[0] : t.size[1];
    INFO("tile at " << t.center[0] << " " << t.center[1] << " x axis " << t.x_axis[0] << " "
                    << t.x_axis[1] << " size " << t.size[0] << " " << t.size[1]);
    CHECK(across <= width - 2 * margin + 1e-9);
    CHECK(across >= 0.35 * side - 1e-9);
    // Cut across, not along (tiles filled in smaller where room opened are square).
    CHECK(along >= across - 1e-9);
    whole_length += along == Approx(side).epsilon(0.02) ? 1 : 0;
    CHECK(t.center[1] - 0.5 * across >= margin - 1e-9);
    CHECK(t.center[1] + 0.5 * across <= width - margin + 1e-9);
  }
  CHECK(whole_length >= 4);
  const Mosaic_quality q = mosaic_quality(m, r.tiles, field, borders);
  CHECK(q.tiles_crossing_features == 0);
  CHECK(q.coverage >= 0.5);
}

TEST_CASE("patches that overlap at their seam share its room, stacked sheets do not", "[mosaic]") {
  // Two unit squares as separate components, as CAD exports leave patches: the second starts
  // halfway across the first, a thousandth above it (ALSTOM_TEST4 in CGAL's data is six such
  // patches). Each is a region of its own, so without looking across them both lay tiles over
  // the shared half, and the quality report sees half of every sample there covered twice
  // (overlap about 0.45). Then the same squares stacked a spacing apart: neither takes room from
  // the other, both are tiled whole.
  const auto two_squares = [](double shift_x, double lift_z) {
    const int n = 20;
    std::vector<std::array<double, 3>> points;
    for (int sheet = 0; sheet < 2; ++sheet)
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
          points.push_back({{double(i) / n + sheet * shift_x, double(j) / n, sheet * lift_z}});
    auto triangles = grid_triangles(n, n);
    const std::size_t first = triangles.size(), offset = std::size_t((n + 1) * (n + 1));
    for (std::size_t t = 0; t < first; ++t)
      triangles.push_back(
          {{triangles[t][0] + offset, triangles[t][1] + offset, triangles[t][2] + offset}});
    Mesh m;
    internal::soup_to_mesh(points, triangles, m);
    return m;
  };
  const std::size_t n = 400;
  {
    Mesh m = two_squares(0.5, 1e-3);
    auto field = constant_field(m, Vector_3(1, 0, 0));
    const auto r = surface_mosaic(m, field, {}, count_options(n));
    REQUIRE(r);
    CHECK(r.stats.regions == 2);
    const Mosaic_quality q = mosaic_quality(m, r.tiles, field, {});
    INFO(r.tiles.size() << " tiles, coverage " << q.coverage << ", overlap " << q.overlap);
    CHECK(q.overlap <= 0.01);
    CHECK(q.coverage >= 0.85);
    // One layer over the seam: the union is 3/4 of the two areas, which the count was made for.
    CHECK(double(r.tiles.size()) <= 0.85 * double(n));
  }
  {
    // Each sheet is tiled as a square alone is with half the tiles.
    Mesh one = two_squares(0.0, 0.0);
    CGAL::Polygon_mesh_processing::keep_largest_connected_components(one, 1);
    one.collect_garbage();
    auto one_field = constant_field(one, Vector_3(1, 0, 0));
    const auto alone = surface_mosaic(one, one_field, {}, count_options(n / 2));
    REQUIRE(alone);
    const Mosaic_quality qa = mosaic_quality(one, alone.tiles, one_field, {});
    Mesh m = two_squares(0.0, 0.1); // a spacing is about 0.07 here
    auto field = constant_field(m, Vector_3(1, 0, 0));
    const auto r = surface_mosaic(m, field, {}, count_options(n));
    REQUIRE(r);
    REQUIRE(r.layout.spacing < 0.1);
    const Mosaic_quality q = mosaic_quality(m, r.tiles, field, {});
    INFO(r.tiles.size() << " tiles, coverage " << q.coverage << ", overlap " << q.overlap
                        << "; one square: " << alone.tiles.size() << " tiles, coverage "
                        << qa.coverage);
    CHECK(std::abs(q.coverage - qa.coverage) <= 0.02);
    CHECK(std::abs(double(r.tiles.size()) - 2.0 * double(alone.tiles.size())) <=
          0.05 * double(r.tiles.size()));
    CHECK(q.overlap <= 0.01);
  }
}

TEST_CASE("course drift and the widest bare patch measure what they say", "[mosaic][quality]") {
  Mesh m = unit_square(40);
  auto field = constant_field(m, Vector_3(1, 0, 0));
  // A 20 x 20 grid of tiles at the cell centres; every other column turned by 10°.
  const int k = 20;
  const double cell = 1.0 / k, side = 0.9 * cell;
  std::vector<Mosaic_tile<Mesh::Face_index>> grid;
  const internal::Surface_arrays<Mesh> s(m, get(CGAL::vertex_point, m), {});
  using Tree =
      CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;
  Tree tree(faces(m).first, faces(m).second, m);
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k; ++i) {
      Mosaic_tile<Mesh::Face_index> t;
      t.center = {{(i + 0.5) * cell, (j + 0.5) * cell, 0}};
      const auto hit = tree.closest_point_and_primitive(Point_3(t.center[0], t.center[1], 0));
      t.face = hit.second;
      const internal::Vec3 c{{t.center[0], t.center[1], 0}};
      const auto b = s.barycentric(s.id(t.face), c);
      t.barycentric = {{b[1], b[2], b[0]}};
      t.normal = {{0, 0, 1}};
      const double a = i % 2 == 1 ? 10 * std::acos(-1.0) / 180 : 0;
      t.x_axis = {{std::cos(a), std::sin(a), 0}};
      t.size = {{side, side}};
      grid.push_back(t);
    }
  Mosaic_quality q = mosaic_quality(m, grid, field, {});
  // Each tile's neighbours within 1.5 cells: 2 of its 4 edge neighbours and 4 diagonal ones are
  // in the other column parity (10°), the 2 others in its own (0°): the median is 10°.
  CHECK(q.course_drift_median == Approx(10).margin(0.01));
  CHECK(q.course_drift_p95 == Approx(10).margin(0.01));
  CHECK(q.largest_gap < 0.25); // only grout
  // Take out the tiles whose centres lie within 0.22 of (0.5, 0.5): the bare patch's widest disk,
  // measured by brute force over all remaining tiles on a fine grid, against the report.
  std::vector<Mosaic_tile<Mesh::Face_index>> holed;
  for (const auto& t : grid)
    if (std::hypot(t.center[0] - 0.5, t.center[1] - 0.5) > 0.22)
      holed.push_back(t);
  for (auto& t : holed)
    t.x_axis = {{1, 0, 0}};
  double widest = 0;
  for (int y = 0; y <= 250; ++y)
    for (int x = 0; x <= 250; ++x) {
      const double px = x / 250.0, py = y / 250.0;
      double nearest = 1e9;
      for (const auto& t : holed) {
        const double dx = std::max(0.0, std::abs(px - t.center[0]) - side / 2),
                     dy = std::max(0.0, std::abs(py - t.center[1]) - side / 2);
        nearest = std::min(nearest, std::hypot(dx, dy));
      }
      widest = std::max(widest, 2 * nearest / side);
    }
  q = mosaic_quality(m, holed, field, {});
  INFO("brute force " << widest << ", report " << q.largest_gap);
  REQUIRE(widest > 3);
  CHECK(q.largest_gap == Approx(widest).epsilon(0.08));
  CHECK(q.course_drift_median == 0);
  // The unit of the widest patch is the layout's tile side (the median), not the first tile's: a
  // half-size tile in a corner, first or last, leaves the figures as they were.
  std::vector<Mosaic_tile<Mesh::Face_index>> small_first = holed;
  small_first.front().size = {{side / 2, side / 2}};
  std::vector<Mosaic_tile<Mesh::Face_index>> small_last = small_first;
  std::rotate(small_last.begin(), small_last.begin() + 1, small_last.end());
  const Mosaic_quality first = mosaic_quality(m, small_first, field, {}),
                       last = mosaic_quality(m, small_last, field, {});
  CHECK(first.largest_gap == Approx(q.largest_gap).epsilon(1e-9));
  CHECK(last.largest_gap == Approx(q.largest_gap).epsilon(1e-9));
  CHECK(first.gap_ideal == Approx(q.gap_ideal).epsilon(1e-9));

  // A bare strip along the square's open border (its last column of tiles taken out): the disk
  // ends at the border, where the surface does, so the strip reads its width, a cell and half a
  // grout (1.17 tiles), not twice it as a disk hanging over the border would (2.33).
  std::vector<Mosaic_tile<Mesh::Face_index>> stripped;
  for (const auto& t : grid)
    if (t.center[0] < 1 - cell) {
      stripped.push_back(t);
      stripped.back().x_axis = {{1, 0, 0}};
    }
  q = mosaic_quality(m, stripped, field, {});
  const double strip = (cell + (cell - side) / 2) / side;
  INFO("bare strip: report " << q.largest_gap << ", its width " << strip);
  CHECK(q.largest_gap == Approx(strip).epsilon(0.03));
  CHECK(q.largest_gap_center[0] > 1 - cell);
}

TEST_CASE("a bare band across a crease is measured to the tiles beside it", "[mosaic][quality]") {
  // An L: the unit square in z = 0 (normal +z) folded down along y = 0 into a wall 0.06 high
  // (normal -y), on a regular grid of 0.02. Tiles 0.09 wide on the 0.1 grid of the top, none on
  // the wall. The wall's point farthest from both a tile and its open bottom edge lies between
  // two tiles (0.005 from each along x and y) at the depth z where hypot(0.005, 0.005, z) = 0.06 −
  // z, z = 0.0296: the widest bare disk is 2 · 0.0304 / 0.09 tiles across (a tile across a crease
  // bounds it; the sample's own side has none; the border bounds it below).
  const int n = 50, rows = 53;
  const double h = 0.06, cell = 0.1, side = 0.09;
  std::vector<std::array<double, 3>> points;
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = double(i) / n, t = -h + 0.02 * j;
      points.push_back(t < 0 ? std::array<double, 3>{{x, 0, t}} : std::array<double, 3>{{x, t, 0}});
    }
  Mesh m;
  internal::soup_to_mesh(points, grid_triangles(n, rows), m);
  auto field = constant_field(m, Vector_3(1, 0, 0));
  using Tree =
      CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;
  Tree tree(faces(m).first, faces(m).second, m);
  const internal::Surface_arrays<Mesh> s(m, get(CGAL::vertex_point, m), {});
  std::vector<Mosaic_tile<Mesh::Face_index>> top;
  for (int j = 0; j < 10; ++j)
    for (int i = 0; i < 10; ++i) {
      Mosaic_tile<Mesh::Face_index> t;
      t.center = {{(i + 0.5) * cell, (j + 0.5) * cell, 0}};
      t.face = tree.closest_point_and_primitive(Point_3(t.center[0], t.center[1], 0)).second;
      const auto b = s.barycentric(s.id(t.face), internal::Vec3{{t.center[0], t.center[1], 0}});
      t.barycentric = {{b[1], b[2], b[0]}};
      t.normal = {{0, 0, 1}};
      t.x_axis = {{1, 0, 0}};
      t.size = {{side, side}};
      top.push_back(t);
    }
  const Mosaic_quality q = mosaic_quality(m, top, field, {});
  const double off = 0.005 * 0.005 * 2, depth = (h * h - off) / (2 * h);
  const double expected = 2 * (h - depth) / side;
  INFO("widest bare patch " << q.largest_gap << " at (" << q.largest_gap_center[0] << ", "
                            << q.largest_gap_center[1] << ", " << q.largest_gap_center[2]
                            << "), expected " << expected << " at z = " << -depth);
  CHECK(q.largest_gap == Approx(expected).epsilon(0.05));
  // It lies on the wall, at that depth.
  CHECK(std::abs(q.largest_gap_center[1]) < 1e-9);
  CHECK(std::abs(q.largest_gap_center[2] + depth) < 0.15 * h);
}

TEST_CASE("a sliver folded over in a crumpled spot is not a bare patch", "[mosaic][quality]") {
  // A sphere under 300 tiles, then one vertex pushed half a height past the opposite edge of one
  // of its faces and lifted off the sphere: that face folds over, a sliver of 0.05 tile areas
  // whose normal is some 130° from the sphere's, with tiles right over it. Every tile near it
  // faces away from the sliver's own normal, so by that normal alone its samples' nearest tiles
  // were some way around the sphere, and the widest bare patch read 1.39 tiles; judged by the
  // normal around its corners too, it reads 0.50, as before the fold.
  Mesh m;
  make_sphere(m, 1.0, 4);
  auto field = aligned_field(m, {});
  const auto r = surface_mosaic(m, field, {}, count_options(300));
  REQUIRE(r);
  const Mosaic_quality before = mosaic_quality(m, r.tiles, field, {});
  const auto h = halfedge(Mesh::Face_index(3000), m);
  const Mesh::Vertex_index v = target(h, m), a = target(next(h, m), m),
                           b = target(next(next(h, m), m), m);
  const Vector_3 ab = m.point(b) - m.point(a);
  const Point_3 foot = m.point(a) + ((m.point(v) - m.point(a)) * ab / ab.squared_length()) * ab;
  const Vector_3 beyond = 0.5 * (foot - m.point(v)), radial = m.point(v) - CGAL::ORIGIN;
  m.point(v) =
      foot + beyond + 1.2 * std::sqrt(beyond.squared_length() / radial.squared_length()) * radial;
  double flipped = 0;
  for (auto g : faces(m)) {
    const Vector_3 n = CGAL::Polygon_mesh_processing::compute_face_normal(g, m);
    const Vector_3 out = m.point(target(halfedge(g, m), m)) - CGAL::ORIGIN;
    if (n * out < -0.5 * std::sqrt(out.squared_length()))
      flipped += CGAL::Polygon_mesh_processing::face_area(g, m);
  }
  const double tile_area = r.tiles.front().size[0] * r.tiles.front().size[1];
  INFO("folded over: " << flipped / tile_area << " tile areas");
  REQUIRE(flipped > 0);
  REQUIRE(flipped < 0.1 * tile_area);
  const Mosaic_quality after = mosaic_quality(m, r.tiles, field, {});
  INFO("widest bare patch " << before.largest_gap << " -> " << after.largest_gap);
  CHECK(after.largest_gap < before.largest_gap + 0.25);
  CHECK(after.coverage == Approx(before.coverage).margin(0.005));
}

TEST_CASE("a tile on a thin slab crosses the crease it lies over, not the one under it",
          "[mosaic][quality]") {
  // A slab 0.08 thick: its top [-1, 1]^2 at z = 0.04, its bottom [-0.8, 0.8]^2 at z = -0.04, sides
  // 22° off the bottom's plane (creases at 20°). A tile 0.2 wide on the top at x = 0.85 ends 0.05
  // short of the top crease at x = 1 but lies over the bottom crease at x = 0.8, 0.08 below its
  // plane, within the half thickness the test allows; one at x = 0.95 lies across the top crease.
  Mesh m = box_of_triangles(0.8, 1, 0.04);
  Feature_line_options fo;
  fo.creases = true;
  fo.crease_angle_degrees = 20;
  const Lines creases = feature_lines(m, fo);
  REQUIRE(creases.size() == 12);
  auto field = constant_field(m, Vector_3(1, 0, 0));
  Mesh::Face_index top = Mesh::null_face();
  for (auto f : faces(m))
    if (CGAL::Polygon_mesh_processing::compute_face_normal(f, m).z() > 0.99)
      top = f;
  auto tile_at = [&](double x) {
    Mosaic_tile<Mesh::Face_index> t;
    t.center = {{x, 0, 0.04}};
    t.face = top;
    t.normal = {{0, 0, 1}};
    t.x_axis = {{1, 0, 0}};
    t.size = {{0.2, 0.2}};
    return t;
  };
  CHECK(mosaic_quality(m, {tile_at(0.85)}, field, creases).tiles_crossing_features == 0);
  CHECK(mosaic_quality(m, {tile_at(0.95)}, field, creases).tiles_crossing_features == 1);
  CHECK(mosaic_quality(m, {tile_at(0.85), tile_at(0.95), tile_at(0)}, field, creases)
            .tiles_crossing_features == 1);
}

TEST_CASE("tiles take the mean colour of their footprint from a texture or vertex colours",
          "[mosaic][colors]") {
  // The unit square with texture coordinates (x, y); the image red on its left half, blue on its
  // right.
  Mesh m = unit_square(40);
  auto uv = m.add_property_map<Mesh::Vertex_index, std::array<double, 2>>("v:uv").first;
  auto rgb = m.add_property_map<Mesh::Vertex_index, Color>("v:color").first;
  for (auto v : vertices(m)) {
    const Point_3& p = m.point(v);
    uv[v] = {{p.x(), p.y()}};
    rgb[v] = Color{p.x(), p.y(), 0}; // linear over the square
  }
  Rgb_image image(64, 64);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x)
      image.set(x, y,
                x < 32 ? std::array<std::uint8_t, 3>{{255, 0, 0}}
                       : std::array<std::uint8_t, 3>{{0, 0, 255}});
  // Tiles 0.1 wide at x = 0.1 ... 0.9 (one astride x = 0.5), turned by 0 or 30°.
  std::vector<Mosaic_tile<Mesh::Face_index>> tiles;
  for (int i = 1; i <= 9; ++i)
    for (const double angle : {0.0, 0.5}) {
      Mosaic_tile<Mesh::Face_index> t;
      t.center = {{0.1 * i, 0.3 + angle, 0}};
      t.normal = {{0, 0, 1}};
      t.x_axis = {{std::cos(angle), std::sin(angle), 0}};
      t.size = {{0.1, 0.1}};
      tiles.push_back(t);
    }
  Tile_color_options o;
  o.samples_per_side = 40;
  CHECK(average_tile_colors(tiles, Texture_colors<Mesh, decltype(uv)>(m, uv, image), o) ==
        tiles.size());
  for (const auto& t : tiles) {
    // The red share of the tile: the part of its rectangle left of x = 0.5, by integration of
    // the rectangle's width across x (a square turned by a, half side h).
    const double a = std::atan2(t.x_axis[1], t.x_axis[0]), h = 0.05;
    double red = 0;
    const int n = 400;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double s = ((i + 0.5) / n - 0.5) * 2 * h, u = ((j + 0.5) / n - 0.5) * 2 * h;
        red += (t.center[0] + s * std::cos(a) - u * std::sin(a) < 0.5);
      }
    red /= double(n) * n;
    INFO("tile at x " << t.center[0] << ", angle " << a << ": red share " << red << ", colour "
                      << t.color.r << " " << t.color.g << " " << t.color.b);
    CHECK(t.color.r == Approx(red).margin(0.04));
    CHECK(t.color.b == Approx(1 - red).margin(0.04));
    CHECK(t.color.g == Approx(0).margin(1e-9));
  }
  // The tile astride the border takes both colours, not the one under its centre.
  CHECK(tiles[8].color.r == Approx(0.5).margin(0.04));
  // Vertex colours linear over the surface average to their value at the centre.
  average_tile_colors(tiles, Vertex_colors<Mesh, decltype(rgb)>(m, rgb));
  for (const auto& t : tiles) {
    CHECK(t.color.r == Approx(t.center[0]).margin(1e-9));
    CHECK(t.color.g == Approx(t.center[1]).margin(1e-9));
  }
}

TEST_CASE("tile counts and sizes follow N = (1 - g) A / (lx ly)", "[mosaic]") {
  Mesh m = test::load("eight.off");
  auto lines_field = aligned_field(m, {}, 2);
  for (const double aspect : {1.0, 2.0}) {
    for (const std::size_t n : {500, 2000}) {
      Surface_mosaic_options o = count_options(n, aspect);
      o.max_iterations = 0;
      o.count = Mosaic_count::exact;
      Surface_mosaic<Mesh> mosaic(m, lines_field, {}, o);
      REQUIRE(mosaic.status() == Mosaic_status::ok);
      CHECK(std::abs(double(mosaic.number_of_tiles()) - double(n)) <= 0.01 * double(n));
      const Mosaic_layout& l = mosaic.layout();
      CHECK(l.tile_size[0] / l.tile_size[1] == Approx(aspect));
      CHECK(double(n) * l.tile_size[0] * l.tile_size[1] / (1 - o.tiles.grout) ==
            Approx(CGAL::Polygon_mesh_processing::area(m)).epsilon(1e-9));
    }
  }
}

TEST_CASE("bordered and genus-2 meshes run end to end, deterministically", "[mosaic]") {
  for (const char* file : {"pig.off", "eight.off"}) {
    Mesh m = test::load(file);
    Feature_line_options fo;
    const Lines border = feature_lines(m, fo);
    auto field = aligned_field(m, border);
    Surface_mosaic_options o = count_options(400);
    o.seed = 3;
    // At 400 tiles both surfaces curve within a tile or two: with the default count the layout
    // leaves out the tiles that would overlap (fewer tiles, little overlap); exactly N covers more
    // and overlaps.
    const auto about = surface_mosaic(m, field, border, o);
    REQUIRE(about);
    const Mosaic_quality qa = mosaic_quality(m, about.tiles, field, border);
    INFO("about N: " << about.tiles.size() << " tiles, coverage " << qa.coverage << ", overlap "
                     << qa.overlap);
    // (Measured 1.07 % on both: issue 35's 1 % is for 3000 tiles, where the eight has 0.75 %.)
    CHECK(qa.overlap <= 0.015);
    CHECK(double(about.tiles.size()) >= 0.85 * 400);
    o.count = Mosaic_count::exact;
    const auto a = surface_mosaic(m, field, border, o);
    const auto b = surface_mosaic(m, field, border, o);
    INFO(file << ": " << a.message);
    REQUIRE(a);
    REQUIRE(a.tiles.size() == b.tiles.size());
    bool same = true;
    for (std::size_t i = 0; i < a.tiles.size(); ++i)
      same = same && a.tiles[i].center == b.tiles[i].center;
    CHECK(same);
    o.seed = 4;
    const auto c = surface_mosaic(m, field, border, o);
    CHECK(c.tiles[0].center != a.tiles[0].center);
    const Mosaic_quality q = mosaic_quality(m, a.tiles, field, border);
    INFO("coverage " << q.coverage << ", overlap " << q.overlap);
    CHECK(q.coverage >= 0.8);
    // pig.off's smallest holes (eyes, nostrils) are narrower than a tile: a few tiles next to them
    // cross.
    CHECK(q.tiles_crossing_features <= a.tiles.size() / 50);
  }
}

TEST_CASE("cut tiles do not overlap and lose no more than their overlap and grout",
          "[mosaic][cut]") {
  Mesh m = unit_square(40);
  auto field = constant_field(m, Vector_3(1, 1, 0));
  Feature_line_options fo;
  const Lines border = feature_lines(m, fo);
  // Exactly N tiles grown from a seed: overlapping where the rows meet, tiles to cut.
  Surface_mosaic_options o = count_options(300);
  o.initialization = Mosaic_initialization::lattice;
  o.count = Mosaic_count::exact;
  auto r = surface_mosaic(m, field, border, o);
  REQUIRE(r);
  const Mosaic_quality before = mosaic_quality(m, r.tiles, field, border);
  REQUIRE(before.overlap > 0);
  const double grout = grid_grout_width(r.layout);
  // A grout width that is not a width is refused, the tiles left as they were.
  auto copy = r.tiles;
  for (const double bad : {-grout, std::numeric_limits<double>::quiet_NaN()}) {
    const Cut_tiles_result refused = cut_tiles(copy, bad);
    CHECK(refused.status == Cut_tiles_status::invalid_options);
    CHECK(!refused.message.empty());
    CHECK(refused.tiles_cut == 0);
  }
  CHECK(copy.size() == r.tiles.size());
  const Cut_tiles_result cut = cut_tiles(r.tiles, grout);
  REQUIRE(cut);
  const Mosaic_quality after = mosaic_quality(m, r.tiles, field, border);
  INFO("before " << before.coverage << "/" << before.overlap << ", after " << after.coverage << "/"
                 << after.overlap);
  CHECK(cut.tiles_cut > 0);
  CHECK(after.overlap == 0);
  // What is cut away is the overlap plus a grout strip along each cut edge, nothing else.
  CHECK(after.coverage >=
        before.coverage - before.overlap - cut.tiles_cut * 2 * grout * r.layout.tile_size[0]);
  for (const auto& t : r.tiles)
    if (!t.outline.empty())
      CHECK(internal::polygon_area(t.outline) < t.size[0] * t.size[1]);
}

TEST_CASE("bad input gets a status and a message", "[mosaic]") {
  Mesh m = test::load("eight.off");
  auto field = aligned_field(m, {});
  auto status = [&](const Surface_mosaic_options& o) {
    return Surface_mosaic<Mesh>(m, field, {}, o).status();
  };
  Surface_mosaic_options none;
  CHECK(status(none) == Mosaic_status::invalid_options); // neither a size nor a count
  Surface_mosaic_options both = count_options(100);
  both.tiles.tile_size = {{0.1, 0.1}};
  CHECK(status(both) == Mosaic_status::invalid_options);
  Surface_mosaic_options grout = count_options(100);
  grout.tiles.grout = 1.5;
  CHECK(status(grout) == Mosaic_status::invalid_options);
  Surface_mosaic_options huge;
  huge.tiles.tile_size = {{1e3, 0}};
  CHECK(status(huge) == Mosaic_status::invalid_options);
  Surface_mosaic_options square_rectangles = count_options(100, 2);
  square_rectangles.symmetry = 4;
  CHECK(status(square_rectangles) == Mosaic_status::invalid_options);
  field[*vertices(m).begin()] = Vector_3(std::nan(""), 0, 0);
  CHECK(status(count_options(100)) == Mosaic_status::invalid_field);
  Mesh empty;
  auto empty_field = empty.add_property_map<Mesh::Vertex_index, Vector_3>("v:tessera_field").first;
  CHECK(Surface_mosaic<Mesh>(empty, empty_field, {}, count_options(10)).status() ==
        Mosaic_status::empty_mesh);
  Mesh quad;
  CGAL::make_quad(Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(1, 1, 0), Point_3(0, 1, 0), quad);
  auto quad_field = quad.add_property_map<Mesh::Vertex_index, Vector_3>("v:tessera_field").first;
  CHECK(Surface_mosaic<Mesh>(quad, quad_field, {}, count_options(10)).status() ==
        Mosaic_status::not_triangle_mesh);
}

TEST_CASE("surface mosaics run on another FaceGraph model: Polyhedron_3", "[mosaic][polyhedron]") {
  using Polyhedron = CGAL::Polyhedron_3<Kernel, CGAL::Polyhedron_items_with_id_3>;
  Polyhedron poly;
  REQUIRE(read_mesh(test::data_path("eight.off"), poly));
  auto field = get(CGAL::dynamic_vertex_property_t<Vector_3>(), poly);
  REQUIRE(smoothest_field(poly, {}, field, Smoothest_field_options{}));
  Surface_mosaic_options o = count_options(300);
  o.count = Mosaic_count::exact;
  const auto r = surface_mosaic(poly, field, {}, o);
  REQUIRE(r);
  CHECK(r.tiles.size() == 300);
  Mesh m = test::load("eight.off");
  auto mesh_field = aligned_field(m, {});
  const auto same = surface_mosaic(m, mesh_field, {}, o);
  // Same vertices and faces in the same order, same field solve: the same layout.
  REQUIRE(same.tiles.size() == r.tiles.size());
  for (std::size_t i = 0; i < r.tiles.size(); ++i)
    for (int k = 0; k < 3; ++k)
      CHECK(r.tiles[i].center[k] == Approx(same.tiles[i].center[k]).margin(1e-9));
}

TEST_CASE("the field and mosaic reports written as JSON carry the results' figures",
          "[mosaic][io]") {
  Mesh m = test::load("eight.off");
  auto field = m.add_property_map<Mesh::Vertex_index, Vector_3>("v:tessera_field").first;
  const Smoothest_field_result fr = smoothest_field(m, {}, field, Smoothest_field_options{});
  REQUIRE(fr);
  // singularities.json: each singular face with its index and centroid; on the closed genus-2
  // eight the indices sum to its Euler characteristic, -2.
  const Field_singularities<Mesh> sing = field_singularities(m, field, 4);
  REQUIRE(sing.singularities.size() >= 8);
  std::ostringstream sj;
  REQUIRE(write_singularities_report(sj, make_singularities_report(m, sing)));
  const nlohmann::json s = nlohmann::json::parse(sj.str());
  REQUIRE(s["singularities"].size() == sing.singularities.size());
  CHECK(s["symmetry"] == 4);
  CHECK(s["euler_characteristic"] == -2);
  CHECK(s["face_index_sum"].get<double>() == -2.0);
  CHECK(s["poincare_hopf_holds"] == true);
  CHECK(s["boundary_loops"].empty());
  double sum = 0;
  for (std::size_t k = 0; k < sing.singularities.size(); ++k) {
    const nlohmann::json& j = s["singularities"][k];
    const Mesh::Face_index f = sing.singularities[k].face;
    CHECK(j["face"].get<std::size_t>() == std::size_t(f));
    CHECK(j["index"].get<double>() == sing.singularities[k].numerator / 4.0);
    sum += j["index"].get<double>();
    const auto h = halfedge(f, m);
    const Point_3 c = CGAL::centroid(m.point(source(h, m)), m.point(target(h, m)),
                                     m.point(target(next(h, m), m)));
    for (int d = 0; d < 3; ++d)
      CHECK(j["position"][std::size_t(d)].get<double>() == Approx(c[d]).margin(1e-12));
  }
  CHECK(sum == -2.0);

  // report.json and tiles.json of a mosaic on that field.
  auto r = surface_mosaic(m, field, {}, count_options(300));
  REQUIRE(r);
  const Mosaic_quality q = mosaic_quality(m, r.tiles, field, {});
  Mosaic_report report = make_mosaic_report("eight.off", {}, fr, 4, 0, 0, r.layout, r.stats, q);
  std::ostringstream rj;
  REQUIRE(write_mosaic_report(rj, report));
  const nlohmann::json j = nlohmann::json::parse(rj.str());
  CHECK(j["mesh"] == "eight.off");
  CHECK(j["quality"]["tiles"].get<std::size_t>() == r.tiles.size());
  CHECK(j["quality"]["coverage"].get<double>() == q.coverage);
  CHECK(j["layout"]["tile_count"].get<std::size_t>() == 300);
  CHECK(j["stats"]["iterations"].get<std::size_t>() == r.stats.iterations);
  CHECK(j["stats"]["energy"].size() == r.stats.energy.size());
  CHECK(j["field"]["energy"].get<double>() == fr.energy);
  CHECK(j["field"]["symmetry"] == 4);
  CHECK(j["repairs"]["merged_vertices"] == 0);
  CHECK(!j.contains("cut_tiles"));
  const double grout = grid_grout_width(r.layout);
  const Cut_tiles_result cut = cut_tiles(r.tiles, grout);
  report.cut_tiles = Mosaic_report_cut{grout, cut};
  std::ostringstream cj;
  REQUIRE(write_mosaic_report(cj, report));
  const nlohmann::json c = nlohmann::json::parse(cj.str());
  CHECK(c["cut_tiles"]["tiles_cut"].get<std::size_t>() == cut.tiles_cut);
  CHECK(c["cut_tiles"]["grout_width"].get<double>() == grout);

  std::ostringstream tj;
  REQUIRE(write_mosaic_tiles_report(tj, make_mosaic_tiles_report(r.tiles)));
  const nlohmann::json t = nlohmann::json::parse(tj.str());
  REQUIRE(t["tiles"].size() == r.tiles.size());
  std::size_t outlines = 0;
  for (std::size_t k = 0; k < r.tiles.size(); ++k) {
    const nlohmann::json& tile = t["tiles"][k];
    CHECK(tile["face"].get<std::size_t>() == std::size_t(r.tiles[k].face));
    CHECK(tile["center"].get<std::array<double, 3>>() == r.tiles[k].center);
    CHECK(tile["color"].get<std::array<int, 3>>() == tile_rgb(r.tiles[k].color));
    CHECK(tile.contains("outline") == !r.tiles[k].outline.empty());
    outlines += tile.contains("outline");
  }
  CHECK(outlines == cut.tiles_cut);

  // feature_lines.json of pig.off's borders: each line's vertices from its first halfedge's source.
  const Mesh pig = test::load("pig.off");
  const Lines border = feature_lines(pig, Feature_line_options{});
  REQUIRE(border.size() >= 3);
  std::vector<Feature_alignment> alignment(border.size(), Feature_alignment::parallel);
  alignment[2] = Feature_alignment::perpendicular;
  std::ostringstream lj;
  REQUIRE(write_feature_lines_report(lj, make_feature_lines_report(pig, border, alignment)));
  const nlohmann::json l = nlohmann::json::parse(lj.str());
  REQUIRE(l.size() == border.size());
  for (std::size_t k = 0; k < border.size(); ++k) {
    CHECK(l[k]["line"] == k);
    CHECK(l[k]["kind"] == "boundary");
    CHECK(l[k]["alignment"] == (k == 2 ? "perpendicular" : "parallel"));
    CHECK(l[k]["closed"] == border[k].closed);
    const auto vs = l[k]["vertices"].get<std::vector<std::size_t>>();
    REQUIRE(vs.size() == border[k].halfedges.size() + 1);
    CHECK(vs.front() == std::size_t(source(border[k].halfedges.front(), pig)));
    for (std::size_t i = 0; i < border[k].halfedges.size(); ++i)
      CHECK(vs[i + 1] == std::size_t(target(border[k].halfedges[i], pig)));
  }
}

TEST_CASE("a tile size field sets each tile's size and the density", "[mosaic][size]") {
  // Size 1 on the left third of the square, 2 on the right third, a ramp between: tiles on the
  // right are twice as wide and a quarter as many per area; N counts tiles of the local size.
  Mesh m = unit_square(80);
  auto field = constant_field(m, Vector_3(1, 0, 0));
  const Lines border = feature_lines(m);
  auto size = m.add_property_map<Mesh::Vertex_index, double>("v:size").first;
  auto size_of_x = [](double x) { return x < 1.0 / 3 ? 1.0 : x > 2.0 / 3 ? 2.0 : 3 * x; };
  for (auto v : vertices(m))
    size[v] = size_of_x(m.point(v).x());
  Surface_mosaic_options o = count_options(900);
  for (const Mosaic_initialization start :
       {Mosaic_initialization::lattice, Mosaic_initialization::error_diffusion}) {
    o.initialization = start;
    INFO("start " << to_string(start));
    const auto r = surface_mosaic(m, field, border, o, CGAL::parameters::scalar_map(size));
    REQUIRE(r);
    // N = Σ area / size² / spacing²: left third 1/3, ramp ∫ 1/(3x)² = 1/6, right third 1/12.
    const double weighted_area = 1.0 / 3 + 1.0 / 6 + 1.0 / 12;
    // (Σ over faces at their centroids: 1e-4 off the integral on this grid.)
    CHECK(r.layout.spacing == Approx(std::sqrt(weighted_area / 900)).epsilon(1e-3));
    // Two strips 0.25 wide away from the border, one in each constant part.
    std::vector<double> left, right;
    for (const auto& t : r.tiles) {
      const double x = t.center[0], y = t.center[1];
      // Each tile's size is the field at its centre times its shrinking (1 where there is room);
      // the field is linear in each triangle, which is at most 0.02 wide, and sizes grow with x.
      CHECK(t.size[0] <= r.layout.tile_size[0] * size_of_x(x + 0.02) * (1 + 1e-9));
      if (y < 0.05 || y > 0.95)
        continue;
      if (x > 0.05 && x < 0.3)
        left.push_back(t.size[0]);
      else if (x > 0.7 && x < 0.95)
        right.push_back(t.size[0]);
    }
    REQUIRE(left.size() > 50);
    REQUIRE(right.size() > 10);
    auto area = [](const std::vector<double>& sides) {
      double a = 0;
      for (const double l : sides)
        a += l * l;
      return a;
    };
    // Both strips as well covered (tiles with their centre in a strip, over its area 0.225) ...
    const double cover_left = area(left) / 0.225, cover_right = area(right) / 0.225;
    std::nth_element(left.begin(), left.begin() + left.size() / 2, left.end());
    std::nth_element(right.begin(), right.begin() + right.size() / 2, right.end());
    INFO("left " << left.size() << " tiles, covering " << cover_left << "; right " << right.size()
                 << ", " << cover_right);
    CHECK(cover_left == Approx(0.9).margin(0.12));
    CHECK(cover_right == Approx(0.9).margin(0.12));
    // ... by tiles twice as wide on the right, four times fewer.
    CHECK(right[right.size() / 2] / left[left.size() / 2] == Approx(2).epsilon(0.05));
    const double density_ratio = double(left.size()) / double(right.size());
    CHECK(density_ratio > 3.2);
    CHECK(density_ratio < 5.0);
    const Mosaic_quality q = mosaic_quality(m, r.tiles, field, border);
    INFO("coverage " << q.coverage << ", overlap " << q.overlap);
    CHECK(q.coverage >= 0.8);
    CHECK(q.overlap <= 0.02);
    CHECK(std::abs(double(r.tiles.size()) - 900.0) <= 0.1 * 900);
  }
  SECTION("only ratios of sizes matter with a count: a quarter of the field lays the same tiles") {
    auto quarter = m.add_property_map<Mesh::Vertex_index, double>("v:quarter").first;
    for (auto v : vertices(m))
      quarter[v] = 0.25 * size[v];
    const auto a = surface_mosaic(m, field, border, o, CGAL::parameters::scalar_map(size));
    const auto b = surface_mosaic(m, field, border, o, CGAL::parameters::scalar_map(quarter));
    REQUIRE(a);
    REQUIRE(b);
    CHECK(b.layout.spacing == Approx(4 * a.layout.spacing));
    // (Rounding makes the two runs part ways over the iterations: compare the figures, not tile by
    // tile; the start is the same lattice.)
    CHECK(std::abs(double(a.tiles.size()) - double(b.tiles.size())) <=
          0.05 * double(a.tiles.size()));
    Surface_mosaic_options start = o;
    start.initialization = Mosaic_initialization::lattice;
    start.max_iterations = 0;
    const Surface_mosaic<Mesh, decltype(CGAL::parameters::scalar_map(size))> sa(
        m, field, border, start, CGAL::parameters::scalar_map(size));
    const Surface_mosaic<Mesh, decltype(CGAL::parameters::scalar_map(size))> sb(
        m, field, border, start, CGAL::parameters::scalar_map(quarter));
    CHECK(sa.number_of_tiles() == sb.number_of_tiles());
    auto median_side = [](const auto& r) {
      std::vector<double> sides;
      for (const auto& t : r.tiles)
        sides.push_back(t.size[0]);
      std::nth_element(sides.begin(), sides.begin() + sides.size() / 2, sides.end());
      return sides[sides.size() / 2];
    };
    CHECK(median_side(b) == Approx(median_side(a)).epsilon(0.01));
    // Charts and the lattice's hash grid follow the largest tile, not size 1 (charts 4 times too
    // wide would each take a quarter of the square: far fewer of them).
    CHECK(double(b.stats.charts) >= 0.8 * double(a.stats.charts));
  }
  SECTION("a size that is not positive, or with the position field, is refused") {
    size[*vertices(m).begin()] = 0;
    CHECK(surface_mosaic(m, field, border, o, CGAL::parameters::scalar_map(size)).status ==
          Mosaic_status::invalid_options);
    size[*vertices(m).begin()] = 1;
    o.initialization = Mosaic_initialization::position_field;
    const auto r = surface_mosaic(m, field, border, o, CGAL::parameters::scalar_map(size));
    CHECK(r.status == Mosaic_status::invalid_options);
    CHECK(r.message.find("size field") != std::string::npos);
  }
  SECTION("the default start grows the lattice with a size field, solves the field without") {
    REQUIRE(Surface_mosaic_options{}.initialization == Mosaic_initialization::automatic);
    o.initialization = Mosaic_initialization::automatic;
    o.max_iterations = 0;
    const auto sized = surface_mosaic(m, field, border, o, CGAL::parameters::scalar_map(size));
    REQUIRE(sized);
    CHECK(sized.stats.lattice_levels == 0); // no position field was solved
    const auto plain = surface_mosaic(m, field, border, o);
    REQUIRE(plain);
    CHECK(plain.stats.lattice_levels > 0);
    CHECK(plain.stats.lattice_points > 0);
  }
}

TEST_CASE("feature lines drawn by hand: polylines of vertex ids", "[mosaic][features][io]") {
  // A 4 x 4 grid of the unit square: vertex j·5 + i at (i, j) / 4.
  Mesh m = unit_square(4);
  std::istringstream in("# a row and a closed loop\n"
                        "5 6 7 8\n"
                        "\n"
                        "6 11 12 7 6  # around one cell's two triangles\n");
  const auto r = read_feature_polylines(in, m);
  REQUIRE(r);
  REQUIRE(r.lines.size() == 2);
  CHECK(r.lines[0].kind == Feature_kind::user);
  CHECK_FALSE(r.lines[0].closed);
  CHECK(r.lines[1].closed);
  const std::vector<std::vector<std::size_t>> ids{{5, 6, 7, 8}, {6, 11, 12, 7, 6}};
  for (std::size_t l = 0; l < 2; ++l) {
    REQUIRE(r.lines[l].halfedges.size() == ids[l].size() - 1);
    for (std::size_t k = 0; k + 1 < ids[l].size(); ++k) {
      CHECK(std::size_t(source(r.lines[l].halfedges[k], m)) == ids[l][k]);
      CHECK(std::size_t(target(r.lines[l].halfedges[k], m)) == ids[l][k + 1]);
    }
  }
  // The lines split nothing but are walls: no tile of a mosaic crosses a drawn row.
  // A row near y = 0.25 on a finer grid (vertices 410..450; inner ones are moved by up to 0.004).
  Mesh fine = unit_square(40);
  std::string row;
  for (int i = 0; i <= 40; ++i)
    row += std::to_string(410 + i) + " ";
  std::istringstream fine_in(row);
  const auto fr = read_feature_polylines(fine_in, fine);
  REQUIRE(fr);
  auto fine_field = constant_field(fine, Vector_3(1, 0, 0));
  Lines fine_lines = feature_lines(fine);
  fine_lines.push_back(fr.lines[0]);
  const auto mr = surface_mosaic(fine, fine_field, fine_lines, count_options(300));
  REQUIRE(mr);
  const Mosaic_quality q = mosaic_quality(fine, mr.tiles, fine_field, fine_lines);
  CHECK(q.tiles_crossing_features == 0);
  std::size_t across = 0; // tiles whose rectangle reaches over y = 0.25
  for (const auto& t : mr.tiles) {
    // The tile's half extent along y (its x axis may run along either axis of the square: a
    // trimmed tile is a rectangle).
    const double half_y =
        0.5 * (std::abs(t.x_axis[1]) * t.size[0] + std::abs(t.x_axis[0]) * t.size[1]);
    across += std::abs(t.center[1] - 0.25) < half_y - 0.004 ? 1 : 0;
  }
  CHECK(across == 0);

  auto fails = [&](const std::string& text, Feature_polylines_read_status status) {
    std::istringstream bad(text);
    const auto b = read_feature_polylines(bad, m);
    CHECK(b.status == status);
    CHECK(b.lines.empty());
    CHECK_FALSE(b.message.empty());
  };
  fails("5 6\n5 12\n", Feature_polylines_read_status::not_an_edge);
  fails("5 6 25\n", Feature_polylines_read_status::index_out_of_range);
  fails("5 x\n", Feature_polylines_read_status::parse_error);
  fails("5\n", Feature_polylines_read_status::parse_error);
  fails("# nothing\n", Feature_polylines_read_status::empty);
}

TEST_CASE("per-vertex numbers read from text or a PLY property", "[mosaic][io]") {
  Mesh m = unit_square(2); // 9 vertices
  auto values = m.add_property_map<Mesh::Vertex_index, double>("v:values", -1).first;
  std::istringstream in("1 2 3 # first row\n4 5.5 6\n7 8 9e-1\n");
  REQUIRE(read_vertex_scalars(in, m, values));
  CHECK(values[Mesh::Vertex_index(4)] == 5.5);
  CHECK(values[Mesh::Vertex_index(8)] == Approx(0.9));
  std::istringstream shorter("1 2 3\n");
  const auto s = read_vertex_scalars(shorter, m, values);
  CHECK(s.status == Vertex_scalars_read_status::wrong_count);
  CHECK(values[Mesh::Vertex_index(0)] == 1); // nothing written
  std::istringstream nan("1 2 3 4 nan 6 7 8 9\n");
  CHECK(read_vertex_scalars(nan, m, values).status == Vertex_scalars_read_status::parse_error);

  // A PLY file with a float property "quality" per vertex, written here.
  const std::string path = test::output_path("quality.ply");
  {
    std::ofstream ply(path);
    ply << "ply\nformat ascii 1.0\nelement vertex 9\nproperty float x\nproperty float y\n"
           "property float z\nproperty float quality\nelement face 8\n"
           "property list uchar int vertex_indices\nend_header\n";
    std::size_t i = 0;
    for (auto v : vertices(m))
      ply << m.point(v) << " " << 0.25 * double(++i) << "\n";
    for (auto f : faces(m)) {
      ply << "3";
      for (auto v : vertices_around_face(halfedge(f, m), m))
        ply << " " << std::size_t(v);
      ply << "\n";
    }
  }
  REQUIRE(read_ply_vertex_scalars(path, "quality", m, values));
  CHECK(values[Mesh::Vertex_index(3)] == Approx(1.0));
  const auto missing = read_ply_vertex_scalars(path, "size", m, values);
  CHECK(missing.status == Vertex_scalars_read_status::no_such_property);
  CHECK(missing.message.find("quality") != std::string::npos);
}

namespace {

// The surface point at c, in the first face that holds it (to 1e-9); fails the test if none does.
internal::Surface_point point_at(const internal::Surface_arrays<Mesh>& s, const internal::Vec3& c) {
  for (std::uint32_t f = 0; f < s.number_of_faces(); ++f) {
    const auto b = s.barycentric_unclamped(f, c);
    if (b[0] > -1e-9 && b[1] > -1e-9 && b[2] > -1e-9 &&
        internal::norm(s.position({f, b}) - c) < 1e-9)
      return internal::Surface_point{f, b};
  }
  FAIL("no face holds the point");
  return internal::Surface_point{};
}

} // namespace

TEST_CASE("two tiles' distance along the surface is the arc their planes bend along", "[mosaic]") {
  // Tiles at two points of a circle of radius r, their normals the circle's: the arc between them,
  // r times the angle, from the chord and the cosine of the angle alone. The separation and the
  // filling stretch footprints by it, so a wrong arc over- or under-counts overlap on every bend.
  const double pi = std::acos(-1.0), r = 0.7;
  for (const double angle : {1e-6, 0.05, 0.4, 1.0, pi / 2, 2 * pi / 3}) {
    const double chord = 2 * r * std::sin(angle / 2);
    INFO("angle " << angle);
    CHECK(internal::bent_length(chord, std::cos(angle)) == Approx(r * angle).epsilon(1e-9));
  }
  // Parallel planes (a plane, or a bump that does not turn either tile): the chord itself.
  CHECK(internal::bent_length(0.3, 1.0) == 0.3);
  CHECK(internal::bent_length(0.3, 1.0 + 1e-15) == 0.3); // rounding past 1 is clamped
}

TEST_CASE("a walk on the surface covers its length however the surface bends", "[mosaic]") {
  using Arrays = internal::Surface_arrays<Mesh>;
  // A plane: the walk ends at start + d across many faces, and stops on the border short by the
  // rest of d.
  Mesh plane = unit_square(20);
  const Arrays p(plane, get(CGAL::vertex_point, plane), {});
  const internal::Surface_point from = point_at(p, internal::Vec3{{0.5, 0.5, 0}});
  const auto inside = p.walk(from, internal::Vec3{{0.31, -0.17, 0}});
  CHECK_FALSE(inside.blocked);
  CHECK(internal::norm(p.position(inside.p) - internal::Vec3{{0.81, 0.33, 0}}) < 1e-9);
  const auto out = p.walk(from, internal::Vec3{{0.8, 0, 0}});
  CHECK(out.blocked);
  CHECK(out.short_by == Approx(0.3).margin(1e-9));
  CHECK(internal::norm(p.position(out.p) - internal::Vec3{{1, 0.5, 0}}) < 1e-9);

  // An open tube unrolls into a plane: around it by its perimeter comes back to the start, an
  // oblique walk advances along the axis by its axial part, and a walk along the axis stops at
  // the end of the tube. (The closest point of the surface to start + d does none of these.)
  Mesh tube;
  make_tube(tube, 1.0, 4.0, 48);
  const Arrays t(tube, get(CGAL::vertex_point, tube), {});
  std::uint32_t f0 = 0;
  for (std::uint32_t f = 0; f < t.number_of_faces(); ++f)
    if (std::abs(t.centroid(f)[0]) < std::abs(t.centroid(f0)[0]))
      f0 = f;
  const internal::Surface_point s0{f0, {{0.2, 0.3, 0.5}}};
  const internal::Vec3 x0 = t.position(s0), axis{{1, 0, 0}};
  const internal::Vec3 around = internal::cross(t.normal(f0), axis);
  REQUIRE(std::abs(internal::dot(t.normal(f0), axis)) < 1e-12);
  const double perimeter = 48 * 2 * std::sin(std::acos(-1.0) / 48);
  const auto loop = t.walk(s0, perimeter * around);
  CHECK_FALSE(loop.blocked);
  CHECK(internal::norm(t.position(loop.p) - x0) < 1e-9);
  const auto half = t.walk(s0, 0.5 * perimeter * around);
  CHECK(internal::norm(t.position(half.p) - x0) > 1.9); // the far side, about a diameter away
  const auto oblique = t.walk(s0, 0.5 * axis + 1.3 * around);
  CHECK_FALSE(oblique.blocked);
  CHECK(t.position(oblique.p)[0] - x0[0] == Approx(0.5).margin(1e-9));
  const auto along = t.walk(s0, 3.0 * axis);
  CHECK(along.blocked);
  CHECK(t.position(along.p)[0] == Approx(2.0).margin(1e-9));
  CHECK(along.short_by == Approx(1.0 + x0[0]).margin(1e-9));
}

TEST_CASE("course drift follows the surface: a helix of tiles around a tube has none",
          "[mosaic][quality]") {
  // Tiles 12 around an open tube and 0.52 apart along it, every one turned 45° to the axis, so
  // that their courses run in helices: the field is parallel along the tube and around it, and a
  // viewer sees straight rows. Each neighbour's axis must be turned into the tile's plane along
  // the surface; projected onto it, neighbours around the tube read 3.9° apart.
  Mesh tube;
  make_tube(tube, 1.0, 4.0, 96);
  const internal::Surface_arrays<Mesh> s(tube, get(CGAL::vertex_point, tube), {});
  auto field = constant_field(tube, Vector_3(1, 0, 0));
  const double pi = std::acos(-1.0), step = 2 * pi / 12;
  std::vector<Mosaic_tile<Mesh::Face_index>> tiles;
  for (int row = -3; row <= 3; ++row)
    for (int k = 0; k < 12; ++k) {
      // On a vertex of the tube (its rings lie 4 / 61 apart, 96 vertices around).
      const double theta = k * step, x = std::round(row * step * 61 / 4) * 4 / 61;
      const internal::Vec3 c{{x, std::cos(theta), std::sin(theta)}};
      Mosaic_tile<Mesh::Face_index> t;
      t.face = s.face_of(point_at(s, c).face);
      t.center = {{c[0], c[1], c[2]}};
      t.normal = {{0, std::cos(theta), std::sin(theta)}};
      const double r = std::sqrt(0.5);
      t.x_axis = {{r, -r * std::sin(theta), r * std::cos(theta)}};
      t.size = {{0.45, 0.45}};
      tiles.push_back(t);
    }
  const Mosaic_quality q = mosaic_quality(tube, tiles, field, {});
  INFO("drift median " << q.course_drift_median << ", p95 " << q.course_drift_p95);
  CHECK(q.course_drift_median < 0.1);
  CHECK(q.course_drift_p95 < 0.1);
}

TEST_CASE("tiles on the surface smoothed at their scale take the plane of their footprint",
          "[mosaic][tile-scale]") {
  using Tile = Mosaic_tile<Mesh::Face_index>;
  // A plate with bumps half a tile spacing wide, slopes up to 20°.
  Mesh m;
  make_plate(m, 1, 1, 90);
  const double pi = std::acos(-1.0), wave = 1.0 / 15, height = 0.004;
  auto bump = [&](double x, double y) {
    return height * std::sin(2 * pi * x / wave) * std::sin(2 * pi * y / wave);
  };
  for (auto v : vertices(m)) {
    const Point_3 p = m.point(v);
    m.point(v) = Point_3(p.x(), p.y(), bump(p.x(), p.y()));
  }
  Surface_mosaic_options o;
  o.tiles.tile_count = 64;
  Mosaic_layout layout;
  REQUIRE_FALSE(mosaic_layout(o.tiles, CGAL::Polygon_mesh_processing::area(m), layout));
  REQUIRE(layout.spacing > 1.5 * wave);
  const Lines border = feature_lines(m, Feature_line_options{});
  REQUIRE(border.size() == 1);

  auto points = m.add_property_map<Mesh::Vertex_index, Point_3>("v:tile_scale").first;
  const Tile_scale_result r = tile_scale_points(m, layout.spacing, border, points);
  INFO(r.message);
  REQUIRE(r.smoothed);
  // One step keeps 1 / (1 + 4π² · 0.08 · (spacing / wave)²) of the bumps (0.08 here) away from
  // the border, which stays where it is.
  double before = 0, after = 0;
  bool border_kept = true;
  for (auto v : vertices(m)) {
    const Point_3 p = m.point(v);
    if (CGAL::is_border(v, m))
      border_kept = border_kept && points[v] == p;
    else if (std::min({p.x(), p.y(), 1 - p.x(), 1 - p.y()}) > layout.spacing) {
      before = std::max(before, std::abs(p.z()));
      after = std::max(after, std::abs(points[v].z()));
    }
  }
  INFO("bump height " << before << " -> " << after << ", largest move " << r.largest_move
                      << " spacings");
  CHECK(after < 0.25 * before);
  CHECK(border_kept);
  CHECK(r.largest_move < 0.1);
  CHECK(r.mean_move > 0);
  // Time 0: the positions as read.
  Tile_scale_options none;
  none.time = 0;
  auto copy = m.add_property_map<Mesh::Vertex_index, Point_3>("v:copy").first;
  CHECK_FALSE(tile_scale_points(m, layout.spacing, border, copy, none).smoothed);
  for (auto v : vertices(m))
    CHECK(copy[v] == m.point(v));

  // Field and tiles laid on the smoothed positions stand within a few degrees of the plate's plane;
  // on the faces as read, each tile tilts with the bump under its centre.
  const auto np = CGAL::parameters::vertex_point_map(points);
  auto field = m.add_property_map<Mesh::Vertex_index, Vector_3>("v:field").first;
  REQUIRE(smoothest_field(
      m, feature_alignment_constraints(m, border, {Feature_alignment::parallel}), field, {}, np));
  auto smooth = surface_mosaic(m, field, border, o, np);
  const auto rough = surface_mosaic(m, field, border, o);
  REQUIRE(smooth);
  REQUIRE(rough);
  auto median_tilt = [](const std::vector<Tile>& tiles) {
    std::vector<double> tilt;
    for (const Tile& t : tiles)
      tilt.push_back(std::acos(std::min(1.0, std::abs(t.normal[2]))) * 180 / std::acos(-1.0));
    std::nth_element(tilt.begin(), tilt.begin() + std::ptrdiff_t(tilt.size() / 2), tilt.end());
    return tilt[tilt.size() / 2];
  };
  INFO("median tilt " << median_tilt(smooth.tiles) << "° smoothed, " << median_tilt(rough.tiles)
                      << "° on the faces as read");
  CHECK(median_tilt(smooth.tiles) < 6);
  CHECK(median_tilt(rough.tiles) > 8);
  // Their centres lie on the smoothed surface until put back onto the mesh, at their face and
  // barycentric coordinates.
  double off = 0;
  for (const Tile& t : smooth.tiles)
    off = std::max(off, std::abs(t.center[2] - bump(t.center[0], t.center[1])));
  CHECK(off > 0.2 * height);
  place_tiles_on_surface(m, smooth.tiles);
  const double cell = 1.0 / 90;
  off = 0;
  for (const Tile& t : smooth.tiles)
    off = std::max(off, std::abs(t.center[2] - bump(t.center[0], t.center[1])));
  // On the mesh: within its linear interpolation's error of the bump (height · (π·cell/wave)²).
  CHECK(off < height * std::pow(pi * cell / wave, 2));
}

TEST_CASE("the tile-scale step shrinks a sphere as mean curvature flow does: R / (1 + 2t/R²)",
          "[mosaic][tile-scale]") {
  // On a sphere Δx = −2x/R², so one implicit step of time t takes the radius to R / (1 + 2t/R²):
  // a wrong time scale (CGAL's operator is 4Δ) or a rescaling to the volume would miss it.
  Mesh m;
  make_sphere(m, 1.0, 4);
  auto points = m.add_property_map<Mesh::Vertex_index, Point_3>("v:tile_scale").first;
  const double spacing = 0.5;
  Tile_scale_options o;
  const Tile_scale_result r = tile_scale_points(m, spacing, Lines{}, points, o);
  INFO(r.message);
  REQUIRE(r.smoothed);
  const double t = o.time * spacing * spacing, expected = 1 / (1 + 2 * t);
  double lowest = 2, highest = 0;
  for (auto v : vertices(m)) {
    const double radius = std::sqrt((points[v] - CGAL::ORIGIN).squared_length());
    lowest = std::min(lowest, radius);
    highest = std::max(highest, radius);
  }
  INFO("radius " << lowest << " to " << highest << ", expected " << expected << ", " << r.iterations
                 << " iterations");
  // The geodesic sphere's cotangent Laplacian is within a few percent of −2/R² at every vertex.
  CHECK(std::abs(lowest - expected) < 0.03 * (1 - expected));
  CHECK(std::abs(highest - expected) < 0.03 * (1 - expected));
  CHECK(r.largest_move * spacing == Approx(1 - expected).epsilon(0.05));
  CHECK(r.iterations > 0);
  CHECK(r.iterations < 100);
}

TEST_CASE("creases read at the tiles' scale: a CAD part's edges are features, a coarse organic "
          "mesh's folds are not",
          "[mosaic][tile-scale][features]") {
  // The cube's 12 edges, each one line between two corners: with tiles a tenth of an edge apart
  // they are 10 spacings long, all of them long lines; with tiles half an edge apart, 2 spacings,
  // none is.
  Mesh cube = test::load("cube-meshed.off");
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(cube);
  const double edge = box.xmax() - box.xmin();
  const Tile_scale_creases fine = tile_scale_creases(cube, edge / 10);
  CHECK(fine.lines == 12);
  CHECK(fine.length == Approx(120).epsilon(1e-9));
  CHECK(fine.long_share == Approx(1));
  CHECK(fine.features);
  const Tile_scale_creases coarse = tile_scale_creases(cube, edge / 2);
  CHECK(coarse.lines == 12);
  CHECK(coarse.length == Approx(24).epsilon(1e-9));
  CHECK(coarse.long_share == 0);
  CHECK_FALSE(coarse.features);

  // At 3000 tiles: fandisk's creases run for many tiles; the elephant's folds sharper than 60°
  // (its coarse triangulation) are scattered edges and short chains.
  const auto spacing_of = [](const Mesh& m) {
    Surface_mosaic_options o;
    o.tiles.tile_count = 3000;
    const auto layout = surface_layout(m, o.tiles);
    REQUIRE(layout);
    return layout->spacing;
  };
  Mesh fandisk = test::load("fandisk.off");
  const Tile_scale_creases cad = tile_scale_creases(fandisk, spacing_of(fandisk));
  INFO("fandisk: " << cad.lines << " lines, " << cad.length << " spacings, long share "
                   << cad.long_share);
  CHECK(cad.long_share > 0.9);
  CHECK(cad.features);
  Mesh elephant = test::load("elephant.off");
  const Tile_scale_creases organic = tile_scale_creases(elephant, spacing_of(elephant));
  INFO("elephant: " << organic.lines << " lines, " << organic.length << " spacings, long share "
                    << organic.long_share);
  CHECK(organic.lines > 10);
  CHECK(organic.long_share < 0.3);
  CHECK_FALSE(organic.features);
}
