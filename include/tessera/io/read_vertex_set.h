// Reading a set of vertices from text (the texture regions a user marks for texture-preserving
// resizing, or any other per-vertex selection): whitespace-separated 0-based vertex ids in the
// order of `vertices(tm)`, '#' starting a comment to the end of its line.
#pragma once

#include <tessera/io/internal/vertex_ids.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <fstream>
#include <istream>
#include <sstream>
#include <string>
#include <vector>

namespace tessera {

enum class Vertex_set_read_status {
  ok,
  cannot_open,
  /// A token that is not a vertex id (the message gives its line).
  parse_error,
  index_out_of_range,
  /// The file names no vertex.
  empty
};

struct Vertex_set_read_result {
  Vertex_set_read_status status = Vertex_set_read_status::ok;
  std::string message;
  /// Distinct vertices marked.
  std::size_t count = 0;
  explicit operator bool() const { return status == Vertex_set_read_status::ok; }
};

/// Reads vertex ids from `in` and sets `marked` (a writable vertex map of bool) to true on them and
/// to false on every other vertex of `tm`. Nothing is written unless the whole input reads.
template <typename PolygonMesh, typename VertexMarkMap>
Vertex_set_read_result read_vertex_set(std::istream& in, const PolygonMesh& tm,
                                       VertexMarkMap marked) {
  const std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> vs(
      vertices(tm).begin(), vertices(tm).end());
  std::vector<char> chosen(vs.size(), 0);
  Vertex_set_read_result r;
  auto fail = [&](Vertex_set_read_status s, std::size_t line, const std::string& what) {
    r.status = s;
    r.message = "line " + std::to_string(line) + ": " + what;
    return r;
  };
  std::string line, token;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    std::istringstream ls(line.substr(0, line.find('#')));
    while (ls >> token) {
      const internal::Vertex_id_token t = internal::parse_vertex_id(token, vs.size());
      if (!t.ok)
        return fail(t.out_of_range ? Vertex_set_read_status::index_out_of_range
                                   : Vertex_set_read_status::parse_error,
                    number, t.message);
      r.count += chosen[t.id] ? 0 : 1;
      chosen[t.id] = 1;
    }
  }
  if (in.bad()) {
    r.status = Vertex_set_read_status::parse_error;
    r.message = "read error";
    return r;
  }
  if (r.count == 0) {
    r.status = Vertex_set_read_status::empty;
    r.message = "no vertex id";
    return r;
  }
  for (std::size_t i = 0; i < vs.size(); ++i)
    put(marked, vs[i], chosen[i] != 0);
  return r;
}

/// Reads a vertex-set file (see `read_vertex_set()`); messages start with the path.
template <typename PolygonMesh, typename VertexMarkMap>
Vertex_set_read_result read_vertex_set_file(const std::string& path, const PolygonMesh& tm,
                                            VertexMarkMap marked) {
  std::ifstream in(path);
  if (!in)
    return {Vertex_set_read_status::cannot_open, path + ": cannot open", 0};
  Vertex_set_read_result r = read_vertex_set(in, tm, marked);
  if (!r)
    r.message = path + ": " + r.message;
  return r;
}

} // namespace tessera
