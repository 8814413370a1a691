// The field-aligned position field of the surface mosaic's first layout: a hierarchy of merged
// vertices, Gauss-Seidel smoothing of lattice positions from the coarsest level down, and the
// lattice points of each face (Jakob et al. 2015, §4-§5; see the header).
#include <tessera/mosaic/internal/position_field.h>

#include <tessera/internal/parallel.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <unordered_map>
#include <utility>

namespace tessera::internal {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

Vec3 normalized(const Vec3& v) {
  const double l = norm(v);
  return l > 0 ? (1 / l) * v : v;
}

// A unit vector of the plane with unit normal n, as close to v as possible (any one when v is
// normal to the plane).
Vec3 in_plane(const Vec3& v, const Vec3& n) {
  Vec3 t = v - dot(v, n) * n;
  if (norm(t) > 1e-12 * (norm(v) + 1e-300))
    return normalized(t);
  t = cross(n, std::abs(n[0]) < 0.9 ? Vec3{{1, 0, 0}} : Vec3{{0, 1, 0}});
  return normalized(t);
}

// One level of the hierarchy. Nodes carry a point x, a unit normal n, a unit direction o in their
// tangent plane (the lattice's first axis; the second is n × o), an area, their neighbours (CSR),
// and up to two directions of feature lines through them (zero vectors when fewer).
struct Level {
  std::vector<Vec3> x, n, o;
  std::vector<double> area;
  std::vector<std::uint32_t> offsets, neighbors;
  std::vector<std::array<Vec3, 2>> features;
  std::vector<std::uint32_t> parent; // node of the next coarser level
  // Set by `hierarchy()` for the sweeps: each node's second axis n × o, and the phases of nodes
  // that can be updated at once (the same for every solve on the level).
  std::vector<Vec3> t;
  std::vector<std::vector<std::uint32_t>> phases;
  std::size_t size() const { return x.size(); }
};

// Adds direction d to a node's feature directions unless one within 30° (as lines) is there.
void add_feature_direction(std::array<Vec3, 2>& f, const Vec3& d) {
  for (Vec3& e : f) {
    if (norm(e) == 0) {
      e = d;
      return;
    }
    if (std::abs(dot(e, d)) > 0.866)
      return;
  }
}

Level finest_level(const Position_field_surface& s) {
  Level l;
  const std::size_t nv = s.points.size();
  l.x = s.points;
  l.n.resize(nv);
  l.o.resize(nv);
  l.area.assign(nv, 0);
  std::vector<Vec3> normal_sum(nv, Vec3{{0, 0, 0}});
  std::vector<std::vector<std::uint32_t>> adjacent(nv);
  for (std::size_t f = 0; f < s.faces.size(); ++f) {
    const auto& c = s.faces[f];
    const double a =
        0.5 * norm(cross(s.points[c[1]] - s.points[c[0]], s.points[c[2]] - s.points[c[0]]));
    for (int k = 0; k < 3; ++k) {
      l.area[c[k]] += a / 3;
      adjacent[c[k]].push_back(c[(k + 1) % 3]);
      adjacent[c[k]].push_back(c[(k + 2) % 3]);
    }
  }
  l.offsets.assign(1, 0);
  for (std::size_t v = 0; v < nv; ++v) {
    auto& a = adjacent[v];
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
    l.neighbors.insert(l.neighbors.end(), a.begin(), a.end());
    l.offsets.push_back(std::uint32_t(l.neighbors.size()));
    l.n[v] = normalized(s.normals[v]);
    if (!(norm(l.n[v]) > 0.5))
      l.n[v] = Vec3{{0, 0, 1}};
    l.o[v] = in_plane(s.directions[v], l.n[v]);
  }
  l.features.assign(nv, {{Vec3{{0, 0, 0}}, Vec3{{0, 0, 0}}}});
  for (const auto& e : s.feature_edges) {
    const Vec3 d = normalized(s.points[e[1]] - s.points[e[0]]);
    if (norm(d) == 0)
      continue;
    add_feature_direction(l.features[e[0]], d);
    add_feature_direction(l.features[e[1]], d);
  }
  return l;
}

// The next coarser level: neighbours matched in pairs, normals most alike and areas least alike
// first (as Instant Meshes scores them: dot(nᵢ, nⱼ)·max(Aᵢ/Aⱼ, Aⱼ/Aᵢ)), a node left alone when all
// its neighbours are taken. Small nodes are so merged into a larger neighbour before the larger
// ones pair up among themselves. (Pairing areas alike first left the smallest nodes alone level
// after level while their neighbours merged around them: the bull's 25k nodes stopped shrinking
// at 3.4k, about one per tile, and the 217k of a 40k-tile mesh at 66k, so the coarsest level held
// no global phase and the finer sweeps paid for it: 4.5 s of the 40k start.)
Level coarser_level(Level& fine) {
  struct Pair {
    double score;
    std::uint32_t a, b;
  };
  std::vector<Pair> pairs;
  for (std::uint32_t i = 0; i < fine.size(); ++i)
    for (std::uint32_t k = fine.offsets[i]; k < fine.offsets[i + 1]; ++k) {
      const std::uint32_t j = fine.neighbors[k];
      if (j <= i)
        continue;
      const double ratio = std::max(fine.area[i], fine.area[j]) /
                           std::max(std::min(fine.area[i], fine.area[j]), 1e-300);
      pairs.push_back({dot(fine.n[i], fine.n[j]) * ratio, i, j});
    }
  std::stable_sort(pairs.begin(), pairs.end(),
                   [](const Pair& p, const Pair& q) { return p.score > q.score; });
  const std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  fine.parent.assign(fine.size(), none);
  Level c;
  auto add_node = [&](std::uint32_t a, std::uint32_t b) {
    const std::uint32_t id = std::uint32_t(c.x.size());
    double area = fine.area[a];
    Vec3 x = fine.area[a] * fine.x[a], n = fine.area[a] * fine.n[a];
    std::array<Vec3, 2> f = fine.features[a];
    fine.parent[a] = id;
    if (b != none) {
      area += fine.area[b];
      x = x + fine.area[b] * fine.x[b];
      n = n + fine.area[b] * fine.n[b];
      for (const Vec3& d : fine.features[b])
        if (norm(d) > 0)
          add_feature_direction(f, d);
      fine.parent[b] = id;
    }
    x = area > 0 ? (1 / area) * x : fine.x[a];
    n = normalized(n);
    if (!(norm(n) > 0.5))
      n = fine.n[a];
    const std::uint32_t big = (b != none && fine.area[b] > fine.area[a]) ? b : a;
    c.x.push_back(x);
    c.n.push_back(n);
    c.o.push_back(in_plane(fine.o[big], n));
    c.area.push_back(area);
    c.features.push_back(f);
  };
  for (const Pair& p : pairs)
    if (fine.parent[p.a] == none && fine.parent[p.b] == none)
      add_node(p.a, p.b);
  for (std::uint32_t i = 0; i < fine.size(); ++i)
    if (fine.parent[i] == none)
      add_node(i, none);
  std::vector<std::vector<std::uint32_t>> adjacent(c.size());
  for (std::uint32_t i = 0; i < fine.size(); ++i)
    for (std::uint32_t k = fine.offsets[i]; k < fine.offsets[i + 1]; ++k) {
      const std::uint32_t a = fine.parent[i], b = fine.parent[fine.neighbors[k]];
      if (a != b)
        adjacent[a].push_back(b);
    }
  c.offsets.assign(1, 0);
  for (auto& a : adjacent) {
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
    c.neighbors.insert(c.neighbors.end(), a.begin(), a.end());
    c.offsets.push_back(std::uint32_t(c.neighbors.size()));
  }
  return c;
}

// The lattice of one node: spacings (wx, wy) along o and n × o.
struct Lattice {
  double wx, wy;
  // The lattice point through p (a lattice point) nearest to q.
  Vec3 nearest(const Vec3& p, const Vec3& o, const Vec3& t, const Vec3& q) const {
    const Vec3 d = q - p;
    return p + (wx * std::round(dot(d, o) / wx)) * o + (wy * std::round(dot(d, t) / wy)) * t;
  }
  // The lattice point through p at the lower corner of the cell holding q.
  Vec3 below(const Vec3& p, const Vec3& o, const Vec3& t, const Vec3& q) const {
    const Vec3 d = q - p;
    return p + (wx * std::floor(dot(d, o) / wx)) * o + (wy * std::floor(dot(d, t) / wy)) * t;
  }
};

// The pair of lattice points, one of each node's lattice (through pi and pj), closest to each other
// among the corners of the two cells that hold the nodes' midpoint.
std::pair<Vec3, Vec3> compatible_points(const Lattice& lattice, const Vec3& xi, const Vec3& oi,
                                        const Vec3& ti, const Vec3& pi, const Vec3& xj,
                                        const Vec3& oj, const Vec3& tj, const Vec3& pj) {
  const Vec3 m = 0.5 * (xi + xj);
  const Vec3 bi = lattice.below(pi, oi, ti, m), bj = lattice.below(pj, oj, tj, m);
  // The four corners of each cell, each once (the inner loop computed each of j's four times).
  std::array<Vec3, 4> qi, qj;
  for (int a = 0; a < 4; ++a) {
    qi[std::size_t(a)] = bi + (lattice.wx * (a & 1)) * oi + (lattice.wy * (a >> 1)) * ti;
    qj[std::size_t(a)] = bj + (lattice.wx * (a & 1)) * oj + (lattice.wy * (a >> 1)) * tj;
  }
  std::size_t best_i = 0, best_j = 0;
  double closest = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < 4; ++a)
    for (std::size_t b = 0; b < 4; ++b) {
      const Vec3 d = qi[a] - qj[b];
      const double d2 = dot(d, d);
      if (d2 < closest)
        closest = d2, best_i = a, best_j = b;
    }
  return {qi[best_i], qj[best_j]};
}

