// Repair of a polygon soup read from a file, counting what each step changed: the steps of CGAL's
// `repair_polygon_soup()` one by one (their counts are not returned by the one-call version), then
// `orient_polygon_soup()` with a visitor that records non-manifold edges and pinched vertices.
#pragma once

#include <tessera/io/mesh_repair.h>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>

#include <algorithm>
#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

namespace tessera::internal {

/// Outcome of `repair_soup()`: the changes made, or the defect that the policy refused.
struct Soup_repair {
  Mesh_changes changes;
  /// Empty when the soup is now a valid polygon mesh; otherwise what is wrong, with places.
  std::string refusal;
  /// True when the soup could be repaired but the policy (`Mesh_repair::none`) forbids it.
  bool refused_by_policy = false;
};

/// Records what `orient_polygon_soup()` finds (the visitor is copied, so it writes through
/// pointers).
struct Orientation_record : CGAL::Polygon_mesh_processing::Default_orientation_visitor {
  std::vector<std::pair<std::size_t, std::size_t>>* non_manifold_edges;
  std::vector<std::size_t>* pinched_vertices;
  std::size_t* reversed;
  Orientation_record(std::vector<std::pair<std::size_t, std::size_t>>* e,
                     std::vector<std::size_t>* p, std::size_t* r)
      : non_manifold_edges(e), pinched_vertices(p), reversed(r) {}
  void non_manifold_edge(std::size_t a, std::size_t b, std::size_t) {
    non_manifold_edges->emplace_back(std::min(a, b), std::max(a, b));
  }
  void non_manifold_vertex(std::size_t v, std::size_t) { pinched_vertices->push_back(v); }
  void polygon_orientation_reversed(std::size_t) { ++*reversed; }
};

template <typename Point>
std::string describe_points(const std::vector<Point>& points, const std::vector<std::size_t>& ids) {
  std::ostringstream os;
  const std::size_t shown = std::min<std::size_t>(ids.size(), 3);
  for (std::size_t i = 0; i < shown; ++i)
    os << (i ? ", " : "") << "vertex " << ids[i] << " at (" << points[ids[i]] << ")";
  if (ids.size() > shown)
    os << ", …";
  return os.str();
}

/// Repairs `points`/`polygons` in place as far as `policy` allows. The caller keeps the file's
/// soup if it needs it: after a refusal the soup is left part-repaired.
template <typename Point>
Soup_repair repair_soup(std::vector<Point>& points, std::vector<std::vector<std::size_t>>& polygons,
                        Mesh_repair policy) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using Traits = typename CGAL::Kernel_traits<Point>::Kernel;
  Soup_repair out;
  Mesh_changes& c = out.changes;

  c.merged_vertices = PMP::merge_duplicate_points_in_polygon_soup(points, polygons);
  // Faces through one vertex twice: with consecutive repeats removed (simplify), a face that still
  // meets a vertex twice is pinched and split into simple faces (a joined pair of face lines).
  std::size_t removed =
      PMP::internal::simplify_polygons_in_polygon_soup(points, polygons, Traits());
  c.split_faces = PMP::internal::split_pinched_polygons_in_polygon_soup(points, polygons, Traits());
  removed = PMP::internal::remove_invalid_polygons_in_polygon_soup(points, polygons);
  removed += PMP::merge_duplicate_polygons_in_polygon_soup(points, polygons);
  c.removed_faces = removed;
  c.removed_vertices = PMP::remove_isolated_points_in_polygon_soup(points, polygons);

  std::vector<std::pair<std::size_t, std::size_t>> edges;
  std::vector<std::size_t> pinched;
  const bool oriented = PMP::orient_polygon_soup(
      points, polygons,
      CGAL::parameters::visitor(Orientation_record{&edges, &pinched, &c.reoriented_faces}));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  c.non_manifold_edges = edges.size();
  c.pinched_vertices = pinched.size();

  if (!edges.empty() && policy != Mesh_repair::all) {
    std::ostringstream os;
    os << edges.size() << (edges.size() == 1 ? " edge is" : " edges are")
       << " shared by more than two faces (the first between vertex " << edges[0].first << " at ("
       << points[edges[0].first] << ") and vertex " << edges[0].second << " at ("
       << points[edges[0].second] << ")); --repair splits them";
    out.refusal = os.str();
    return out;
  }
  if (!oriented && edges.empty() && pinched.empty())
    out.refusal = "the surface is not orientable (a Möbius band or a Klein bottle)";
  else if (!PMP::is_polygon_soup_a_polygon_mesh(polygons))
    out.refusal = "the faces do not form a manifold surface even after repair";
  if (out.refusal.empty() && policy == Mesh_repair::none && c.any()) {
    out.refused_by_policy = true;
    out.refusal = "needs repairs (" + c.to_string() + ")";
    if (!pinched.empty())
      out.refusal += ", pinched at " + describe_points(points, pinched);
  }
  return out;
}

} // namespace tessera::internal
