// The body of `mosaic_quality()` (tessera/mosaic/quality_report.h) and its steps: coverage and
// overlap of the tiles at samples spread by error diffusion, the widest bare patch, orientation
// against the field, rows and gaps, course drift, and tiles crossing feature lines. Included at the
// end of the public header; nothing here is meant to be called directly.
#pragma once

#include <tessera/mosaic/quality_report.h>

#include <tessera/internal/named_parameters.h>
#include <tessera/internal/parallel.h>
#include <tessera/mosaic/internal/error_diffusion.h>
#include <tessera/mosaic/internal/feature_segments.h>
#include <tessera/mosaic/internal/point_search.h>
#include <tessera/mosaic/internal/quality_measures.h>
#include <tessera/mosaic/internal/segment_box.h>
#include <tessera/mosaic/internal/surface_arrays.h>
#include <tessera/mosaic/internal/tile_frames.h>

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace tessera::internal {

// The tiles and the feature lines `mosaic_quality()` measures, by the mesh they lie on.
template <typename TriangleMesh>
using Mosaic_tiles_of =
    std::vector<Mosaic_tile<typename boost::graph_traits<TriangleMesh>::face_descriptor>>;
template <typename TriangleMesh>
using Feature_lines_of =
    std::vector<Feature_line<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>>;

// The tiles being measured: their frames, the largest side of any, and a search over their
// centres.
template <typename FaceDescriptor> struct Quality_tiles {
  explicit Quality_tiles(const std::vector<Mosaic_tile<FaceDescriptor>>& t)
      : tiles(t), f(tile_frames(t)) {
    for (const auto& tile : t)
      largest = std::max({largest, tile.size[0], tile.size[1]});
    search.reset(f.centres);
  }
  const std::vector<Mosaic_tile<FaceDescriptor>>& tiles;
  Tile_frames f;
  double largest = 0;
  Point_search search;
};

// The layout's tile side: the median over the tiles, so that shrunk, trimmed or filled tiles (or
// another tool's tiles of several sizes) do not make the figures depend on the tiles' order.
template <typename FaceDescriptor>
double median_tile_side(const std::vector<Mosaic_tile<FaceDescriptor>>& tiles) {
  std::vector<double> sides(tiles.size());
  for (std::size_t i = 0; i < tiles.size(); ++i)
    sides[i] = std::sqrt(tiles[i].size[0] * tiles[i].size[1]);
  return percentile(std::move(sides), 0.5);
}

// Tile i over the sample at p, on a face of normal n whose corners' faces have the area-weighted
// normal `ring`: `h`, the tiles over the sample so far (0, 1, or 2 for two or more), counts the
// tile when it covers the sample, and `nearest` falls to the sample's distance to the tile's
// rectangle (in the tile's plane, on the side the sample faces).
template <typename FaceDescriptor>
void test_tile_over_sample(const Quality_tiles<FaceDescriptor>& t, std::size_t i, const Vec3& p,
                           const Vec3& n, const Vec3& ring, char& h, double& nearest) {
  if (h >= 2)
    return;
  const auto& tile = t.tiles[i];
  const Vec3 d = p - t.f.centres[i];
  // A tile across a crease (up to 120° from the sample's face) bounds a bare patch as one
  // beside it does; one on the other side of a thin part (facing away) does not. Facing is also
  // judged against the normal around the face's corners: a sliver folded over in a crumpled spot
  // of the mesh faces away from every tile above it, and femur's at seed 2, 0.014 tile² with
  // a tile 0.07 tiles away, read as a bare patch 2.87 tiles wide.
  const double facing = dot(t.f.ns[i], n);
  if (facing <= -0.5 && dot(t.f.ns[i], ring) <= -0.5)
    return;
  const double x = dot(d, t.f.xs[i]), y = dot(d, t.f.ys[i]);
  const double dx = std::max(0.0, std::abs(x) - tile.size[0] / 2),
               dy = std::max(0.0, std::abs(y) - tile.size[1] / 2);
  nearest = std::min(nearest, std::hypot(dx, dy, dot(d, t.f.ns[i])));
  if (facing <= 0 || std::abs(dot(d, t.f.ns[i])) > 0.5 * t.largest)
    return; // covering is judged by the face's own normal
  const bool in = tile.outline.empty()
                      ? std::abs(x) <= tile.size[0] / 2 && std::abs(y) <= tile.size[1] / 2
                      : inside_outline(tile.outline, x, y);
  h = char(h + in);
}

// Samples [first, last) (they come face by face) against the tiles: `hits[k]`, the tiles over
// sample k (0, 1, or 2 for two or more), and for a sample no tile covers, `bare[k]`, its distance
// to the nearest tile. A tile covers a sample only within √(1/4 + 1/4 + 1/4) = 0.866 of the largest
// side of it (half the side along each axis, half the largest side off its plane): the tiles within
// that reach of a face's samples, found by one range query per face, are all the candidates,
// whatever their number.
template <typename TriangleMesh, typename FaceDescriptor>
void cover_samples(const Surface_arrays<TriangleMesh>& s, const Quality_tiles<FaceDescriptor>& t,
                   const std::vector<Surface_point>& samples, const std::vector<Vec3>& ring,
                   std::size_t first, std::size_t last, std::size_t candidates,
                   std::vector<char>& hits, std::vector<double>& bare) {
  const double cover_reach = 0.8661 * t.largest;
  std::vector<std::size_t> near;
  for (std::size_t k = first; k < last;) {
    const std::uint32_t f = samples[k].face;
    std::size_t end = k + 1;
    while (end < last && samples[end].face == f)
      ++end;
    const Vec3 c = s.centroid(f);
    double radius = 0;
    for (int j = 0; j < 3; ++j)
      radius = std::max(radius, norm(s.point(f, j) - c));
    near.clear();
    t.search.within(c, radius + cover_reach, near);
    const Vec3& n = s.normal(f);
    for (; k < end; ++k) {
      const Vec3 p = s.position(samples[k]);
      double nearest = std::numeric_limits<double>::infinity();
      for (const std::size_t i : near)
        test_tile_over_sample(t, i, p, n, ring[f], hits[k], nearest);
      if (hits[k] != 0)
        continue;
      // A tile beyond the reach is farther than reach − (its half diagonal, at most
      // 0.7072 of the largest side) from the sample: only a nearer bare distance is final.
      if (nearest > 0.158 * t.largest)
        t.search.nearest(p, candidates, [&](std::size_t i, double) {
          test_tile_over_sample(t, i, p, n, ring[f], hits[k], nearest);
        });
      bare[k] = nearest;
    }
  }
}

// Distances to the surface's open borders (its holes and rims): an AABB tree of the border edges.
class Border_distance {
public:
  template <typename TriangleMesh> explicit Border_distance(const Surface_arrays<TriangleMesh>& s) {
    for (std::uint32_t f = 0; f < s.number_of_faces(); ++f)
      for (int k = 0; k < 3; ++k)
        if (s.across(f, k) == no_index)
          segments_.emplace_back(point(s.point(f, k)), point(s.point(f, (k + 1) % 3)));
    if (segments_.empty())
      return;
    tree_.insert(segments_.begin(), segments_.end());
    tree_.build();
    tree_.accelerate_distance_queries();
  }
  /// Distance from p to the nearest border edge; infinite on a closed surface.
  double operator()(const Vec3& p) const {
    return segments_.empty() ? std::numeric_limits<double>::infinity()
                             : std::sqrt(tree_.squared_distance(point(p)));
  }

private:
  using K = CGAL::Epick;
  using Segments = std::vector<K::Segment_3>;
  using Tree = CGAL::AABB_tree<
      CGAL::AABB_traits<K, CGAL::AABB_segment_primitive<K, Segments::const_iterator>>>;
  static K::Point_3 point(const Vec3& v) { return {v[0], v[1], v[2]}; }
  Segments segments_;
  Tree tree_;
};

// Coverage and overlap at samples spread by error diffusion, and the widest bare patch in units
// of `side`.
template <typename TriangleMesh, typename FaceDescriptor>
void measure_coverage(const Surface_arrays<TriangleMesh>& s, const Quality_tiles<FaceDescriptor>& t,
                      const Mosaic_quality_options& options, double side, Mosaic_quality& q) {
  const std::size_t wanted =
      std::size_t(std::ceil(options.samples_per_tile * double(t.tiles.size())));
  const auto samples = error_diffusion_points(s, wanted, options.seed);
  // Each face's normal around its corners: the area-weighted normals of the faces at each corner.
  std::vector<Vec3> corner_sum(s.number_of_vertices(), Vec3{{0, 0, 0}});
  for (std::uint32_t f = 0; f < s.number_of_faces(); ++f)
    for (const std::uint32_t v : s.corners(f))
      corner_sum[v] = corner_sum[v] + s.area(f) * s.normal(f);
  std::vector<Vec3> ring(s.number_of_faces());
  for (std::uint32_t f = 0; f < s.number_of_faces(); ++f) {
    const auto& c = s.corners(f);
    const Vec3 sum = corner_sum[c[0]] + corner_sum[c[1]] + corner_sum[c[2]];
    const double length = norm(sum);
    ring[f] = length > 0 ? (1 / length) * sum : s.normal(f);
  }
  // Samples are independent: in parallel.
  std::vector<char> hits(samples.size(), 0);
  std::vector<double> bare(samples.size(), 0);
  parallel_blocks(samples.size(), [&](std::size_t first, std::size_t last) {
    cover_samples(s, t, samples, ring, first, last, options.candidates, hits, bare);
  });
  std::size_t covered = 0, doubled = 0;
  for (char h : hits) {
    covered += h >= 1;
    doubled += h >= 2;
  }
  q.samples = samples.size();
  // The disk of an uncovered sample ends at its nearest tile and at the surface's open border: a
  // disk that hangs over a rim or a hole is not bare surface (blade's open tip, a strip of rim a
  // fifth of a tile wide beside a hole two tiles across, read 4.9 tiles). The samples farthest from
  // every tile first, until no farther one can be wider.
  std::vector<std::pair<double, std::size_t>> farthest;
  for (std::size_t k = 0; k < bare.size(); ++k)
    if (std::isfinite(bare[k]) && bare[k] > 0)
      farthest.push_back({-bare[k], k});
  std::sort(farthest.begin(), farthest.end());
  const Border_distance border(s);
  for (const auto& [minus_tile, k] : farthest) {
    if (-2 * minus_tile / side <= q.largest_gap)
      break;
    const Vec3 c = s.position(samples[k]);
    const double radius = std::min(-minus_tile, border(c));
    if (2 * radius / side > q.largest_gap) {
      q.largest_gap = 2 * radius / side;
      q.largest_gap_center = {{c[0], c[1], c[2]}};
    }
  }
  if (!samples.empty()) {
    q.coverage = double(covered) / double(samples.size());
    q.overlap = double(doubled) / double(samples.size());
  }
}

// Orientation against the field at each centre (power average of the face's corners).
template <typename TriangleMesh, typename VertexFieldMap, typename FaceDescriptor>
void measure_orientation(const TriangleMesh& tm, const VertexFieldMap& field,
                         const Quality_tiles<FaceDescriptor>& t, int symmetry, Mosaic_quality& q) {
  std::vector<double> orientation;
  for (std::size_t i = 0; i < t.tiles.size(); ++i) {
    // The field at the face's corners in the order of the tile's barycentric coordinates.
    std::array<Vec3, 3> x;
    std::size_t k = 0;
    for (auto v : CGAL::vertices_around_face(halfedge(t.tiles[i].face, tm), tm))
      if (k < 3)
        x[k++] = to_vec3(get(field, v));
    double a = 0;
    if (interpolated_field_angle(x, t.tiles[i].barycentric, t.f.xs[i], t.f.ys[i], symmetry, a))
      orientation.push_back(std::abs(a) * 180 / std::acos(-1.0));
  }
  q.orientation_error_median = percentile(orientation, 0.5);
  q.orientation_error_p95 = percentile(orientation, 0.95);
  q.orientation_error_max =
      orientation.empty() ? 0 : *std::max_element(orientation.begin(), orientation.end());
}

// Tile i's nearest neighbour on its side of the surface so far: its distance in i's plane, the
// angle between the direction to it and i's nearest axis, and the gap between the two along the
// axis that separates them.
struct Row_neighbour {
  double distance = std::numeric_limits<double>::infinity(), angle = 0, gap = 0;
};

// Tile j as a candidate for tile i's nearest neighbour `r`.
template <typename FaceDescriptor>
void closer_row_neighbour(const Quality_tiles<FaceDescriptor>& t, std::size_t i, std::size_t j,
                          Row_neighbour& r) {
  const Tile_frames& f = t.f;
  if (j == i || dot(f.ns[i], f.ns[j]) <= 0.5)
    return;
  const Vec3 d = f.centres[j] - f.centres[i];
  const double x = dot(d, f.xs[i]), y = dot(d, f.ys[i]);
  const double dist = std::hypot(x, y);
  if (!(dist < r.distance))
    return;
  r.distance = dist;
  const double a = std::atan2(std::abs(y), std::abs(x)) * 180 / std::acos(-1.0);
  r.angle = std::min(a, 90 - a);
  // Half extents of j along i's axes (j may be turned against i).
  const double c = std::abs(dot(f.xs[j], f.xs[i])), sn = std::abs(dot(f.xs[j], f.ys[i]));
  const double jx = 0.5 * (t.tiles[j].size[0] * c + t.tiles[j].size[1] * sn);
  const double jy = 0.5 * (t.tiles[j].size[0] * sn + t.tiles[j].size[1] * c);
  const double gx = std::abs(x) - t.tiles[i].size[0] / 2 - jx,
               gy = std::abs(y) - t.tiles[i].size[1] / 2 - jy;
  r.gap = std::max(gx, gy);
}

// Rows and gaps: each tile's nearest neighbour on its side of the surface.
template <typename FaceDescriptor>
void measure_rows_and_gaps(const Quality_tiles<FaceDescriptor>& t, Mosaic_quality& q) {
  std::vector<double> rows, gaps;
  for (std::size_t i = 0; i < t.tiles.size(); ++i) {
    Row_neighbour r;
    t.search.nearest(t.f.centres[i], 7,
                     [&](std::size_t j, double) { closer_row_neighbour(t, i, j, r); });
    if (r.distance < std::numeric_limits<double>::infinity()) {
      rows.push_back(r.angle);
      gaps.push_back(r.gap);
    }
  }
  q.row_alignment_median = percentile(rows, 0.5);
  q.row_alignment_p95 = percentile(rows, 0.95);
  if (!gaps.empty()) {
    double sum = 0;
    for (double g : gaps)
      sum += g;
    q.gap_mean = sum / double(gaps.size());
    q.gap_min = *std::min_element(gaps.begin(), gaps.end());
  }
}

// The course drift between tile i and its neighbour j (squared distance d2), appended to `drift`
// in degrees when j is within `reach` on i's side of the surface: the angle between i's x axis and
// j's turned into i's plane, modulo `period`.
inline void add_course_drift(const Tile_frames& f, std::size_t i, std::size_t j, double d2,
                             double reach, double period, std::vector<double>& drift) {
  if (j == i || dot(f.ns[i], f.ns[j]) <= 0.5 || d2 > reach * reach)
    return;
  // j's axis turned about nj × ni until nj meets ni. Projected instead, a helix around a tube
  // read as drift though the tiles turn with the surface only: 45° to a tube 12 tiles around, 3.9°
  // between neighbours around it.
  const Vec3 xj = turned(f.xs[j], f.ns[j], f.ns[i]);
  double a = std::atan2(dot(xj, f.ys[i]), dot(xj, f.xs[i]));
  a = std::remainder(a, period);
  drift.push_back(std::abs(a) * 180 / std::acos(-1.0));
}

// Course drift: each tile against its neighbours within 1.5 spacings (spacing √(A/N)).
template <typename FaceDescriptor>
void measure_course_drift(const Quality_tiles<FaceDescriptor>& t, int symmetry, Mosaic_quality& q) {
  std::vector<double> drift;
  const double reach = 1.5 * std::sqrt(q.area / double(t.tiles.size()));
  const double period = 2 * std::acos(-1.0) / symmetry;
  for (std::size_t i = 0; i < t.tiles.size(); ++i)
    t.search.nearest(t.f.centres[i], 9, [&](std::size_t j, double d2) {
      add_course_drift(t.f, i, j, d2, reach, period, drift);
    });
  q.course_drift_median = percentile(drift, 0.5);
  q.course_drift_p95 = percentile(drift, 0.95);
}

// Tiles crossing feature lines: the part of a segment near the tile's plane passes through its
// rectangle (the test the mosaic's last pass clears), for the lines of the tile's own connected
// component beside a face within 60° of the tile's plane.
template <typename TriangleMesh, typename FaceDescriptor>
std::size_t tiles_crossing_features(const Surface_arrays<TriangleMesh>& s,
                                    const Quality_tiles<FaceDescriptor>& t,
                                    const Feature_lines_of<TriangleMesh>& features) {
  const Tile_frames& f = t.f;
  const Feature_segments<TriangleMesh> segments(s, features, -1);
  std::size_t count = 0;
  for (std::size_t i = 0; i < t.tiles.size(); ++i) {
    bool crosses = false;
    auto test = [&](const Vec3& a3, const Vec3& b3) {
      std::array<double, 2> a, b;
      crosses = crosses || segment_crosses_tile(a3 - f.centres[i], b3 - f.centres[i], f.xs[i],
                                                f.ys[i], f.ns[i], t.tiles[i].size, a, b);
    };
    segments.segments_near_facing(s.region(s.id(t.tiles[i].face)), f.centres[i],
                                  tile_reach(t.tiles[i].size), f.ns[i], test);
    count += crosses;
  }
  return count;
}

} // namespace tessera::internal

