// What `tessera cut` and `tessera quadrangulate` write to result.json, for library users: a plain
// report struct per result kind, built from the library's results (`make_cut_report`,
// `make_quadrangulation_report`), and one JSON writer per kind compiled into Tessera::core
// (nlohmann-json stays private). The keys and their meanings are doc/formats.md's; the CLI writes
// through these and nothing else, so a library user gets the same file.
#pragma once

#include <tessera/io/internal/index_list.h>
#include <tessera/topology/cut_graph.h>
#include <tessera/topology/method_names.h>
#include <tessera/topology/parameterize_tiles.h>
#include <tessera/topology/quadrangulate.h>
#include <tessera/topology/validate_charts.h>
#include <tessera/topology/validate_cut.h>
#include <tessera/topology/validate_quadrangulation.h>

#include <algorithm>
#include <cstddef>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace tessera {

/// One polygon of a cut (one per component of the surface).
struct Cut_report_polygon {
  long genus = 0;
  std::size_t boundaries = 0;
  std::size_t sides = 0;
  std::size_t basepoint = 0; ///< a vertex of mesh.off
  /// The polygon's corners as vertices of opened.off, in boundary order.
  std::vector<std::size_t> corners;
  /// Its sides labelled by partner pairs in boundary order from the first corner ("a1 b1 a1^-1
  /// b1^-1 …", `Cut_polygon::word`).
  std::string word;
};

/// result.json of `tessera cut`.
struct Cut_report {
  std::string method, cost, kernel = "double";
  double seconds = 0, cut_length = 0, cut_cost = 0;
  std::size_t added_vertices = 0;
  /// Whether the polygons are in canonical form (`--canonical`), and the moves that took.
  bool canonical = false;
  std::size_t canonical_moves = 0;
  long genus = 0; ///< summed over the components
  std::size_t boundaries = 0;
  std::vector<Cut_report_polygon> polygons;
  std::vector<std::size_t> multipoints;           ///< vertices of mesh.off
  std::vector<std::size_t> opened_to_mesh_vertex; ///< per vertex of opened.off
  bool valid = false;
  std::vector<std::string> validation_problems;
  std::optional<std::string> exact_mesh; ///< the exact coordinates' file, when written
};

/// One quad of a quadrangulation.
struct Quad_report {
  std::vector<std::size_t> corners;        ///< vertices of mesh.off, in boundary order
  std::vector<std::size_t> opened_corners; ///< the same corners as vertices of opened.off
  double angle_distortion = 0, area_distortion = 0, stretch = 0;
  std::size_t flipped = 0, degenerate = 0;
};

/// result.json of `tessera quadrangulate`.
struct Quadrangulation_report {
  std::string method, cost, kernel = "double";
  double seconds = 0, cut_length = 0, cut_cost = 0, source_cut_length = 0;
  /// Whether the source cut was the canonical schema (`--from schema --canonical`).
  bool source_canonical = false;
  std::size_t faces_before = 0, faces_after = 0; ///< the refinement's growth
  std::size_t refinements = 0, local_refinements = 0, added_corners = 0, cutting_paths = 0;
  std::size_t quads = 0;
  long genus = 0;
  std::size_t boundaries = 0;
  std::vector<std::size_t> source_polygon_corner_counts;
  std::vector<std::size_t> multipoints;
  std::vector<std::size_t> opened_to_mesh_vertex;
  std::vector<std::size_t> tiles; ///< the quad of each face of opened.off
  std::vector<Quad_report> quad_tiles;
  std::size_t worst_tile = 0, flipped = 0;
  bool valid = false;
  std::vector<std::string> validation_problems;
  std::optional<std::string> exact_mesh;
};

/// Writes `report` as JSON (one key a line); false when the stream failed.
bool write_cut_report(std::ostream& out, const Cut_report& report);
/// Writes `report` as JSON (one key a line); false when the stream failed.
bool write_quadrangulation_report(std::ostream& out, const Quadrangulation_report& report);