// Moves lattice point p of a node so that the node's feature lines run midway between two rows of
// its lattice: along the axis most across each line, the node sits half a spacing off a lattice
// point (a tile's edge then lies half a grout width off the line).
Vec3 align_to_features(const Lattice& lattice, const Level& l, std::uint32_t i, Vec3 p) {
  const Vec3 t = cross(l.n[i], l.o[i]);
  bool done[2] = {false, false};
  for (const Vec3& d : l.features[i]) {
    if (norm(d) == 0)
      break;
    const int axis = std::abs(dot(d, l.o[i])) < std::abs(dot(d, t)) ? 0 : 1;
    // Only a line that runs along the other axis (within 10°) can lie between two rows; the field
    // follows the feature lines it was aligned to, not every open border.
    if (done[axis] || std::abs(dot(d, axis == 0 ? t : l.o[i])) < 0.985)
      continue;
    done[axis] = true;
    const Vec3& a = axis == 0 ? l.o[i] : t;
    const double w = axis == 0 ? lattice.wx : lattice.wy;
    const double c = dot(l.x[i] - p, a) - 0.5 * w;
    p = p + (c - w * std::round(c / w)) * a;
  }
  return p;
}

// The nodes of a level in phases no two neighbours share (a greedy colouring in node order): the
// nodes of one phase can be updated at once. Deterministic, so a result does not depend on the
// number of threads.
std::vector<std::vector<std::uint32_t>> phases_of(const Level& l) {
  std::vector<int> color(l.size(), -1);
  std::vector<std::vector<std::uint32_t>> phases;
  std::vector<char> taken;
  for (std::uint32_t i = 0; i < l.size(); ++i) {
    taken.assign(phases.size() + 1, 0);
    for (std::uint32_t k = l.offsets[i]; k < l.offsets[i + 1]; ++k)
      if (color[l.neighbors[k]] >= 0)
        taken[std::size_t(color[l.neighbors[k]])] = 1;
    std::size_t c = 0;
    while (taken[c])
      ++c;
    if (c == phases.size())
      phases.emplace_back();
    color[i] = int(c);
    phases[c].push_back(i);
  }
  return phases;
}

