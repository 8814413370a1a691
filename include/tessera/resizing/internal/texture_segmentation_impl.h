// The implementation of segment_texture() (tessera/resizing/texture_segmentation.h): the
// per-vertex features (curvature statistics over a ball of radius ρ, the texel period), the mean
// shift, the modes joined into regions, and the closing that joins texels into one texture.
// Included by texture_segmentation.h after the types it uses (Texture_segmentation_options,
// Texture_segmentation_result, …); nothing here is meant to be called directly.
#pragma once

#include <tessera/internal/index_sets.h>
#include <tessera/internal/named_parameters.h>
#include <tessera/resizing/internal/signed_curvatures.h>
#include <tessera/resizing/internal/texel_period.h>
#include <tessera/resizing/internal/texture_pieces.h>
#include <tessera/topology/internal/graph_search.h>
#include <tessera/internal/parallel.h>

#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>

#include <boost/iterator/counting_iterator.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <memory>
#include <numeric>
#include <random>
#include <string>
#include <vector>

namespace tessera {
namespace internal {

using Texture_point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;

/// Per vertex, in the order of `vertices(tm)`: the position and the scale-free curvature
/// statistics (ρ²E_K, ρE_H, ρ⁴D_K, ρ²D_H) over the vertices within ρ of it (reached through the
/// mesh's edges), weighted by their areas; and the texel period read from the mean curvature.
struct Texture_features {
  std::vector<Texture_point> position;
  std::vector<std::array<double, 4>> statistics;
  /// Per vertex: a third of its triangles' area, its normal, its mean curvature about the median
  /// and whether its jet was fitted (what `texel_period_from_curvature` reads).
  std::vector<double> area, mean_curvature;
  std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Vector_3> normal;
  std::vector<char> fitted_at;
  double ring_radius = 0;
  double mean_edge_length = 0;
  Texel_period period;
  std::size_t fitted = 0;
};

/// `rings` > 0: ρ = rings mean edge lengths; 0: ρ = a third of the texel period (`given_period`
/// if positive, else the one found; a ball
/// that reaches from any gap into the texels around it, and spreads the texture past its last
/// texels by no more).
template <typename TriangleMesh, typename VertexPointMap, typename VertexIndexMap>
Texture_features texture_features(const TriangleMesh& tm, VertexPointMap vpm, VertexIndexMap index,
                                  std::size_t rings, std::size_t fitting_rings,
                                  bool with_statistics = true, double given_period = 0) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  const std::size_t n = std::size_t(num_vertices(tm));
  Texture_features out;
  auto point = [&](vertex_descriptor w) {
    const auto& p = get(vpm, w);
    return Texture_point(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  };
  out.position.resize(n);
  for (vertex_descriptor v : vertices(tm))
    out.position[get(index, v)] = point(v);
  double length = 0;
  for (auto e : edges(tm))
    length += CGAL::to_double(
        PMP::edge_length(halfedge(e, tm), tm, CGAL::parameters::vertex_point_map(vpm)));
  out.mean_edge_length = length / double(std::max<std::size_t>(1, num_edges(tm)));
  // Each vertex's area: a third of its triangles'.
  std::vector<double> area(n, 0);
  for (auto f : faces(tm)) {
    std::array<Texture_point, 3> p;
    std::size_t k = 0;
    for (vertex_descriptor w : CGAL::vertices_around_face(halfedge(f, tm), tm))
      if (k < 3)
        p[k++] = point(w);
    const double a = std::sqrt(CGAL::squared_area(p[0], p[1], p[2])) / 3;
    for (vertex_descriptor w : CGAL::vertices_around_face(halfedge(f, tm), tm))
      area[get(index, w)] += a;
  }

  // K and H per vertex, H signed against the mesh's vertex normal (the Monge normal's
  // orientation is arbitrary).
  std::vector<std::array<double, 2>> curvature(n, {{0, 0}});
  std::vector<char> fitted(n, 0);
  fit_signed_curvatures(tm, vpm, std::max<std::size_t>(fitting_rings, 1), point,
                        [&](vertex_descriptor v, double gaussian, double mean, const auto&) {
                          const std::size_t i = get(index, v);
                          curvature[i] = {{gaussian, mean}};
                          fitted[i] = 1;
                          ++out.fitted;
                        });
  if (out.fitted == 0)
    return out;

  // The texel period: the given one, or read from the mean curvature about its median.
  {
    std::vector<double> h;
    for (std::size_t i = 0; i < n; ++i)
      if (fitted[i])
        h.push_back(curvature[i][1]);
    std::nth_element(h.begin(), h.begin() + std::ptrdiff_t(h.size() / 2), h.end());
    const double median = h[h.size() / 2];
    h.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i)
      h[i] = fitted[i] ? curvature[i][1] - median : 0;
    out.normal.assign(n, {0, 0, 0});
    for (vertex_descriptor v : vertices(tm))
      if (halfedge(v, tm) != boost::graph_traits<TriangleMesh>::null_halfedge()) {
        const auto m = PMP::compute_vertex_normal(v, tm, CGAL::parameters::vertex_point_map(vpm));
        out.normal[get(index, v)] = {CGAL::to_double(m.x()), CGAL::to_double(m.y()),
                                     CGAL::to_double(m.z())};
      }
    out.mean_curvature = std::move(h);
    out.area = area;
    out.fitted_at = fitted;
  }
  if (given_period > 0) {
    out.period.period = given_period;
    out.period.periodic = true;
    out.period.mean_edge_length = out.mean_edge_length;
  } else {
    CGAL::Bbox_3 box;
    for (const Texture_point& p : out.position)
      box += p.bbox();
    const double diagonal =
        std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                  CGAL::square(box.zmax() - box.zmin()));
    out.period = texel_period_from_curvature(out.position, out.normal, area, out.mean_curvature,
                                             fitted, out.mean_edge_length, diagonal);
  }
  out.ring_radius = rings > 0 ? double(rings) * out.mean_edge_length
                              : std::max(out.period.period / 3, 2 * out.mean_edge_length);
  if (!with_statistics)
    return out;

