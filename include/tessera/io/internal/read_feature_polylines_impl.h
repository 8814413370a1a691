// Implementation of tessera::read_feature_polylines (see tessera/io/read_feature_polylines.h).
#pragma once

#include <tessera/io/read_feature_polylines.h>

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