// Gauss-Seidel sweeps, a phase at a time on every core (Instant Meshes' scheme): each node takes
// the running average of its neighbours' compatible lattice points (the average moved along with
// the node's own lattice), kept in its tangent plane, aligned to its feature lines and stored as
// its lattice point nearest to it. (217k vertices under 40k tiles: 2.5 s on one core, 1.45 s on
// two.)
void smooth(const Lattice& lattice, const Level& l, std::vector<Vec3>& p, int sweeps) {
  const std::vector<Vec3>& t = l.t;
  auto update = [&](std::uint32_t i) {
    const Vec3& ti = t[i];
    Vec3 sum = p[i];
    double weight = 0;
    for (std::uint32_t k = l.offsets[i]; k < l.offsets[i + 1]; ++k) {
      const std::uint32_t j = l.neighbors[k];
      const auto q =
          compatible_points(lattice, l.x[i], l.o[i], ti, sum, l.x[j], l.o[j], t[j], p[j]);
      sum = (1 / (weight + 1)) * (weight * q.first + q.second);
      weight += 1;
      sum = sum - dot(l.n[i], sum - l.x[i]) * l.n[i];
    }
    sum = align_to_features(lattice, l, i, sum);
    p[i] = lattice.nearest(sum, l.o[i], ti, l.x[i]);
  };
  for (int sweep = 0; sweep < sweeps; ++sweep)
    for (const std::vector<std::uint32_t>& phase : l.phases)
      parallel_blocks(
          phase.size(),
          [&](std::size_t first, std::size_t last) {
            for (std::size_t m = first; m < last; ++m)
              update(phase[m]);
          },
          1024);
}

