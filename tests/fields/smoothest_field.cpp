// The smoothest-field solver, eq. 1 of Lai et al. as the reference, and singularity indices.
#include "corpus.h"

#include <tessera/blas_threads.h>
#include <tessera/fields.h>

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>

#include <catch2/catch.hpp>

#include <dlfcn.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <utility>
#include <vector>

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

TEST_CASE("set_blas_threads sets OpenBLAS's threads when OpenBLAS is the loaded BLAS", "[fields]") {
  REQUIRE_FALSE(tessera::set_blas_threads(0));
  if (tessera::blas_threads() == 0) {
    // Another BLAS (or none loaded): nothing to set, and the call says so.
    REQUIRE_FALSE(tessera::set_blas_threads(1));
    return;
  }
  REQUIRE(tessera::set_blas_threads(1));
  CHECK(tessera::blas_threads() == 1);
  // CHOLMOD loads OpenMP (Debian builds it so): its loops then take only the idle cores.
  if (dlsym(RTLD_DEFAULT, "omp_get_dynamic") != nullptr)
    CHECK(tessera::openmp_dynamic_threads());
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
  auto fresh = field_map(m, "v:tessera_fresh");
  REQUIRE(smoothest_field(m, c, fresh, {}));
  for (auto v : vertices(m))
    CHECK((field[v] - fresh[v]).squared_length() < 1e-20);
  c.push_back({Mesh::Vertex_index(500), Vector_3(0, 0, 1)});
  const auto r3 = solver.solve(c, field);
  CHECK(r3.factorized);
  CHECK_FALSE(r3.analysis_reused); // a new hard vertex: another pattern
  CHECK(solver.number_of_factorizations() == 2);

  // New soft weights on the same hard vertices: factorized again, numerically only, and still the
  // answer of a new solver (a stale factorization, or one of the old pattern's values, is not).
  for (double weight : {0.3, 5.0}) {
    auto soft = c;
    for (std::size_t k = 0; k < 40; ++k)
      soft.push_back({Mesh::Vertex_index(7 + 13 * k), Vector_3(std::cos(0.1 * double(k)), 1, 0),
                      Constraint_kind::soft, weight});
    const auto r = solver.solve(soft, field);
    REQUIRE(r);
    CHECK(r.factorized);
    CHECK(r.analysis_reused);
    REQUIRE(smoothest_field(m, soft, fresh, {}));
    double worst = 0;
    for (auto v : vertices(m))
      worst = std::max(worst, (field[v] - fresh[v]).squared_length());
    INFO("soft weight " << weight);
    CHECK(worst < 1e-20);
  }
  CHECK(solver.number_of_factorizations() == 4);

  // Soft weights on every vertex hold the system: conjugate gradients from the last field solve it,
  // with no factorization, to the answer of a new solver (which, having no field to start from,
  // factorizes). Capped at two iterations they do not converge, and the solve factorizes.
  auto held = c;
  for (auto v : vertices(m))
    held.push_back(
        {v, Vector_3(1, 0.5, std::sin(0.01 * double(v.idx()))), Constraint_kind::soft, 0.2});
  const auto rh = solver.solve(held, field);
  REQUIRE(rh);
  CHECK(rh.solver == "Eigen ConjugateGradient");
  CHECK_FALSE(rh.factorized);
  CHECK(rh.iterative_iterations > 0);
  CHECK(solver.number_of_factorizations() == 4);
  const auto fresh_held = smoothest_field(m, held, fresh, {});
  REQUIRE(fresh_held);
  CHECK(fresh_held.factorized);
  CHECK(fresh_held.iterative_iterations == 0);
  auto differs_by = [&] {
    double worst = 0;
    for (auto v : vertices(m))
      worst = std::max(worst, (field[v] - fresh[v]).squared_length());
    return worst;
  };
  CHECK(differs_by() < 1e-16);
  Smoothest_field_options capped;
  capped.iterative_iterations = 2;
  Smoothest_field_solver<Mesh> short_of_it(m, capped);
  REQUIRE(short_of_it.solve(c, field));
  const auto rc = short_of_it.solve(held, field);
  REQUIRE(rc);
  CHECK(rc.factorized);
  CHECK(rc.iterative_iterations == 2);
  CHECK(differs_by() < 1e-16);
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

TEST_CASE("a surface with no area gives an error, not a field of NaNs", "[fields]") {
  // read_mesh refuses such a file; a library user can still build one. Before the check the
  // solve returned status ok with every vector NaN (found by tests/cli/degenerate.sh).
  Mesh m;
  make_sphere(m, 1.0, 1);
  for (auto v : vertices(m))
    m.point(v) = Point_3(m.point(v).x(), 0, 0); // every vertex on the x axis
  auto field = field_map(m);
  const auto r = smoothest_field(m, {}, field);
  INFO(r.message);
  CHECK(r.status == Field_status::solver_failed);
}

TEST_CASE("the solve's energy is not above eq. 1's converged energy", "[fields]") {
  Mesh sphere;
  make_sphere(sphere, 1.0, 2);
  Mesh patch = planar_patch(8);
  for (Mesh* m : {&sphere, &patch}) {
    auto solved = field_map(*m, "v:tessera_solved");
    auto iterated = field_map(*m, "v:tessera_iterated");
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

TEST_CASE("the inverse power iteration stops at its tolerance with the converged field",
          "[fields]") {
  // The default tolerance against iterations run to the limit of double precision: the energy
  // (a Rayleigh quotient, second order in the error) agrees, the vectors nearly so, in fewer
  // solves; a tolerance of 1 stops after the first.
  const Mesh m = test::load("eight.off");
  Mesh a = m, b = m;
  auto fa = field_map(a), fb = field_map(b);
  Smoothest_field_options tight;
  tight.eigen_tolerance = 1e-15;
  tight.eigen_iterations = 300;
  const auto converged = smoothest_field(b, {}, fb, tight);
  REQUIRE(converged);
  const auto r = smoothest_field(a, {}, fa, {});
  REQUIRE(r);
  CHECK(r.eigen_iterations >= 2);
  CHECK(r.eigen_iterations < converged.eigen_iterations);
  CHECK(r.energy == Approx(converged.energy).epsilon(1e-6));
  const auto basis = bases(a);
  double mean = 0; // degrees between the two crosses
  for (auto v : vertices(a))
    mean += symmetric_angle_degrees(fa[v], fb[v], basis[v].normal, 4) / double(num_vertices(a));
  CHECK(mean < 0.5);
  Smoothest_field_options loose;
  loose.eigen_tolerance = 1;
  const auto once = smoothest_field(a, {}, fa, loose);
  REQUIRE(once);
  CHECK(once.eigen_iterations == 1);
  CHECK(once.energy > r.energy);
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
  auto ortho = field_map(m, "v:tessera_orthogonal");
  Smoothest_field_options o;
  o.symmetry = 1;
  REQUIRE(smoothest_field(m, {Constraint{Mesh::Vertex_index(0), Vector_3(1, 0, 0)}}, field, o));
  orthogonal_field(m, field, ortho);
  for (auto v : vertices(m)) {
    CHECK(std::abs(field[v] * ortho[v]) < 1e-12);
    CHECK(ortho[v].squared_length() == Approx(field[v].squared_length()));
  }
}

TEST_CASE("fields read a user's vertex_point_map", "[fields]") {
  // The surface rotated by 90° about x in a second point map: the field solved there, with its
  // constraint rotated too, is the rotated field, and the singularities are the same faces. A
  // solver that read the mesh's own points would project the rotated constraint onto the wrong
  // tangent planes.
  Mesh m = test::load("eight.off");
  auto rotate = [](const Vector_3& a) { return Vector_3(a.x(), -a.z(), a.y()); };
  auto rotated = m.add_property_map<Mesh::Vertex_index, Point_3>("v:tessera_rotated").first;
  for (auto v : vertices(m))
    rotated[v] = CGAL::ORIGIN + rotate(m.point(v) - CGAL::ORIGIN);
  const auto np = CGAL::parameters::vertex_point_map(rotated);
  auto plain = field_map(m, "v:tessera_plain");
  auto user = field_map(m, "v:tessera_user");
  const Mesh::Vertex_index c(10);
  const Vector_3 normal = CGAL::Polygon_mesh_processing::compute_vertex_normal(c, m);
  const Vector_3 d = CGAL::cross_product(normal, Vector_3(0.3, 1, 0.2));
  Smoothest_field_options o;
  o.symmetry = 4;
  REQUIRE(smoothest_field(m, {Constraint{c, d}}, plain, o));
  REQUIRE(smoothest_field(m, {Constraint{c, rotate(d)}}, user, o, np));
  double worst = 0;
  for (auto v : vertices(m))
    worst = std::max(worst, std::sqrt((user[v] - rotate(plain[v])).squared_length()));
  CHECK(worst < 1e-9);
  const auto sp = field_singularities(m, plain, 4);
  const auto su = field_singularities(m, user, 4, np);
  REQUIRE(sp.singularities.size() == su.singularities.size());
  for (std::size_t i = 0; i < sp.singularities.size(); ++i) {
    CHECK(sp.singularities[i].face == su.singularities[i].face);
    CHECK(sp.singularities[i].numerator == su.singularities[i].numerator);
  }
  CHECK(field_energy(m, user, 4, np) == Approx(field_energy(m, plain, 4)).epsilon(1e-9));
}

namespace {

// Distance from `b` to the nearest of the n rotations of `a` about `normal` (`a` tangent): two
// meshes may measure a field's angles from different edges and so store another of its n vectors.
double symmetric_distance(const Vector_3& a, const Vector_3& b, const Vector_3& normal, int n) {
  const Vector_3 a_perp = CGAL::cross_product(normal, a);
  double best = std::numeric_limits<double>::max();
  for (int k = 0; k < n; ++k) {
    const double t = 2 * std::acos(-1.0) * k / n;
    best = std::min(best, std::sqrt((std::cos(t) * a + std::sin(t) * a_perp - b).squared_length()));
  }
  return best;
}

// The singular faces of `s` as (sorted vertex ids, index numerator), sorted: comparable across
// meshes whose vertices `id` numbers alike.
template <typename TriangleMesh, typename VertexId>
std::vector<std::pair<std::array<std::size_t, 3>, int>>
singular_faces(const TriangleMesh& tm, const Field_singularities<TriangleMesh>& s, VertexId id) {
  std::vector<std::pair<std::array<std::size_t, 3>, int>> out;
  for (const auto& f : s.singularities) {
    std::array<std::size_t, 3> ids{};
    std::size_t k = 0;
    for (auto v : vertices_around_face(halfedge(f.face, tm), tm))
      if (k < 3)
        ids[k++] = id(v);
    std::sort(ids.begin(), ids.end());
    out.push_back({ids, f.numerator});
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Hausdorff distance between the points of two scenes' polylines and dots (two meshes may list
// their vertices and faces in different orders); brute force, for small scenes.
double scene_distance(const Render_scene& a, const Render_scene& b) {
  auto points = [](const Render_scene& scene) {
    std::vector<std::array<double, 3>> out;
    for (const auto& line : scene.polylines)
      out.insert(out.end(), line.points.begin(), line.points.end());
    for (const auto& point : scene.points)
      out.push_back(point.position);
    return out;
  };
  auto one_way = [](const auto& from, const auto& to) {
    double worst = 0;
    for (const auto& p : from) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const auto& q : to)
        nearest = std::min(nearest, (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                                        (p[2] - q[2]) * (p[2] - q[2]));
      worst = std::max(worst, nearest);
    }
    return std::sqrt(worst);
  };
  const auto pa = points(a), pb = points(b);
  return std::max(one_way(pa, pb), one_way(pb, pa));
}

} // namespace

TEST_CASE("fields, singularities and strokes on Polyhedron_3 agree with Surface_mesh",
          "[fields][singularities][polyhedron]") {
  using Polyhedron = CGAL::Polyhedron_3<Kernel>;
  using Poly_vertex = boost::graph_traits<Polyhedron>::vertex_descriptor;
  struct Case {
    const char* file;
    long euler_characteristic;
  };
  for (const Case& c : {Case{"eight.off", -2}, Case{"mesh_with_border.off", 1}}) {
    Mesh mesh = test::load(c.file);
    Polyhedron poly;
    std::vector<std::pair<Mesh::Vertex_index, Poly_vertex>> copied;
    CGAL::copy_face_graph(
        mesh, poly, CGAL::parameters::vertex_to_vertex_output_iterator(std::back_inserter(copied)));
    REQUIRE(copied.size() == num_vertices(mesh));
    // The Surface_mesh vertex of every Polyhedron_3 vertex, and back.
    auto mesh_id = get(CGAL::dynamic_vertex_property_t<std::size_t>(), poly);
    std::vector<Poly_vertex> poly_vertex(num_vertices(mesh));
    for (const auto& [mv, pv] : copied) {
      put(mesh_id, pv, std::size_t(mv));
      poly_vertex[std::size_t(mv)] = pv;
    }
    std::vector<Tangent_basis<Vector_3>> basis(num_vertices(mesh));
    vertex_tangent_bases(mesh, CGAL::make_property_map(basis));

    // Four hard controls and a soft one, at the same vertices of both meshes.
    std::vector<Constraint> mesh_constraints;
    std::vector<Smoothest_field_solver<Polyhedron>::Constraint> poly_constraints;
    for (std::size_t k = 0; k < 5; ++k) {
      const std::size_t v = k * num_vertices(mesh) / 5;
      const Vector_3 d(1, k * 0.5, 0.3);
      const Constraint_kind kind = k == 4 ? Constraint_kind::soft : Constraint_kind::hard;
      const double weight = k == 4 ? 2 : 1;
      mesh_constraints.push_back({Mesh::Vertex_index(std::uint32_t(v)), d, kind, weight});
      poly_constraints.push_back({poly_vertex[v], d, kind, weight});
    }
    auto mesh_field = field_map(mesh);
    auto poly_field = get(CGAL::dynamic_vertex_property_t<Vector_3>(), poly);
    for (int n : {1, 2, 4}) {
      Smoothest_field_options o;
      o.symmetry = n;
      const Smoothest_field_result rm = smoothest_field(mesh, mesh_constraints, mesh_field, o);
      const Smoothest_field_result rp = smoothest_field(poly, poly_constraints, poly_field, o);
      REQUIRE(rm);
      REQUIRE(rp);
      double worst = 0;
      for (auto pv : vertices(poly)) {
        const std::size_t i = get(mesh_id, pv);
        worst = std::max(worst, symmetric_distance(mesh_field[Mesh::Vertex_index(std::uint32_t(i))],
                                                   get(poly_field, pv), basis[i].normal, n));
      }
      const auto sm = field_singularities(mesh, mesh_field, n);
      const auto sp = field_singularities(poly, poly_field, n);
      REQUIRE(sm);
      REQUIRE(sp);
      const auto faces_m =
          singular_faces(mesh, sm, [](Mesh::Vertex_index v) { return std::size_t(v); });
      const auto faces_p = singular_faces(poly, sp, [&](Poly_vertex v) { return get(mesh_id, v); });
      std::vector<int> loops_m, loops_p;
      for (const auto& b : sm.boundary_loops)
        loops_m.push_back(b.numerator);
      for (const auto& b : sp.boundary_loops)
        loops_p.push_back(b.numerator);
      std::sort(loops_m.begin(), loops_m.end());
      std::sort(loops_p.begin(), loops_p.end());
      // Strokes and singularity dots, the Polyhedron_3's through an explicit vertex_point_map.
      Render_scene scene_m, scene_p;
      add_field(scene_m, mesh, mesh_field, sm);
      add_field(scene_p, poly, poly_field, sp, {},
                CGAL::parameters::vertex_point_map(get(CGAL::vertex_point, poly)));
      const double stroke_difference = scene_distance(scene_m, scene_p);
      INFO(c.file << " symmetry " << n << ": field differs by up to " << worst << ", energy "
                  << rm.energy << " / " << rp.energy << ", " << sm.singularities.size() << " / "
                  << sp.singularities.size() << " singular faces, index sums " << sm.face_index_sum
                  << "+" << sm.boundary_index_sum << " / " << sp.face_index_sum << "+"
                  << sp.boundary_index_sum << ", strokes " << scene_m.polylines.size() << " / "
                  << scene_p.polylines.size() << " differing by up to " << stroke_difference);
      CHECK(worst < 1e-9);
      CHECK(rp.energy == Approx(rm.energy).epsilon(1e-9));
      CHECK(sp.euler_characteristic == c.euler_characteristic);
      CHECK(sp.face_index_sum + sp.boundary_index_sum == n * c.euler_characteristic);
      CHECK(faces_p == faces_m);
      CHECK(loops_p == loops_m);
      // A line's or cross's strokes are the same segments whichever of its n vectors is stored.
      CHECK(scene_p.polylines.size() == scene_m.polylines.size());
      CHECK(scene_p.points.size() == scene_m.points.size());
      CHECK(stroke_difference < 1e-9);
    }
  }
}