  // Eqs. 1–2: area-weighted means and variances over the fitted vertices within ρ.
  const double r = out.ring_radius;
  const std::array<double, 4> scale{{r * r, r, r * r * r * r, r * r}};
  out.statistics.assign(n, {{0, 0, 0, 0}});
  // Each vertex's ball is gathered and summed on its own: in parallel, one mark per block.
  const std::vector<vertex_descriptor> all(vertices(tm).begin(), vertices(tm).end());
  parallel_blocks(all.size(), [&](std::size_t first, std::size_t last) {
    std::vector<char> mark(n, 0);
    std::vector<vertex_descriptor> ball;
    for (std::size_t a = first; a < last; ++a) {
      const vertex_descriptor v = all[a];
      if (halfedge(v, tm) == boost::graph_traits<TriangleMesh>::null_halfedge())
        continue;
      const Texture_point& centre = out.position[get(index, v)];
      ball.assign(1, v);
      mark[get(index, v)] = 1;
      for (std::size_t k = 0; k < ball.size(); ++k)
        for (vertex_descriptor w : CGAL::vertices_around_target(halfedge(ball[k], tm), tm)) {
          const std::size_t j = get(index, w);
          if (!mark[j] && CGAL::squared_distance(out.position[j], centre) <= r * r) {
            mark[j] = 1;
            ball.push_back(w);
          }
        }
      std::array<double, 2> sum{{0, 0}}, square{{0, 0}};
      double mass = 0;
      for (vertex_descriptor w : ball) {
        const std::size_t j = get(index, w);
        mark[j] = 0;
        if (!fitted[j])
          continue;
        for (std::size_t c = 0; c < 2; ++c) {
          sum[c] += area[j] * curvature[j][c];
          square[c] += area[j] * curvature[j][c] * curvature[j][c];
        }
        mass += area[j];
      }
      if (!(mass > 0))
        continue;
      std::array<double, 4>& s = out.statistics[get(index, v)];
      for (std::size_t c = 0; c < 2; ++c) {
        const double mean = sum[c] / mass;
        s[c] = mean * scale[c];
        s[c + 2] = std::max(0.0, square[c] / mass - mean * mean) * scale[c + 2];
      }
    }
  });
  return out;
}

