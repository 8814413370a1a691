// How good a mosaic is, measured on the surface: coverage and overlap of the tiles, their
// orientation against the field, how well neighbours line up in rows, the grout gaps, and tiles
// that cross a feature line. Works on any tiles (Tessera's or another tool's) given as
// `Mosaic_tile`s.
#pragma once

#include <tessera/fields/feature_lines.h>
#include <tessera/internal/named_parameters.h>
#include <tessera/internal/parallel.h>
#include <tessera/mosaic/internal/error_diffusion.h>
#include <tessera/mosaic/internal/feature_segments.h>
#include <tessera/mosaic/internal/point_search.h>
#include <tessera/mosaic/internal/quality_measures.h>
#include <tessera/mosaic/internal/segment_box.h>
#include <tessera/mosaic/internal/surface_arrays.h>
#include <tessera/mosaic/tile.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <vector>

namespace tessera {

struct Mosaic_quality_options {
  /// Surface samples per tile (spread by error diffusion, i.e. uniform in area): the coverage and
  /// overlap figures are fractions of these samples, exact to about 1/√(samples) each.
  double samples_per_tile = 40;
  /// Tiles a bare sample's distance to the nearest tile is also taken over (the nearest centres),
  /// where no tile within covering reach is near it.
  std::size_t candidates = 12;
  /// Symmetry n of the field for the orientation error (angles are taken modulo 2π/n).
  int symmetry = 4;
  unsigned seed = 7;
};

/// The figures of a mosaic. Fractions are of the surface area A; angles in degrees; lengths in the
/// mesh's units.
struct Mosaic_quality {
  std::size_t tiles = 0, samples = 0;
  double area = 0;
  /// Area covered by at least one tile (tiles taken in their planes, a sample counting as covered
  /// when its projection along the tile's normal falls inside the tile, within half a tile's size
  /// of its plane and on the side its normal faces), over A.
  double coverage = 0;
  /// Area covered by two tiles or more, over A.
  double overlap = 0;
  /// Angle between each tile's x axis and the field at its centre, modulo 2π/n: median, 95th
  /// percentile, largest.
  double orientation_error_median = 0, orientation_error_p95 = 0, orientation_error_max = 0;
  /// Angle between the direction to each tile's nearest neighbour (in the tile's plane) and the
  /// tile's nearest axis: 0 when tiles sit in rows and columns along the field, 45 for a diagonal.
  double row_alignment_median = 0, row_alignment_p95 = 0;
  /// Gap between each tile and its nearest neighbour along the axis that separates them (negative
  /// when they overlap): mean and smallest over the tiles; the layout's ideal is the grout width.
  double gap_mean = 0, gap_min = 0, gap_ideal = 0;
  /// Course drift: angle between the x axes of neighbouring tiles (each tile against its
  /// neighbours within 1.5 spacings on its side of the surface, the other's axis turned into its
  /// plane by the least rotation that takes the other's normal to its own, as a connection
  /// transports it), modulo 2π/n: median and 95th percentile. What a viewer sees as rows that bend
  /// or tiles at odd angles, whatever the field was.
  double course_drift_median = 0, course_drift_p95 = 0;
  /// The widest bare patch: the diameter of the largest disk of the surface that no tile touches
  /// (twice the largest distance from an uncovered sample to its nearest tile facing less than 120°
  /// away from the sample's face: across a crease, not across a thin part), in units of the
  /// tile side √(l_x·l_y) (the median over the tiles). A regular layout's is about the grout width,
  /// ~0.05 tiles at g = 0.1.
  double largest_gap = 0;
  /// Where that disk is: the uncovered sample farthest from every tile (0, 0, 0 when none is).
  std::array<double, 3> largest_gap_center{{0, 0, 0}};
  /// Tiles whose rectangle crosses a feature line.
  std::size_t tiles_crossing_features = 0;
};

/// Measures `tiles` on `tm` against `field` (a vertex property map of vectors) and `features`.
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh, typename VertexFieldMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Mosaic_quality mosaic_quality(
    const TriangleMesh& tm,
    const std::vector<Mosaic_tile<typename boost::graph_traits<TriangleMesh>::face_descriptor>>&
        tiles,
    const VertexFieldMap& field,
    const std::vector<
        Feature_line<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>>& features,
    const Mosaic_quality_options& options = {},
    const NamedParameters& np = CGAL::parameters::default_values()) {
  using internal::Vec3;
  Mosaic_quality q;
  q.tiles = tiles.size();
  const auto vpm = internal::vertex_point_map(tm, np);
  const internal::Surface_arrays<TriangleMesh> s(tm, vpm, {});
  q.area = s.total_area();
  if (tiles.empty() || faces(tm).empty())
    return q;
  auto v3 = [](const std::array<double, 3>& a) { return Vec3{{a[0], a[1], a[2]}}; };
  std::vector<Vec3> centres, xs, ys, ns;
  double largest = 0;
  for (const auto& t : tiles) {
    centres.push_back(v3(t.center));
    ns.push_back(v3(t.normal));
    xs.push_back(v3(t.x_axis));
    ys.push_back(internal::cross(ns.back(), xs.back()));
    largest = std::max({largest, t.size[0], t.size[1]});
  }
  const internal::Point_search search(centres);

  // Coverage and overlap.
  const std::size_t wanted =
      std::size_t(std::ceil(options.samples_per_tile * double(tiles.size())));
  const auto samples = internal::error_diffusion_points(s, wanted, options.seed);
  // Tiles over each sample (0, 1, or 2 for two or more); samples are independent: in parallel.
  std::vector<char> hits(samples.size(), 0);
  // For each sample no tile covers, its distance to the nearest tile's rectangle (in that tile's
  // plane, on the side the sample faces).
  std::vector<double> bare(samples.size(), 0);
  // A tile covers a sample only within √(1/4 + 1/4 + 1/4) = 0.866 of the largest side of it (half
  // the side along each axis, half the largest side off its plane): the tiles within that reach
  // of a face's samples, found by one range query per face (the samples come face by face), are
  // all the candidates, whatever their number.
  const double cover_reach = 0.8661 * largest;
  const auto test = [&](std::size_t k, std::size_t i, const Vec3& p, const Vec3& n,
                        double& nearest) {
    char& h = hits[k];
    if (h >= 2)
      return;
    const Vec3 d = p - centres[i];
    // A tile across a crease (up to 120° from the sample's face) bounds a bare patch as one
    // beside it does; one on the other side of a thin part (facing away) does not.
    const double facing = internal::dot(ns[i], n);
    if (facing <= -0.5)
      return;
    const double x = internal::dot(d, xs[i]), y = internal::dot(d, ys[i]);
    const double dx = std::max(0.0, std::abs(x) - tiles[i].size[0] / 2),
                 dy = std::max(0.0, std::abs(y) - tiles[i].size[1] / 2);
    nearest = std::min(nearest, std::hypot(dx, dy, internal::dot(d, ns[i])));
    if (facing <= 0 || std::abs(internal::dot(d, ns[i])) > 0.5 * largest)
      return;
    const bool in = tiles[i].outline.empty()
                        ? std::abs(x) <= tiles[i].size[0] / 2 && std::abs(y) <= tiles[i].size[1] / 2
                        : internal::inside_outline(tiles[i].outline, x, y);
    h = char(h + in);
  };
  internal::parallel_blocks(samples.size(), [&](std::size_t first, std::size_t last) {
    std::vector<std::size_t> near;
    for (std::size_t k = first; k < last;) {
      const std::uint32_t f = samples[k].face;
      std::size_t end = k + 1;
      while (end < last && samples[end].face == f)
        ++end;
      const Vec3 c = s.centroid(f);
      double radius = 0;
      for (int j = 0; j < 3; ++j)
        radius = std::max(radius, internal::norm(s.point(f, j) - c));
      near.clear();
      search.within(c, radius + cover_reach, near);
      const Vec3& n = s.normal(f);
      for (; k < end; ++k) {
        const Vec3 p = s.position(samples[k]);
        double nearest = std::numeric_limits<double>::infinity();
        for (const std::size_t i : near)
          test(k, i, p, n, nearest);
        if (hits[k] != 0)
          continue;
        // A tile beyond the reach is farther than reach − (its half diagonal, at most
        // 0.7072 of the largest side) from the sample: only a nearer bare distance is final.
        if (nearest > 0.158 * largest)
          search.nearest(p, options.candidates,
                         [&](std::size_t i, double) { test(k, i, p, n, nearest); });
        bare[k] = nearest;
      }
    }
  });
  std::size_t covered = 0, doubled = 0;
  for (char h : hits) {
    covered += h >= 1;
    doubled += h >= 2;
  }
  q.samples = samples.size();
  // The layout's tile side: the median over the tiles, so that shrunk, trimmed or filled tiles (or
  // another tool's tiles of several sizes) do not make the figures depend on the tiles' order.
  std::vector<double> sides(tiles.size());
  for (std::size_t i = 0; i < tiles.size(); ++i)
    sides[i] = std::sqrt(tiles[i].size[0] * tiles[i].size[1]);
  const double side = internal::percentile(std::move(sides), 0.5);
  for (std::size_t k = 0; k < bare.size(); ++k)
    if (std::isfinite(bare[k]) && 2 * bare[k] / side > q.largest_gap) {
      q.largest_gap = 2 * bare[k] / side;
      const Vec3 c = s.position(samples[k]);
      q.largest_gap_center = {{c[0], c[1], c[2]}};
    }
  if (!samples.empty()) {
    q.coverage = double(covered) / double(samples.size());
    q.overlap = double(doubled) / double(samples.size());
  }

  // Orientation against the field at each centre (power average of the face's corners).
  const int sym = options.symmetry;
  std::vector<double> orientation, rows, gaps;
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    // The field at the face's corners in the order of the tile's barycentric coordinates.
    std::array<Vec3, 3> x;
    std::size_t k = 0;
    for (auto v : CGAL::vertices_around_face(halfedge(tiles[i].face, tm), tm))
      if (k < 3)
        x[k++] = internal::to_vec3(get(field, v));
    double a = 0;
    if (internal::interpolated_field_angle(x, tiles[i].barycentric, xs[i], ys[i], sym, a))
      orientation.push_back(std::abs(a) * 180 / std::acos(-1.0));
  }
  q.orientation_error_median = internal::percentile(orientation, 0.5);
  q.orientation_error_p95 = internal::percentile(orientation, 0.95);
  q.orientation_error_max =
      orientation.empty() ? 0 : *std::max_element(orientation.begin(), orientation.end());

