// Validation of any cutting of a surface into charts, Tessera's or another tool's (libigl's
// cut_to_disk, Blender seams, xatlas): the cutting is given as a chart mesh whose face i is face i
// of the surface and whose vertices are copies of the surface's, as an opened mesh or a texture
// layout stores it. Checks that every chart is a disk, that the seam sides pair up, where the
// corners are, and, when asked, that the charts form a polygonal schema (one 4g-gon at one
// basepoint, with its side word) or a quad layout (four corners per chart, no T-junctions).
#pragma once

#include <tessera/topology/open_mesh.h>
#include <tessera/topology/pinched_texture_vertex.h>

#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace tessera {

/// What the charts are expected to form.
enum class Expected_cutting {
  /// Any cutting into disks.
  disks,
  /// A polygonal schema: each closed component of genus g >= 1 is one chart with 4g sides whose
  /// corners are all one vertex (the basepoint), and each bordered component one chart.
  schema,
  /// A quad layout: every chart a disk with exactly four corners.
  quads
};

struct Validate_charts_options {
  Expected_cutting expect = Expected_cutting::disks;
  /// Vertices of the surface (indices in vertex order) that are corners although the seams do not
  /// branch there, such as a quadrangulation's multipoints.
  std::vector<std::size_t> marked_corners;
  /// For a schema: check with CGAL's Curves_on_surface_topology that every side is a
  /// non-contractible loop (costs a copy of the surface into a combinatorial map).
  bool check_loops_non_contractible = false;
};

enum class Cutting_problem_kind {
  /// The charts do not copy the surface: face counts, a face's corners or a gluing differ.
  mismatch,
  not_a_disk,
  /// A seam side without exactly one reversed partner.
  unpaired_side,
  /// A seam that ends inside the surface (a slit): harmless for disks, wrong for a schema or quads.
  dangling_seam,
  /// Not the expected schema: several charts for one component, corners at several vertices, or a
  /// side count other than 4g.
  not_a_schema,
  /// A chart without exactly four corners (a T-junction, or a tile that is not a quad).
  not_a_quad,
  contractible_loop,
  /// A face with zero area in the texture layout.
  degenerate_uv_face,
  /// A face turned against the rest of its chart in the texture layout (a fold).
  inverted_uv_face,
  /// Charts (or one chart with itself) touching at one point of the texture layout: a note, not a
  /// fault (see `Cutting_validation::notes`).
  pinched_texture_vertex
};

/// One problem, with the surface's elements it concerns (indices in vertex and face order).
struct Cutting_problem {
  Cutting_problem_kind kind;
  std::string message;
  std::vector<std::size_t> vertices;
  std::vector<std::size_t> faces;
};

/// One chart: a connected component of the chart mesh.
struct Chart_summary {
  std::size_t faces = 0;
  long euler_characteristic = 0;
  std::size_t boundary_loops = 0;
  /// Corners along the chart's boundary, in boundary order (the chart on the left), as surface
  /// vertex indices.
  std::vector<std::size_t> corners;
  /// The same corners as vertex indices of the chart mesh (distinct even where several corners are
  /// one surface vertex, as a schema's basepoint).
  std::vector<std::size_t> chart_corners;
  std::size_t sides = 0;
  /// Sides in boundary order from the first corner, labelled by their partner pairs ("a1 b1 a1^-1
  /// b1^-1 ..."), "B" for a side along the surface's own border. The first corner of a chart with
  /// one boundary loop is where the longest run of commutators x y x^-1 y^-1 starts (a canonical
  /// schema reads canonically), else the corner with the smallest chart vertex index.
  std::string word;
  bool is_disk() const { return euler_characteristic == 1 && boundary_loops == 1; }
};

enum class Cutting_validation_status { valid, invalid };

struct Cutting_validation {
  Cutting_validation_status status = Cutting_validation_status::valid;
  /// The first problem, or a one-line summary when valid.
  std::string message;
  std::vector<Chart_summary> charts;
  /// Surface edges cut by the seams (the surface's own border not included).
  std::size_t seam_edges = 0;
  /// Surface vertices that are corners.
  std::size_t corner_vertices = 0;
  /// The chart of every face, in face order.
  std::vector<std::size_t> chart_of_face;
  std::vector<Cutting_problem> problems;
  /// What is worth knowing but leaves the cutting valid (charts touching at a point).
  std::vector<Cutting_problem> notes;
  explicit operator bool() const { return status == Cutting_validation_status::valid; }
};

/// Validates the cutting of `tm` into the charts of `charts`: face i of `charts` copies face i of
/// `tm`, and `chart_to_mesh[k]` is the vertex of `tm` that the k-th vertex of `charts` (in vertex
/// order) copies. Any FaceGraph with polygonal faces; geometry is only read to name likely
/// T-junctions (corners with a flat angle in a chart that has too many).
template <typename PolygonMesh, typename ChartMesh>
Cutting_validation validate_charts(
    const PolygonMesh& tm, const ChartMesh& charts,
    const std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>& chart_to_mesh,
    const Validate_charts_options& options = {});

/// Validates a texture layout: `uv[k]` holds the coordinates of the k-th vertex of `charts` (in
/// vertex order). A chart's orientation is the sign of its total signed area (a chart may be
/// mirrored as a whole); faces of zero area or of the other sign are problems. The signed areas are
/// exact when `FT` is (CGAL::Epeck's number type read from text by `read_obj_with_uvs()`).
/// `pinched` (from `read_obj_with_uvs()`): texture vertices split into several chart vertices,
/// each reported as a note naming the charts that touch there.
template <typename ChartMesh, typename FT>
Cutting_validation validate_uv_layout(const ChartMesh& charts,
                                      const std::vector<std::array<FT, 2>>& uv,
                                      const std::vector<Pinched_texture_vertex>& pinched = {});

/// Validates seams given as an edge map on `tm`: `tm` is opened along them (CGAL::Seam_mesh) and
/// the charts are checked as by `validate_charts()`.
template <typename PolygonMesh, typename SeamEdgeMap>
Cutting_validation validate_seams(const PolygonMesh& tm, SeamEdgeMap seam_edges,
                                  const Validate_charts_options& options = {}) {
  auto seam_vertices = get(CGAL::dynamic_vertex_property_t<bool>(), tm);
  for (auto v : vertices(tm))
    put(seam_vertices, v, false);
  for (auto e : edges(tm))
    if (get(seam_edges, e)) {
      put(seam_vertices, source(halfedge(e, tm), tm), true);
      put(seam_vertices, target(halfedge(e, tm), tm), true);
    }
  PolygonMesh opened;
  const auto origin = open_along_seams(tm, seam_edges, seam_vertices, opened);
  return validate_charts(tm, opened, origin, options);
}

} // namespace tessera

#include <tessera/topology/internal/validate_charts_impl.h>