/// Grows the texels of a coarser texture (the pieces `piece[i]` with `chosen[piece]` set, each
/// about one texel) into their cells: every vertex within `spread` of a piece, or within half a
/// `period` of a piece's centre (its area-weighted centroid, taken at the piece's vertex nearest
/// to it), becomes texture; distances along the edges (`length`). The statistics spread a texel
/// by the fine texture's ball only, which for a texel wider than that ends the region inside the
/// outer texels: the base faired under them was then pinned to their slopes, a step at the
/// region's border that the resize's vulnerability read as a rigid rim.
template <typename TriangleMesh, typename VertexIndexMap, typename Search, typename Length>
void grow_to_texel_cells(const TriangleMesh& tm, VertexIndexMap vim, Search& search, Length length,
                         const std::vector<Texture_point>& position,
                         const std::vector<double>& area, const std::vector<std::size_t>& piece,
                         const std::vector<char>& chosen, double period, double spread,
                         std::vector<char>& texture) {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  const std::size_t pieces = chosen.size();
  std::vector<std::array<double, 3>> sum(pieces, {0, 0, 0});
  std::vector<double> weight(pieces, 0);
  for (std::size_t i = 0; i < piece.size(); ++i)
    if (piece[i] != no_piece && chosen[piece[i]]) {
      const std::size_t p = piece[i];
      sum[p][0] += area[i] * position[i].x();
      sum[p][1] += area[i] * position[i].y();
      sum[p][2] += area[i] * position[i].z();
      weight[p] += area[i];
    }
  std::vector<Texture_point> centroid(pieces);
  for (std::size_t p = 0; p < pieces; ++p)
    if (weight[p] > 0)
      centroid[p] =
          Texture_point(sum[p][0] / weight[p], sum[p][1] / weight[p], sum[p][2] / weight[p]);
  std::vector<vertex_descriptor> centre(pieces, boost::graph_traits<TriangleMesh>::null_vertex());
  std::vector<double> best(pieces, std::numeric_limits<double>::infinity());
  const double reach = std::max(0.5 * period, spread);
  std::vector<std::pair<vertex_descriptor, double>> seeds;
  for (vertex_descriptor v : vertices(tm)) {
    const std::size_t i = get(vim, v);
    if (piece[i] == no_piece || !chosen[piece[i]] || !(weight[piece[i]] > 0))
      continue;
    const std::size_t p = piece[i];
    const double d = CGAL::squared_distance(position[i], centroid[p]);
    if (d < best[p]) {
      best[p] = d;
      centre[p] = v;
    }
    seeds.emplace_back(v, reach - spread);
  }
  for (vertex_descriptor v : centre)
    if (v != boost::graph_traits<TriangleMesh>::null_vertex())
      seeds.emplace_back(v, reach - 0.5 * period);
  if (seeds.empty())
    return;
  search.run_seeded(seeds, length);
  for (vertex_descriptor v : vertices(tm))
    if (search.distance(v) <= reach)
      texture[get(vim, v)] = 1;
}

/// The body of `segment_texture` (texture_segmentation.h).
template <typename TriangleMesh, typename VertexRegionMap, typename VertexTextureMap,
          typename NamedParameters>
