// Property-based sweep: random surfaces from the generators (genus, holes, resolution, vertex
// noise, several components, quads among the triangles), random cut methods, costs and basepoints;
// every result is checked by the library's validators and against the known topology: cuts (some
// also on exact coordinates, their refinement checked with tolerance 0), quadrangulations, fields
// and surface mosaics. CI runs a few dozen seeded cases; set
// TESSERA_SWEEP_CASES (and TESSERA_SWEEP_SEED, TESSERA_SWEEP_MAX_GENUS) for thousands locally:
//   TESSERA_SWEEP_CASES=2000 build/tests/tessera_tests "[sweep]"
#include "corpus.h"

#include <tessera/fields.h>
#include <tessera/io.h>
#include <tessera/mosaic/quality_report.h>
#include <tessera/mosaic/surface_mosaic.h>
#include <tessera/topology.h>
#include <tessera/topology/validate_refinement.h>

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include <catch2/catch.hpp>

#include <cstdlib>
#include <unistd.h>
#include <random>
#include <sstream>

using namespace tessera;

namespace {

std::size_t env_or(const char* name, std::size_t fallback) {
  const char* value = std::getenv(name);
  return value ? std::size_t(std::strtoull(value, nullptr, 10)) : fallback;
}

struct Sweep_case {
  Mesh mesh;
  long genus = 0;             // per component (all components alike)
  std::size_t boundaries = 0; // per component
  std::size_t components = 1;
  std::size_t quads = 0; // faces of the file that were quads, triangulated on reading
  bool smooth = false;   // Loop-subdivided (without it, a box of walls one lattice cell wide)
  std::string name;
};

// Writes `tm` as OFF with about a third of its triangles merged in pairs into quads (each pair
// across an inner edge: a, b, c and b, a, d make a, d, b, c), and reads it back through read_mesh,
// which triangulates them: the sweep's polygonal input. Returns the number of quads written.
std::size_t through_polygonal_file(Mesh& tm, std::mt19937& rng, const std::string& path) {
  std::vector<Point_3> points(tm.points().begin(), tm.points().end());
  std::vector<std::vector<std::size_t>> polygons;
  std::vector<bool> used(tm.num_faces(), false); // slots, removed faces included
  std::size_t quads = 0;
  for (auto f : faces(tm)) {
    if (used[f.idx()])
      continue;
    used[f.idx()] = true;
    const auto h0 = halfedge(f, tm);
    std::vector<std::size_t> polygon;
    for (auto v : vertices_around_face(h0, tm))
      polygon.push_back(v.idx());
    if (rng() % 3 == 0)
      for (auto h : halfedges_around_face(h0, tm)) {
        const auto g = opposite(h, tm);
        if (is_border(g, tm) || used[face(g, tm).idx()])
          continue;
        used[face(g, tm).idx()] = true;
        polygon = {source(h, tm).idx(), target(next(g, tm), tm).idx(), target(h, tm).idx(),
                   target(next(h, tm), tm).idx()};
        ++quads;
        break;
      }
    polygons.push_back(polygon);
  }
  REQUIRE(
      CGAL::IO::write_polygon_soup(path, points, polygons, CGAL::parameters::stream_precision(17)));
  const Read_mesh_result r = read_mesh(path, tm);
  INFO(r.message);
  REQUIRE(r);
  CHECK(r.triangulated_faces == quads);
  return quads;
}

Sweep_case random_case(std::mt19937& rng, std::size_t max_genus) {
  Sweep_case c;
  auto pick = [&](std::size_t lo, std::size_t hi) {
    return std::uniform_int_distribution<std::size_t>(lo, hi)(rng);
  };
  Genus_surface_options o;
  o.cell_resolution = pick(2, 4);
  o.wall_resolution = pick(1, 2);
  o.subdivision_steps = pick(0, 1);
  c.smooth = o.subdivision_steps > 0;
  c.genus = long(pick(0, max_genus));
  Mesh one;
  make_genus_surface(one, std::size_t(c.genus), o);
  if (pick(0, 1) == 1) {
    const std::size_t wanted = pick(1, std::min<std::size_t>(50, num_faces(one) / 40 + 1));
    c.boundaries = punch_holes(one, wanted, unsigned(rng()));
  }
  // Vertex noise up to a tenth of the lattice step keeps the surface embedded.
  const double step = 1.0 / double(o.cell_resolution) / double(1 << o.subdivision_steps);
  std::uniform_real_distribution<double> noise(-0.1 * step, 0.1 * step);
  const bool noisy = pick(0, 1) == 1;
  if (noisy)
    for (auto v : vertices(one))
      one.point(v) = one.point(v) + Vector_3(noise(rng), noise(rng), noise(rng));
  if (pick(0, 3) == 0)
    c.quads = through_polygonal_file(
        one, rng, test::output_path("sweep-polygons-" + std::to_string(::getpid()) + ".off"));
  c.components = pick(0, 4) == 0 ? 2 : 1;
  for (std::size_t k = 0; k < c.components; ++k) {
    const Vector_3 shift(0, 10.0 * double(k), 0);
    Mesh copy = one;
    for (auto v : vertices(copy))
      copy.point(v) = copy.point(v) + shift;
    CGAL::copy_face_graph(copy, c.mesh);
  }
  std::ostringstream name;
  name << "genus " << c.genus << ", " << c.boundaries << " holes, " << c.components
       << " components, resolution " << o.cell_resolution << "/" << o.wall_resolution << "/"
       << o.subdivision_steps << (noisy ? ", noisy" : "") << ", " << num_faces(c.mesh) << " faces"
       << (c.quads > 0 ? ", " + std::to_string(c.quads) + " quads in the file" : "");
  c.name = name.str();
  return c;
}

constexpr std::size_t no_case = std::size_t(-1);

// Draws `cases` random cases from `seed` and checks each (only case `only` when it is not no_case).
void sweep(std::size_t cases, std::size_t seed, std::size_t max_genus, std::size_t only) {
  std::mt19937 rng{static_cast<unsigned>(seed)};
  std::size_t cuts = 0, exact_cuts = 0, quads = 0, fields = 0, mosaics = 0;
  for (std::size_t i = 0; i < cases; ++i) {
    INFO("drawing case " << i << " (seed " << seed << ")");
    Sweep_case c = random_case(rng, max_genus);
    const Cut_method method = std::array<Cut_method, 3>{
        Cut_method::greedy, Cut_method::intermediate, Cut_method::schema}[rng() % 3];
    const bool curvature = rng() % 2 == 1;
    // A basepoint must be an interior vertex (a border one is refused, as tested elsewhere).
    std::optional<std::size_t> basepoint;
    if (rng() % 2 == 1) {
      Mesh::Vertex_index v(std::uint32_t(rng() % num_vertices(c.mesh)));
      while (CGAL::is_border(v, c.mesh))
        v = Mesh::Vertex_index((v.idx() + 1) % num_vertices(c.mesh));
      basepoint = std::size_t(v.idx());
    }
    INFO("case " << i << " (seed " << seed << "): " << c.name << ", method " << to_string(method)
                 << (curvature ? ", curvature cost" : "") << ", basepoint "
                 << (basepoint ? std::to_string(*basepoint) : std::string("first vertex")));

    // TESSERA_SWEEP_ONLY=i replays case i alone (the random draws of the cases before it are
    // made, their work skipped), to look into a failure of a long run.
    if (only != no_case && i != only)
      continue;
    Cut_options options;
    options.method = method;
    options.basepoint = basepoint;
    options.cost.kind = curvature ? Edge_cost_kind::curvature : Edge_cost_kind::euclidean;
    {
      Mesh mesh = c.mesh;
      auto seam_e = mesh.add_property_map<Mesh::Edge_index, bool>("e:tessera_seam", false).first;
      auto seam_v = mesh.add_property_map<Mesh::Vertex_index, bool>("v:tessera_seam", false).first;
      const auto result = cut_to_disk(mesh, seam_e, seam_v, options);
      INFO(result.message);
      REQUIRE(result);
      const Cut_validation v = validate_cut(mesh, seam_e, seam_v, result);
      INFO(test::joined(v.problems));
      CHECK(bool(v));
      REQUIRE(result.polygons.size() == c.components);
      for (const auto& polygon : result.polygons) {
        CHECK(polygon.genus == c.genus);
        CHECK(polygon.boundaries == c.boundaries);
      }
      ++cuts;
    }
    if (i % 6 == 1) {
      // The same cut on exact coordinates (each the exact value of its double): every vertex the
      // cut's refinement adds lies exactly on the input, not merely within a rounding error.
      Exact_mesh original;
      CGAL::copy_face_graph(c.mesh, original);
      Exact_mesh mesh = original;
      auto seam_e =
          mesh.add_property_map<Exact_mesh::Edge_index, bool>("e:tessera_seam", false).first;
      auto seam_v =
          mesh.add_property_map<Exact_mesh::Vertex_index, bool>("v:tessera_seam", false).first;
      const auto result = cut_to_disk(mesh, seam_e, seam_v, options);
      INFO("exact: " << result.message);
      REQUIRE(result);
      const Cut_validation v = validate_cut(mesh, seam_e, seam_v, result);
      INFO(test::joined(v.problems));
      CHECK(bool(v));
      Validate_refinement_options exact;
      exact.tolerance = 0;
      const Refinement_validation r = validate_refinement(original, mesh, exact);
      INFO(r.message);
      CHECK(bool(r));
      ++exact_cuts;
    }
    if (i % 2 == 0) {
      Mesh mesh = c.mesh;
      auto tile = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:tessera_tile", 0).first;
      auto seam_e = mesh.add_property_map<Mesh::Edge_index, bool>("e:tessera_seam", false).first;
      auto seam_v = mesh.add_property_map<Mesh::Vertex_index, bool>("v:tessera_seam", false).first;
      Quadrangulation_options qo;
      qo.cut = options;
      const auto result = quadrangulate(mesh, tile, seam_e, seam_v, qo);
      INFO(result.message);
      REQUIRE(result);
      const auto v = validate_quadrangulation(mesh, tile, seam_e, seam_v, result);
      INFO(test::joined(v.problems));
      CHECK(bool(v));
      ++quads;
    }
    {
      auto field = c.mesh.add_property_map<Mesh::Vertex_index, Vector_3>("v:tessera_field").first;
      const auto solved = smoothest_field(c.mesh, {}, field);
      INFO(solved.message);
      REQUIRE(solved);
      const auto s = field_singularities(c.mesh, field, 4);
      REQUIRE(s);
      CHECK(s.poincare_hopf_holds());
      ++fields;
      if (i % 4 == 3 && c.smooth) {
        // A surface mosaic along that field, one tile per 20 faces: exactly that many tiles, each
        // finite, on the surface and in its plane, covering most of it (tiles scattered at random
        // cover about a third: tests/mosaic/surface_mosaic.cpp). Only on the smooth surfaces: the
        // unsubdivided ones are boxes whose flat sides, one or two lattice cells wide, are
        // narrower than a tile (a 1,000-case run at genus up to 20 had coverage 0.33-0.49 on
        // them, and nowhere else).
        const auto borders = feature_lines(c.mesh, Feature_line_options{});
        Surface_mosaic_options mo;
        mo.tiles.tile_count = std::max<std::size_t>(20, num_faces(c.mesh) / 20);
        // Exactly N: the default count lets the lattice decide, and on these noisy surfaces, whose
        // handles are a few tiles around, it left out up to 45 % of the tiles (issue 35's note).
        mo.count = Mosaic_count::exact;
        const auto m = surface_mosaic(c.mesh, field, borders, mo);
        INFO(m.message);
        REQUIRE(m);
        // Exactly N, less the tiles left out because they could not clear a border.
        CHECK(m.tiles.size() + m.stats.removed_at_features == mo.tiles.tile_count);
        const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(c.mesh);
        const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) +
                                          CGAL::square(box.ymax() - box.ymin()) +
                                          CGAL::square(box.zmax() - box.zmin()));
        std::size_t off_surface = 0;
        for (const auto& t : m.tiles) {
          const Point_3 centre(t.center[0], t.center[1], t.center[2]);
          const auto& b = t.barycentric;
          std::array<Point_3, 3> corner;
          std::size_t k = 0;
          for (auto v : vertices_around_face(halfedge(t.face, c.mesh), c.mesh))
            corner[k++] = c.mesh.point(v);
          const Point_3 on_face =
              CGAL::barycenter(corner[0], b[0], corner[1], b[1], corner[2], b[2]);
          if (!(std::sqrt(CGAL::squared_distance(centre, on_face)) <= 1e-9 * diagonal) ||
              !(std::abs(t.normal[0] * t.x_axis[0] + t.normal[1] * t.x_axis[1] +
                         t.normal[2] * t.x_axis[2]) < 1e-9))
            ++off_surface;
        }
        CHECK(off_surface == 0);
        const Mosaic_quality q = mosaic_quality(c.mesh, m.tiles, field, borders);
        INFO("coverage " << q.coverage << ", overlap " << q.overlap << "; " << m.tiles.size()
                         << " tiles, " << m.stats.moved_off_features << " moved off and "
                         << m.stats.removed_at_features << " left out at borders");
        CHECK(q.tiles_crossing_features == 0);
        if (q.tiles_crossing_features > 0) // kept to be looked into, or made a test
          write_mesh(test::output_path("sweep-case-" + std::to_string(i) + ".off"), c.mesh);
        // Between many holes the strips are narrower than a tile, so coverage is asked of surfaces
        // with few holes only.
        if (c.boundaries <= 3)
          CHECK(q.coverage >= 0.5);
        ++mosaics;
      }
    }
  }
  UNSCOPED_INFO(cuts << " cuts (" << exact_cuts << " exact), " << quads << " quadrangulations, "
                     << fields << " fields, " << mosaics << " mosaics");
  CHECK(cuts == (only == no_case ? cases : std::size_t(only < cases ? 1 : 0)));
}

} // namespace

TEST_CASE("random surfaces: every cut, quadrangulation, field and mosaic validates", "[sweep]") {
  sweep(env_or("TESSERA_SWEEP_CASES", 24), env_or("TESSERA_SWEEP_SEED", 2026),
        env_or("TESSERA_SWEEP_MAX_GENUS", 6), env_or("TESSERA_SWEEP_ONLY", no_case));
}

// Found by a 1,000-case run: genus 13 with 45 holes, where a hole's rim curves away below a tile's
// corner; the feature clearance looked for segments in a box that held the tile's rectangle but
// not the slab about its plane, so it missed the rim the quality report saw.
TEST_CASE("sweep regression: seed 31, case 231 (a hole's rim under a tile's corner)", "[sweep]") {
  sweep(232, 31, 20, 231);
}
