// Implementation of tessera::make_cut_report (see tessera/io/result_reports.h).
#pragma once

#include <tessera/io/result_reports.h>

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

template <typename TriangleMesh, typename OpenedMesh>
Cut_report
make_cut_report(const TriangleMesh& tm, const Cut_result<TriangleMesh>& result,
                const Cut_options& options, const Cut_validation& validation,
                const Cutting_validation& charts, const OpenedMesh& opened,
                const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>&
                    opened_to_mesh,
                double seconds) {
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

template <typename TriangleMesh>
Quadrangulation_report make_quadrangulation_report(
    const TriangleMesh& tm, const Quadrangulation_result<TriangleMesh>& result,
    const Quadrangulation_options& options, std::size_t faces_before,
    const Quadrangulation_validation& validation, const Tile_parameterization_result& param,
    const Cutting_validation& charts,
    const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>&
        opened_to_mesh,
    const std::vector<std::size_t>& tile_of_opened_face, double seconds) {
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
