// The smoothest-field solver, eq. 1 of Lai et al. as the reference, and singularity indices.
#include "corpus.h"

#include <tessera/fields.h>

#include <CGAL/boost/graph/generators.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace tessera;
using Constraint = Smoothest_field_solver<Mesh>::Constraint;

namespace {

Mesh::Property_map<Mesh::Vertex_index, Vector_3>
field_map(Mesh& m, const std::string& name = "v:tessera_field") {
  return m.add_property_map<Mesh::Vertex_index, Vector_3>(name, CGAL::NULL_VECTOR).first;
}

// A planar n x n grid in z = 0 with slightly irregular interior vertices.
Mesh planar_patch(int n) {
  Mesh m;
  CGAL::make_grid(
      n, n, m,
      [n](int i, int j) {
        const bool inner = i > 0 && j > 0 && i < n && j < n;
        const double dx = inner ? 0.2 * std::sin(3.0 * i + 7.0 * j) : 0,
                     dy = inner ? 0.2 * std::cos(5.0 * i + j) : 0;
        return Point_3(i + dx, j + dy, 0);
      },
      true);
  return m;
}

// A flat disk of radius 1: the square grid mapped by the elliptical grid mapping, so the boundary
// is a finely sampled circle.
Mesh flat_disk(int n) {
  Mesh m;
  CGAL::make_grid(
      n, n, m,
      [n](int i, int j) {
        const double x = 2.0 * i / n - 1, y = 2.0 * j / n - 1;
        return Point_3(x * std::sqrt(1 - y * y / 2), y * std::sqrt(1 - x * x / 2), 0);
      },
      true);
  return m;
}

double angle_degrees(const Vector_3& a, const Vector_3& b) {
  return std::atan2(std::sqrt(CGAL::cross_product(a, b).squared_length()), a * b) * 180 /
         std::acos(-1.0);
}

// Smallest angle between `d` and one of the n rotations of `x` about `normal` (x tangent).
double symmetric_angle_degrees(const Vector_3& x, const Vector_3& d, const Vector_3& normal,
                               int n) {
  const Vector_3 t = d - (d * normal) * normal;
  double best = 180;
  Vector_3 r = x;
  for (int k = 0; k < n; ++k) {
    best = std::min(best, angle_degrees(r, t));
    r = n == 4 ? CGAL::cross_product(normal, r) : -r;
  }
  return best;
}

std::vector<Tangent_basis<Vector_3>> bases(const Mesh& m) {
  std::vector<Tangent_basis<Vector_3>> basis(num_vertices(m));
  vertex_tangent_bases(m, CGAL::make_property_map(basis));
  return basis;
}

} // namespace

TEST_CASE("a single constraint on a planar patch gives a constant field", "[fields]") {
  Mesh m = planar_patch(12);
  auto field = field_map(m);
  for (int n : {1, 2, 4}) {
    Smoothest_field_options o;
    o.symmetry = n;
    const Vector_3 d(1, 2, 0);
    const auto r = smoothest_field(m, {Constraint{Mesh::Vertex_index(40), d}}, field, o);
    REQUIRE(r);
    CHECK(r.energy == Approx(0).margin(1e-9));
    const auto basis = bases(m);
    for (auto v : vertices(m))
      CHECK(symmetric_angle_degrees(field[v], d, basis[v].normal, n) < 1e-6);
  }
}

TEST_CASE("a field with every vertex hard-constrained is the constraints themselves", "[fields]") {
  // Nothing is left to solve: the empty free block must not reach the factorization (it asserted).
  Mesh m = planar_patch(6);
  auto field = field_map(m);
  std::vector<Constraint> all;
  for (auto v : vertices(m))
    all.push_back({v, Vector_3(1, double(std::size_t(v) % 3), 0)});
  const auto r = smoothest_field(m, all, field, Smoothest_field_options{});
  REQUIRE(r);
  const auto basis = bases(m);
  for (const auto& c : all)
    CHECK(symmetric_angle_degrees(field[c.vertex], c.direction, basis[c.vertex].normal, 4) < 1e-6);
}

