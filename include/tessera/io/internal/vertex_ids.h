// parse_vertex_id(): one token of a file of 0-based vertex ids, checked against the vertex count,
// shared by read_vertex_set() (tessera/io/read_vertex_set.h) and read_feature_polylines()
// (tessera/io/read_feature_polylines.h).
#pragma once

#include <cstddef>
#include <string>

namespace tessera::internal {

/// One token of a file of vertex ids (here and in `read_feature_polylines()`): a 0-based id below
/// `vertices`, or what is wrong with it.
struct Vertex_id_token {
  std::size_t id = 0;
  bool ok = false, out_of_range = false;
  std::string message;
};

inline Vertex_id_token parse_vertex_id(const std::string& token, std::size_t vertices) {
  Vertex_id_token t;
  if (token.size() > 19 || token.find_first_not_of("0123456789") != std::string::npos) {
    t.message = "'" + token.substr(0, 40) + "' is not a vertex id";
    return t;
  }
  const unsigned long long id = std::stoull(token);
  if (id >= vertices) {
    t.out_of_range = true;
    t.message = "vertex ids must be below " + std::to_string(vertices);
    return t;
  }
  t.id = std::size_t(id), t.ok = true;
  return t;
}

} // namespace tessera::internal
