// `Surface_mosaic`'s start (tessera/mosaic/surface_mosaic.h): where the tiles are first laid. The
// lattice grown along the field from a seed per region (grown again with rows closer together when
// it holds too few tiles), the position field's lattice, and the count fitted to N (tiles added at
// the widest holes, the most crowded left out). Internal, included by surface_mosaic_impl.h.
#pragma once

#include <tessera/mosaic/surface_mosaic.h>

#include <tessera/internal/parallel.h>
#include <tessera/mosaic/internal/position_field.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <random>
#include <unordered_map>

namespace tessera {

// Holes: face centroids farther than `min_spacings` × the local spacing from every point of
// `search`, the widest first (in local spacings), each more than a local spacing from the holes
// before it; at most `limit` of them.
template <typename TriangleMesh, typename NamedParameters>
std::vector<std::uint32_t> Surface_mosaic<TriangleMesh, NamedParameters>::largest_holes(
    const internal::Point_search& search, double min_spacings, std::size_t limit) const {
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  auto spacing_at = [&](std::uint32_t f) { return layout_.spacing * face_size(f); };
  // Each face's distance to the nearest point, on every core (a query per face: at 200k faces
  // the lattice start's hole rounds took most of its time on one).
  std::vector<double> nearest(s.number_of_faces(), std::numeric_limits<double>::infinity());
  internal::parallel_blocks(s.number_of_faces(), [&](std::size_t first, std::size_t last) {
    for (std::size_t f = first; f < last; ++f)
      search.nearest(s.centroid(std::uint32_t(f)), 1,
                     [&](std::size_t, double d2) { nearest[f] = std::sqrt(d2); });
  });
  std::vector<std::pair<double, std::uint32_t>> holes;
  for (std::uint32_t f = 0; f < s.number_of_faces(); ++f) {
    const double local = spacing_at(f);
    if (nearest[f] > min_spacings * local)
      holes.push_back({-nearest[f] / local, f});
  }
  return widest_apart(std::move(holes), limit);
}

// The faces of `holes` ((−width, face) pairs), the widest first, each more than a local spacing
// from those before it; at most `limit` of them.
template <typename TriangleMesh, typename NamedParameters>
std::vector<std::uint32_t> Surface_mosaic<TriangleMesh, NamedParameters>::widest_apart(
    std::vector<std::pair<double, std::uint32_t>> holes, std::size_t limit) const {
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  std::sort(holes.begin(), holes.end());
  std::vector<internal::Vec3> chosen;
  std::vector<std::uint32_t> faces;
  for (const auto& h : holes) {
    if (faces.size() == limit)
      break;
    const internal::Vec3 c = s.centroid(h.second);
    const double local = layout_.spacing * face_size(h.second);
    bool apart = true;
    for (const auto& o : chosen)
      apart = apart && internal::norm(o - c) > local;
    if (!apart)
      continue;
    chosen.push_back(c);
    faces.push_back(h.second);
  }
  return faces;
}

// Lattice initialization: from a seed in each region (the face closest to the region's area
// centroid), tiles are laid breadth first one cell apart along the field's two directions (a
// step walked along the surface, `Surface_arrays::walk`), skipping a place closer than 0.75 cell
// to a tile already laid (in that tile's frame) or where the walk met a border or feature line
// more than a twelfth of a cell short (the step left the region). Where the fronts of the growth
// meet, the lattices' phases differ: tiles closer than a cell or gaps. Beyond N, the most crowded
// tiles go; below N, tiles are added at the largest holes (only holes a cell wide with
// `Mosaic_count::at_most`). Lai et al. start from random points (§3.2), from which the
// repulsion settles into grains of rows squeezed along one axis (on the "eight", half the tiles
// had their nearest neighbour at 0.93 of a tile side or closer, where the grid puts it at 1.05),
// and rows are not created or removed by the repulsion; a lattice start leaves defects only
// where fronts meet.
template <typename TriangleMesh, typename NamedParameters>
std::vector<internal::Surface_point>
Surface_mosaic<TriangleMesh, NamedParameters>::lattice_points() {
  // A lattice that holds fewer than N tiles (its rows diverge over curved parts, its fronts meet
  // out of phase) is grown again with rows closer together (by the square root of the
  // shortfall), so the grout narrows evenly instead of the missing tiles crowding into holes
  // (exactly N) or their area staying bare (about N); never closer than a tile side, where tiles
  // would touch. With the default count the lattice aims at 2 % over N: the separation leaves
  // out more crowded tiles than it adds in bare patches (net 1.6 % of the lattice, median of the
  // ten meshes of doc/mosaic.md), and coverage follows the count. (Exactly N, on the eight:
  // overlap 3.3 % → 2.3 %. About N, on the ten: coverage up 0.003–0.018 where the lattice fell
  // 3–4 % short. Further rounds gave nothing.)
  const double aim = options_.count == Mosaic_count::about ? 1.02 : 1.0;
  std::size_t grown = 0;
  std::vector<internal::Surface_point> points = lattice_points(1, grown);
  if (options_.count != Mosaic_count::at_most && grown < aim * layout_.tile_count) {
    const double scale = std::max(std::sqrt(1 - layout_.grout),
                                  std::sqrt(double(grown) / (aim * double(layout_.tile_count))));
    points = lattice_points(scale, grown);
  }
  return fit_count(std::move(points));
}

template <typename TriangleMesh, typename NamedParameters>
std::vector<internal::Surface_point>
Surface_mosaic<TriangleMesh, NamedParameters>::lattice_points(double scale,
                                                              std::size_t& grown) const {
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  const double root = std::sqrt(layout_.aspect);
  const double step_u = scale * layout_.spacing * root, step_v = scale * layout_.spacing / root;
  // The hash grid's cells hold the reach of the largest tiles.
  const double cell = std::max(step_u, step_v) * largest_size_;
  std::vector<internal::Surface_point> out;
  std::vector<internal::Vec3> where;
  std::vector<double> sizes; // the size field at each laid tile
  std::vector<std::array<internal::Vec3, 2>> frames;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> grid;
  auto key = [&](long x, long y, long z) {
    return (std::uint64_t(x & 0x1fffff) << 42) | (std::uint64_t(y & 0x1fffff) << 21) |
           std::uint64_t(z & 0x1fffff);
  };
  auto cell_of = [&](const internal::Vec3& p) {
    return std::array<long, 3>{{long(std::floor(p[0] / cell)), long(std::floor(p[1] / cell)),
                                long(std::floor(p[2] / cell))}};
  };
  auto frame_at = [&](const internal::Surface_point& p) {
    const internal::Vec3 x = tile_x_axis(p);
    return std::array<internal::Vec3, 2>{{x, internal::cross(s.normal(p.face), x)}};
  };
  // Calls visit(j) for every laid tile j in the 27 grid cells around q that faces the same way
  // as `normal` (not the far side of a thin part).
  auto for_each_near = [&](const internal::Vec3& q, const internal::Vec3& normal, auto&& visit) {
    const auto c = cell_of(q);
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy)
        for (long dz = -1; dz <= 1; ++dz) {
          const auto it = grid.find(key(c[0] + dx, c[1] + dy, c[2] + dz));
          if (it != grid.end())
            for (const std::uint32_t j : it->second)
              if (internal::dot(s.normal(out[j].face), normal) >= 0.5)
                visit(j);
        }
  };
  // (`size`: the size field at q; a place is taken at the larger of its size and tile j's.)
  auto free_at = [&](const internal::Vec3& q, const internal::Vec3& normal, double size) {
    bool free = true;
    for_each_near(q, normal, [&](std::uint32_t j) {
      // Taken when inside 0.75 cell of tile j in its plane and, in space, closer than 0.75 of
      // the longer cell side: on a part a few tiles around, the next tile of a row seen in j's
      // plane is much nearer than it is.
      const internal::Vec3 d = q - where[j];
      const double h = std::max(size, sizes[j]);
      if (std::abs(internal::dot(d, frames[j][0])) < 0.75 * step_u * h &&
          std::abs(internal::dot(d, frames[j][1])) < 0.75 * step_v * h &&
          internal::norm(d) < 0.75 * std::max(step_u, step_v) * h)
        free = false;
    });
    return free;
  };
  auto lay = [&](const internal::Surface_point& p) {
    const internal::Vec3 q = s.position(p);
    const auto c = cell_of(q);
    grid[key(c[0], c[1], c[2])].push_back(std::uint32_t(out.size()));
    out.push_back(p);
    where.push_back(q);
    frames.push_back(frame_at(p));
    sizes.push_back(size_at(p));
  };
  // Seeds: per region, the face closest to its area centroid; with a size field, the closest of
  // those with the smallest size, so that rows grow from small tiles towards larger ones (where
  // `fit_count()` thins them) and never leave gaps narrower than a cell between them.
  std::vector<internal::Vec3> centroid(s.number_of_regions(), internal::Vec3{{0, 0, 0}});
  std::vector<double> area(s.number_of_regions(), 0);
  for (std::uint32_t f = 0; f < s.number_of_faces(); ++f) {
    centroid[s.region(f)] = centroid[s.region(f)] + s.area(f) * s.centroid(f);
    area[s.region(f)] += s.area(f);
  }
  std::vector<std::uint32_t> seed(s.number_of_regions(), internal::no_index);
  std::vector<double> best(s.number_of_regions(), std::numeric_limits<double>::infinity());
  std::vector<double> smallest(best);
  for (std::uint32_t f = 0; f < s.number_of_faces(); ++f) {
    const std::uint32_t r = s.region(f);
    const double d = internal::norm(s.centroid(f) - (1 / area[r]) * centroid[r]);
    const double h = face_size(f);
    if (h < smallest[r] * (1 - 1e-9) || (h <= smallest[r] * (1 + 1e-9) && d < best[r]))
      best[r] = d, seed[r] = f, smallest[r] = std::min(smallest[r], h);
  }
  // The seed of the options places the first tile at a random point of that face, which shifts
  // the region's whole lattice.
  std::mt19937 rng(options_.seed);
  std::uniform_real_distribution<double> unit(0, 1);
  std::deque<std::uint32_t> queue;
  for (std::uint32_t r = 0; r < s.number_of_regions(); ++r)
    if (seed[r] != internal::no_index && area[r] > 0) {
      double a = unit(rng), b = unit(rng);
      if (a + b > 1)
        a = 1 - a, b = 1 - b;
      queue.push_back(std::uint32_t(out.size()));
      lay(internal::Surface_point{seed[r], {{a, b, 1 - a - b}}});
    }
  // The four places a cell away from tile i along its axes (`left`: a step left the region).
  struct Step {
    internal::Surface_point p;
    internal::Vec3 q;
    bool left;
  };
  auto steps_from = [&](std::uint32_t i) {
    const internal::Surface_point from = out[i];
    const std::array<internal::Vec3, 2> fr = frames[i];
    // A cell of the size at the tile it starts from; each quarter below takes the size where it
    // starts, so that a size field's cells add up along the row.
    const double hu = step_u * sizes[i], hv = step_v * sizes[i];
    std::array<Step, 4> result;
    int m = 0;
    for (const auto& d : {hu * fr[0], -hu * fr[0], hv * fr[1], -hv * fr[1]}) {
      // A cell along the surface in four walks, each along the row's direction in the tangent
      // plane of the face reached, so the row follows that direction rather than a geodesic.
      Step& st = result[std::size_t(m++)];
      st.p = from;
      st.q = where[i];
      st.left = false;
      for (int k = 0; k < 4 && !st.left; ++k) {
        const internal::Vec3 n = s.normal(st.p.face);
        const internal::Vec3 t = d - internal::dot(d, n) * n;
        const double l = internal::norm(t);
        if (!(l > 0)) {
          st.left = true;
          break;
        }
        const double quarter = 0.25 * internal::norm(d) * size_at(st.p) / sizes[i];
        const auto walked = s.walk(st.p, (quarter / l) * t);
        st.p = walked.p;
        st.q = s.position(st.p);
        st.left = walked.short_by > std::max(hu, hv) / 12; // left the region
      }
    }
    return result;
  };
  // Breadth first, a wave at a time: the steps from every tile of a wave depend only on that
  // tile, so they are taken on every core (the projections are most of the time: 200k triangles
  // and 40k tiles, 1.7 s on one), then laid in the queue's order, which keeps the result of
  // taking one tile at a time.
  while (!queue.empty()) {
    const std::vector<std::uint32_t> wave(queue.begin(), queue.end());
    queue.clear();
    std::vector<std::array<Step, 4>> steps(wave.size());
    internal::parallel_blocks(
        wave.size(),
        [&](std::size_t first, std::size_t last) {
          for (std::size_t w = first; w < last; ++w)
            steps[w] = steps_from(wave[w]);
        },
        16);
    for (const std::array<Step, 4>& from : steps)
      for (const Step& st : from) {
        if (st.left || !free_at(st.q, s.normal(st.p.face), size_at(st.p)))
          continue;
        queue.push_back(std::uint32_t(out.size()));
        lay(st.p);
      }
  }
  grown = out.size();
  return out;
}

