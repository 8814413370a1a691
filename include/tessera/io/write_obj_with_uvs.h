// Writing a FaceGraph with texture coordinates as Wavefront OBJ (v, vt and f v/vt lines), e.g. a
// CGAL::Seam_mesh after Surface_mesh_parameterization, so any viewer shows the parameterization. A
// Seam_mesh is written the way texturing tools store seams: one `v` per vertex of the underlying
// mesh (in its order), one `vt` per vertex of the seam mesh, so `tessera check` reads the charts
// back.
#pragma once

#include <tessera/internal/seam_vertex_keys.h>
#include <tessera/io/internal/shortest_doubles.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Dynamic_property_map.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
template <class TM, class SEM, class SVM> class Seam_mesh;
} // namespace CGAL

namespace tessera {

/// Writes `g` with `uv` (a readable vertex property map of 2D points) to the OBJ file `path`.
/// Returns false when the file cannot be written.
template <typename FaceGraph, typename VertexUVMap>
bool write_obj_with_uvs(const std::string& path, const FaceGraph& g, VertexUVMap uv) {
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
  std::ofstream os(path);
  if (!os)
    return false;
  internal::write_shortest_doubles(os);
  os << "# written by Tessera\n";
  const auto vpm = get(CGAL::vertex_point, g);
  auto index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), g);
  std::size_t n = 0;
  for (vertex_descriptor v : vertices(g)) {
    const auto& p = get(vpm, v);
    const auto& t = get(uv, v);
    os << "v " << CGAL::to_double(p.x()) << " " << CGAL::to_double(p.y()) << " "
       << CGAL::to_double(p.z()) << "\n"
       << "vt " << CGAL::to_double(t.x()) << " " << CGAL::to_double(t.y()) << "\n";
    put(index, v, ++n);
  }
  for (auto f : faces(g)) {
    os << "f";
    for (vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, g), g)) {
      const std::size_t i = get(index, v);
      os << " " << i << "/" << i;
    }
    os << "\n";
  }
  return bool(os);
}

/// Writes a CGAL::Seam_mesh: `v` lines are the underlying mesh's vertices in its vertex order, `vt`
/// lines the seam mesh's vertices (a seam vertex has one per side), faces in the mesh's face order.
template <class TM, class SEM, class SVM, typename VertexUVMap>
bool write_obj_with_uvs(const std::string& path, const CGAL::Seam_mesh<TM, SEM, SVM>& sm,
                        VertexUVMap uv) {
  using Seam_mesh = CGAL::Seam_mesh<TM, SEM, SVM>;
  using seam_vertex = typename boost::graph_traits<Seam_mesh>::vertex_descriptor;
  const TM& tm = sm.mesh();
  std::ofstream os(path);
  if (!os)
    return false;
  internal::write_shortest_doubles(os);
  os << "# written by Tessera: v per mesh vertex, vt per seam-mesh vertex\n";
  const auto vpm = get(CGAL::vertex_point, tm);
  const auto vim = CGAL::get_initialized_vertex_index_map(tm);
  for (auto v : vertices(tm)) {
    const auto& p = get(vpm, v);
    os << "v " << CGAL::to_double(p.x()) << " " << CGAL::to_double(p.y()) << " "
       << CGAL::to_double(p.z()) << "\n";
  }
  // Each seam-mesh vertex's `vt` number, by its key.
  const internal::Seam_vertex_keys<TM> key(tm);
  std::vector<std::size_t> index(key.size(), 0);
  std::size_t n = 0;
  for (seam_vertex v : vertices(sm)) {
    const auto& t = get(uv, v);
    os << "vt " << CGAL::to_double(t.x()) << " " << CGAL::to_double(t.y()) << "\n";
    index[key(v)] = ++n;
  }
  for (auto f : faces(sm)) {
    os << "f";
    for (auto h : CGAL::halfedges_around_face(halfedge(f, sm), sm))
      os << " " << get(vim, target(h.tmhd, tm)) + 1 << "/" << index[key(target(h, sm))];
    os << "\n";
  }
  return bool(os);
}

} // namespace tessera