  // Rows and gaps: each tile's nearest neighbour on its side of the surface.
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    double best = std::numeric_limits<double>::infinity(), angle = 0, gap = 0;
    search.nearest(centres[i], 7, [&](std::size_t j, double) {
      if (j == i || internal::dot(ns[i], ns[j]) <= 0.5)
        return;
      const Vec3 d = centres[j] - centres[i];
      const double x = internal::dot(d, xs[i]), y = internal::dot(d, ys[i]);
      const double r = std::hypot(x, y);
      if (!(r < best))
        return;
      best = r;
      const double a = std::atan2(std::abs(y), std::abs(x)) * 180 / std::acos(-1.0);
      angle = std::min(a, 90 - a);
      // Half extents of j along i's axes (j may be turned against i).
      const double c = std::abs(internal::dot(xs[j], xs[i])),
                   sn = std::abs(internal::dot(xs[j], ys[i]));
      const double jx = 0.5 * (tiles[j].size[0] * c + tiles[j].size[1] * sn);
      const double jy = 0.5 * (tiles[j].size[0] * sn + tiles[j].size[1] * c);
      const double gx = std::abs(x) - tiles[i].size[0] / 2 - jx,
                   gy = std::abs(y) - tiles[i].size[1] / 2 - jy;
      gap = std::max(gx, gy);
    });
    if (best < std::numeric_limits<double>::infinity()) {
      rows.push_back(angle);
      gaps.push_back(gap);
    }
  }
  // Course drift: each tile against its neighbours within 1.5 spacings (spacing √(A/N)).
  std::vector<double> drift;
  const double reach = 1.5 * std::sqrt(q.area / double(tiles.size()));
  const double period = 2 * std::acos(-1.0) / sym;
  for (std::size_t i = 0; i < tiles.size(); ++i)
    search.nearest(centres[i], 9, [&](std::size_t j, double d2) {
      if (j == i || internal::dot(ns[i], ns[j]) <= 0.5 || d2 > reach * reach)
        return;
      // j's axis turned about nj × ni until nj meets ni. Projected instead, a helix around a
      // tube read as drift though the tiles turn with the surface only: 45° to a tube 12 tiles
      // around, 3.9° between neighbours around it.
      const Vec3 xj = turned(xs[j], ns[j], ns[i]);
      double a = std::atan2(internal::dot(xj, ys[i]), internal::dot(xj, xs[i]));
      a = std::remainder(a, period);
      drift.push_back(std::abs(a) * 180 / std::acos(-1.0));
    });
  q.course_drift_median = internal::percentile(drift, 0.5);
  q.course_drift_p95 = internal::percentile(drift, 0.95);
  q.row_alignment_median = internal::percentile(rows, 0.5);
  q.row_alignment_p95 = internal::percentile(rows, 0.95);
  if (!gaps.empty()) {
    double sum = 0;
    for (double g : gaps)
      sum += g;
    q.gap_mean = sum / double(gaps.size());
    q.gap_min = *std::min_element(gaps.begin(), gaps.end());
  }
  // The ideal gap: a cell of area A/N holds a tile and its grout.
  const double cell = std::sqrt(q.area / double(tiles.size()));
  q.gap_ideal = cell - side;

  // Tiles crossing feature lines: the part of a segment near the tile's plane passes through its
  // rectangle (the test the mosaic's last pass clears), for the lines of the tile's own connected
  // component.
  if (!features.empty()) {
    const internal::Feature_segments<TriangleMesh> segments(s, features, -1);
    for (std::size_t i = 0; i < tiles.size(); ++i) {
      bool crosses = false;
      auto test = [&](const Vec3& a3, const Vec3& b3) {
        std::array<double, 2> a, b;
        crosses = crosses || internal::segment_crosses_tile(a3 - centres[i], b3 - centres[i], xs[i],
                                                            ys[i], ns[i], tiles[i].size, a, b);
      };
      segments.segments_near(s.region(s.id(tiles[i].face)), centres[i],
                             internal::tile_reach(tiles[i].size), test);
      q.tiles_crossing_features += crosses;
    }
  }
  return q;
}

} // namespace tessera
