// Readers of cuttings made elsewhere, for tessera::validate_charts and validate_seams: a seam file
// (one mesh edge per line, as two vertex ids) and an OBJ whose vertices are split by texture
// coordinates, the way most tools store seams. CGAL's OBJ reader drops the texture indices of
// `f v/vt` corners, hence a reader of its own here. Numbers go through the point type's own parser,
// so an exact kernel (CGAL::Epeck) reads decimal text and p/q rationals without rounding.
#pragma once

#include <tessera/topology/pinched_texture_vertex.h>

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <cstddef>
#include <fstream>
#include <istream>
#include <string>
#include <vector>

namespace tessera {

enum class Cutting_read_status {
  ok,
  cannot_open,
  /// A line that is not what the format says (the message gives its number).
  parse_error,
  /// A vertex or texture-coordinate index outside the file's range.
  index_out_of_range,
  /// A seam line naming two vertices that share no edge.
  not_an_edge,
  /// Faces that do not form a manifold, consistently oriented surface, or texture coordinates that
  /// glue faces in a way the surface does not.
  not_a_surface,
  no_faces
};

struct Cutting_read_result {
  Cutting_read_status status = Cutting_read_status::ok;
  std::string message;
  /// Seam edges read (seam files), or texture-coordinate corners (OBJ).
  std::size_t count = 0;
  explicit operator bool() const { return status == Cutting_read_status::ok; }
};

/// Reads seams from `in` into `seam_edges` (set to true; other edges are left as they are): every
/// line that is not blank and does not start with '#' holds the 0-based ids (in vertex order) of
/// the two ends of one edge of `tm`.
template <typename PolygonMesh, typename SeamEdgeMap>
Cutting_read_result read_seams(std::istream& in, const PolygonMesh& tm, SeamEdgeMap seam_edges);

/// Reads a seam file (see `read_seams()`).
template <typename PolygonMesh, typename SeamEdgeMap>
Cutting_read_result read_seam_file(const std::string& path, const PolygonMesh& tm,
                                   SeamEdgeMap seam_edges) {
  std::ifstream in(path);
  if (!in)
    return {Cutting_read_status::cannot_open, path + ": cannot open", 0};
  Cutting_read_result r = read_seams(in, tm, seam_edges);
  if (!r)
    r.message = path + ": " + r.message;
  return r;
}

/// A surface and its texture layout as read from an OBJ: `mesh` is built from the positions and
/// faces (vertex i is the file's i-th `v`), `charts` has one vertex per fan of faces around a
/// (position, texture coordinate) pair (one per pair, except at `pinched` ones) and face i copying
/// face i of `mesh`, as `validate_charts()` takes them.
template <typename PolygonMesh> struct Uv_layout {
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  using Point = typename boost::property_traits<
      typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::type>::value_type;
  using FT = typename CGAL::Kernel_traits<Point>::Kernel::FT;
  PolygonMesh mesh;
  PolygonMesh charts;
  /// The vertex of `mesh` each vertex of `charts` (in vertex order) copies.
  std::vector<vertex_descriptor> chart_to_mesh;
  /// The texture coordinates of each vertex of `charts`, in vertex order.
  std::vector<std::array<FT, 2>> uv;
  /// Texture vertices where charts touch at a point, split in `charts` (in file order).
  std::vector<Pinched_texture_vertex> pinched;
};

/// Reads `v`, `vt` and `f` lines of an OBJ (negative, relative indices included; `v/vt/vn`
/// corners; faces of any degree; `o`, `g`, `usemtl` and other lines are skipped, so several objects
/// read as one surface). Every face corner needs a texture coordinate. A `vt` may serve several
/// `v`: the chart vertices are (v, vt) pairs, and a pair whose faces form several fans sharing no
/// edge (charts touching at a point in the layout, which a halfedge mesh cannot hold as one vertex)
/// is split into one chart vertex per fan and listed in `out.pinched`.
template <typename PolygonMesh>
Cutting_read_result read_obj_with_uvs(std::istream& in, Uv_layout<PolygonMesh>& out);

/// Reads an OBJ file with texture coordinates (see `read_obj_with_uvs(std::istream&, ...)`).
template <typename PolygonMesh>
Cutting_read_result read_obj_with_uvs(const std::string& path, Uv_layout<PolygonMesh>& out) {
  std::ifstream in(path);
  if (!in)
    return {Cutting_read_status::cannot_open, path + ": cannot open", 0};
  Cutting_read_result r = read_obj_with_uvs(in, out);
  if (!r)
    r.message = path + ": " + r.message;
  return r;
}

/// Reads an OFF or OBJ text file as a polygon soup with the number type of `Point`'s kernel, for
/// exact work: every coordinate goes through the number type's own parser, so with CGAL::Epeck
/// decimal text (`0.1`) and rationals (`1/3`, as `write_exact_off()` writes them) are read without
/// rounding (CGAL's OFF scanner rounds through double). Faces are 0-based vertex-id lists (OBJ's
/// 1-based and negative indices converted; its `v/vt/vn` corners give their `v`). Vertices keep the
/// file's order.
template <typename Point>
Cutting_read_result read_exact_polygon_soup(const std::string& path, std::vector<Point>& points,
                                            std::vector<std::vector<std::size_t>>& polygons);

/// Reads the vertex coordinates of an OFF or OBJ text file exactly (see
/// `read_exact_polygon_soup()`).
template <typename Point>
Cutting_read_result read_exact_coordinates(const std::string& path, std::vector<Point>& points) {
  std::vector<std::vector<std::size_t>> polygons;
  return read_exact_polygon_soup(path, points, polygons);
}

/// Reads an OFF or OBJ text file into `tm` with exact coordinates (see
/// `read_exact_polygon_soup()`); vertex i of the file is the i-th vertex of `tm` (for
/// CGAL::Surface_mesh, its index). Fails with `not_a_surface` when the faces do not form a
/// manifold, consistently oriented polygon mesh (this reader repairs nothing, so that ids keep
/// their meaning) and with `no_faces` on a file without faces.
template <typename PolygonMesh>
Cutting_read_result read_exact_polygon_mesh(const std::string& path, PolygonMesh& tm) {
  using Point = typename boost::property_traits<
      typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::type>::value_type;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  Cutting_read_result r = read_exact_polygon_soup(path, points, polygons);
  if (!r)
    return r;
  if (polygons.empty())
    return {Cutting_read_status::no_faces, path + ": no faces", 0};
  if (!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons))
    return {Cutting_read_status::not_a_surface,
            path + ": the faces do not form a manifold, consistently oriented polygon mesh", 0};
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, tm);
  r.count = num_vertices(tm);
  return r;
}

} // namespace tessera

#include <tessera/io/internal/read_cutting_impl.h>
