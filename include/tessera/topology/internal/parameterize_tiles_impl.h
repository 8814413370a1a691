// Internals of the per-tile parameterization (Favreau et al. 2009, §5.2): the tiles' own meshes cut
// out along the seams, each solved by CGAL's parameterizers in parallel, the per-face UVs with
// mirrored tiles turned back, the distortion per tile, and the copy in doubles for exact kernels.
// Included by topology/parameterize_tiles.h after its public types; not for direct use.
#pragma once

// Surface_mesh's graph traits must be declared before CGAL::Seam_mesh is instantiated.
#include <CGAL/Surface_mesh.h>

#include <tessera/internal/parallel.h>
#include <tessera/internal/seam_vertex_keys.h>
#include <tessera/progress.h>
#include <tessera/topology/internal/parameterization_errors.h>
#include <tessera/topology/edge_cost.h>
#include <tessera/topology/internal/double_geometry.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/Surface_mesh_parameterization/ARAP_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Square_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <mutex>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace tessera {
namespace internal {

/// A UV map of a Seam_mesh's vertices stored in a halfedge map of the underlying mesh, at the
/// halfedge that represents each seam-mesh vertex.
template <typename SeamMesh, typename HalfedgeUVMap> struct Seam_vertex_uv_map {
  using key_type = typename boost::graph_traits<SeamMesh>::vertex_descriptor;
  using value_type = typename boost::property_traits<HalfedgeUVMap>::value_type;
  using reference = value_type;
  using category = boost::read_write_property_map_tag;
  HalfedgeUVMap uv;
  friend value_type get(const Seam_vertex_uv_map& m, key_type k) { return get(m.uv, k.hd.tmhd); }
  friend void put(const Seam_vertex_uv_map& m, key_type k, const value_type& p) {
    put(m.uv, k.hd.tmhd, p);
  }
};

// One tile's mesh: its seam-mesh vertices (local vertex i is vertices[i]) and its faces as local
// vertex ids (each face's degree, then its corners).
template <typename SeamVertex, typename Point_2> struct Tile_mesh {
  std::vector<SeamVertex> vertices;
  std::vector<std::size_t> faces;
  // A border halfedge, reversed (none: not in the tile).
  std::size_t border_source = std::size_t(-1), border_target = std::size_t(-1);
  std::vector<std::size_t> corners; // the sides' first vertices
  std::vector<Point_2> uv;
};

// Parameterizes one tile on a mesh of its own built from `m` (the unit square for a quad, a free
// border otherwise); the UVs go to `m.uv`, the outcome to `d`.
template <typename TriangleMesh, typename SeamVertex, typename Point_2, typename VertexPointMap>
void parameterize_tile_mesh(const TriangleMesh& tm, VertexPointMap points,
                            Tile_mesh<SeamVertex, Point_2>& m, Tile_distortion& d,
                            const Tile_parameterization_options& options) {
  namespace SMP = CGAL::Surface_mesh_parameterization;
  using Point_3 = typename boost::property_traits<
      typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type;
  using Local = CGAL::Surface_mesh<Point_3>;
  using Local_vertex = typename Local::Vertex_index;
  using Local_uv_map = typename Local::template Property_map<Local_vertex, Point_2>;
  using Local_square = SMP::Square_border_arc_length_parameterizer_3<Local>;
  constexpr std::size_t none = std::size_t(-1);
  Local local;
  local.reserve(typename Local::size_type(m.vertices.size()), 0, 0);
  for (const SeamVertex v : m.vertices)
    local.add_vertex(get(points, target(v.hd.tmhd, tm)));
  std::vector<Local_vertex> corners;
  for (std::size_t i = 0; i < m.faces.size(); i += m.faces[i] + 1) {
    corners.clear();
    for (std::size_t k = 1; k <= m.faces[i]; ++k)
      corners.push_back(Local_vertex(typename Local::size_type(m.faces[i + k])));
    local.add_face(corners);
  }
  const Local_uv_map local_uv =
      local.template add_property_map<Local_vertex, Point_2>("v:tessera_uv").first;
  const auto vertex = [](std::size_t i) { return Local_vertex(typename Local::size_type(i)); };
  auto local_border = Local::null_halfedge();
  if (m.border_source != none && m.border_target != none)
    local_border =
        opposite(halfedge(vertex(m.border_source), vertex(m.border_target), local).first, local);
  SMP::Error_code err = SMP::OK;
  if (local_border == Local::null_halfedge() || !is_border(local_border, local) ||
      std::count(m.corners.begin(), m.corners.end(), none) != 0) {
    err = SMP::ERROR_BORDER_TOO_SHORT;
  } else if (m.corners.size() == 4) {
    const Local_square border(vertex(m.corners[0]), vertex(m.corners[1]), vertex(m.corners[2]),
                              vertex(m.corners[3]));
    if (options.quad_interior == Quad_interior::mean_value)
      err = SMP::parameterize(
          local, SMP::Mean_value_coordinates_parameterizer_3<Local, Local_square>(border),
          local_border, local_uv);
    else
      err = SMP::parameterize(
          local, SMP::Discrete_conformal_map_parameterizer_3<Local, Local_square>(border),
          local_border, local_uv);
  } else if (options.free_border == Free_border_method::lscm) {
    err = SMP::parameterize(local, SMP::LSCM_parameterizer_3<Local>(), local_border, local_uv);
  } else {
    err = SMP::parameterize(local, SMP::ARAP_parameterizer_3<Local>(), local_border, local_uv);
  }
  d.parameterized = err == SMP::OK;
  if (!d.parameterized)
    d.message = internal::parameterization_error_message(err);
  else
    for (std::size_t i = 0; i < m.vertices.size(); ++i)
      m.uv.push_back(get(local_uv, vertex(i)));
}

// The distortion of every parameterized tile from the UVs in `uv` (double coordinates), with the
// flipped and degenerate triangles, the result's totals, status and worst tile.
template <typename TriangleMesh, typename FaceTileMap, typename HalfedgeUVMap>
void measure_tile_distortion(const TriangleMesh& tm, FaceTileMap tile_of_face, HalfedgeUVMap uv,
                             Tile_parameterization_result& result) {
  using Point_2 = typename boost::property_traits<HalfedgeUVMap>::value_type;
  const std::size_t number_of_tiles = result.tiles.size();
  struct Sums {
    double area3 = 0, area2 = 0, angle = 0, stretch = 0;
    std::vector<std::pair<double, double>> areas; // (3D, UV) per triangle
  };
  std::vector<Sums> sums(number_of_tiles);
  const auto vpm = get(CGAL::vertex_point, tm);
  for (auto f : faces(tm)) {
    const std::size_t t = get(tile_of_face, f);
    if (t >= number_of_tiles || !result.tiles[t].parameterized)
      continue;
    std::vector<std::array<double, 3>> p;
    std::vector<Point_2> q;
    for (auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      p.push_back(internal::to_double_array(get(vpm, target(h, tm))));
      q.push_back(get(uv, h));
    }
    const CGAL::Orientation o = CGAL::orientation(q[0], q[1], q[2]);
    if (o != CGAL::LEFT_TURN) {
      ++(o == CGAL::RIGHT_TURN ? result.tiles[t].flipped : result.tiles[t].degenerate);
      continue;
    }
    const double du1 = CGAL::to_double(q[1].x() - q[0].x()),
                 dv1 = CGAL::to_double(q[1].y() - q[0].y());
    const double du2 = CGAL::to_double(q[2].x() - q[0].x()),
                 dv2 = CGAL::to_double(q[2].y() - q[0].y());
    const double det = du1 * dv2 - du2 * dv1;
    std::array<double, 3> ss, st, p1, p2;
    for (int k = 0; k < 3; ++k) {
      p1[k] = p[1][k] - p[0][k];
      p2[k] = p[2][k] - p[0][k];
      ss[k] = (p1[k] * dv2 - p2[k] * dv1) / det;
      st[k] = (p2[k] * du1 - p1[k] * du2) / det;
    }
    const auto dot = [](const std::array<double, 3>& x, const std::array<double, 3>& y) {
      return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
    };
    const double a = dot(ss, ss), b = dot(ss, st), c = dot(st, st);
    const double root = std::sqrt((a - c) * (a - c) + 4 * b * b);
    const double s1 = std::sqrt((a + c + root) / 2),
                 s2 = std::sqrt(std::max(0.0, (a + c - root) / 2));
    const std::array<double, 3> n{{p1[1] * p2[2] - p1[2] * p2[1], p1[2] * p2[0] - p1[0] * p2[2],
                                   p1[0] * p2[1] - p1[1] * p2[0]}};
    const double area3 = std::sqrt(dot(n, n)) / 2, area2 = det / 2;
    if (s2 <= 0 || area3 <= 0) {
      ++result.tiles[t].degenerate;
      continue;
    }
    Sums& s = sums[t];
    s.area3 += area3;
    s.area2 += area2;
    s.angle += area3 * s1 / s2;
    s.stretch += area3 * (a + c) / 2;
    s.areas.emplace_back(area3, area2);
  }
  for (std::size_t t = 0; t < number_of_tiles; ++t) {
    Tile_distortion& d = result.tiles[t];
    const Sums& s = sums[t];
    if (d.parameterized && s.area3 > 0 && s.area2 > 0) {
      d.angle = s.angle / s.area3;
      // (a + c) / 2 scales with (area3 / area2): normalize so a similarity gives 1.
      d.stretch = std::sqrt(s.stretch / s.area3) * std::sqrt(s.area2 / s.area3);
      double area = 0;
      for (const auto& [a3, a2] : s.areas) {
        const double r = (a2 / s.area2) / (a3 / s.area3);
        area += a3 * std::max(r, 1 / r);
      }
      d.area = area / s.area3;
    }
    result.flipped += d.flipped;
    result.degenerate += d.degenerate;
    if (!d.parameterized) {
      result.status = Tile_parameterization_status::tile_failed;
      result.message = "tile " + std::to_string(t) + ": " + d.message;
    }
    if (d.stretch > result.tiles[result.worst_tile].stretch)
      result.worst_tile = t;
  }
}

template <typename TriangleMesh, typename Tile, typename FaceTileMap, typename SeamEdgeMap,
          typename SeamVertexMap, typename HalfedgeUVMap>
Tile_parameterization_result
parameterize_tiles_impl(const TriangleMesh& tm, const std::vector<Tile>& tiles,
                        FaceTileMap tile_of_face, SeamEdgeMap seam_edges,
                        SeamVertexMap seam_vertices, HalfedgeUVMap uv,
                        const Tile_parameterization_options& options) {
  using Seam_mesh = CGAL::Seam_mesh<TriangleMesh, SeamEdgeMap, SeamVertexMap>;
  using seam_halfedge = typename boost::graph_traits<Seam_mesh>::halfedge_descriptor;
  using seam_vertex = typename boost::graph_traits<Seam_mesh>::vertex_descriptor;
  using Point_2 = typename boost::property_traits<HalfedgeUVMap>::value_type;

  Seam_mesh sm(tm, seam_edges, seam_vertices);
  std::size_t seams = 0;
  for (auto e : edges(tm))
    seams += get(seam_edges, e) ? 1 : 0;
  sm.set_seam_edges_number(typename Seam_mesh::edges_size_type(seams));
  const internal::Seam_vertex_uv_map<Seam_mesh, HalfedgeUVMap> suv{uv};
  auto seam_vertex_of = [&](typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h) {
    return target(seam_halfedge(h, false), sm);
  };

  // Each tile is parameterized on a mesh of its own, with one vertex per seam-mesh vertex (a
  // corner of the schema is one mesh vertex that a quad touches four times): CGAL's `parameterize`
  // on the whole Seam_mesh costs the whole mesh in every call (its dynamic maps and vertex
  // iteration), which made the parameterization of many tiles quadratic (299 quads of 2.15M faces:
  // 96 s; see doc/performance-notes.md). The tiles' meshes are independent, so they are solved in
  // parallel; everything read from the caller's maps is gathered before and every UV written after,
  // in one thread.
  using Tile_mesh = internal::Tile_mesh<seam_vertex, Point_2>;
  constexpr std::size_t none = std::size_t(-1);

  std::vector<Tile_mesh> meshes(tiles.size());
  Tile_parameterization_result result;
  result.tiles.resize(tiles.size());
  // Each seam-mesh vertex's tile and local id, by its key.
  const internal::Seam_vertex_keys<TriangleMesh> key(tm);
  std::vector<std::size_t> owner_of(key.size(), none), local_of_key(key.size(), none);
  for (auto f : faces(tm)) {
    const std::size_t t = get(tile_of_face, f);
    if (t >= tiles.size())
      continue;
    Tile_mesh& m = meshes[t];
    m.faces.push_back(0);
    const std::size_t at = m.faces.size() - 1;
    for (auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      const seam_vertex v = seam_vertex_of(h);
      const std::size_t k = key(v);
      if (owner_of[k] == none) {
        owner_of[k] = t;
        local_of_key[k] = m.vertices.size();
        m.vertices.push_back(v);
      } else if (owner_of[k] != t && result.tiles[t].message.empty()) {
        result.tiles[t].message = "the tile shares a vertex with tile " +
                                  std::to_string(owner_of[k]) +
                                  ": their common border is not on the seams";
      }
      m.faces.push_back(local_of_key[k]);
      ++m.faces[at];
    }
  }
  const auto local_of = [&](std::size_t t, seam_vertex v) {
    const std::size_t k = key(v);
    return owner_of[k] == t ? local_of_key[k] : none;
  };
  for (std::size_t t = 0; t < tiles.size(); ++t) {
    const auto& sides = tiles[t].sides;
    Tile_mesh& m = meshes[t];
    const seam_halfedge bhd = opposite(seam_halfedge(sides.front().front(), false), sm);
    if (!is_border(bhd, sm) && result.tiles[t].message.empty())
      result.tiles[t].message = "the tile's first side is not on the seams";
    m.border_source = local_of(t, target(bhd, sm));
    m.border_target = local_of(t, source(bhd, sm));
    if (sides.size() == 4)
      for (const auto& side : sides)
        m.corners.push_back(local_of(t, source(seam_halfedge(side.front(), false), sm)));
  }

  const auto points = get(CGAL::vertex_point, tm);
  std::mutex progress_mutex;
  std::size_t done = 0;
  internal::parallel_blocks(
      tiles.size(),
      [&](std::size_t first, std::size_t last) {
        for (std::size_t t = first; t < last; ++t) {
          Tile_distortion& d = result.tiles[t];
          Tile_mesh& m = meshes[t];
          if (!d.message.empty())
            continue;
          parameterize_tile_mesh(tm, points, m, d, options);
          if (options.progress) {
            const std::lock_guard<std::mutex> lock(progress_mutex);
            options.progress({"parameterizing tiles", ++done, tiles.size()});
          }
        }
      },
      1);
  for (const Tile_mesh& m : meshes)
    for (std::size_t i = 0; i < m.uv.size(); ++i)
      put(suv, m.vertices[i], m.uv[i]);

  // Per-face UVs; tiles mapped with the wrong orientation are mirrored by (u, v) -> (v, u), which
  // keeps the unit square's corners on its corners.
  std::vector<std::pair<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor, Point_2>>
      corner_uv;
  std::vector<double> signed_area(tiles.size(), 0);
  for (auto f : faces(tm)) {
    const std::size_t t = get(tile_of_face, f);
    std::vector<Point_2> q;
    for (auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      q.push_back(get(suv, seam_vertex_of(h)));
      corner_uv.emplace_back(h, q.back());
    }
    if (t < tiles.size() && result.tiles[t].parameterized)
      signed_area[t] += CGAL::to_double(CGAL::area(q[0], q[1], q[2]));
  }
  for (auto& [h, p] : corner_uv)
    if (signed_area[get(tile_of_face, face(h, tm))] < 0)
      p = Point_2(p.y(), p.x());
  for (const auto& [h, p] : corner_uv)
    put(uv, h, p);

  // Distortion, from double coordinates.
  measure_tile_distortion(tm, tile_of_face, uv, result);
  return result;
}

// One tile of a copy of the mesh: only its sides, which is all parameterize_tiles() reads.
template <typename Halfedge> struct Copied_tile { std::vector<std::vector<Halfedge>> sides; };

// parameterize_tiles() on a copy of `tm` with double coordinates; UVs copied back halfedge by
// halfedge.
template <typename TriangleMesh, typename Tile, typename FaceTileMap, typename SeamEdgeMap,
          typename SeamVertexMap, typename HalfedgeUVMap>
Tile_parameterization_result
parameterize_tiles_in_doubles(const TriangleMesh& tm, const std::vector<Tile>& tiles,
                              FaceTileMap tile_of_face, SeamEdgeMap seam_edges,
                              SeamVertexMap seam_vertices, HalfedgeUVMap uv,
                              const Tile_parameterization_options& options) {
  using Copy = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;
  using GT = boost::graph_traits<TriangleMesh>;
  Copy copy;
  auto v2v = get(CGAL::dynamic_vertex_property_t<Copy::Vertex_index>(), tm);
  auto h2h = get(CGAL::dynamic_halfedge_property_t<Copy::Halfedge_index>(), tm);
  auto f2f = get(CGAL::dynamic_face_property_t<Copy::Face_index>(), tm);
  CGAL::copy_face_graph(
      tm, copy,
      CGAL::parameters::vertex_to_vertex_map(v2v).halfedge_to_halfedge_map(h2h).face_to_face_map(
          f2f));
  auto copy_tile = copy.add_property_map<Copy::Face_index, std::size_t>("f:tessera_tile", 0).first;
  auto copy_seam_e = copy.add_property_map<Copy::Edge_index, bool>("e:tessera_seam", false).first;
  auto copy_seam_v = copy.add_property_map<Copy::Vertex_index, bool>("v:tessera_seam", false).first;
  auto copy_uv = copy.add_property_map<Copy::Halfedge_index,
                                       typename boost::property_traits<HalfedgeUVMap>::value_type>(
                         "h:tessera_uv")
                     .first;
  for (auto f : faces(tm))
    put(copy_tile, get(f2f, f), std::size_t(get(tile_of_face, f)));
  for (auto e : edges(tm))
    put(copy_seam_e, edge(get(h2h, halfedge(e, tm)), copy), bool(get(seam_edges, e)));
  for (auto v : vertices(tm))
    put(copy_seam_v, get(v2v, v), bool(get(seam_vertices, v)));
  std::vector<Copied_tile<Copy::Halfedge_index>> copied(tiles.size());
  for (std::size_t t = 0; t < tiles.size(); ++t)
    for (const auto& side : tiles[t].sides) {
      copied[t].sides.emplace_back();
      for (typename GT::halfedge_descriptor h : side)
        copied[t].sides.back().push_back(get(h2h, h));
    }
  Tile_parameterization_result r =
      parameterize_tiles_impl(copy, copied, copy_tile, copy_seam_e, copy_seam_v, copy_uv, options);
  for (auto h : halfedges(tm))
    if (!is_border(h, tm))
      put(uv, h, get(copy_uv, get(h2h, h)));
  return r;
}

} // namespace internal
} // namespace tessera
