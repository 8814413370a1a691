// The body of topology/unstick_loops.h's unstick_loops() (Favreau et al. 2009, §3.3.1 and §4.2):
// centroids in crowded faces, the strands' points inserted on the edges they cross, the loops
// joined inside faces and the split faces triangulated. Included at the end of the public header.
#pragma once

#include <tessera/topology/unstick_loops.h>

#include <tessera/topology/internal/loop_strands.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace tessera {

template <typename TriangleMesh, typename NamedParameters>
Unstick_result<TriangleMesh>
unstick_loops(TriangleMesh& tm, const System_of_loops<TriangleMesh>& sys,
              const Unstick_options& options, const NamedParameters& np) {
  using GT = boost::graph_traits<TriangleMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using edge_descriptor = typename GT::edge_descriptor;
  using face_descriptor = typename GT::face_descriptor;
  auto vpm = internal::writable_vertex_point_map(tm, np);
  using Point = typename boost::property_traits<decltype(vpm)>::value_type;
  using FT = typename CGAL::Kernel_traits<Point>::Kernel::FT;

  Unstick_result<TriangleMesh> result;
  auto stop = [&](Unstick_status status, std::string message) {
    result.status = status;
    result.message = std::move(message);
    return result;
  };
  if (!(options.outer_offset > 0 && options.outer_offset < 0.5))
    return stop(Unstick_status::invalid_input, "outer_offset must lie in (0, 1/2)");
  if (sys.loops.empty())
    return result;
  if (!CGAL::is_triangle_mesh(tm))
    return stop(Unstick_status::invalid_input, "the mesh is not triangulated");
  internal::Loop_strands<TriangleMesh> strands(tm, sys);
  if (!strands.valid)
    return stop(Unstick_status::invalid_input, strands.message);
  // The refinement below adds no edge at the border, so a vertex the strands cannot turn around is
  // found here, before the mesh is touched.
  if (!strands.route(sys.basepoint))
    return stop(Unstick_status::invalid_input, strands.message);
  const std::size_t faces_before = std::size_t(num_faces(tm));

  // The scratch data below are hash maps over the elements near the loops, not property maps over
  // the whole mesh: the refinement then costs what the loops cost (a dynamic property map would
  // allocate and fill an array per element kind, and move it when the mesh grows).
  // new_vertices index + 1 of every added vertex; the original ones are absent.
  std::unordered_map<vertex_descriptor, std::size_t> slot;
  auto slot_of = [&](vertex_descriptor v) {
    const auto s = slot.find(v);
    return s == slot.end() ? std::size_t(0) : s->second;
  };
  auto record = [&](vertex_descriptor v, const Point& p,
                    const std::array<vertex_descriptor, 3>& support) {
    put(vpm, v, p);
    result.new_vertices.push_back({v, support});
    slot[v] = result.new_vertices.size();
  };

  // A face with two cut edges leaves no edge to cross between them for a strand turning there: put
  // a vertex at its centroid, so every face at a path vertex has at most one cut edge.
  const std::unordered_set<edge_descriptor> cut(strands.cut_edges.begin(), strands.cut_edges.end());
  std::unordered_set<face_descriptor> crowded;
  std::vector<face_descriptor> to_split;
  for (edge_descriptor e : strands.cut_edges)
    for (halfedge_descriptor h : {halfedge(e, tm), opposite(halfedge(e, tm), tm)}) {
      if (is_border(h, tm) || crowded.count(face(h, tm)) > 0)
        continue;
      int cut_sides = 0;
      for (halfedge_descriptor s : CGAL::halfedges_around_face(h, tm))
        cut_sides += int(cut.count(edge(s, tm)));
      if (cut_sides < 2)
        continue;
      crowded.insert(face(h, tm));
      to_split.push_back(face(h, tm));
    }
  for (face_descriptor f : to_split) {
    const halfedge_descriptor h = halfedge(f, tm);
    const std::array<vertex_descriptor, 3> corners = {target(h, tm), target(next(h, tm), tm),
                                                      source(h, tm)};
    const Point c =
        CGAL::centroid(get(vpm, corners[0]), get(vpm, corners[1]), get(vpm, corners[2]));
    record(target(CGAL::Euler::add_center_vertex(h, tm), tm), c, corners);
  }
  strands.route(sys.basepoint); // succeeds as above: the centroids changed no border

  // Points to insert on edges: a crossing (c, level) of a strand is the point at offset
  // λ = outer_offset * level / n from source(c) along c; the generator of loop i is split at its
  // midpoint. Order along an edge's reference halfedge: points measured from its source (level
  // increasing), the midpoint, then points measured from its target (level decreasing).
  const std::size_t n = strands.strands.size();
  struct Edge_point {
    std::size_t strand; // strand index, or n + loop index for a generator midpoint
    std::size_t index;  // position in the strand's crossings
    std::size_t level;
    std::pair<int, std::size_t> key;
  };
  // Per split edge, the halfedge its points are ordered along (compared by descriptor: an edge
  // descriptor may remember either of its halfedges) and the points.
  std::vector<std::pair<halfedge_descriptor, std::vector<Edge_point>>> per_edge;
  std::unordered_map<edge_descriptor, std::size_t> group; // index in per_edge
  auto add_point = [&](halfedge_descriptor from, std::size_t strand, std::size_t index,
                       std::size_t level) {
    const auto [at, added] = group.emplace(edge(from, tm), per_edge.size());
    if (added)
      per_edge.push_back({from, {}});
    auto& [along, points] = per_edge[at->second];
    const bool forward = along == from;
    const std::pair<int, std::size_t> key = strand >= n ? std::make_pair(1, std::size_t(0))
                                            : forward   ? std::make_pair(0, level)
                                                        : std::make_pair(2, n + 1 - level);
    points.push_back({strand, index, level, key});
  };
  for (std::size_t s = 0; s < n; ++s)
    for (std::size_t k = 0; k < strands.strands[s].crossings.size(); ++k)
      add_point(strands.strands[s].crossings[k].first, s, k,
                strands.strands[s].crossings[k].second);
  for (std::size_t i = 0; i < sys.loops.size(); ++i)
    add_point(strands.strands[2 * i].exit, n + i, 0, 0);

  std::vector<std::vector<vertex_descriptor>> crossing_vertices(n);
  for (std::size_t s = 0; s < n; ++s)
    crossing_vertices[s].resize(strands.strands[s].crossings.size());
  std::vector<vertex_descriptor> midpoints(sys.loops.size());
  for (auto& [h, points] : per_edge) {
    std::sort(points.begin(), points.end(),
              [](const Edge_point& a, const Edge_point& b) { return a.key < b.key; });
    // Splitting h inserts a vertex before its target: h stays the piece that ends at y.
    const vertex_descriptor x = source(h, tm), y = target(h, tm);
    const Point px = get(vpm, x), py = get(vpm, y);
    for (const Edge_point& ep : points) {
      const vertex_descriptor v = target(CGAL::Euler::split_edge(h, tm), tm);
      if (ep.strand >= n) {
        record(v, CGAL::midpoint(px, py), {x, y, GT::null_vertex()});
        midpoints[ep.strand - n] = v;
        continue;
      }
      const bool forward = ep.key.first == 0;
      const vertex_descriptor near = forward ? x : y, far = forward ? y : x;
      const Point& p = forward ? px : py;
      const Point& q = forward ? py : px;
      // A point on an edge to a centroid lies inside the original face that centroid split.
      const std::array<vertex_descriptor, 3> support =
          slot_of(far) == 0 ? std::array<vertex_descriptor, 3>{near, far, GT::null_vertex()}
                            : result.new_vertices[slot_of(far) - 1].support;
      const FT lambda = FT(options.outer_offset) * FT(double(ep.level)) / FT(double(n));
      record(v, p + lambda * (q - p), support);
      crossing_vertices[ep.strand][ep.index] = v;
    }
  }

  // Join consecutive points of every loop inside the face they share.
  auto join = [&](vertex_descriptor p, vertex_descriptor q) {
    const std::pair<halfedge_descriptor, bool> existing = halfedge(p, q, tm);
    if (existing.second)
      return existing.first;
    for (halfedge_descriptor h : CGAL::halfedges_around_target(p, tm)) {
      if (is_border(h, tm))
        continue;
      for (halfedge_descriptor g : CGAL::halfedges_around_face(h, tm))
        if (target(g, tm) == q)
          return CGAL::Euler::split_face(h, g, tm);
    }
    return GT::null_halfedge();
  };
  for (std::size_t i = 0; i < sys.loops.size(); ++i) {
    std::vector<vertex_descriptor> points{sys.basepoint};
    points.insert(points.end(), crossing_vertices[2 * i].begin(), crossing_vertices[2 * i].end());
    points.push_back(midpoints[i]);
    points.insert(points.end(), crossing_vertices[2 * i + 1].rbegin(),
                  crossing_vertices[2 * i + 1].rend());
    points.push_back(sys.basepoint);
    std::vector<halfedge_descriptor> loop;
    for (std::size_t k = 0; k + 1 < points.size(); ++k) {
      loop.push_back(join(points[k], points[k + 1]));
      if (loop.back() == GT::null_halfedge())
        return stop(Unstick_status::failed, "internal error: consecutive points of loop " +
                                                std::to_string(i) + " share no face");
    }
    result.loops.push_back(std::move(loop));
  }

  // Only faces at new vertices can have more than 3 sides; they are triangulated in face order.
  const auto fim = CGAL::get_initialized_face_index_map(tm);
  std::vector<face_descriptor> polygons;
  for (const auto& added : result.new_vertices)
    for (face_descriptor f : CGAL::faces_around_target(halfedge(added.vertex, tm), tm))
      if (f != GT::null_face() && CGAL::halfedges_around_face(halfedge(f, tm), tm).size() > 3)
        polygons.push_back(f);
  std::sort(polygons.begin(), polygons.end(),
            [&](face_descriptor a, face_descriptor b) { return get(fim, a) < get(fim, b); });
  polygons.erase(std::unique(polygons.begin(), polygons.end()), polygons.end());
  if (!CGAL::Polygon_mesh_processing::triangulate_faces(polygons, tm,
                                                        CGAL::parameters::vertex_point_map(vpm)))
    return stop(Unstick_status::failed, "a refined face could not be triangulated");
  result.new_faces = std::size_t(num_faces(tm)) - faces_before;
  return result;
}

} // namespace tessera
