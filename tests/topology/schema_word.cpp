// The cut-and-paste normalization on words alone (no mesh): every one-vertex word of an orientable
// closed surface must come out canonical, each move must keep the surface (one vertex, the same
// genus), and the moves must be at most two per handle.
#include <tessera/topology/internal/schema_word.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>
#include <random>
#include <string>
#include <vector>

using namespace tessera::internal;

namespace {

// Vertex classes of the polygon's corners once its sides are glued in pairs (corner i is where side
// i starts); a border side glues nothing.
std::size_t vertex_classes(const Schema_word& w) {
  const std::size_t n = w.size();
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  const auto find = [&](std::size_t x) {
    while (parent[x] != x)
      x = parent[x] = parent[parent[x]];
    return x;
  };
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> ends;
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t tail = i, head = (i + 1) % n;
    if (w[i].inverse)
      std::swap(tail, head);
    if (ends.size() <= w[i].letter)
      ends.resize(w[i].letter + 1);
    ends[w[i].letter].push_back({tail, head});
  }
  for (const auto& e : ends)
    if (e.size() == 2) {
      parent[find(e[0].first)] = find(e[1].first);
      parent[find(e[0].second)] = find(e[1].second);
    }
  std::size_t classes = 0;
  for (std::size_t i = 0; i < n; ++i)
    classes += find(i) == i ? 1 : 0;
  return classes;
}

std::string canonical_text(std::size_t genus) {
  std::string out;
  for (std::size_t k = 1; k <= genus; ++k) {
    const std::string a = "a" + std::to_string(k), b = "b" + std::to_string(k);
    out += (k > 1 ? " " : "") + a + " " + b + " " + a + "^-1 " + b + "^-1";
  }
  return out;
}

} // namespace

TEST_CASE("cut-and-paste makes every one-vertex schema word canonical", "[topology][canonical]") {
  std::mt19937 rng(12);
  std::size_t words = 0, bordered = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const std::size_t genus = 1 + rng() % 6;
    Schema_word w;
    for (std::size_t l = 0; l < 2 * genus; ++l) {
      w.push_back({l, false});
      w.push_back({l, true});
    }
    std::shuffle(w.begin(), w.end(), rng);
    // A random pairing of 4g sides is a closed orientable surface; keep those whose corners are
    // all one vertex (the polygonal schemata), whose genus is then g by Euler's formula.
    if (vertex_classes(w) != 1)
      continue;
    ++words;
    // Every other word gets holes: blocks c h c^-1 or nested c1 h1 c2 h2 c2^-1 c1^-1 (h a border
    // side) inserted at random corners, as a schema of a bordered surface joins its holes.
    std::size_t holes = 0, borders = 0, next = 2 * genus;
    if (words % 2 == 0) {
      holes = 1 + rng() % 4;
      ++bordered;
    }
    for (std::size_t k = 0; k < holes; ++k) {
      Schema_word block{{next, false}, {next + 1, false}, {next, true}};
      if (rng() % 2 == 0)
        block = {{next, false},     {next + 1, false}, {next + 2, false},
                 {next + 3, false}, {next + 2, true},  {next, true}};
      next += block.size() == 3 ? 2 : 4;
      borders += block.size() == 3 ? 1 : 2;
      w.insert(w.begin() + long(rng() % (w.size() + 1)), block.begin(), block.end());
    }
    const std::size_t classes = vertex_classes(w);
    const Canonical_plan plan = plan_canonical_schema(w, next);
    INFO(word_text(w) << " -> " << word_text(plan.word));
    REQUIRE(plan.commutators == genus);
    const std::string text = word_text(plan.word, plan.first_commutator);
    if (holes == 0) {
      CHECK(text == canonical_text(genus));
      CHECK(plan.moves.size() <= 2 * genus);
    } else {
      // The commutators first, in one run; the holes' blocks after them.
      CHECK(text.rfind(canonical_text(genus) + " ", 0) == 0);
      CHECK(std::size_t(std::count(text.begin(), text.end(), 'B')) == borders);
      CHECK(plan.moves.size() <= 2 * genus + 3 * (genus - 1));
    }
    // Replaying the moves gives the planned word, and every intermediate polygon is still the
    // same surface: as many sides, glued into as many vertices.
    Schema_word replay = w;
    for (const Cut_and_paste_move& m : plan.moves) {
      REQUIRE(m.to - m.from >= 2);
      REQUIRE(m.to - m.from <= replay.size() - 2);
      replay = cut_and_paste(replay, m);
      REQUIRE(replay.size() == w.size());
      REQUIRE(vertex_classes(replay) == classes);
    }
    CHECK(replay == plan.word);
  }
  CHECK(words > 1000);
  CHECK(bordered > 500);
}

TEST_CASE("one cut-and-paste move, by hand", "[topology][canonical]") {
  // x A y B x^-1 C y^-1 D with one letter per block (A = 4, B = 5, C = 6, D = 7, borders): the
  // diagonal c = 8 from before x to after x^-1, glued along y, gives D c C B x^-1 c^-1 x A.
  const Schema_word w{{0, false}, {4, false}, {1, false}, {5, false},
                      {0, true},  {6, false}, {1, true},  {7, false}};
  const Schema_word expected{{7, false}, {8, false}, {6, false}, {5, false},
                             {0, true},  {8, true},  {0, false}, {4, false}};
  CHECK(cut_and_paste(w, {0, 5, 1, 8}) == expected);
  // Border letters (once each) are never glued, and a pair c h c^-1 that is linked with nothing
  // is left whole: the torus with two holes, x c h c^-1 y x^-1 d k d^-1 y^-1, becomes one
  // commutator followed by the two holes' blocks.
  const Schema_word holed{{0, false}, {2, false}, {3, false}, {2, true}, {1, false},
                          {0, true},  {4, false}, {5, false}, {4, true}, {1, true}};
  const Canonical_plan plan = plan_canonical_schema(holed, 6);
  CHECK(plan.commutators == 1);
  CHECK(plan.moves.size() == 2);
  CHECK(word_text(plan.word, plan.first_commutator) == "a1 b1 a1^-1 b1^-1 a2 B a2^-1 b2 B b2^-1");
}
