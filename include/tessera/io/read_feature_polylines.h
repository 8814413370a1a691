// Reading feature lines a user draws (`tessera field` and `tessera mosaic --feature-file`): one
// polyline per text line, as whitespace-separated 0-based vertex ids in the order of
// `vertices(tm)`, each two consecutive ones joined by an edge of the mesh; a line that ends where
// it starts is closed; '#' starts a comment to the end of its line. The lines come back as
// `Feature_line`s of kind `Feature_kind::user`, which `feature_alignment_constraints()` and the
// mosaics take like detected ones.
#pragma once

#include <tessera/fields/feature_lines.h>
#include <tessera/io/internal/vertex_ids.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <fstream>
#include <istream>
#include <sstream>
#include <string>
#include <vector>

namespace tessera {

enum class Feature_polylines_read_status {
  ok,
  cannot_open,
  /// A token that is not a vertex id, or a polyline of a single vertex (the message gives its
  /// line).
  parse_error,
  index_out_of_range,
  /// Two consecutive vertices of a polyline share no edge (the message names them).
  not_an_edge,
  /// The file holds no polyline.
  empty
};

template <typename HalfedgeDescriptor> struct Feature_polylines_read_result {
  Feature_polylines_read_status status = Feature_polylines_read_status::ok;
  std::string message;
  std::vector<Feature_line<HalfedgeDescriptor>> lines;
  explicit operator bool() const { return status == Feature_polylines_read_status::ok; }
};

/// Reads polylines of vertex ids from `in` (the format above) as feature lines of `tm`.
template <typename PolygonMesh>
Feature_polylines_read_result<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor>
read_feature_polylines(std::istream& in, const PolygonMesh& tm) {
  using GT = boost::graph_traits<PolygonMesh>;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  const std::vector<typename GT::vertex_descriptor> vs(vertices(tm).begin(), vertices(tm).end());
  Feature_polylines_read_result<halfedge_descriptor> r;
  auto fail = [&](Feature_polylines_read_status s, std::size_t line, const std::string& what) {
    r.status = s;
    r.message = "line " + std::to_string(line) + ": " + what;
    r.lines.clear();
    return r;
  };
  std::string text, token;
  for (std::size_t number = 1; std::getline(in, text); ++number) {
    std::istringstream ls(text.substr(0, text.find('#')));
    std::vector<std::size_t> ids;
    while (ls >> token) {
      const internal::Vertex_id_token t = internal::parse_vertex_id(token, vs.size());
      if (!t.ok)
        return fail(t.out_of_range ? Feature_polylines_read_status::index_out_of_range
                                   : Feature_polylines_read_status::parse_error,
                    number, t.message);
      ids.push_back(t.id);
    }
    if (ids.empty())
      continue;
    if (ids.size() < 2)
      return fail(Feature_polylines_read_status::parse_error, number,
                  "a polyline needs two vertices or more");
    Feature_line<halfedge_descriptor> line;
    line.kind = Feature_kind::user;
    for (std::size_t k = 0; k + 1 < ids.size(); ++k) {
      const auto h = halfedge(vs[ids[k]], vs[ids[k + 1]], tm);
      if (!h.second)
        return fail(Feature_polylines_read_status::not_an_edge, number,
                    "vertices " + std::to_string(ids[k]) + " and " + std::to_string(ids[k + 1]) +
                        " share no edge");
      line.halfedges.push_back(h.first);
    }
    line.closed = ids.front() == ids.back();
    r.lines.push_back(std::move(line));
  }
  if (in.bad()) {
    r.status = Feature_polylines_read_status::parse_error;
    r.message = "read error";
    r.lines.clear();
    return r;
  }
  if (r.lines.empty()) {
    r.status = Feature_polylines_read_status::empty;
    r.message = "no polyline";
  }
  return r;
}

/// Reads a feature-polyline file (see `read_feature_polylines()`); messages start with the path.
template <typename PolygonMesh>
Feature_polylines_read_result<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor>
read_feature_polylines_file(const std::string& path, const PolygonMesh& tm) {
  std::ifstream in(path);
  if (!in) {
    Feature_polylines_read_result<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor> r;
    r.status = Feature_polylines_read_status::cannot_open;
    r.message = path + ": cannot open";
    return r;
  }
  auto r = read_feature_polylines(in, tm);
  if (!r)
    r.message = path + ": " + r.message;
  return r;
}

} // namespace tessera