// The direction halfway between a and b as symmetric directions (b turned by the multiple of
// 2π/symmetry nearest to a, in b's plane), in the plane of normal n.
Vec3 middle_direction(const Vec3& a, const Vec3& na, const Vec3& b, const Vec3& nb, int symmetry,
                      const Vec3& n) {
  const Vec3 oa = in_plane(a, na), ob = in_plane(b, nb), tb = cross(nb, ob);
  Vec3 best = ob;
  double most = -2;
  const Vec3 turns[4] = {ob, -1.0 * ob, tb, -1.0 * tb};
  for (int k = 0; k < (symmetry == 4 ? 4 : 2); ++k)
    if (dot(turns[k], oa) > most)
      most = dot(turns[k], oa), best = turns[k];
  return in_plane(oa + best, n);
}

// `s` with every edge longer than `longest` split at its midpoint, again until none is (faces
// split in two, three or four as their edges were, sharing the midpoints); `origin[f]` is the face
// of the input that face f of the result lies in. The position field needs a few vertices per
// lattice cell: on a coarse mesh (the paper's eight holds 10 tiles per vertex) a face's corners
// disagree about the lattice inside it. Stops before the surface exceeds `most_vertices`.
Position_field_surface refined(const Position_field_surface& in, double longest, int symmetry,
                               std::size_t most_vertices, std::vector<std::uint32_t>& origin) {
  Position_field_surface s = in;
  for (Vec3& n : s.normals) {
    n = normalized(n);
    if (!(norm(n) > 0.5))
      n = Vec3{{0, 0, 1}};
  }
  origin.resize(s.faces.size());
  std::iota(origin.begin(), origin.end(), 0u);
  auto key = [](std::uint32_t a, std::uint32_t b) {
    return a < b ? (std::uint64_t(a) << 32) | b : (std::uint64_t(b) << 32) | a;
  };
  std::unordered_map<std::uint64_t, char> features;
  for (const auto& e : s.feature_edges)
    features[key(e[0], e[1])] = 1;
  const double l2 = longest * longest;
  for (int round = 0; round < 16; ++round) {
    // Each long edge's midpoint (its vertex, once added) and the sum of the normals of the faces
    // beside it. The normal of a midpoint: the mean of its ends' normals (smooth over a curved
    // surface), unless that is more than 20° from the mean of the faces beside its edge. (Inside a
    // large flat face the ends' mean tilted every new vertex towards its corners' averaged
    // normals: an open box of 10 triangles under 2000 tiles lost 14 % of its lattice points,
    // coverage 0.75.)
    struct Middle {
      std::uint32_t vertex = 0;
      Vec3 beside{{0, 0, 0}};
    };
    std::unordered_map<std::uint64_t, Middle> middle;
    for (std::size_t f = 0; f < s.faces.size(); ++f)
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t a = s.faces[f][k], b = s.faces[f][(k + 1) % 3];
        const Vec3 d = s.points[b] - s.points[a];
        if (dot(d, d) > l2) {
          Middle& m = middle[key(a, b)];
          m.beside = m.beside + s.face_normals[f];
        }
      }
    if (middle.empty() || s.points.size() + middle.size() > most_vertices)
      break;
    // Midpoints in the order of their edges' keys: the result does not depend on hashing.
    std::vector<std::uint64_t> keys;
    for (const auto& m : middle)
      keys.push_back(m.first);
    std::sort(keys.begin(), keys.end());
    for (const std::uint64_t k : keys) {
      const std::uint32_t a = std::uint32_t(k >> 32), b = std::uint32_t(k & 0xffffffffu);
      const std::uint32_t m = std::uint32_t(s.points.size());
      Middle& edge = middle[k];
      edge.vertex = m;
      const Vec3 ends = normalized(s.normals[a] + s.normals[b]), faces = normalized(edge.beside);
      const Vec3 n = norm(faces) > 0.5 && !(dot(ends, faces) > 0.94) ? faces : ends;
      s.points.push_back(0.5 * (s.points[a] + s.points[b]));
      s.normals.push_back(norm(n) > 0.5 ? n : s.normals[a]);
      s.directions.push_back(middle_direction(s.directions[a], s.normals[a], s.directions[b],
                                              s.normals[b], symmetry, s.normals.back()));
      if (features.count(k)) {
        features[key(a, m)] = 1;
        features[key(m, b)] = 1;
      }
    }
    std::vector<std::array<std::uint32_t, 3>> faces;
    std::vector<Vec3> normals;
    std::vector<std::uint32_t> regions, from;
    for (std::size_t f = 0; f < s.faces.size(); ++f) {
      const auto& c = s.faces[f];
      std::array<std::uint32_t, 3> mid;
      int split = 0;
      for (int k = 0; k < 3; ++k) {
        const auto it = middle.find(key(c[k], c[(k + 1) % 3]));
        mid[k] = it == middle.end() ? std::numeric_limits<std::uint32_t>::max() : it->second.vertex;
        split += it != middle.end();
      }
      auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t d) {
        faces.push_back({{a, b, d}});
        normals.push_back(s.face_normals[f]);
        regions.push_back(s.face_regions[f]);
        from.push_back(origin[f]);
      };
      const std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
      if (split == 0) {
        add(c[0], c[1], c[2]);
      } else if (split == 3) {
        add(c[0], mid[0], mid[2]);
        add(mid[0], c[1], mid[1]);
        add(mid[2], mid[1], c[2]);
        add(mid[0], mid[1], mid[2]);
      } else if (split == 1) {
        const int k = mid[0] != none ? 0 : mid[1] != none ? 1 : 2;
        add(c[k], mid[k], c[(k + 2) % 3]);
        add(mid[k], c[(k + 1) % 3], c[(k + 2) % 3]);
      } else { // two edges: the corner between them cut off, the rest split by its shorter diagonal
        const int k = mid[0] == none ? 1 : mid[1] == none ? 2 : 0; // edges k and k+1 split
        const std::uint32_t a = c[k], b = c[(k + 1) % 3], d = c[(k + 2) % 3];
        const std::uint32_t mk = mid[k], ml = mid[(k + 1) % 3];
        add(mk, b, ml);
        const Vec3 e1 = s.points[ml] - s.points[a], e2 = s.points[d] - s.points[mk];
        if (dot(e1, e1) <= dot(e2, e2)) {
          add(a, mk, ml);
          add(a, ml, d);
        } else {
          add(a, mk, d);
          add(mk, ml, d);
        }
      }
    }
    s.faces = std::move(faces);
    s.face_normals = std::move(normals);
    s.face_regions = std::move(regions);
    origin = std::move(from);
  }
  s.feature_edges.clear();
  std::vector<std::uint64_t> lines;
  for (const auto& f : features)
    lines.push_back(f.first);
  std::sort(lines.begin(), lines.end());
  for (const std::uint64_t k : lines)
    s.feature_edges.push_back({{std::uint32_t(k >> 32), std::uint32_t(k & 0xffffffffu)}});
  return s;
}

