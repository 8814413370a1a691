// k-nearest-neighbour and range queries over a set of 3D points (tile centres) with CGAL's kd-tree
// (`Orthogonal_k_neighbor_search` and `Fuzzy_sphere` over indices, the points read through a
// property map).
#pragma once

#include <tessera/fields/internal/vertex_frames.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>

#include <boost/iterator/counting_iterator.hpp>

#include <cstddef>
#include <iterator>
#include <memory>
#include <utility>
#include <vector>

namespace tessera::internal {

class Point_search {
public:
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Point = K::Point_3;

  Point_search() = default;
  explicit Point_search(const std::vector<Vec3>& points) { reset(points); }

  void reset(const std::vector<Vec3>& points) {
    points_.clear();
    points_.reserve(points.size());
    for (const Vec3& p : points)
      points_.emplace_back(p[0], p[1], p[2]);
    tree_.reset();
    if (points_.empty())
      return;
    tree_ = std::make_unique<Tree>(boost::counting_iterator<std::size_t>(0),
                                   boost::counting_iterator<std::size_t>(points_.size()),
                                   typename Tree::Splitter(), Traits(map()));
    tree_->build();
  }
  std::size_t size() const { return points_.size(); }

  /// Calls `visit(index, squared_distance)` for the k points nearest to q, nearest first.
  template <typename Visitor> void nearest(const Vec3& q, std::size_t k, Visitor&& visit) const {
    if (!tree_ || k == 0)
      return;
    Search search(*tree_, Point(q[0], q[1], q[2]), (unsigned int)(k), 0, true, Distance(map()));
    for (auto it = search.begin(); it != search.end(); ++it)
      visit(it->first, it->second);
  }

  /// Appends to `out` the index of every point within distance r of q, in no particular order (a
  /// range query: no priority queue, so cheaper than `nearest` where a radius bounds what is
  /// wanted).
  void within(const Vec3& q, double r, std::vector<std::size_t>& out) const {
    if (tree_)
      tree_->search(std::back_inserter(out),
                    CGAL::Fuzzy_sphere<Traits>(Point(q[0], q[1], q[2]), r, 0, Traits(map())));
  }

private:
  using Map = CGAL::Pointer_property_map<Point>::const_type;
  using Traits = CGAL::Search_traits_adapter<std::size_t, Map, CGAL::Search_traits_3<K>>;
  using Search = CGAL::Orthogonal_k_neighbor_search<Traits>;
  using Tree = Search::Tree;
  using Distance = Search::Distance;
  Map map() const { return CGAL::make_property_map(points_); }

  std::vector<Point> points_;
  std::unique_ptr<Tree> tree_;
};

} // namespace tessera::internal