namespace tessera {

template <typename TriangleMesh, typename VertexFieldMap, typename NamedParameters>
Mosaic_quality mosaic_quality(const TriangleMesh& tm,
                              const internal::Mosaic_tiles_of<TriangleMesh>& tiles,
                              const VertexFieldMap& field,
                              const internal::Feature_lines_of<TriangleMesh>& features,
                              const Mosaic_quality_options& options, const NamedParameters& np) {
  Mosaic_quality q;
  q.tiles = tiles.size();
  const auto vpm = internal::vertex_point_map(tm, np);
  const internal::Surface_arrays<TriangleMesh> s(tm, vpm, {});
  q.area = s.total_area();
  if (tiles.empty() || faces(tm).empty())
    return q;
  const internal::Quality_tiles<typename boost::graph_traits<TriangleMesh>::face_descriptor> t(
      tiles);
  const double side = internal::median_tile_side(tiles);
  internal::measure_coverage(s, t, options, side, q);
  internal::measure_orientation(tm, field, t, options.symmetry, q);
  internal::measure_rows_and_gaps(t, q);
  internal::measure_course_drift(t, options.symmetry, q);
  // The ideal gap: a cell of area A/N holds a tile and its grout.
  const double cell = std::sqrt(q.area / double(tiles.size()));
  q.gap_ideal = cell - side;
  if (!features.empty())
    q.tiles_crossing_features = internal::tiles_crossing_features(s, t, features);
  return q;
}

} // namespace tessera
