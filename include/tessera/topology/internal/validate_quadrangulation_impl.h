// Implementation of tessera::validate_quadrangulation (see
// tessera/topology/validate_quadrangulation.h).
#pragma once

#include <tessera/topology/validate_quadrangulation.h>

// Surface_mesh (the opened copy) must be known before CGAL::Seam_mesh is instantiated.
#include <CGAL/Surface_mesh.h>

#include <tessera/topology/open_mesh.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include <set>
#include <string>
#include <unordered_map>
#include <vector>

namespace tessera {

template <typename TriangleMesh, typename FaceTileMap, typename SeamEdgeMap, typename SeamVertexMap>
Quadrangulation_validation
validate_quadrangulation(const TriangleMesh& tm, FaceTileMap tile_of_face, SeamEdgeMap seam_edges,
                         SeamVertexMap seam_vertices,
                         const Quadrangulation_result<TriangleMesh>& result) {
  using GT = boost::graph_traits<TriangleMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using Point = typename boost::property_traits<
      typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type>::value_type;
  using Opened = CGAL::Surface_mesh<Point>;
  using opened_vertex = typename Opened::Vertex_index;
  Quadrangulation_validation v;
  const std::size_t n_tiles = result.tiles.size();

  Opened opened;
  const auto origin = open_along_seams(tm, seam_edges, seam_vertices, opened);
  const std::vector<typename GT::face_descriptor> tm_faces(faces(tm).begin(), faces(tm).end());
  std::unordered_map<typename GT::face_descriptor, std::size_t> position;
  for (std::size_t i = 0; i < tm_faces.size(); ++i)
    position.emplace(tm_faces[i], i);
  auto component = opened
                       .template add_property_map<typename Opened::Face_index, std::size_t>(
                           "f:tessera_component")
                       .first;
  const std::size_t n_components =
      CGAL::Polygon_mesh_processing::connected_components(opened, component);

  // 1. One disk per tile, matching the tile map.
  v.tiles_are_disks = n_components == n_tiles;
  if (!v.tiles_are_disks)
    v.problems.push_back("the opened mesh has " + std::to_string(n_components) +
                         " components for " + std::to_string(n_tiles) + " tiles");
  std::vector<std::size_t> tile_of_component(n_components, std::size_t(-1));
  for (typename Opened::Face_index f : faces(opened)) {
    const std::size_t t = get(tile_of_face, tm_faces[std::size_t(f)]);
    std::size_t& seen = tile_of_component[component[f]];
    if (t >= n_tiles || (seen != std::size_t(-1) && seen != t)) {
      v.tiles_are_disks = false;
      v.problems.push_back("the tile map disagrees with the opened components");
      break;
    }
    seen = t;
  }
  std::vector<long> chi(n_components, 0);
  std::vector<std::size_t> loops(n_components, 0), border_length(n_components, 0);
  std::vector<std::set<opened_vertex>> border_vertices(n_components);
  for (typename Opened::Face_index f : faces(opened))
    ++chi[component[f]];
  for (typename Opened::Edge_index e : edges(opened)) {
    auto h = halfedge(e, opened);
    if (is_border(h, opened))
      h = opposite(h, opened);
    --chi[component[face(h, opened)]];
  }
  for (opened_vertex x : vertices(opened))
    ++chi[component[face(is_border(halfedge(x, opened), opened)
                             ? opposite(halfedge(x, opened), opened)
                             : halfedge(x, opened),
                         opened)]];
  std::set<typename Opened::Halfedge_index> walked;
  for (typename Opened::Halfedge_index h : halfedges(opened)) {
    if (!is_border(h, opened))
      continue;
    const std::size_t c = component[face(opposite(h, opened), opened)];
    ++border_length[c];
    border_vertices[c].insert(target(h, opened));
    if (walked.count(h))
      continue;
    ++loops[c];
    for (auto g : CGAL::halfedges_around_face(h, opened))
      walked.insert(g);
  }
  for (std::size_t c = 0; c < n_components; ++c)
    if (chi[c] != 1 || loops[c] != 1) {
      v.tiles_are_disks = false;
      v.problems.push_back("opened component " + std::to_string(c) + " is not a disk (chi " +
                           std::to_string(chi[c]) + ", " + std::to_string(loops[c]) +
                           " boundaries)");
    }

  // Corners as opened vertices: the copy of a side's first vertex in the face on its left.
  auto opened_source = [&](typename GT::halfedge_descriptor h) {
    const typename Opened::Face_index f(typename Opened::size_type(position.at(face(h, tm))));
    for (opened_vertex x : CGAL::vertices_around_face(halfedge(f, opened), opened))
      if (origin[std::size_t(x)] == source(h, tm))
        return std::make_pair(x, component[f]);
    return std::make_pair(opened_vertex(), std::size_t(-1));
  };

  // 2. Four sides and corners per tile, and 3. no other branch points on its boundary.
  std::vector<std::size_t> cut_degree(num_vertices(tm), 0);
  const auto vim = CGAL::get_initialized_vertex_index_map(tm);
  for (auto e : edges(tm))
    if (get(seam_edges, e) || is_border_edge(halfedge(e, tm), tm))
      for (vertex_descriptor x : {source(halfedge(e, tm), tm), target(halfedge(e, tm), tm)})
        ++cut_degree[get(vim, x)];
  const std::set<vertex_descriptor> marked(result.multipoints.begin(), result.multipoints.end());
  v.four_corners = true;
  v.corners_where_borders_meet = true;
  for (std::size_t t = 0; t < n_tiles; ++t) {
    const auto& tile = result.tiles[t];
    const std::string where = "tile " + std::to_string(t) + ": ";
    if (tile.sides.size() != 4 || tile.corners.size() != 4) {
      v.four_corners = false;
      v.problems.push_back(where + std::to_string(tile.sides.size()) + " sides");
      continue;
    }
    std::set<opened_vertex> corners;
    std::size_t c = std::size_t(-1), halfedges_in_sides = 0;
    for (std::size_t i = 0; i < 4; ++i) {
      const auto& side = tile.sides[i];
      halfedges_in_sides += side.size();
      const auto [x, cx] = opened_source(side.front());
      corners.insert(x);
      if (c != std::size_t(-1) && cx != c)
        v.four_corners = false;
      c = cx;
      if (source(side.front(), tm) != tile.corners[i] ||
          target(side.back(), tm) != tile.corners[(i + 1) % 4] ||
          get(tile_of_face, face(side.front(), tm)) != t)
        v.four_corners = false;
    }
    if (!v.four_corners || c >= n_components || corners.size() != 4 ||
        border_length[c] != halfedges_in_sides) {
      v.four_corners = false;
      v.problems.push_back(where +
                           "its sides and corners do not go once around its opened boundary");
      continue;
    }
    for (opened_vertex x : border_vertices[c]) {
      const vertex_descriptor m = origin[std::size_t(x)];
      const bool branch = cut_degree[get(vim, m)] != 2 || marked.count(m) > 0;
      if (branch != (corners.count(x) > 0)) {
        v.corners_where_borders_meet = false;
        v.problems.push_back(where + (branch ? "a vertex where borders meet is not a corner"
                                             : "a corner is not where borders meet"));
      }
    }
  }

  // 4. Tile count.
  std::size_t expected = 0;
  v.tile_count = result.polygon_corners.size() == result.cut.polygons.size();
  for (std::size_t p = 0; p < result.polygon_corners.size() && v.tile_count; ++p) {
    const std::size_t m = result.polygon_corners[p];
    expected += m / 2 - 1;
    const auto& poly = result.cut.polygons[p];
    if (result.cut.method == Cut_method::schema && poly.boundaries == 0 && poly.genus > 0 &&
        m != std::size_t(4 * poly.genus)) {
      v.tile_count = false;
      v.problems.push_back("a schema of genus " + std::to_string(poly.genus) + " gave " +
                           std::to_string(m) + " corners");
    }
  }
  if (expected != n_tiles) {
    v.tile_count = false;
    v.problems.push_back(std::to_string(n_tiles) + " tiles, expected " + std::to_string(expected));
  }
  const bool valid =
      v.tiles_are_disks && v.four_corners && v.corners_where_borders_meet && v.tile_count;
  v.status =
      valid ? Quadrangulation_validation_status::valid : Quadrangulation_validation_status::invalid;
  v.message = v.problems.empty() ? (valid ? "valid" : "invalid") : v.problems.front();
  return v;
}

} // namespace tessera
