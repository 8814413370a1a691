// Union-find over the indices 0 … n−1 for the modules that join elements by index (texture pieces,
// grounding groups, segmentation modes): Boost's disjoint_sets over two vectors.
#pragma once

#include <boost/pending/disjoint_sets.hpp>
#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <vector>

namespace tessera::internal {

// The rank and parent maps are iterator property maps, whose get()/put() argument-dependent lookup
// finds wherever this is instantiated. (Over raw pointers only ordinary lookup at the point where
// Boost's header is first read can find them, and a boost::detail::get declared before it, e.g. by
// Boost.Graph's compressed sparse row graph, which CGAL's remeshing includes, hides them.)
class Index_sets {
public:
  explicit Index_sets(std::size_t n)
      : rank_(n, 0), parent_(n), sets_(Map(rank_.begin()), Map(parent_.begin())) {
    for (std::size_t i = 0; i < n; ++i)
      sets_.make_set(i);
  }
  Index_sets(const Index_sets&) = delete; // the maps point into this object's vectors
  Index_sets& operator=(const Index_sets&) = delete;

  /// The representative of i's set.
  std::size_t find(std::size_t i) { return sets_.find_set(i); }
  /// Joins the sets of a and b.
  void unite(std::size_t a, std::size_t b) { sets_.union_set(a, b); }

private:
  using Map = boost::iterator_property_map<std::vector<std::size_t>::iterator,
                                           boost::typed_identity_property_map<std::size_t>>;
  std::vector<std::size_t> rank_, parent_;
  boost::disjoint_sets<Map, Map> sets_;
};

} // namespace tessera::internal
