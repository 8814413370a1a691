// What `tessera cut` and `tessera quadrangulate` write to result.json, for library users: a plain
// report struct per result kind, built from the library's results (`make_cut_report`,
// `make_quadrangulation_report`), and one JSON writer per kind compiled into Tessera::core
// (nlohmann-json stays private). The keys and their meanings are doc/formats.md's; the CLI writes
// through these and nothing else, so a library user gets the same file.
#pragma once

#include <tessera/topology/cut_graph.h>
#include <tessera/topology/method_names.h>
#include <tessera/topology/parameterize_tiles.h>
#include <tessera/topology/quadrangulate.h>
#include <tessera/topology/validate_charts.h>
#include <tessera/topology/validate_cut.h>
#include <tessera/topology/validate_quadrangulation.h>

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
                double seconds = 0);

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
    const std::vector<std::size_t>& tile_of_opened_face, double seconds = 0);

} // namespace tessera

#include <tessera/io/internal/result_reports_impl.h>
