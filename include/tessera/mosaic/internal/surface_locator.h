// Surface_locator: the closest point of a triangle mesh to a query, as a face and barycentric
// weights (CGAL's `Polygon_mesh_processing::locate_with_AABB_tree`), where tessera/mosaic/
// tile_colors.h reads a surface's colours.
#pragma once

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <optional>

namespace tessera::internal {

// The closest point of a triangle mesh to a query: its face and barycentric coordinates for the
// face's vertices source(halfedge(f)), target(halfedge(f)), target(next(halfedge(f))).
template <typename TriangleMesh> class Surface_locator {
public:
  using GT = boost::graph_traits<TriangleMesh>;
  using face_descriptor = typename GT::face_descriptor;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using VPM = typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type;
  using Point = typename boost::property_traits<VPM>::value_type;
  using K = typename CGAL::Kernel_traits<Point>::Kernel;
  using Tree = CGAL::AABB_tree<
      CGAL::AABB_traits<K, CGAL::AABB_face_graph_triangle_primitive<TriangleMesh, VPM>>>;

  /// The closest point: its face, and its face's corners with their weights.
  struct Location {
    face_descriptor face;
    std::array<vertex_descriptor, 3> corner;
    std::array<double, 3> weight;
  };

  explicit Surface_locator(const TriangleMesh& tm) : tm_(tm) {
    CGAL::Polygon_mesh_processing::build_AABB_tree(tm, tree_);
  }
  /// The closest point of the mesh to p; nothing when the mesh has no face.
  std::optional<Location> locate(const std::array<double, 3>& p) const {
    if (faces(tm_).empty())
      return std::nullopt;
    const auto loc =
        CGAL::Polygon_mesh_processing::locate_with_AABB_tree(Point(p[0], p[1], p[2]), tree_, tm_);
    const auto h = halfedge(loc.first, tm_);
    Location at{loc.first, {{source(h, tm_), target(h, tm_), target(next(h, tm_), tm_)}}, {}};
    for (int i = 0; i < 3; ++i)
      at.weight[i] = std::clamp(CGAL::to_double(loc.second[i]), 0.0, 1.0);
    const double sum = at.weight[0] + at.weight[1] + at.weight[2];
    if (sum > 0)
      for (double& w : at.weight)
        w /= sum;
    return at;
  }

private:
  const TriangleMesh& tm_;
  Tree tree_;
};

} // namespace tessera::internal