/// The report of a cut of `tm` (after `cut_to_disk`; Surface_mesh-like, ids are indices):
/// `opened`/`opened_to_mesh` from `open_along_seams`, `charts` from `validate_charts(tm, opened,
/// opened_to_mesh, …)` with the cut's multipoints marked (each polygon's corners come from its
/// chart, listed from the polygon's first corner as its word reads), `validation` from
/// `validate_cut`. `seconds` is the time the caller measured.
template <typename TriangleMesh, typename OpenedMesh>
Cut_report
make_cut_report(const TriangleMesh& tm, const Cut_result<TriangleMesh>& result,
                const Cut_options& options, const Cut_validation& validation,
                const Cutting_validation& charts, const OpenedMesh& opened,
                const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>&
                    opened_to_mesh,
                double seconds = 0) {
  Cut_report r;
  r.method = to_string(options.method);
  r.cost = to_string(options.cost.kind);
  r.seconds = seconds;
  r.cut_length = result.cut_length;
  r.cut_cost = result.cut_cost;
  r.added_vertices = result.added_vertices;
  r.canonical = result.canonical;
  r.canonical_moves = result.canonical_moves;
  for (const auto& p : result.polygons) {
    Cut_report_polygon q;
    q.genus = p.genus;
    q.boundaries = p.boundaries;
    q.sides = p.sides.size();
    q.basepoint = std::size_t(p.basepoint);
    if (!p.sides.empty() && !p.sides.front().empty()) {
      const std::size_t f = std::size_t(face(p.sides.front().front(), tm));
      if (f < charts.chart_of_face.size()) {
        const Chart_summary& chart = charts.charts[charts.chart_of_face[f]];
        q.corners = chart.chart_corners;
        // The chart lists its corners from its smallest vertex id; the polygon (and its word)
        // starts at the copy of its first corner in the face left of its first side.
        const auto first = source(p.sides.front().front(), tm);
        const auto opened_face =
            typename OpenedMesh::Face_index(typename OpenedMesh::Face_index::size_type(f));
        for (auto v : vertices_around_face(halfedge(opened_face, opened), opened)) {
          const auto it = std::find(q.corners.begin(), q.corners.end(), std::size_t(v));
          if (std::size_t(v) < opened_to_mesh.size() && opened_to_mesh[std::size_t(v)] == first &&
              it != q.corners.end())
            std::rotate(q.corners.begin(), it, q.corners.end());
        }
      }
    }
    q.word = p.word;
    r.genus += q.genus;
    r.boundaries += q.boundaries;
    r.polygons.push_back(std::move(q));
  }
  r.multipoints = internal::index_list(result.multipoints);
  r.opened_to_mesh_vertex = internal::index_list(opened_to_mesh);
  r.valid = bool(validation);
  r.validation_problems = validation.problems;
  return r;
}

/// The report of a quadrangulation of `tm`: `faces_before` the face count before
/// `quadrangulate`, `tile_of_opened_face` the quad of each face of `opened` (from
/// `open_along_seams`), `charts` from `validate_charts(tm, opened, opened_to_mesh, …)` with the
/// multipoints marked (each quad's corners come from its chart), `param` from
/// `parameterize_tiles`.
template <typename TriangleMesh>
Quadrangulation_report make_quadrangulation_report(
    const TriangleMesh& tm, const Quadrangulation_result<TriangleMesh>& result,
    const Quadrangulation_options& options, std::size_t faces_before,
    const Quadrangulation_validation& validation, const Tile_parameterization_result& param,
    const Cutting_validation& charts,
    const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>&
        opened_to_mesh,
    const std::vector<std::size_t>& tile_of_opened_face, double seconds = 0) {
  Quadrangulation_report r;
  r.method = to_string(options.cut.method);
  r.cost = to_string(options.cut.cost.kind);
  r.seconds = seconds;
  r.cut_length = result.cut_length;
  r.cut_cost = result.cut_cost;
  r.source_cut_length = result.cut.cut_length;
  r.source_canonical = result.cut.canonical;
  r.faces_before = faces_before;
  r.faces_after = std::size_t(num_faces(tm));
  r.refinements = result.refinements;
  r.local_refinements = result.local_refinements;
  r.added_corners = result.added_corners;
  r.cutting_paths = result.cutting_paths;
  r.quads = result.number_of_quads();
  for (const auto& p : result.cut.polygons) {
    r.genus += p.genus;
    r.boundaries += p.boundaries;
  }
  r.source_polygon_corner_counts = result.polygon_corners;
  r.multipoints = internal::index_list(result.multipoints);
  r.opened_to_mesh_vertex = internal::index_list(opened_to_mesh);
  r.tiles = tile_of_opened_face;
  std::vector<const Chart_summary*> chart_of_tile(result.tiles.size(), nullptr);
  for (std::size_t f = 0; f < charts.chart_of_face.size() && f < tile_of_opened_face.size(); ++f)
    if (tile_of_opened_face[f] < chart_of_tile.size())
      chart_of_tile[tile_of_opened_face[f]] = &charts.charts[charts.chart_of_face[f]];
  for (std::size_t t = 0; t < result.tiles.size(); ++t) {
    Quad_report q;
    if (const Chart_summary* chart = chart_of_tile[t]) {
      q.corners = chart->corners;
      q.opened_corners = chart->chart_corners;
    }
    if (t < param.tiles.size()) {
      const Tile_distortion& d = param.tiles[t];
      q.angle_distortion = d.angle;
      q.area_distortion = d.area;
      q.stretch = d.stretch;
      q.flipped = d.flipped;
      q.degenerate = d.degenerate;
    }
    r.quad_tiles.push_back(std::move(q));
  }
  r.worst_tile = param.worst_tile;
  r.flipped = param.flipped;
  r.valid = bool(validation);
  r.validation_problems = validation.problems;
  return r;
}

} // namespace tessera
