// Feature_segments: the feature lines a surface mosaic keeps its tiles off (Lai, Hu, Martin,
// "Surface Mosaics" §5.2: tiles near a feature line feel a repulsion from their mirror image across
// it, so their edges settle half a grout width from the line and no tile straddles it). For a point
// of a region it finds the closest point of the feature lines that bound that region (a CGAL AABB
// tree of segments per region). Used by Surface_mosaic and mosaic_quality().
#pragma once

#include <tessera/fields/feature_lines.h>
#include <tessera/mosaic/internal/surface_arrays.h>

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <memory>
#include <vector>

namespace tessera::internal {

template <typename TriangleMesh> class Feature_segments {
public:
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Segment = K::Segment_3;
  using Primitive = CGAL::AABB_segment_primitive<K, typename std::vector<Segment>::const_iterator>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;

  /// Segments of `lines` bounding each region of `s`; `reach` is the distance within which a face
  /// is flagged as near a feature of its own region (no face is flagged when it is negative).
  Feature_segments(const Surface_arrays<TriangleMesh>& s,
                   const std::vector<Feature_line<halfedge_descriptor>>& lines, double reach)
      : segments_(s.number_of_regions()), sides_(s.number_of_regions()),
        trees_(s.number_of_regions()), near_(s.number_of_faces(), 0) {
    const TriangleMesh& tm = s.mesh();
    auto point = [&](auto v) {
      const Vec3& p = s.vertex_point(s.id(v));
      return K::Point_3(p[0], p[1], p[2]);
    };
    for (const auto& line : lines)
      for (halfedge_descriptor h : line.halfedges) {
        const Segment seg(point(source(h, tm)), point(target(h, tm)));
        // The normals of the faces on either side (one face's twice on a border).
        std::array<Vec3, 2> sides;
        for (int k = 0; k < 2; ++k) {
          const halfedge_descriptor side = k == 0 ? h : opposite(h, tm);
          const halfedge_descriptor other = k == 0 ? opposite(h, tm) : h;
          sides[k] = s.normal(s.id(face(is_border(side, tm) ? other : side, tm)));
        }
        std::uint32_t r0 = no_index;
        for (halfedge_descriptor side : {h, opposite(h, tm)}) {
          if (is_border(side, tm))
            continue;
          const std::uint32_t r = s.region(s.id(face(side, tm)));
          if (r == r0)
            continue;
          segments_[r].push_back(seg);
          sides_[r].push_back(sides);
          r0 = r;
        }
      }
    for (std::size_t r = 0; r < segments_.size(); ++r) {
      if (segments_[r].empty())
        continue;
      trees_[r] = std::make_unique<Tree>(segments_[r].cbegin(), segments_[r].cend());
      trees_[r]->accelerate_distance_queries();
    }
    for (std::uint32_t f = 0; reach >= 0 && f < s.number_of_faces(); ++f) {
      const Tree* tree = trees_[s.region(f)].get();
      if (!tree)
        continue;
      const Vec3 c = s.centroid(f);
      double extent = 0;
      for (int k = 0; k < 3; ++k)
        extent = std::max(extent, norm(s.point(f, k) - c));
      const double d2 = tree->squared_distance(K::Point_3(c[0], c[1], c[2]));
      near_[f] = d2 <= (reach + extent) * (reach + extent);
    }
  }

  /// Whether face f may lie within `reach` of a feature line of its region.
  bool near(std::uint32_t f) const { return near_[f] != 0; }
  /// The closest point to p on the feature lines bounding `region`; false when it has none.
  bool closest(std::uint32_t region, const Vec3& p, Vec3& q) const {
    const Tree* tree = trees_[region].get();
    if (!tree)
      return false;
    const K::Point_3 c = tree->closest_point(K::Point_3(p[0], p[1], p[2]));
    q = Vec3{{c.x(), c.y(), c.z()}};
    return true;
  }

  /// Calls visit(a, b) for every segment of the feature lines of `region` whose bounding box meets
  /// the cube of half-side `radius` around p.
  template <typename Visitor>
  void segments_near(std::uint32_t region, const Vec3& p, double radius, Visitor&& visit) const {
    visit_near(region, p, radius, nullptr, visit);
  }

  /// As `segments_near()`, for the segments with a face beside them whose normal is within 60° of
  /// `n`: a crease between faces that all turn away from a tile's plane (the far side of a slab
  /// thinner than a tile) is not one the tile lies across.
  template <typename Visitor>
  void segments_near_facing(std::uint32_t region, const Vec3& p, double radius, const Vec3& n,
                            Visitor&& visit) const {
    visit_near(region, p, radius, &n, visit);
  }

private:
  std::vector<std::vector<Segment>> segments_;
  std::vector<std::vector<std::array<Vec3, 2>>> sides_; // face normals beside each segment
  std::vector<std::unique_ptr<Tree>> trees_;
  std::vector<char> near_;

  template <typename Visitor>
  void visit_near(std::uint32_t region, const Vec3& p, double radius, const Vec3* facing,
                  Visitor& visit) const {
    const Tree* tree = trees_[region].get();
    if (!tree)
      return;
    const CGAL::Bbox_3 box(p[0] - radius, p[1] - radius, p[2] - radius, p[0] + radius,
                           p[1] + radius, p[2] + radius);
    std::vector<typename Tree::Primitive_id> hits;
    tree->all_intersected_primitives(box, std::back_inserter(hits));
    for (const auto& id : hits) {
      if (facing) {
        const auto& sides = sides_[region][std::size_t(id - segments_[region].cbegin())];
        if (std::max(dot(sides[0], *facing), dot(sides[1], *facing)) < 0.5)
          continue;
      }
      const Segment& seg = *id;
      visit(Vec3{{seg.source().x(), seg.source().y(), seg.source().z()}},
            Vec3{{seg.target().x(), seg.target().y(), seg.target().z()}});
    }
  }
};

} // namespace tessera::internal