Texture_segmentation_result
segment_texture_impl(const TriangleMesh& tm, VertexRegionMap region, VertexTextureMap is_texture,
                     const Texture_segmentation_options& options, const NamedParameters& np) {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Point = internal::Texture_point;
  using Statistics = std::array<double, 4>;
  const auto vpm = internal::vertex_point_map(tm, np);
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  Texture_segmentation_result result;
  auto fail = [&](Texture_segmentation_status status, std::string message) {
    result.status = status;
    result.message = std::move(message);
    return result;
  };
  for (double value : {options.position_window, options.mean_window, options.variance_window,
                       options.texture_threshold, options.texel_period})
    if (!std::isfinite(value) || value < 0)
      return fail(Texture_segmentation_status::invalid_options,
                  "windows, threshold and texel period must be finite and not negative");
  if (faces(tm).empty())
    return fail(Texture_segmentation_status::empty_mesh, "the mesh has no faces");

  const std::size_t rings =
      options.rings > 0 ? options.rings
      : options.sample_size > 0
          ? std::max<std::size_t>(1,
                                  std::size_t(std::ceil((std::sqrt(options.sample_size) - 1) / 2)))
          : 0;
  const internal::Texture_features features = internal::texture_features(
      tm, vpm, vim, rings, options.fitting_rings, true, options.texel_period);
  if (features.fitted == 0)
    return fail(Texture_segmentation_status::no_curvature,
                "no vertex has the 6 points in its rings that a jet needs");
  result.ring_radius = features.ring_radius;
  result.period = features.period;
  result.rings = std::size_t(std::lround(features.ring_radius / features.mean_edge_length));
  const std::size_t n = features.position.size();
  const std::vector<Point>& position = features.position;
  const std::vector<Statistics>& statistics = features.statistics;

  // Automatic windows.
  auto percentile = [](std::vector<double> values, double q) {
    const std::size_t k = std::min(values.size() - 1, std::size_t(q * double(values.size())));
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
    return values[k];
  };
  std::vector<double> mean_spread(n), variance_size(n);
  {
    std::vector<double> ek(n), eh(n);
    for (std::size_t i = 0; i < n; ++i) {
      ek[i] = statistics[i][0];
      eh[i] = statistics[i][1];
    }
    const double mk = percentile(ek, 0.5), mh = percentile(eh, 0.5);
    for (std::size_t i = 0; i < n; ++i) {
      mean_spread[i] = std::hypot(statistics[i][0] - mk, statistics[i][1] - mh);
      variance_size[i] = std::hypot(statistics[i][2], statistics[i][3]);
    }
  }
  result.position_window =
      options.position_window > 0 ? options.position_window : 4 * features.ring_radius;
  result.mean_window = options.mean_window > 0 ? options.mean_window
                                               : std::max(1e-3, 0.5 * percentile(mean_spread, 0.9));
  result.variance_window = options.variance_window > 0
                               ? options.variance_window
                               : std::max(1e-3, 0.5 * percentile(variance_size, 0.9));
  const double hp = result.position_window, hq = result.mean_window, ht = result.variance_window;

  // Mean shift from every vertex with the product Epanechnikov kernel: each step moves to the
  // plain mean of the vertices inside all three windows.
  using Point_map = typename CGAL::Pointer_property_map<Point>::const_type;
  using Traits = CGAL::Search_traits_adapter<
      std::size_t, Point_map,
      CGAL::Search_traits_3<CGAL::Exact_predicates_inexact_constructions_kernel>>;
  using Tree = CGAL::Kd_tree<Traits>;
  using Sphere = CGAL::Fuzzy_sphere<Traits>;
  auto inside = [](const Statistics& a, const Statistics& b, double wq, double wt) {
    const double q0 = a[0] - b[0], q1 = a[1] - b[1], t0 = a[2] - b[2], t1 = a[3] - b[3];
    return q0 * q0 + q1 * q1 <= wq * wq && t0 * t0 + t1 * t1 <= wt * wt;
  };
  std::vector<Point> mode_position(position);
  std::vector<Statistics> mode_statistics(statistics);
  {
    // The density is estimated from at most `max_samples` vertices drawn at random (seeded; a
    // stride over the vertex order aliases with the rows of grid-like meshes), while a path still
    // starts from every vertex.
    std::vector<std::size_t> samples(n);
    std::iota(samples.begin(), samples.end(), std::size_t(0));
    if (options.max_samples > 0 && n > options.max_samples) {
      std::mt19937 random(1);
      std::shuffle(samples.begin(), samples.end(), random);
      samples.resize(options.max_samples);
    }
    const Point_map map(position.data());
    Tree tree(samples.begin(), samples.end(), typename Tree::Splitter(), Traits(map));
    tree.build();
    // A path creeps towards its mode: at 25k vertices 70 % of its steps are taken within a
    // quarter window of where it ends. So scouts (a random 1/32 of the vertices, at least 64) run
    // their paths to the end first, and every other path stops as soon as it comes within a
    // quarter of each window of a scout's mode, taking that mode (the first such scout in index
    // order): the modes are joined at half a window below, so the regions are the same, and the
    // mean shift takes 2-3 times fewer steps. The paths are independent and the built trees are
    // only read: one block of paths per thread; the result does not depend on the thread count.
    std::vector<std::size_t> scouts(n);
    std::iota(scouts.begin(), scouts.end(), std::size_t(0));
    {
      std::mt19937 random(2);
      std::shuffle(scouts.begin(), scouts.end(), random);
      scouts.resize(std::min(n, std::max<std::size_t>(64, n / 32)));
      std::sort(scouts.begin(), scouts.end());
    }
    std::vector<Point> scout_position;
    std::vector<Statistics> scout_statistics;
    std::unique_ptr<Tree> scout_tree;
    const double c = options.convergence;
    auto shift = [&](std::size_t i, std::vector<std::size_t>& found) {
      Point y = position[i];
      Statistics f = statistics[i];
      for (std::size_t iteration = 0; iteration < options.max_iterations; ++iteration) {
        std::array<double, 3> sum_p{{0, 0, 0}};
        Statistics sum_f{{0, 0, 0, 0}};
        std::size_t count = 0;
        found.clear();
        tree.search(std::back_inserter(found), Sphere(y, hp, 0, Traits(map)));
        for (std::size_t j : found) {
          if (!inside(statistics[j], f, hq, ht))
            continue;
          sum_p[0] += position[j].x();
          sum_p[1] += position[j].y();
          sum_p[2] += position[j].z();
          for (std::size_t k = 0; k < 4; ++k)
            sum_f[k] += statistics[j][k];
          ++count;
        }
        if (count == 0)
          break;
        const double inv = 1 / double(count);
        const Point next(sum_p[0] * inv, sum_p[1] * inv, sum_p[2] * inv);
        for (double& x : sum_f)
          x *= inv;
        const bool still =
            CGAL::squared_distance(next, y) <= c * c * hp * hp && inside(sum_f, f, c * hq, c * ht);
        y = next;
        f = sum_f;
        if (still)
          break;
        if (scout_tree) {
          found.clear();
          scout_tree->search(std::back_inserter(found),
                             Sphere(y, 0.25 * hp, 0, Traits(Point_map(scout_position.data()))));
          std::size_t first = scout_position.size();
          for (std::size_t k : found)
            if (k < first && inside(scout_statistics[k], f, 0.25 * hq, 0.25 * ht))
              first = k;
          if (first < scout_position.size()) {
            y = scout_position[first];
            f = scout_statistics[first];
            break;
          }
        }
      }
      mode_position[i] = y;
      mode_statistics[i] = f;
    };
    internal::parallel_blocks(
        scouts.size(),
        [&](std::size_t first, std::size_t last) {
          std::vector<std::size_t> found;
          for (std::size_t k = first; k < last; ++k)
            shift(scouts[k], found);
        },
        8);
    for (std::size_t i : scouts) {
      scout_position.push_back(mode_position[i]);
      scout_statistics.push_back(mode_statistics[i]);
    }
    scout_tree =
        std::make_unique<Tree>(boost::counting_iterator<std::size_t>(0),
                               boost::counting_iterator<std::size_t>(scout_position.size()),
                               typename Tree::Splitter(), Traits(Point_map(scout_position.data())));
    scout_tree->build();
    std::vector<char> is_scout(n, 0);
    for (std::size_t i : scouts)
      is_scout[i] = 1;
    internal::parallel_blocks(n, [&](std::size_t first, std::size_t last) {
      std::vector<std::size_t> found;
      for (std::size_t i = first; i < last; ++i)
        if (!is_scout[i])
          shift(i, found);
    });
  }

  // Modes: converged points within half a window of each other, joined transitively.
  internal::Index_sets sets(n);
  {
    // Paths end in few places: each joins the first representative mode it is near, and the
    // representatives near each other are joined (pairs of representatives, not of vertices).
    std::vector<std::size_t> representatives;
    for (std::size_t i = 0; i < n; ++i) {
      bool joined = false;
      for (std::size_t r : representatives)
        if (CGAL::squared_distance(mode_position[i], mode_position[r]) <= 0.25 * hp * hp &&
            inside(mode_statistics[i], mode_statistics[r], 0.5 * hq, 0.5 * ht)) {
          sets.unite(i, r);
          joined = true;
          break;
        }
      if (!joined)
        representatives.push_back(i);
    }
    for (std::size_t a = 0; a < representatives.size(); ++a)
      for (std::size_t b = a + 1; b < representatives.size(); ++b) {
        const std::size_t i = representatives[a], j = representatives[b];
        if (CGAL::squared_distance(mode_position[i], mode_position[j]) <= 0.25 * hp * hp &&
            inside(mode_statistics[i], mode_statistics[j], 0.5 * hq, 0.5 * ht))
          sets.unite(j, i);
      }
  }
  std::vector<std::size_t> label(n, n), id(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t r = sets.find(i);
    if (label[r] == n) {
      label[r] = result.regions.size();
      result.regions.emplace_back();
    }
    id[i] = label[r];
    Texture_region& g = result.regions[id[i]];
    ++g.vertices;
    g.mean_curvature_variance += statistics[i][3];
    g.gaussian_curvature_variance += statistics[i][2];
  }
  for (Texture_region& g : result.regions) {
    g.mean_curvature_variance /= double(g.vertices);
    g.gaussian_curvature_variance /= double(g.vertices);
    g.texture = g.mean_curvature_variance > options.texture_threshold;
  }
  // The texture is the texture regions closed by n rings (dilated, then eroded): the narrow gaps
  // between texels, whose curvature varies little, join the texels around them.
  std::vector<char> texture(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    // A vertex of a texture region whose own ball hardly varies is smooth surface the mean shift
    // joined to the texels beside it (a lobe of the flat margin): it is left out (the closing
    // below gives the gaps between texels back).
    texture[i] =
        result.regions[id[i]].texture && statistics[i][3] >= 0.25 * options.texture_threshold ? 1
                                                                                              : 0;
  auto grow = [&](char value) { // one ring: vertices next to `value` take it
    std::vector<char> next = texture;
    for (vertex_descriptor v : vertices(tm)) {
      if (halfedge(v, tm) == boost::graph_traits<TriangleMesh>::null_halfedge())
        continue;
      const std::size_t i = get(vim, v);
      if (texture[i] == value)
        continue;
      for (vertex_descriptor w : CGAL::vertices_around_target(halfedge(v, tm), tm))
        if (texture[get(vim, w)] == value) {
          next[i] = value;
          break;
        }
    }
    texture.swap(next);
  };
  if (options.closing_rings != Texture_segmentation_options::automatic) {
    for (std::size_t k = 0; k < options.closing_rings; ++k)
      grow(1);
    for (std::size_t k = 0; k < options.closing_rings; ++k)
      grow(0);
  } else {
    // Dilated by ρ, then eroded by ρ, distances along the edges (Dijkstra from the whole set).
    internal::Mesh_indices<TriangleMesh> indices(tm);
    internal::Shortest_path_tree<TriangleMesh> search(tm, indices);
    auto length = [&](auto e) {
      return CGAL::to_double(CGAL::Polygon_mesh_processing::edge_length(
          halfedge(e, tm), tm, CGAL::parameters::vertex_point_map(vpm)));
    };
    // By default the closing reaches 1.5ρ (half a period: the gaps between texels), and the
    // region is dilated by ρ/2 more than it is eroded: a texel's cell reaches half a period
    // from its centre, past its footprint and the ρ by which the statistics spread it.
    const double reach = rings > 0 ? result.ring_radius : 1.5 * result.ring_radius;
    const double margin = rings > 0 ? 0 : 0.125 * result.ring_radius;
    auto grow_by_distance = [&](char value, double by) {
      std::vector<vertex_descriptor> sources;
      for (vertex_descriptor v : vertices(tm))
        if (texture[get(vim, v)] == value)
          sources.push_back(v);
      if (sources.empty())
        return;
      search.run(sources, length);
      for (vertex_descriptor v : vertices(tm))
        if (search.distance(v) <= by)
          texture[get(vim, v)] = value;
    };
    grow_by_distance(1, reach + margin);
    grow_by_distance(0, reach);
    // A second texture coarser than the period found (the shortest strong one) stays apart as
    // single texels: a closing at this period does not reach across its gaps. So the pieces
    // too small to hold a few texels of this period (under 6 P²) are read again at their own
    // period (their mean curvature's autocorrelation over their vertices alone); when it is
    // periodic and a quarter longer or more, they are closed at it as above (the closing of those
    // pieces, added to the texture). Up to two coarser scales.
    for (std::size_t scale = 0; scale < 2 && rings == 0; ++scale) {
      const double period =
          result.coarser_periods.empty() ? result.period.period : result.coarser_periods.back();
      std::vector<std::size_t> count;
      const std::vector<std::size_t> piece = internal::texture_pieces(tm, vim, texture, count);
      std::vector<double> piece_area(count.size(), 0);
      for (std::size_t i = 0; i < n; ++i)
        if (piece[i] != internal::no_piece)
          piece_area[piece[i]] += features.area[i];
      std::vector<char> small(n, 0), valid(n, 0);
      std::vector<char> small_piece(count.size(), 0);
      CGAL::Bbox_3 box;
      for (std::size_t i = 0; i < n; ++i)
        if (piece[i] != internal::no_piece && piece_area[piece[i]] < 6 * period * period) {
          small[i] = 1;
          small_piece[piece[i]] = 1;
          valid[i] = features.fitted_at[i];
          box += position[i].bbox();
        }
      if (!(period > 0) || std::count(small_piece.begin(), small_piece.end(), 1) < 4)
        break;
      const double diagonal =
          std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                    CGAL::square(box.zmax() - box.zmin()));
      const Texel_period coarser = internal::texel_period_from_curvature(
          position, features.normal, features.area, features.mean_curvature, valid,
          features.mean_edge_length, diagonal);
      if (!coarser.periodic || coarser.period < 1.25 * period)
        break;
      result.coarser_periods.push_back(coarser.period);
      // The statistics spread each texel by the ball's radius ρ = P/3 of the period found; at
      // the coarser period they would have spread it by more: the pieces are first dilated by
      // the difference.
      const double radius = coarser.period / 3;
      std::vector<char> kept = texture;
      texture = small;
      grow_to_texel_cells(tm, vim, search, length, position, features.area, piece, small_piece,
                          coarser.period, radius - period / 3 + 0.125 * radius, texture);
      grow_by_distance(1, 1.5 * radius);
      grow_by_distance(0, 1.5 * radius);
      for (std::size_t i = 0; i < n; ++i)
        texture[i] = texture[i] || kept[i];
    }
  }
  for (vertex_descriptor v : vertices(tm)) {
    const std::size_t i = get(vim, v);
    put(region, v, id[i]);
    put(is_texture, v, texture[i] != 0);
    result.texture_vertices += texture[i] ? 1 : 0;
  }
  return result;
}

} // namespace internal
} // namespace tessera
