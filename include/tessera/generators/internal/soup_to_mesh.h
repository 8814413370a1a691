// A polygon soup of double coordinates and triangles into any MutableFaceGraph (the generators
// build their surfaces as soups).
#pragma once

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <boost/property_map/property_map.hpp>

#include <array>
#include <cstddef>
#include <vector>

namespace tessera {

namespace internal {

template <typename MutableFaceGraph>
void soup_to_mesh(const std::vector<std::array<double, 3>>& coords,
                  const std::vector<std::array<std::size_t, 3>>& triangles, MutableFaceGraph& tm) {
  using Point = typename boost::property_traits<
      typename boost::property_map<MutableFaceGraph, CGAL::vertex_point_t>::type>::value_type;
  std::vector<Point> points;
  points.reserve(coords.size());
  for (const auto& c : coords)
    points.emplace_back(c[0], c[1], c[2]);
  clear(tm);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, tm);
}

} // namespace internal

} // namespace tessera
