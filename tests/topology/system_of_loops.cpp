// The greedy system of loops: 2g loops through the basepoint, each closed, and the shortest loop on
// a torus of revolution is the meridian.
#include "corpus.h"

#include <tessera/topology/edge_cost.h>
#include <tessera/topology/system_of_loops.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace tessera;

namespace {
template <typename Loop>
bool is_closed_walk_at(const Mesh& m, const Loop& loop, Mesh::Vertex_index b) {
  if (loop.empty() || source(loop.front(), m) != b || target(loop.back(), m) != b)
    return false;
  for (std::size_t i = 1; i < loop.size(); ++i)
    if (source(loop[i], m) != target(loop[i - 1], m))
      return false;
  return true;
}
} // namespace

TEST_CASE("the greedy system of loops has 2g closed loops at the basepoint", "[topology]") {
  for (auto& e : test::generated_corpus(4, 2)) {
    INFO(e.name);
    auto cost = e.mesh.add_property_map<Mesh::Edge_index, double>("e:tessera_cost").first;
    compute_edge_costs(e.mesh, cost);
    const auto b = *vertices(e.mesh).begin();
    const auto sys = greedy_system_of_loops(e.mesh, b, cost);
    CHECK(long(sys.loops.size()) == 2 * e.genus);
    for (std::size_t i = 0; i < sys.loops.size(); ++i) {
      CHECK(is_closed_walk_at(e.mesh, sys.loops[i], b));
      double len = 0;
      for (auto h : sys.loops[i])
        len += cost[edge(h, e.mesh)];
      CHECK(len == Approx(sys.lengths[i]));
      if (i > 0)
        CHECK(sys.lengths[i - 1] <= sys.lengths[i]);
    }
  }
}

TEST_CASE("the shortest loop of a torus of revolution is the meridian", "[topology]") {
  const double pi = std::acos(-1.0), R = 3.0, r = 1.0;
  Mesh torus;
  make_torus(torus, R, r, 120, 60);
  auto cost = torus.add_property_map<Mesh::Edge_index, double>("e:tessera_cost").first;
  compute_edge_costs(torus, cost);
  const auto sys = greedy_system_of_loops(torus, *vertices(torus).begin(), cost);
  REQUIRE(sys.loops.size() == 2);
  // The inscribed 60-gon of the tube circle: 2 r sin(pi/60) * 60.
  CHECK(sys.lengths[0] == Approx(2 * r * std::sin(pi / 60) * 60).epsilon(1e-9));
  CHECK(sys.lengths[0] == Approx(2 * pi * r).epsilon(2e-3));
  // The second loop goes around the axis: at least the inner equator 2 pi (R - r).
  CHECK(sys.lengths[1] >= 2 * pi * (R - r) * 0.99);
}
