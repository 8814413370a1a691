// Reading one number per vertex (the tile size of `tessera mosaic --tile-size-field`, or any other
// per-vertex scalar): from text, whitespace-separated numbers in the order of `vertices(tm)`, '#'
// starting a comment to the end of its line; or from a vertex property of a PLY file (CGAL's
// Surface_mesh PLY reader keeps every property it does not know as a property map "v:NAME").
#pragma once

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <istream>
#include <string>
#include <vector>

namespace tessera {

enum class Vertex_scalars_read_status {
  ok,
  cannot_open,
  /// A token that is not a finite number (the message gives its line).
  parse_error,
  /// Not one number per vertex of the mesh.
  wrong_count,
  /// A PLY file without that vertex property (the message lists the ones it has).
  no_such_property
};

struct Vertex_scalars_read_result {
  Vertex_scalars_read_status status = Vertex_scalars_read_status::ok;
  std::string message;
  explicit operator bool() const { return status == Vertex_scalars_read_status::ok; }
};

/// Reads one number per vertex of `tm` from `in` into `map` (a writable vertex map of double);
/// nothing is written unless the whole input reads.
template <typename PolygonMesh, typename VertexScalarMap>
Vertex_scalars_read_result read_vertex_scalars(std::istream& in, const PolygonMesh& tm,
                                               VertexScalarMap map);

/// Reads vertex property `name` of the PLY file `path` (any numeric type) into `map`, one value
/// per vertex of `tm`, which must have the file's vertices in the file's order; messages start
/// with the path.
template <typename PolygonMesh, typename VertexScalarMap>
Vertex_scalars_read_result read_ply_vertex_scalars(const std::string& path, const std::string& name,
                                                   const PolygonMesh& tm, VertexScalarMap map);

/// Reads a text file of per-vertex numbers (see `read_vertex_scalars()`); messages start with the
/// path.
template <typename PolygonMesh, typename VertexScalarMap>
Vertex_scalars_read_result read_vertex_scalars_file(const std::string& path, const PolygonMesh& tm,
                                                    VertexScalarMap map);

} // namespace tessera

#include <tessera/io/internal/read_vertex_scalars_impl.h>