// The hierarchy: the surface's vertices, then coarser levels until one has few nodes or matching
// no longer shrinks it. It depends on the surface alone, not on the spacing.
std::vector<Level> hierarchy(const Position_field_surface& surface) {
  std::vector<Level> levels;
  levels.push_back(finest_level(surface));
  while (levels.back().size() > 8) {
    Level next = coarser_level(levels.back());
    if (next.size() * 10 > levels.back().size() * 9)
      break;
    levels.push_back(std::move(next));
  }
  for (Level& l : levels) {
    l.t.resize(l.size());
    for (std::uint32_t i = 0; i < l.size(); ++i)
      l.t[i] = cross(l.n[i], l.o[i]);
    l.phases = phases_of(l);
  }
  return levels;
}

// The lattice point of every vertex, from the coarsest level down: each level starts from its
// parents' points and is smoothed.
std::vector<Vec3> solve_on(const std::vector<Level>& levels, const Lattice& lattice,
                           const Position_field_options& options) {
  // The coarsest level starts at random points of its nodes' cells (as Instant Meshes does): the
  // seed sets the lattice's phase.
  std::vector<Vec3> p = levels.back().x;
  std::mt19937 rng(options.seed);
  std::uniform_real_distribution<double> unit(0, 1);
  for (std::uint32_t i = 0; i < p.size(); ++i) {
    const Level& l = levels.back();
    const double a = unit(rng), b = unit(rng);
    p[i] = l.x[i] + (a * lattice.wx) * l.o[i] + (b * lattice.wy) * cross(l.n[i], l.o[i]);
  }
  for (std::size_t k = levels.size(); k-- > 0;) {
    const Level& l = levels[k];
    if (k + 1 < levels.size()) { // from the coarser level's points
      std::vector<Vec3> fine(l.size());
      for (std::uint32_t i = 0; i < l.size(); ++i) {
        const Vec3& q = p[l.parent[i]];
        const Vec3 in = q - dot(l.n[i], q - l.x[i]) * l.n[i];
        fine[i] = lattice.nearest(in, l.o[i], cross(l.n[i], l.o[i]), l.x[i]);
      }
      p = std::move(fine);
    }
    smooth(lattice, l, p, k == 0 ? options.sweeps_finest : options.sweeps_per_level);
  }
  return p;
}