// The tiles of a position field's lattice (`internal::position_field_points`): the field at the
// vertices, the lattice's spacings those of a cell (√η·spacing along the field, spacing/√η
// across), feature lines and open borders as the edges between faces of different regions or of
// none.
template <typename TriangleMesh, typename NamedParameters>
std::vector<internal::Surface_point>
Surface_mosaic<TriangleMesh, NamedParameters>::position_field_points() {
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  internal::Position_field_surface in;
  const std::size_t nv = s.number_of_vertices(), nf = s.number_of_faces();
  in.points.resize(nv);
  in.normals.assign(nv, internal::Vec3{{0, 0, 0}});
  for (std::uint32_t v = 0; v < nv; ++v)
    in.points[v] = s.vertex_point(v);
  in.directions = vertex_field_;
  in.faces.resize(nf);
  in.face_normals.resize(nf);
  in.face_regions.resize(nf);
  for (std::uint32_t f = 0; f < nf; ++f) {
    in.faces[f] = s.corners(f);
    in.face_normals[f] = s.normal(f);
    in.face_regions[f] = s.region(f);
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = s.corners(f)[k];
      in.normals[v] = in.normals[v] + s.area(f) * s.normal(f);
      // Each feature edge once (from the face with the smaller index, or the only one).
      const std::uint32_t g = s.across(f, k);
      if (s.neighbor(f, k) == internal::no_index && (g == internal::no_index || f < g))
        in.feature_edges.push_back({{v, s.corners(f)[(k + 1) % 3]}});
    }
  }
  internal::Position_field_options po;
  po.spacing_x = layout_.spacing * std::sqrt(layout_.aspect);
  po.spacing_y = layout_.spacing / std::sqrt(layout_.aspect);
  // Edges are split at the layout's spacing, also where the lattice is solved with rows closer.
  po.split_length = std::min(po.spacing_x, po.spacing_y);
  po.symmetry = symmetry_;
  po.seed = options_.seed;
  // Splitting stops at 32 new vertices a tile (the organic meshes at 3000 tiles take under 8): on
  // a strip of slivers 1e-12 high every edge is longer than a cell, and 4M vertices took minutes.
  po.most_vertices = nv + 32 * layout_.tile_count;
  // The count is aimed as `lattice_points()` aims it: a lattice short of 2 % over N has its rows
  // closer, by the square root of the shortfall, never closer than 0.965 of the spacing (at 0.95
  // the lion head took 9.7 % more tiles than N and the cow's widest bare patch reached 2.04
  // tiles; at 0.965 all eight organic meshes of doc/mosaic.md covered 0.85 or more). The position
  // field loses rows where lattices meet: 7–10 % of N on every organic mesh measured, about none
  // on a plane. So it is solved at the closest spacing first, which is final on curved surfaces,
  // and solved again with rows farther apart only where that lays more than 2 % over the aim (a
  // plane: 1/0.965² = 1.07 N). One solve instead of two on the meshes that need closer rows: at
  // 207k triangles and 40k tiles it saves 1.5 s.
  const double aim = options_.count == Mosaic_count::about ? 1.02 : 1.0;
  const double wanted = aim * double(layout_.tile_count);
  if (options_.count != Mosaic_count::at_most) {
    const double closest = std::max(0.965, std::sqrt(1 - layout_.grout));
    po.spacing_x *= closest;
    po.spacing_y *= closest;
    po.rescale = [closest, wanted](std::size_t found) {
      // The spacing (over the layout's) that lays `wanted` points, if found ∝ 1/spacing².
      const double fits = std::min(1.0, closest * std::sqrt(double(found) / wanted));
      return fits > 1.01 * closest ? fits / closest : 1.0;
    };
  }
  internal::Position_field_stats ps;
  std::vector<internal::Surface_point> out;
  for (const internal::Lattice_point& p : internal::position_field_points(in, po, &ps))
    out.push_back(internal::Surface_point{p.face, s.barycentric(p.face, p.at)});
  stats_.lattice_levels = ps.levels;
  stats_.lattice_points = out.size();
  return out;
}

