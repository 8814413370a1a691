// Implementation of tessera::validate_cut (see tessera/topology/validate_cut.h).
#pragma once

#include <tessera/topology/validate_cut.h>

// Surface_mesh (the opened copy) must be known before CGAL::Seam_mesh is instantiated.
#include <CGAL/Surface_mesh.h>

#include <tessera/topology/open_mesh.h>
#include <tessera/validation/mesh_info.h>

#include <CGAL/Curves_on_surface_topology.h>
#include <CGAL/Path_on_surface.h>

#include <map>
#include <string>
#include <vector>

namespace tessera {

template <typename TriangleMesh, typename SeamEdgeMap, typename SeamVertexMap>
Cut_validation validate_cut(const TriangleMesh& tm, SeamEdgeMap seam_edges,
                            SeamVertexMap seam_vertices, const Cut_result<TriangleMesh>& result,
                            const Validate_cut_options& options) {
  using GT = boost::graph_traits<TriangleMesh>;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using Point = typename boost::property_traits<
      typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type>::value_type;
  Cut_validation v;

  // 1. Disks: the opened mesh has one component per polygon, each with chi = 1 and one boundary.
  CGAL::Surface_mesh<Point> opened;
  open_along_seams(tm, seam_edges, seam_vertices, opened);
  const Mesh_info info = mesh_info(opened, {false});
  v.opens_to_disks = info.components.size() == result.polygons.size();
  if (!v.opens_to_disks)
    v.problems.push_back("the opened mesh has " + std::to_string(info.components.size()) +
                         " components for " + std::to_string(result.polygons.size()) + " polygons");
  for (std::size_t c = 0; c < info.components.size(); ++c)
    if (info.components[c].euler_characteristic != 1 || info.components[c].boundary_loops != 1) {
      v.opens_to_disks = false;
      v.problems.push_back("opened component " + std::to_string(c) + " is not a disk (chi " +
                           std::to_string(info.components[c].euler_characteristic) + ", " +
                           std::to_string(info.components[c].boundary_loops) + " boundaries)");
    }

  auto is_cut = [&](halfedge_descriptor h) {
    return get(seam_edges, edge(h, tm)) || is_border_edge(h, tm);
  };
  const auto vim = CGAL::get_initialized_vertex_index_map(tm);
  std::vector<std::size_t> degree(std::size_t(num_vertices(tm)), 0);
  for (auto e : edges(tm))
    if (is_cut(halfedge(e, tm))) {
      ++degree[get(vim, source(halfedge(e, tm), tm))];
      ++degree[get(vim, target(halfedge(e, tm), tm))];
    }
  auto cut_degree = [&](vertex_descriptor v) { return degree[get(vim, v)]; };

  // 2. Side pairing, and 3. corners at branch points only.
  v.sides_paired = true;
  v.corners_are_branch_points = true;
  std::size_t side_halfedges = 0;
  for (std::size_t p = 0; p < result.polygons.size(); ++p) {
    const auto& poly = result.polygons[p];
    const auto& sides = poly.sides;
    const std::string where = "polygon " + std::to_string(p) + ": ";
    if (sides.size() != poly.corners.size() && !(sides.size() == 1 && poly.corners.empty())) {
      v.corners_are_branch_points = false;
      v.problems.push_back(where + "sides and corners do not match");
    }
    for (vertex_descriptor c : poly.corners)
      if (cut_degree(c) == 2) {
        v.corners_are_branch_points = false;
        v.problems.push_back(where + "a corner is not a branch point of the cut graph");
      }
    for (std::size_t i = 0; i < sides.size(); ++i) {
      const auto& s = sides[i];
      side_halfedges += s.size();
      if (target(s.back(), tm) != source(sides[(i + 1) % sides.size()].front(), tm)) {
        v.sides_paired = false;
        v.problems.push_back(where + "side " + std::to_string(i) +
                             " does not end where the next starts");
      }
      for (std::size_t k = 0; k + 1 < s.size(); ++k)
        if (cut_degree(target(s[k], tm)) != 2) {
          v.corners_are_branch_points = false;
          v.problems.push_back(where + "a branch point lies inside side " + std::to_string(i));
        }
      const bool along_border = is_border(opposite(s.front(), tm), tm);
      std::size_t partners = 0;
      for (const auto& t : sides) {
        if (t.size() != s.size())
          continue;
        bool reversed = true;
        for (std::size_t k = 0; k < s.size() && reversed; ++k)
          reversed = t[s.size() - 1 - k] == opposite(s[k], tm);
        partners += reversed ? 1 : 0;
      }
      if (partners != (along_border ? 0u : 1u)) {
        v.sides_paired = false;
        v.problems.push_back(where + "side " + std::to_string(i) + " has " +
                             std::to_string(partners) + " reversed partners");
      }
    }
  }
  // The sides walk the whole boundary of the opened mesh exactly once.
  std::size_t opened_border = 0;
  for (auto h : halfedges(opened))
    opened_border += is_border(h, opened) ? 1 : 0;
  if (side_halfedges != opened_border) {
    v.sides_paired = false;
    v.problems.push_back("the sides hold " + std::to_string(side_halfedges) +
                         " halfedges, the opened boundary " + std::to_string(opened_border));
  }

  // 4. Schema: 4g sides at the basepoint on closed components.
  v.schema_shape = true;
  if (result.method == Cut_method::schema)
    for (std::size_t p = 0; p < result.polygons.size(); ++p) {
      const auto& poly = result.polygons[p];
      if (poly.boundaries != 0 || poly.genus == 0)
        continue;
      bool all_at_base = true;
      for (vertex_descriptor c : poly.corners)
        all_at_base = all_at_base && c == poly.basepoint;
      if (poly.sides.size() != std::size_t(4 * poly.genus) || !all_at_base) {
        v.schema_shape = false;
        v.problems.push_back("polygon " + std::to_string(p) + ": a schema of genus " +
                             std::to_string(poly.genus) + " needs " +
                             std::to_string(4 * poly.genus) + " sides at the basepoint, got " +
                             std::to_string(poly.sides.size()));
      }
    }

  // 5. The canonical form, read again from the sides.
  if (result.canonical)
    for (std::size_t p = 0; p < result.polygons.size(); ++p) {
      const auto& poly = result.polygons[p];
      if (poly.genus <= 0)
        continue;
      internal::Schema_word word;
      std::vector<std::vector<halfedge_descriptor>> forward;
      std::size_t commutators = 0;
      if (internal::read_schema_word(tm, poly.sides, word, forward)) {
        for (std::size_t i = 0; i < word.size(); ++i) {
          if (internal::commutator_at(word, i) && i + 3 < word.size()) {
            ++commutators;
            i += 3;
          } else {
            break; // the commutators come first, in one run
          }
        }
      }
      if (commutators != std::size_t(poly.genus) ||
          (poly.boundaries == 0 && word.size() != std::size_t(4 * poly.genus))) {
        v.canonical_form = false;
        v.problems.push_back("polygon " + std::to_string(p) + ": the word " +
                             internal::word_text(word) + " is not canonical (" +
                             std::to_string(commutators) + " commutators from its first side, " +
                             "genus " + std::to_string(poly.genus) + ")");
      }
    }

  // 6. Non-contractible schema loops (each side of a schema polygon is a loop at the basepoint).
  if (options.check_loops_non_contractible && result.method == Cut_method::schema) {
    CGAL::Surface_mesh_topology::Curves_on_surface_topology<TriangleMesh> cst(tm);
    for (const auto& poly : result.polygons)
      for (const auto& side : poly.sides) {
        if (source(side.front(), tm) != target(side.back(), tm))
          continue;
        CGAL::Surface_mesh_topology::Path_on_surface<TriangleMesh> path(tm);
        for (halfedge_descriptor h : side)
          path.push_back(h);
        if (cst.is_contractible(path)) {
          v.loops_non_contractible = false;
          v.problems.push_back("a schema loop is contractible");
        }
      }
  }
  const bool valid = v.opens_to_disks && v.sides_paired && v.corners_are_branch_points &&
                     v.schema_shape && v.loops_non_contractible && v.canonical_form;
  v.status = valid ? Cut_validation_status::valid : Cut_validation_status::invalid;
  v.message = v.problems.empty() ? (valid ? "valid" : "invalid") : v.problems.front();
  return v;
}

} // namespace tessera
