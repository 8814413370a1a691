// The planar mosaics' Voronoi labelling checked against CGAL: for a constant field the diagram is
// an ordinary L∞ Voronoi diagram of the sites in the field's frame (equivalently an L1 diagram
// after a further 45° turn), which CGAL's Segment_Delaunay_graph_Linf_2 computes with exact
// predicates.
#include <tessera/mosaic/planar_voronoi.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Segment_Delaunay_graph_Linf_2.h>
#include <CGAL/Segment_Delaunay_graph_Linf_filtered_traits_2.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <random>

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Traits = CGAL::Segment_Delaunay_graph_Linf_filtered_traits_2<K>;
using Linf_diagram = CGAL::Segment_Delaunay_graph_Linf_2<Traits>;
} // namespace

TEST_CASE("planar Voronoi labels agree with CGAL's exact L-infinity diagram",
          "[mosaic][planar][exact]") {
  const int w = 200, h = 150;
  for (double angle : {0.0, 0.3, -1.1}) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> ux(0, w - 1), uy(0, h - 1);
    const double c = std::cos(angle), s = std::sin(angle);
    // A point in the field's frame, where the metric is plain L∞.
    auto frame = [&](double x, double y) { return K::Point_2(c * x + s * y, -s * x + c * y); };
    std::vector<tessera::Planar_site> sites;
    Linf_diagram diagram;
    std::map<K::Point_2, int> site_of;
    for (int i = 0; i < 80; ++i) {
      const tessera::Planar_site site{ux(rng), uy(rng), angle, 1};
      sites.push_back(site);
      const K::Point_2 p = frame(site.x, site.y);
      site_of[p] = i;
      diagram.insert(p);
    }
    REQUIRE(diagram.is_valid());
    const tessera::Planar_voronoi v = tessera::planar_voronoi(w, h, sites);

    std::size_t compared = 0;
    Linf_diagram::Vertex_handle hint;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        // Distances to the two nearest sites: L∞ is at most the Euclidean length, so moving one
        // pixel changes each by at most 1, and a gap over 2 puts the pixel farther than one pixel
        // from every exact bisector.
        double d1 = 1e300, d2 = 1e300;
        for (const auto& site : sites) {
          const double d = tessera::planar_site_distance(site, 1, x, y);
          if (d < d1)
            d2 = d1, d1 = d;
          else if (d < d2)
            d2 = d;
        }
        if (d2 - d1 <= 2)
          continue;
        hint = diagram.nearest_neighbor(frame(x, y), hint);
        REQUIRE(hint->site().is_point());
        const int exact = site_of.at(hint->site().point());
        REQUIRE(v.label_at(x, y) == exact);
        ++compared;
      }
    // Most pixels are far from bisectors: the comparison covers the image.
    CHECK(compared > std::size_t(w * h) / 2);
  }
}
