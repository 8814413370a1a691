// Implementation of tessera::cut_to_disk (see tessera/topology/cut_graph.h).
#pragma once

#include <tessera/topology/cut_graph.h>
#include <tessera/topology/unstick_loops.h>

#include <cmath>
#include <memory>

namespace tessera {

template <typename TriangleMesh, typename EdgeCostMap, typename SeamEdgeMap, typename SeamVertexMap,
          typename NamedParameters>
Cut_result<TriangleMesh> cut_to_disk(TriangleMesh& tm, EdgeCostMap cost, SeamEdgeMap seam_edges,
                                     SeamVertexMap seam_vertices, const Cut_options& options,
                                     const NamedParameters& np) {
  const auto vpm = internal::writable_vertex_point_map(tm, np);
  using GT = boost::graph_traits<TriangleMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using face_descriptor = typename GT::face_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using edge_descriptor = typename GT::edge_descriptor;

  Cut_result<TriangleMesh> result;
  result.method = options.method;
  // As in CGAL, validity of the halfedge structure is a precondition (checked in debug builds:
  // it costs as much as a third of the cut itself); `read_mesh()` guarantees it for files.
  CGAL_precondition(CGAL::is_valid_polygon_mesh(tm));
  if (!CGAL::is_triangle_mesh(tm)) {
    result.status = Cut_status::invalid_mesh;
    result.message = "the mesh is not a triangle mesh";
    return result;
  }

  // Components (the tiles of the uncut mesh), their basepoints, genus and boundaries.
  const M_tiling<TriangleMesh> uncut(tm);
  std::vector<face_descriptor> component_face(uncut.number_of_tiles(), GT::null_face());
  std::vector<vertex_descriptor> basepoints(component_face.size(), GT::null_vertex());
  for (face_descriptor f : faces(tm)) {
    const std::size_t c = uncut.tile_of(f);
    if (component_face[c] == GT::null_face())
      component_face[c] = f;
  }
  for (vertex_descriptor v : vertices(tm)) {
    if (halfedge(v, tm) == GT::null_halfedge())
      continue;
    const halfedge_descriptor h = halfedge(v, tm);
    const std::size_t c = uncut.tile_of(face(is_border(h, tm) ? opposite(h, tm) : h, tm));
    if (basepoints[c] == GT::null_vertex())
      basepoints[c] = v;
  }
  if (options.basepoint) {
    const std::size_t basepoint = *options.basepoint;
    if (basepoint >= std::size_t(num_vertices(tm))) {
      result.status = Cut_status::invalid_basepoint;
      result.message = "basepoint " + std::to_string(basepoint) +
                       " is not a vertex index (the mesh has " + std::to_string(num_vertices(tm)) +
                       " vertices)";
      return result;
    }
    const auto vim = CGAL::get_initialized_vertex_index_map(tm);
    for (vertex_descriptor v : vertices(tm))
      if (std::size_t(get(vim, v)) == basepoint) {
        if (halfedge(v, tm) == GT::null_halfedge() || is_border(v, tm)) {
          result.status = Cut_status::invalid_basepoint;
          result.message = "basepoint " + std::to_string(basepoint) +
                           " must be an interior vertex of the surface";
          return result;
        }
        basepoints[uncut.tile_of(face(halfedge(v, tm), tm))] = v;
      }
  }
  // A basepoint on a border would make every loop touch the boundary: move it inside.
  for (std::size_t c = 0; c < basepoints.size(); ++c)
    if (is_border(basepoints[c], tm))
      for (vertex_descriptor v : vertices_around_face(halfedge(component_face[c], tm), tm))
        if (!is_border(v, tm))
          basepoints[c] = v;

  // The greedy systems of loops, one per component of positive genus, shared by the strategies.
  std::vector<System_of_loops<TriangleMesh>> systems(basepoints.size());
  const auto components = uncut.tiles_without_faces();
  const std::size_t n = basepoints.size();
  report_progress(options.progress, "systems of loops", 0, n);
  for (std::size_t c = 0; c < basepoints.size(); ++c) {
    const auto& tile = components[uncut.tile_of(component_face[c])];
    Cut_polygon<TriangleMesh> polygon;
    polygon.basepoint = basepoints[c];
    polygon.genus = tile.genus;
    polygon.boundaries = tile.boundaries.size();
    result.polygons.push_back(polygon);
    if (tile.genus > 0)
      systems[c] = greedy_system_of_loops(tm, basepoints[c], cost);
    report_progress(options.progress, "systems of loops", c + 1, n);
  }

  // The schema's loops share stems and touch: refine the mesh around them so that they become
  // disjoint except at the basepoint (Favreau et al. §3.3.1). Edges the refinement adds cost their
  // Euclidean length.
  if (options.method == Cut_method::schema) {
    const std::size_t old_edges = std::size_t(num_edges(tm));
    for (std::size_t c = 0; c < basepoints.size(); ++c) {
      report_progress(options.progress, "schema loops made disjoint", c, n);
      if (systems[c].loops.empty())
        continue;
      auto refined = unstick_loops(tm, systems[c], Unstick_options{}, np);
      if (!refined) {
        result.status = Cut_status::refinement_failed;
        result.message = "the schema's loops could not be made disjoint: " + refined.message;
        return result;
      }
      result.added_vertices += refined.new_vertices.size();
      systems[c].loops = std::move(refined.loops);
    }
    report_progress(options.progress, "schema loops made disjoint", n, n);
    if (result.added_vertices > 0) {
      // Meshes that store indices in their elements (Polyhedron_items_with_id_3) number the new
      // elements (appended last, so the new edges keep the highest indices); for Surface_mesh this
      // does nothing.
      CGAL::get_initialized_vertex_index_map(tm);
      CGAL::get_initialized_halfedge_index_map(tm);
      CGAL::get_initialized_face_index_map(tm);
      const auto eim = CGAL::get_initialized_edge_index_map(tm);
      for (edge_descriptor e : edges(tm))
        if (std::size_t(get(eim, e)) >= old_edges) {
          const auto h = halfedge(e, tm);
          put(cost, e,
              std::sqrt(CGAL::to_double(
                  CGAL::squared_distance(get(vpm, source(h, tm)), get(vpm, target(h, tm))))));
        }
      // Faces were split: name each component by a face at its basepoint.
      for (std::size_t c = 0; c < basepoints.size(); ++c) {
        const halfedge_descriptor h = halfedge(basepoints[c], tm);
        component_face[c] = face(is_border(h, tm) ? opposite(h, tm) : h, tm);
      }
    }
  }
  double total_cost = 0;
  for (edge_descriptor e : edges(tm))
    total_cost += double(get(cost, e));

  bool schema_loops_cut = true;
  auto cut_with = [&](M_tiling<TriangleMesh>& tiling, internal::Loop_order order) {
    internal::Cut_graph_builder<TriangleMesh, EdgeCostMap> builder(tiling, cost);
    for (std::size_t c = 0; c < basepoints.size(); ++c) {
      if (result.polygons[c].genus > 0 && options.method == Cut_method::schema) {
        // Disjoint loops through the basepoint: the first is closed, the others run from the
        // basepoint back to it across the cut made so far.
        for (const auto& loop : systems[c].loops)
          schema_loops_cut = schema_loops_cut && tiling.cut(loop) == Cut_path_status::ok;
      } else if (result.polygons[c].genus > 0) {
        builder.lower_genus(systems[c].loops, result.polygons[c].genus, order);
      } else if (result.polygons[c].boundaries == 0) {
        builder.slit_sphere(basepoints[c]);
      }
    }
    // The schema and Alg. 3 join boundaries preferably at existing multipoints (for the schema, the
    // basepoint), so that few corners are added.
    builder.join_boundaries(options.method == Cut_method::greedy ? 0.0 : total_cost);
    tiling.clear_marks();
  };
  auto seam_cost = [&](const M_tiling<TriangleMesh>& tiling) {
    double sum = 0;
    for (edge_descriptor e : tiling.seam_edges())
      sum += double(get(cost, e));
    return sum;
  };

  // Greedy: two cuts, the loops in two orders, the shorter kept.
  const std::size_t cuts = options.method == Cut_method::greedy ? 2 : 1;
  report_progress(options.progress, "cut graphs", 0, cuts);
  auto best = std::make_unique<M_tiling<TriangleMesh>>(tm);
  cut_with(*best, internal::Loop_order::genus_lowering_first);
  report_progress(options.progress, "cut graphs", 1, cuts);
  if (options.method == Cut_method::greedy) {
    auto plain = std::make_unique<M_tiling<TriangleMesh>>(tm);
    cut_with(*plain, internal::Loop_order::all_pieces);
    report_progress(options.progress, "cut graphs", 2, cuts);
    if (seam_cost(*plain) < seam_cost(*best)) {
      best = std::move(plain);
      result.used_system_of_loops = true;
    }
  }
  M_tiling<TriangleMesh>& tiling = *best;
  if (!schema_loops_cut) {
    result.status = Cut_status::refinement_failed;
    result.message = "a refined schema loop could not be cut (it crosses an earlier loop)";
  }

  // The canonical schema: cut-and-paste on each polygon of positive genus.
  std::vector<halfedge_descriptor> first_side(basepoints.size(), GT::null_halfedge());
  result.canonical = options.canonical && options.method == Cut_method::schema && schema_loops_cut;
  if (result.canonical)
    for (std::size_t c = 0; c < basepoints.size(); ++c) {
      report_progress(options.progress, "canonical schema moves", c, n);
      if (result.polygons[c].genus <= 0)
        continue;
      const auto canonical = internal::make_schema_canonical(
          tm, tiling, component_face[c], result.polygons[c].genus, cost, options.cost, vpm);
      if (!canonical.ok) {
        result.status = Cut_status::canonical_failed;
        result.canonical = false;
        result.message = "component " + std::to_string(c) + ": " + canonical.message;
        break;
      }
      result.canonical_moves += canonical.moves;
      result.added_vertices += canonical.added_vertices;
      first_side[c] = canonical.first_side;
    }
  if (result.canonical)
    report_progress(options.progress, "canonical schema moves", n, n);

  // Read the polygons off the final tiling and check each component opened into one disk.
  const auto tiles = tiling.tiles_without_faces();
  for (std::size_t c = 0; c < basepoints.size(); ++c) {
    const auto& tile = tiles[tiling.tile_of(component_face[c])];
    if (tile.boundaries.size() != 1 || tile.genus != 0) {
      result.status = Cut_status::not_a_disk;
      result.message = "component " + std::to_string(c) + " did not open into a disk (" +
                       std::to_string(tile.boundaries.size()) + " boundaries, genus " +
                       std::to_string(tile.genus) + ")";
    }
    auto& polygon = result.polygons[c];
    for (const auto& side : tile.sides) {
      polygon.sides.push_back(side.halfedges);
      if (tiling.is_multipoint(source(side.halfedges.front(), tm)))
        polygon.corners.push_back(source(side.halfedges.front(), tm));
    }
    // A canonical polygon starts at its first commutator.
    for (std::size_t i = 0; first_side[c] != GT::null_halfedge() && i < polygon.sides.size(); ++i)
      if (polygon.sides[i].front() == first_side[c] &&
          polygon.corners.size() == polygon.sides.size()) {
        std::rotate(polygon.sides.begin(), polygon.sides.begin() + long(i), polygon.sides.end());
        std::rotate(polygon.corners.begin(), polygon.corners.begin() + long(i),
                    polygon.corners.end());
        break;
      }
    polygon.word = internal::polygon_word(tm, polygon.sides);
  }
  for (vertex_descriptor v : vertices(tm))
    if (tiling.is_multipoint(v))
      result.multipoints.push_back(v);
  result.cut_cost = seam_cost(tiling);
  for (edge_descriptor e : tiling.seam_edges()) {
    const auto h = halfedge(e, tm);
    result.cut_length += std::sqrt(
        CGAL::to_double(CGAL::squared_distance(get(vpm, source(h, tm)), get(vpm, target(h, tm)))));
  }
  tiling.export_seams(seam_edges, seam_vertices);
  return result;
}

} // namespace tessera
