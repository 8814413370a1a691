// Materializes a cut: copies the mesh opened along its seams (a CGAL::Seam_mesh) into a new
// FaceGraph whose faces are in the same order as the input's, and reports which input vertex every
// vertex of the opened mesh comes from.
#pragma once

#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include <cstddef>
#include <iterator>
#include <unordered_map>
#include <utility>
#include <vector>

namespace tessera {

/// Copies `tm` opened along the seams in `seam_edges`/`seam_vertices` into `opened` (cleared first)
/// and returns, for every vertex of `opened` (in its vertex order), the vertex of `tm` it copies.
/// Face i of `opened` is face i of `tm`.
template <typename TriangleMesh, typename SeamEdgeMap, typename SeamVertexMap, typename OpenedMesh>
std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>
open_along_seams(const TriangleMesh& tm, SeamEdgeMap seam_edges, SeamVertexMap seam_vertices,
                 OpenedMesh& opened) {
  using Seam_mesh = CGAL::Seam_mesh<TriangleMesh, SeamEdgeMap, SeamVertexMap>;
  using seam_vertex = typename boost::graph_traits<Seam_mesh>::vertex_descriptor;
  using opened_vertex = typename boost::graph_traits<OpenedMesh>::vertex_descriptor;

  Seam_mesh sm(tm, seam_edges, seam_vertices);
  std::size_t seams = 0;
  for (auto e : edges(tm))
    if (get(seam_edges, e))
      ++seams;
  sm.set_seam_edges_number(typename Seam_mesh::edges_size_type(seams));

  clear(opened);
  std::vector<std::pair<seam_vertex, opened_vertex>> v2v;
  CGAL::copy_face_graph(
      sm, opened, CGAL::parameters::vertex_to_vertex_output_iterator(std::back_inserter(v2v)));
  std::unordered_map<opened_vertex, typename boost::graph_traits<TriangleMesh>::vertex_descriptor>
      origin;
  // A seam-mesh vertex is represented by a halfedge of `tm` that arrives at the vertex it copies.
  for (const auto& [sv, ov] : v2v)
    origin.emplace(ov, target(sv.hd.tmhd, tm));
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> out;
  for (opened_vertex v : vertices(opened))
    out.push_back(origin.at(v));
  return out;
}

} // namespace tessera
