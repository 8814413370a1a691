// Reading feature lines a user draws (`tessera field` and `tessera mosaic --feature-file`): one
// polyline per text line, as whitespace-separated 0-based vertex ids in the order of
// `vertices(tm)`, each two consecutive ones joined by an edge of the mesh; a line that ends where
// it starts is closed; '#' starts a comment to the end of its line. The lines come back as
// `Feature_line`s of kind `Feature_kind::user`, which `feature_alignment_constraints()` and the
// mosaics take like detected ones.
#pragma once

#include <tessera/fields/feature_lines.h>

#include <boost/graph/graph_traits.hpp>

#include <istream>
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
read_feature_polylines(std::istream& in, const PolygonMesh& tm);

/// Reads a feature-polyline file (see `read_feature_polylines()`); messages start with the path.
template <typename PolygonMesh>
Feature_polylines_read_result<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor>
read_feature_polylines_file(const std::string& path, const PolygonMesh& tm);

} // namespace tessera

#include <tessera/io/internal/read_feature_polylines_impl.h>
