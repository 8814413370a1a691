// Values, one per vertex in the order of vertices(tm), put into a vertex map (the readers of
// tessera/io/read_vertex_scalars.h, which includes this after its result types).
#pragma once

#include <tessera/io/read_vertex_scalars.h>

#include <cstddef>
#include <iterator>
#include <string>
#include <vector>

namespace tessera {

namespace internal {

template <typename PolygonMesh, typename VertexScalarMap>
Vertex_scalars_read_result put_vertex_scalars(const std::vector<double>& values,
                                              const PolygonMesh& tm, VertexScalarMap map) {
  const std::size_t nv = std::size_t(std::distance(vertices(tm).begin(), vertices(tm).end()));
  if (values.size() != nv)
    return {Vertex_scalars_read_status::wrong_count,
            std::to_string(values.size()) + " numbers for " + std::to_string(nv) + " vertices"};
  std::size_t i = 0;
  for (auto v : vertices(tm))
    put(map, v, values[i++]);
  return {};
}

} // namespace internal

} // namespace tessera