// The lattice points inside the faces of `s` (refined from the input; `origin` its faces' input
// faces) from the lattice point `p` of every vertex.
std::vector<Lattice_point> lattice_points(const Position_field_surface& s,
                                          const std::vector<std::uint32_t>& origin,
                                          const std::vector<Vec3>& p, const Lattice& lattice,
                                          Position_field_stats* stats) {
  const auto t0 = Clock::now();
  const double wx = lattice.wx, wy = lattice.wy;
  // Each face's lattice points from its first corner's lattice in the face's plane (a little
  // beyond the face, so that none is lost between two faces whose lattices differ by a rounding;
  // the duplicates go below). Faces whose corners' lattices agree go first, so that where two
  // lattices meet, the points kept are those of whole cells.
  struct Candidate {
    double misfit;
    std::uint32_t face;
    Vec3 at, x_axis;
  };
  std::vector<Candidate> candidates;
  for (std::uint32_t f = 0; f < s.faces.size(); ++f) {
    const auto& c = s.faces[f];
    const Vec3& n = s.face_normals[f];
    const Vec3 x0 = s.points[c[0]];
    const Vec3 o = in_plane(s.directions[c[0]], n), t = cross(n, o);
    const Vec3 origin = p[c[0]] - dot(n, p[c[0]] - x0) * n;
    // Misfit: how far the other corners' lattice points are from this lattice.
    double misfit = 0;
    for (int k = 1; k < 3; ++k) {
      const Vec3 q = p[c[k]] - dot(n, p[c[k]] - x0) * n;
      misfit = std::max(misfit, norm(lattice.nearest(origin, o, t, q) - q));
    }
    std::array<double, 3> u, v;
    for (int k = 0; k < 3; ++k) {
      const Vec3 d = s.points[c[k]] - origin;
      u[k] = dot(d, o) / wx;
      v[k] = dot(d, t) / wy;
    }
    const double det = (u[1] - u[0]) * (v[2] - v[0]) - (u[2] - u[0]) * (v[1] - v[0]);
    if (!(std::abs(det) > 0))
      continue;
    const long i0 = long(std::floor(*std::min_element(u.begin(), u.end()))),
               i1 = long(std::ceil(*std::max_element(u.begin(), u.end())));
    const long j0 = long(std::floor(*std::min_element(v.begin(), v.end()))),
               j1 = long(std::ceil(*std::max_element(v.begin(), v.end())));
    // A face more than 4096 cells long (the splitting stopped at its vertex budget: a strip of
    // slivers 1e-12 high under cells 1e-6 wide) gives no points: its holes are filled later.
    if (i1 - i0 > 4096 || j1 - j0 > 4096)
      continue;
    const double slack = 1e-3;
    // The rows j of column i: those where the face crosses the slab |u − i| ≤ ½, a cell more on
    // either side (the box of a sliver many cells long at a slant held 10¹⁰ cells).
    auto rows = [&](long i) {
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      const double a = double(i) - 0.5, b = double(i) + 0.5;
      for (int k = 0; k < 3; ++k) {
        const int l = (k + 1) % 3;
        if (u[k] >= a && u[k] <= b)
          lo = std::min(lo, v[k]), hi = std::max(hi, v[k]);
        for (const double at : {a, b})
          if ((u[k] - at) * (u[l] - at) < 0) {
            const double w = v[k] + (at - u[k]) / (u[l] - u[k]) * (v[l] - v[k]);
            lo = std::min(lo, w), hi = std::max(hi, w);
          }
      }
      return lo > hi ? std::pair<long, long>{1, 0}
                     : std::pair<long, long>{std::max(j0, long(std::floor(lo)) - 1),
                                             std::min(j1, long(std::ceil(hi)) + 1)};
    };
    for (long i = i0; i <= i1; ++i) {
      const std::pair<long, long> r = rows(i);
      for (long j = r.first; j <= r.second; ++j) {
        const double b1 =
            ((double(i) - u[0]) * (v[2] - v[0]) - (u[2] - u[0]) * (double(j) - v[0])) / det;
        const double b2 =
            ((u[1] - u[0]) * (double(j) - v[0]) - (double(i) - u[0]) * (v[1] - v[0])) / det;
        const double b0 = 1 - b1 - b2;
        if (b0 < -slack || b1 < -slack || b2 < -slack)
          continue;
        const std::array<double, 3> b{{std::max(b0, 0.0), std::max(b1, 0.0), std::max(b2, 0.0)}};
        const double sum = b[0] + b[1] + b[2];
        const Vec3 at = (b[0] / sum) * s.points[c[0]] + (b[1] / sum) * s.points[c[1]] +
                        (b[2] / sum) * s.points[c[2]];
        candidates.push_back({misfit, f, at, o});
      }
    }
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& a, const Candidate& b) { return a.misfit < b.misfit; });
  // Keep a candidate unless one kept before lies within 0.55 cell of it along both axes of either's
  // lattice (same region, facing the same way): a spatial hash of cells a spacing wide.
  const double cell = std::max(wx, wy);
  auto key = [](long x, long y, long z) {
    return (std::uint64_t(x & 0x1fffff) << 42) | (std::uint64_t(y & 0x1fffff) << 21) |
           std::uint64_t(z & 0x1fffff);
  };
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> grid;
  std::vector<std::uint32_t> kept;
  auto close_in = [&](const Candidate& a, const Candidate& b) {
    const Vec3 d = b.at - a.at;
    const Vec3& n = s.face_normals[a.face];
    const Vec3 t = cross(n, a.x_axis);
    return std::abs(dot(d, a.x_axis)) < 0.55 * wx && std::abs(dot(d, t)) < 0.55 * wy &&
           std::abs(dot(d, n)) < 0.55 * cell;
  };
  std::size_t merged = 0;
  for (std::uint32_t k = 0; k < candidates.size(); ++k) {
    const Candidate& c = candidates[k];
    const long gx = long(std::floor(c.at[0] / cell)), gy = long(std::floor(c.at[1] / cell)),
               gz = long(std::floor(c.at[2] / cell));
    bool duplicate = false;
    for (long dx = -1; dx <= 1 && !duplicate; ++dx)
      for (long dy = -1; dy <= 1 && !duplicate; ++dy)
        for (long dz = -1; dz <= 1 && !duplicate; ++dz) {
          const auto it = grid.find(key(gx + dx, gy + dy, gz + dz));
          if (it == grid.end())
            continue;
          for (const std::uint32_t m : it->second) {
            const Candidate& o = candidates[m];
            if (s.face_regions[o.face] != s.face_regions[c.face] ||
                dot(s.face_normals[o.face], s.face_normals[c.face]) < 0.5)
              continue;
            if (close_in(o, c) || close_in(c, o)) {
              duplicate = true;
              break;
            }
          }
        }
    if (duplicate) {
      ++merged;
      continue;
    }
    grid[key(gx, gy, gz)].push_back(k);
    kept.push_back(k);
  }
  std::vector<Lattice_point> out;
  out.reserve(kept.size());
  std::sort(kept.begin(), kept.end(), [&](std::uint32_t a, std::uint32_t b) {
    return origin[candidates[a].face] != origin[candidates[b].face]
               ? origin[candidates[a].face] < origin[candidates[b].face]
               : a < b;
  });
  for (const std::uint32_t k : kept)
    out.push_back({origin[candidates[k].face], candidates[k].at});
  if (stats) {
    stats->extracted = candidates.size();
    stats->merged = merged;
    stats->seconds_extract = seconds_since(t0);
  }
  return out;
}

} // namespace

