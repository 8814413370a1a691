// The scale of a geometric texture read from the surface itself: the area-weighted spatial
// autocorrelation of the mean curvature, whose first peak past the central lobe is the texels'
// period (the distance between neighbouring texels), so no sample size has to be given. The
// public entry is `estimate_texel_period` (texel_period.h beside texture_segmentation.h).
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>

#include <boost/iterator/counting_iterator.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <random>
#include <vector>

namespace tessera {

/// The texels' scale found from the surface (`estimate_texel_period`).
struct Texel_period {
  /// Distance between neighbouring texels in model units: the first peak of the mean curvature's
  /// autocorrelation past its central lobe, or, when the texture shows no period, twice the
  /// lobe's extent (the first minimum), about a texel's diameter with its margin.
  double period = 0;
  /// Radius of the central lobe (first minimum of the autocorrelation): about a texel's radius.
  double lobe = 0;
  /// Whether a peak was found; its height above the first minimum, relative to the
  /// autocorrelation at 0 (1: a perfectly periodic texture).
  bool periodic = false;
  double peak_strength = 0;
  /// Largest distance searched and the mean edge length (the bins are a tenth of it).
  double search_radius = 0;
  double mean_edge_length = 0;
};

namespace internal {

/// The first minimum of a normalized autocorrelation `c` past the point where it fell below a
/// half: the lowest point before the curve rises 0.1 above it (smaller wiggles are noise).
inline std::size_t autocorrelation_lobe(const std::vector<double>& c) {
  std::size_t lobe = 0;
  while (lobe + 1 < c.size() && c[lobe] >= 0.5)
    ++lobe;
  for (std::size_t b = lobe; b < c.size() && c[b] < c[lobe] + 0.1; ++b)
    if (c[b] < c[lobe])
      lobe = b;
  return lobe;
}

/// The first real peak of `c` past `lobe`: a local maximum over ± half the lobe that rises above
/// the minimum by at least 0.6 of the highest peak's rise and by 0.05 (the peaks at two periods
/// and along diagonals are often as high, and noise makes small ones), not the end of a slope
/// still rising at the search radius. Returns `lobe` when there is none.
inline std::size_t autocorrelation_peak(const std::vector<double>& c, std::size_t lobe) {
  const std::size_t bins = c.size();
  std::size_t highest = lobe;
  for (std::size_t b = lobe; b < bins; ++b)
    if (c[b] > c[highest])
      highest = b;
  const double rise = c[highest] - c[lobe];
  const std::size_t half = std::max<std::size_t>(1, lobe / 2);
  if (rise < 0.05)
    return lobe;
  for (std::size_t b = lobe + 1; b + half < bins; ++b) {
    if (c[b] - c[lobe] < 0.6 * rise)
      continue;
    bool local = true;
    for (std::size_t k = b - std::min(b, half); k <= b + half && local; ++k)
      local = c[k] <= c[b];
    if (local)
      return b;
  }
  return lobe;
}

/// Autocorrelation of `h` (per vertex, already centred) over Euclidean distance, with sources
/// drawn with probability ∝ area·h² (so they sit in the texture) and every neighbour weighted by
/// its area (so the result does not depend on the sampling). `position`, `normal`, `area`, `h`
/// and `valid` are per vertex.
///
/// The pairs are also binned by direction: the offset projected into the source's tangent plane,
/// its angle (modulo π) measured from the x axis projected there (y where x is almost normal),
/// in 8 sectors. A texture of parallel ridges repeats only across them, and averaging over all
/// directions smears that peak away; a square lattice peaks at the period along its rows and at
/// √2 times it along the diagonals. So the period is the nearest peak among the sectors whose
/// peak is at least half as strong as the strongest.
inline Texel_period texel_period_from_curvature(
    const std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>& position,
    const std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Vector_3>& normal,
    const std::vector<double>& area, const std::vector<double>& h, const std::vector<char>& valid,
    double mean_edge_length, double diagonal) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Point = Kernel::Point_3;
  using Vector = Kernel::Vector_3;
  using Point_map = CGAL::Pointer_property_map<Point>::const_type;
  using Traits = CGAL::Search_traits_adapter<std::size_t, Point_map, CGAL::Search_traits_3<Kernel>>;
  using Tree = CGAL::Kd_tree<Traits>;
  using Sphere = CGAL::Fuzzy_sphere<Traits>;
  Texel_period out;
  out.mean_edge_length = mean_edge_length;
  const std::size_t n = position.size();
  // Texels are rarely wider than 60 edges; a quarter of the model bounds the search otherwise.
  const double radius = std::min(0.25 * diagonal, 60 * mean_edge_length);
  out.search_radius = radius;
  std::vector<double> weight(n, 0);
  double total = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (valid[i]) {
      weight[i] = area[i] * h[i] * h[i];
      total += weight[i];
    }
  if (!(total > 0) || !(radius > 0))
    return out;
  std::mt19937 random(7);
  std::discrete_distribution<std::size_t> draw(weight.begin(), weight.end());
  constexpr std::size_t sources = 384, sectors = 8;
  const double pi = std::acos(-1.0);
  const std::size_t bins = std::size_t(std::ceil(10 * radius / mean_edge_length)) + 1;
  const double width = radius / double(bins - 1);
  // sum[s][b], mass[s][b]: sector s, distance bin b; sector `sectors` is all directions.
  std::vector<std::vector<double>> sum(sectors + 1, std::vector<double>(bins, 0)),
      mass(sectors + 1, std::vector<double>(bins, 0));
  const Point_map map(position.data());
  Tree tree(boost::counting_iterator<std::size_t>(0), boost::counting_iterator<std::size_t>(n),
            Tree::Splitter(), Traits(map));
  tree.build();
  std::vector<std::size_t> found;
  for (std::size_t s = 0; s < sources; ++s) {
    const std::size_t i = draw(random);
    // The source's tangent frame, its first axis the x axis projected (y if x is too steep).
    Vector nz = normal[i];
    const double length = std::sqrt(nz.squared_length());
    nz = length > 0 ? nz / length : Vector(0, 0, 1);
    Vector u = Vector(1, 0, 0) - nz.x() * nz;
    if (u.squared_length() < 0.1)
      u = Vector(0, 1, 0) - nz.y() * nz;
    u = u / std::sqrt(u.squared_length());
    const Vector v = CGAL::cross_product(nz, u);
    found.clear();
    tree.search(std::back_inserter(found), Sphere(position[i], radius, 0, Traits(map)));
    for (std::size_t j : found) {
      if (!valid[j])
        continue;
      const Vector q = position[j] - position[i];
      const std::size_t b = std::size_t(std::sqrt(q.squared_length()) / width + 0.5);
      if (b >= bins)
        continue;
      double angle = std::atan2(q * v, q * u);
      if (angle < 0)
        angle += pi;
      const std::size_t sector = std::min(sectors - 1, std::size_t(angle / pi * double(sectors)));
      const double product = area[j] * h[i] * h[j];
      sum[sector][b] += product;
      mass[sector][b] += area[j];
      sum[sectors][b] += product;
      mass[sectors][b] += area[j];
    }
  }
  // Mean product per bin, smoothed over ± half an edge length, relative to the value at 0 (of
  // all directions: at 0 the sectors are empty or noisy).
  auto curve = [&](std::size_t sector, double c0) {
    std::vector<double> c(bins, 0);
    for (std::size_t b = 0; b < bins; ++b) {
      double x = 0, m = 0;
      for (std::size_t k = b >= 5 ? b - 5 : 0; k <= std::min(bins - 1, b + 5); ++k) {
        x += sum[sector][k];
        m += mass[sector][k];
      }
      c[b] = m > 0 ? x / m / c0 : 0;
    }
    return c;
  };
  std::vector<double> c = curve(sectors, 1);
  const double c0 = c[0];
  if (!(c0 > 0))
    return out;
  for (double& x : c)
    x /= c0;
  const std::size_t lobe = autocorrelation_lobe(c);
  out.lobe = std::max(double(lobe) * width, mean_edge_length);
  std::array<double, sectors> strength{}, at{};
  double strongest = 0;
  for (std::size_t sector = 0; sector < sectors; ++sector) {
    const std::vector<double> cs = curve(sector, c0);
    const std::size_t peak = autocorrelation_peak(cs, lobe);
    if (peak > lobe) {
      strength[sector] = cs[peak] - cs[lobe];
      at[sector] = double(peak) * width;
      strongest = std::max(strongest, strength[sector]);
    }
  }
  for (std::size_t sector = 0; sector < sectors; ++sector)
    if (strength[sector] > 0 && strength[sector] >= 0.5 * strongest &&
        (!out.periodic || at[sector] < out.period)) {
      out.periodic = true;
      out.period = at[sector];
      out.peak_strength = strength[sector];
    }
  if (!out.periodic)
    out.period = 2 * out.lobe;
  return out;
}

/// What the period is read from, per vertex: position, a third of its triangles' area, the
/// mesh's vertex normal, the signed mean curvature of its jet and whether the jet was fitted
/// (`mean_curvature_samples`, signed_curvatures.h); and the mean edge length.
struct Mean_curvature_samples {
  std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> position;
  std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Vector_3> normal;
  std::vector<double> area, h;
  std::vector<char> fitted;
  double mean_edge_length = 0;
};

/// The period over the vertices i where `member(i)` holds: their mean curvature about its median
/// there, the search bounded by their bounding box. Empty when none of them was fitted.
template <typename Member>
Texel_period texel_period_over(const Mean_curvature_samples& s, Member&& member) {
  const std::size_t n = s.position.size();
  std::vector<char> valid(n, 0);
  std::vector<double> values;
  CGAL::Bbox_3 box;
  for (std::size_t i = 0; i < n; ++i)
    if (member(i)) {
      box += s.position[i].bbox();
      if (s.fitted[i]) {
        valid[i] = 1;
        values.push_back(s.h[i]);
      }
    }
  if (values.empty())
    return {};
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(values.size() / 2),
                   values.end());
  const double median = values[values.size() / 2];
  std::vector<double> centred(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    if (valid[i])
      centred[i] = s.h[i] - median;
  const double diagonal =
      std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                CGAL::square(box.zmax() - box.zmin()));
  return texel_period_from_curvature(s.position, s.normal, s.area, centred, valid,
                                     s.mean_edge_length, diagonal);
}

} // namespace internal
} // namespace tessera
