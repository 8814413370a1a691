// Property-based sweep: random surfaces from the generators (genus, holes, resolution, vertex
// noise, several components), random cut methods, costs and basepoints; every result is checked by
// the library's validators and against the known topology. CI runs a few dozen seeded cases; set
// TESSERA_SWEEP_CASES (and TESSERA_SWEEP_SEED, TESSERA_SWEEP_MAX_GENUS) for thousands locally:
//   TESSERA_SWEEP_CASES=2000 build/tests/tessera_tests "[sweep]"
#include "corpus.h"

#include <tessera/fields.h>
#include <tessera/topology.h>

#include <CGAL/boost/graph/copy_face_graph.h>

#include <catch2/catch.hpp>

#include <cstdlib>
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
  std::string name;
};

Sweep_case random_case(std::mt19937& rng, std::size_t max_genus) {
  Sweep_case c;
  auto pick = [&](std::size_t lo, std::size_t hi) {
    return std::uniform_int_distribution<std::size_t>(lo, hi)(rng);
  };
  Genus_surface_options o;
  o.cell_resolution = pick(2, 4);
  o.wall_resolution = pick(1, 2);
  o.subdivision_steps = pick(0, 1);
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
       << o.subdivision_steps << (noisy ? ", noisy" : "") << ", " << num_faces(c.mesh) << " faces";
  c.name = name.str();
  return c;
}

} // namespace

TEST_CASE("random surfaces: every cut, quadrangulation and field validates", "[sweep]") {
  const std::size_t cases = env_or("TESSERA_SWEEP_CASES", 24);
  const std::size_t seed = env_or("TESSERA_SWEEP_SEED", 2026);
  const std::size_t max_genus = env_or("TESSERA_SWEEP_MAX_GENUS", 6);
  std::mt19937 rng{static_cast<unsigned>(seed)};
  std::size_t cuts = 0, quads = 0, fields = 0;
  for (std::size_t i = 0; i < cases; ++i) {
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
    }
  }
  UNSCOPED_INFO(cuts << " cuts, " << quads << " quadrangulations, " << fields << " fields");
  CHECK(cuts == cases);
}