// The initial tiles brought to the count the options ask for. Beyond N (unless `about`) the most
// crowded tiles go first, one of each close pair (dropping by crowding alone took both, and left
// holes: the cube's overlap was 0.8 % where it is 0.5 %). Then tiles are added at the largest
// holes, a round at a time: face centroids farthest from every tile, a cell apart; with `exact`
// until there are N tiles, otherwise only in holes a cell wide (a centroid farther than 0.85
// spacing from every tile; a regular lattice has none), never beyond N with `at_most`.
template <typename TriangleMesh, typename NamedParameters>
std::vector<internal::Surface_point>
Surface_mosaic<TriangleMesh, NamedParameters>::fit_count(std::vector<internal::Surface_point> out) {
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  const std::size_t count = layout_.tile_count;
  const double root = std::sqrt(layout_.aspect);
  const double step_u = layout_.spacing * root, step_v = layout_.spacing / root;
  internal::Point_search search;
  auto positions = [&] {
    std::vector<internal::Vec3> at;
    for (const auto& p : out)
      at.push_back(s.position(p));
    return at;
  };
  // With a size field, a lattice grown row by row keeps the row spacing of the size where the
  // rows started (grown from size 1.5 into size 2, rows 0.75 cell apart): tiles closer than 0.8
  // of a local cell to another go (one of each pair), and the holes below get tiles again. (With
  // exactly N tiles only the count decides.)
  const bool thin = !vertex_size_.empty() &&
                    options_.initialization == Mosaic_initialization::lattice &&
                    options_.count != Mosaic_count::exact;
  const bool over = options_.count != Mosaic_count::about && out.size() > count;
  if (thin || over) {
    const std::vector<internal::Vec3> at = positions();
    search.reset(at);
    std::vector<std::pair<double, std::uint32_t>> crowding;
    std::vector<std::uint32_t> partner(out.size(), internal::no_index);
    for (std::uint32_t i = 0; i < out.size(); ++i) {
      const internal::Vec3 x = tile_x_axis(out[i]), n = s.normal(out[i].face);
      const internal::Vec3 y = internal::cross(n, x);
      double nearest = std::numeric_limits<double>::infinity();
      search.nearest(at[i], 9, [&](std::size_t j, double) {
        if (j == i || internal::dot(s.normal(out[j].face), n) < 0.5)
          return;
        const internal::Vec3 d = at[j] - at[i];
        const double m = std::max(std::abs(internal::dot(d, x)) / step_u,
                                  std::abs(internal::dot(d, y)) / step_v) /
                         size_at(out[i]);
        if (m < nearest)
          nearest = m, partner[i] = std::uint32_t(j);
      });
      crowding.push_back({nearest, i});
    }
    std::stable_sort(crowding.begin(), crowding.end());
    std::vector<char> drop(out.size(), 0);
    std::size_t extra = thin ? out.size() : out.size() - count;
    for (const auto& c : crowding) {
      const std::uint32_t i = c.second;
      if (extra == 0 || (thin && !(c.first < 0.8)))
        break;
      if (partner[i] != internal::no_index && drop[partner[i]])
        continue;
      drop[i] = 1, --extra;
    }
    std::vector<internal::Surface_point> kept;
    for (std::uint32_t i = 0; i < out.size(); ++i)
      if (!drop[i])
        kept.push_back(out[i]);
    out = std::move(kept);
  }
  const bool exact = options_.count == Mosaic_count::exact;
  const std::size_t most =
      options_.count == Mosaic_count::about ? std::numeric_limits<std::size_t>::max() : count;
  while (out.size() < most) {
    search.reset(positions());
    const std::size_t before = out.size();
    for (const std::uint32_t f : largest_holes(search, exact ? 0 : 0.85, most - out.size()))
      out.push_back(internal::Surface_point{f, {{1.0 / 3, 1.0 / 3, 1.0 / 3}}});
    if (out.size() == before)
      break;
  }
  return out;
}

} // namespace tessera