std::vector<Vec3> solve_position_field(const Position_field_surface& surface,
                                       const Position_field_options& options,
                                       Position_field_stats* stats) {
  const auto t0 = Clock::now();
  const std::vector<Level> levels = hierarchy(surface);
  std::vector<Vec3> p = solve_on(levels, Lattice{options.spacing_x, options.spacing_y}, options);
  if (stats) {
    stats->levels = levels.size();
    stats->seconds_solve = seconds_since(t0);
  }
  return p;
}

std::vector<Lattice_point> position_field_points(const Position_field_surface& input,
                                                 const Position_field_options& options,
                                                 Position_field_stats* stats) {
  const auto t_refine = Clock::now();
  std::vector<std::uint32_t> origin;
  const Position_field_surface s =
      refined(input,
              options.split_length > 0 ? options.split_length
                                       : std::min(options.spacing_x, options.spacing_y),
              options.symmetry, options.most_vertices, origin);
  if (stats) {
    stats->vertices = s.points.size();
    stats->seconds_refine = seconds_since(t_refine);
  }
  const auto t_solve = Clock::now();
  const std::vector<Level> levels = hierarchy(s);
  Lattice lattice{options.spacing_x, options.spacing_y};
  std::vector<Vec3> p = solve_on(levels, lattice, options);
  if (stats) {
    stats->levels = levels.size();
    stats->seconds_solve = seconds_since(t_solve);
  }
  std::vector<Lattice_point> out = lattice_points(s, origin, p, lattice, stats);
  const double factor = options.rescale ? options.rescale(out.size()) : 1;
  if (factor > 0 && factor != 1) { // again, on the same hierarchy
    const auto t_again = Clock::now();
    lattice = Lattice{factor * options.spacing_x, factor * options.spacing_y};
    p = solve_on(levels, lattice, options);
    if (stats) {
      stats->seconds_solve += seconds_since(t_again);
      stats->rescaled = factor;
    }
    out = lattice_points(s, origin, p, lattice, stats);
  }
  return out;
}

} // namespace tessera::internal
