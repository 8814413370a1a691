// Names of the topology module's choices as the command line, reports, benchmarks and tests spell
// them (`tessera cut --method schema --cost curvature`): one table per enum, which both the parser
// and the printer read, so that the two cannot drift apart.
#pragma once

#include <tessera/internal/enum_names.h>
#include <tessera/topology/cut_graph.h>
#include <tessera/topology/edge_cost.h>
#include <tessera/topology/parameterize_tiles.h>

#include <optional>
#include <string_view>

namespace tessera {

/// Every cut method and its name, in the order the manual lists them.
inline constexpr internal::Enum_names<Cut_method, 3> cut_method_names{
    {{Cut_method::greedy, "greedy"},
     {Cut_method::schema, "schema"},
     {Cut_method::intermediate, "intermediate"}}};

/// Every edge cost kind and its name.
inline constexpr internal::Enum_names<Edge_cost_kind, 2> edge_cost_kind_names{
    {{Edge_cost_kind::euclidean, "euclidean"}, {Edge_cost_kind::curvature, "curvature"}}};

/// Every quad interior map and its name (`tessera quadrangulate --interior`).
inline constexpr internal::Enum_names<Quad_interior, 2> quad_interior_names{
    {{Quad_interior::mean_value, "mean-value"}, {Quad_interior::discrete_conformal, "conformal"}}};

/// "greedy", "schema" or "intermediate".
inline const char* to_string(Cut_method method) {
  return internal::enum_name(cut_method_names, method);
}

/// The cut method called `name` (exactly, in lower case), or nothing for any other name.
inline std::optional<Cut_method> parse_cut_method(std::string_view name) {
  return internal::enum_value(cut_method_names, name);
}

/// "euclidean" or "curvature".
inline const char* to_string(Edge_cost_kind kind) {
  return internal::enum_name(edge_cost_kind_names, kind);
}

/// The edge cost kind called `name` (exactly, in lower case), or nothing for any other name.
inline std::optional<Edge_cost_kind> parse_edge_cost_kind(std::string_view name) {
  return internal::enum_value(edge_cost_kind_names, name);
}

} // namespace tessera
