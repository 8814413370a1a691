// Implementation of tessera::read_ply_vertex_scalars (see tessera/io/read_vertex_scalars.h).
#pragma once

#include <tessera/io/read_vertex_scalars.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/Simple_cartesian.h>
#include <boost/graph/graph_traits.hpp>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <istream>
#include <sstream>
#include <string>
#include <vector>
#include <tessera/io/internal/vertex_scalars.h>

namespace tessera {

template <typename PolygonMesh, typename VertexScalarMap>
Vertex_scalars_read_result read_vertex_scalars(std::istream& in, const PolygonMesh& tm,
                                               VertexScalarMap map) {
  std::vector<double> values;
  std::string line, token;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    std::istringstream ls(line.substr(0, line.find('#')));
    while (ls >> token) {
      std::size_t used = 0;
      double x = 0;
      try {
        x = std::stod(token, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != token.size() || !std::isfinite(x))
        return {Vertex_scalars_read_status::parse_error, "line " + std::to_string(number) + ": '" +
                                                             token.substr(0, 40) +
                                                             "' is not a finite number"};
      values.push_back(x);
    }
  }
  if (in.bad())
    return {Vertex_scalars_read_status::parse_error, "read error"};
  return internal::put_vertex_scalars(values, tm, map);
}

template <typename PolygonMesh, typename VertexScalarMap>
Vertex_scalars_read_result read_ply_vertex_scalars(const std::string& path, const std::string& name,
                                                   const PolygonMesh& tm, VertexScalarMap map) {
  using Ply_mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;
  std::ifstream in(path, std::ios::binary);
  if (!in)
    return {Vertex_scalars_read_status::cannot_open, path + ": cannot open"};
  Ply_mesh ply;
  std::string comments;
  bool read = false;
  try {
    read = CGAL::IO::read_PLY(in, ply, comments, false);
  } catch (const std::exception&) {
    read = false;
  }
  if (!read)
    return {Vertex_scalars_read_status::parse_error, path + ": not a PLY file CGAL reads"};
  std::vector<double> values;
  auto take = [&](auto tag) {
    using T = decltype(tag);
    const auto found = ply.template property_map<Ply_mesh::Vertex_index, T>("v:" + name);
    if (!found.second)
      return false;
    for (auto v : vertices(ply))
      values.push_back(double(get(found.first, v)));
    return true;
  };
  if (!(take(float()) || take(double()) || take(std::int8_t()) || take(std::uint8_t()) ||
        take(std::int16_t()) || take(std::uint16_t()) || take(std::int32_t()) ||
        take(std::uint32_t()))) {
    std::string have;
    for (const std::string& p : ply.properties<Ply_mesh::Vertex_index>())
      if (p.rfind("v:", 0) == 0 && p != "v:connectivity" && p != "v:removed" && p != "v:point")
        have += (have.empty() ? "" : ", ") + p.substr(2);
    return {Vertex_scalars_read_status::no_such_property,
            path + ": no vertex property '" + name + "'" +
                (have.empty() ? std::string(" (it has none)") : " (it has: " + have + ")")};
  }
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i]))
      return {Vertex_scalars_read_status::parse_error,
              path + ": vertex " + std::to_string(i) + " has a non-finite " + name};
  Vertex_scalars_read_result r = internal::put_vertex_scalars(values, tm, map);
  if (!r)
    r.message = path + ": " + r.message +
                " (the mesh was repaired on reading: give the values "
                "as a text file of the repaired mesh's vertices)";
  return r;
}

template <typename PolygonMesh, typename VertexScalarMap>
Vertex_scalars_read_result read_vertex_scalars_file(const std::string& path, const PolygonMesh& tm,
                                                    VertexScalarMap map) {
  std::ifstream in(path);
  if (!in)
    return {Vertex_scalars_read_status::cannot_open, path + ": cannot open"};
  Vertex_scalars_read_result r = read_vertex_scalars(in, tm, map);
  if (!r)
    r.message = path + ": " + r.message;
  return r;
}

} // namespace tessera