TEST_CASE("every hard constraint is met exactly and soft ones are approached", "[fields]") {
  Mesh m;
  make_sphere(m, 1.0, 3);
  auto field = field_map(m);
  std::vector<Constraint> hard;
  for (std::size_t k = 0; k < 8; ++k)
    hard.push_back({Mesh::Vertex_index(k * 71), Vector_3(std::cos(k), std::sin(k), 0.5)});
  for (int n : {1, 2, 4}) {
    INFO("symmetry " << n);
    Smoothest_field_options o;
    o.symmetry = n;
    REQUIRE(smoothest_field(m, hard, field, o));
    const auto basis = bases(m);
    for (const Constraint& c : hard) {
      const Vector_3 nrm = basis[c.vertex].normal, x = field[c.vertex];
      CHECK(std::abs(x.squared_length() - 1) < 1e-12);
      CHECK(std::abs(x * nrm) < 1e-12);
      // Some rotation of x by 2π/n about the normal is the constraint's tangential direction.
      CHECK(symmetric_angle_degrees(x, c.direction, nrm, n) < 1e-7);
    }
  }
  // A strong soft constraint lands close, a weak one less so.
  Smoothest_field_options o;
  o.symmetry = 1;
  const auto basis = bases(m);
  std::vector<Constraint> soft = hard;
  for (double weight : {1e6, 1e-2}) {
    for (auto& c : soft)
      c.kind = Constraint_kind::soft, c.weight = weight;
    REQUIRE(smoothest_field(m, soft, field, o));
    double worst = 0;
    for (const Constraint& c : soft)
      worst = std::max(
          worst, symmetric_angle_degrees(field[c.vertex], c.direction, basis[c.vertex].normal, 1));
    if (weight > 1)
      CHECK(worst < 0.01);
    else
      CHECK(worst > 1);
  }
}

TEST_CASE("the solver reuses its factorization when only constraint values change", "[fields]") {
  Mesh m;
  make_torus(m, 3, 1, 40, 16);
  auto field = field_map(m);
  Smoothest_field_solver<Mesh> solver(m, {});
  std::vector<Constraint> c{{Mesh::Vertex_index(3), Vector_3(1, 0, 0)},
                            {Mesh::Vertex_index(300), Vector_3(0, 1, 0)}};
  auto r1 = solver.solve(c, field);
  REQUIRE(r1);
  CHECK(r1.factorized);
  c[0].direction = Vector_3(0, 0, 1);
  c[1].direction = Vector_3(1, 1, 0);
  auto r2 = solver.solve(c, field);
  REQUIRE(r2);
  CHECK_FALSE(r2.factorized);
  CHECK(solver.number_of_factorizations() == 1);
  // Same answer as a fresh one-shot solve.
  auto fresh = field_map(m, "v:fresh");
  REQUIRE(smoothest_field(m, c, fresh, {}));
  for (auto v : vertices(m))
    CHECK((field[v] - fresh[v]).squared_length() < 1e-20);
  c.push_back({Mesh::Vertex_index(500), Vector_3(0, 0, 1)});
  CHECK(solver.solve(c, field).factorized);
  CHECK(solver.number_of_factorizations() == 2);
}

TEST_CASE("bad constraints and symmetries are reported, not crashed on", "[fields]") {
  Mesh m;
  make_sphere(m, 1.0, 1);
  auto field = field_map(m);
  Smoothest_field_options o;
  o.symmetry = 3;
  CHECK(smoothest_field(m, {}, field, o).status == Field_status::invalid_symmetry);
  CHECK(field_singularities(m, field, 5).status == Field_status::invalid_symmetry);
  o.symmetry = 4;
  const auto far = Mesh::Vertex_index(num_vertices(m) + 10);
  CHECK(smoothest_field(m, {Constraint{far, Vector_3(1, 0, 0)}}, field, o).status ==
        Field_status::invalid_constraint);
  const auto v = Mesh::Vertex_index(0);
  const Vector_3 normal = m.point(v) - CGAL::ORIGIN;
  CHECK(smoothest_field(m, {Constraint{v, normal}}, field, o).status ==
        Field_status::invalid_constraint);
  CHECK(smoothest_field(m, {Constraint{v, Vector_3(NAN, 0, 0)}}, field, o).status ==
        Field_status::invalid_constraint);
  CHECK(smoothest_field(m, {Constraint{v, Vector_3(1, 0, 0), Constraint_kind::soft, -1}}, field, o)
            .status == Field_status::invalid_constraint);
  o.symmetry = 1;
  CHECK(smoothest_field(m, {Constraint{v, Vector_3(0, 1, 0)}, Constraint{v, Vector_3(0, -1, 0)}},
                        field, o)
            .status == Field_status::conflicting_constraints);
}

TEST_CASE("the solve's energy is not above eq. 1's converged energy", "[fields]") {
  Mesh sphere;
  make_sphere(sphere, 1.0, 2);
  Mesh patch = planar_patch(8);
  for (Mesh* m : {&sphere, &patch}) {
    auto solved = field_map(*m, "v:solved");
    auto iterated = field_map(*m, "v:iterated");
    std::vector<Constraint> c{{Mesh::Vertex_index(5), Vector_3(1, 0, 0)},
                              {Mesh::Vertex_index(num_vertices(*m) - 7), Vector_3(0.3, 1, 0.2)},
                              {Mesh::Vertex_index(num_vertices(*m) / 2), Vector_3(-1, 0.5, 0)}};
    Smoothest_field_options o;
    o.symmetry = 1;
    o.normalize = false;
    const auto r = smoothest_field(*m, c, solved, o);
    REQUIRE(r);
    CHECK(field_energy(*m, solved, 1) == Approx(r.energy).epsilon(1e-12));
    Lai_iteration_options lo;
    lo.tolerance = 1e-12;
    lo.max_iterations = 400000;
    const auto it = lai_iteration_field(*m, c, iterated, lo);
    REQUIRE(it);
    CHECK(it.converged);
    const double eq1 = field_energy(*m, iterated, 1);
    CHECK(r.energy <= eq1 * (1 + 1e-9));
    if (m == &patch) {
      // On a plane projection is transport: eq. 1's fixed point is the same minimiser.
      CHECK(eq1 == Approx(r.energy).epsilon(1e-6));
      for (auto v : vertices(*m))
        CHECK((solved[v] - iterated[v]).squared_length() < 1e-10);
    }
  }
}

TEST_CASE("Poincaré–Hopf holds on closed and bordered surfaces", "[fields][singularities]") {
  std::vector<test::Corpus_entry> corpus;
  Mesh sphere, torus;
  make_sphere(sphere, 1.0, 3);
  make_torus(torus, 3, 1, 40, 16);
  corpus.push_back({"sphere", sphere, 0, 0});
  corpus.push_back({"torus", torus, 1, 0});
  for (auto& e : test::generated_corpus(2, 2))
    corpus.push_back(e);
  corpus.push_back({"eight.off", test::load("eight.off"), 2, 0});
  corpus.push_back({"pig.off", test::load("pig.off"), 0, 7});
  for (auto& e : corpus) {
    auto field = field_map(e.mesh);
    const long chi = 2 - 2 * e.genus - long(e.boundaries);
    for (int n : {1, 2, 4})
      for (bool constrained : {false, true}) {
        INFO(e.name << " symmetry " << n << (constrained ? " constrained" : " smoothest"));
        std::vector<Constraint> c;
        if (constrained)
          for (std::size_t k = 0; k < 5; ++k)
            c.push_back(
                {Mesh::Vertex_index(k * num_vertices(e.mesh) / 5), Vector_3(1, k * 0.5, 0.3)});
        Smoothest_field_options o;
        o.symmetry = n;
        REQUIRE(smoothest_field(e.mesh, c, field, o));
        const auto s = field_singularities(e.mesh, field, n);
        REQUIRE(s);
        CHECK(s.integrality_defect < 1e-6);
        CHECK(s.euler_characteristic == chi);
        CHECK(s.boundary_loops.size() == e.boundaries);
        CHECK(s.face_index_sum + s.boundary_index_sum == n * chi);
        if (e.boundaries == 0)
          CHECK(s.face_index_sum == n * chi);
      }
  }
}

TEST_CASE("the smoothest cross field on a sphere has eight +1/4 singularities",
          "[fields][singularities]") {
  Mesh m;
  make_sphere(m, 1.0, 3);
  auto field = field_map(m);
  REQUIRE(smoothest_field(m, {}, field, {}));
  const auto s = field_singularities(m, field, 4);
  REQUIRE(s.singularities.size() == 8);
  for (const auto& sing : s.singularities)
    CHECK(sing.numerator == 1);
}

TEST_CASE("a field tangent to a disk's boundary has boundary index 0", "[fields][singularities]") {
  Mesh m = flat_disk(16);
  auto field = field_map(m);
  const auto lines = feature_lines(m);
  REQUIRE(lines.size() == 1);
  for (int n : {1, 2, 4}) {
    Smoothest_field_options o;
    o.symmetry = n;
    REQUIRE(smoothest_field(
        m, feature_alignment_constraints(m, lines, {Feature_alignment::parallel}), field, o));
    const auto s = field_singularities(m, field, n);
    REQUIRE(s.boundary_loops.size() == 1);
    CHECK(s.boundary_loops[0].numerator == 0);
    CHECK(s.face_index_sum == n);
  }
}

TEST_CASE("the orthogonal field is N x X", "[fields]") {
  Mesh m;
  make_sphere(m, 1.0, 2);
  auto field = field_map(m);
  auto ortho = field_map(m, "v:ortho");
  Smoothest_field_options o;
  o.symmetry = 1;
  REQUIRE(smoothest_field(m, {Constraint{Mesh::Vertex_index(0), Vector_3(1, 0, 0)}}, field, o));
  orthogonal_field(m, field, ortho);
  for (auto v : vertices(m)) {
    CHECK(std::abs(field[v] * ortho[v]) < 1e-12);
    CHECK(ortho[v].squared_length() == Approx(field[v].squared_length()));
  }
}
