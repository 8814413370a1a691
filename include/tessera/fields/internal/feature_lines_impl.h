// Implementation of tessera::feature_lines (see tessera/fields/feature_lines.h).
#pragma once

#include <tessera/fields/feature_lines.h>

#include <tessera/fields/smoothest_field.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/boost/graph/helpers.h>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace tessera {

template <typename TriangleMesh, typename FaceRegion, typename NamedParameters>
std::vector<Feature_line<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>>
feature_lines(const TriangleMesh& tm, const Feature_line_options& options, FaceRegion face_region,
              const NamedParameters& np) {
  using GT = boost::graph_traits<TriangleMesh>;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using vertex_descriptor = typename GT::vertex_descriptor;
  auto sharp = get(CGAL::dynamic_edge_property_t<bool>(), tm);
  for (auto e : edges(tm))
    put(sharp, e, false);
  if (options.creases)
    CGAL::Polygon_mesh_processing::detect_sharp_edges(
        tm, options.crease_angle_degrees, sharp,
        CGAL::parameters::vertex_point_map(internal::vertex_point_map(tm, np)));
  // Kind of each edge: -1 when it is no feature.
  auto kind = get(CGAL::dynamic_edge_property_t<int>(), tm);
  auto degree = get(CGAL::dynamic_vertex_property_t<int>(), tm);
  for (auto v : vertices(tm))
    put(degree, v, 0);
  for (auto e : edges(tm)) {
    const halfedge_descriptor h = halfedge(e, tm);
    int k = -1;
    if (is_border(e, tm)) {
      if (options.boundary)
        k = int(Feature_kind::boundary);
    } else if (get(sharp, e)) {
      k = int(Feature_kind::crease);
    } else if (options.color_boundaries &&
               face_region(face(h, tm)) != face_region(face(opposite(h, tm), tm))) {
      k = int(Feature_kind::color_boundary);
    }
    put(kind, e, k);
    if (k >= 0) {
      put(degree, source(h, tm), get(degree, source(h, tm)) + 1);
      put(degree, target(h, tm), get(degree, target(h, tm)) + 1);
    }
  }
  auto visited = get(CGAL::dynamic_edge_property_t<bool>(), tm);
  for (auto e : edges(tm))
    put(visited, e, false);
  // The feature halfedge leaving v that continues `h` (same kind), or null where the line must end.
  auto continuation = [&](halfedge_descriptor h) {
    const vertex_descriptor v = target(h, tm);
    if (get(degree, v) != 2)
      return GT::null_halfedge();
    for (halfedge_descriptor g : CGAL::halfedges_around_source(v, tm))
      if (edge(g, tm) != edge(h, tm) && get(kind, edge(g, tm)) >= 0)
        return get(kind, edge(g, tm)) == get(kind, edge(h, tm)) && !get(visited, edge(g, tm))
                   ? g
                   : GT::null_halfedge();
    return GT::null_halfedge();
  };
  std::vector<Feature_line<halfedge_descriptor>> lines;
  auto trace = [&](halfedge_descriptor h) {
    Feature_line<halfedge_descriptor> line;
    line.kind = Feature_kind(get(kind, edge(h, tm)));
    while (h != GT::null_halfedge()) {
      put(visited, edge(h, tm), true);
      line.halfedges.push_back(h);
      h = continuation(h);
    }
    const vertex_descriptor first = source(line.halfedges.front(), tm);
    line.closed = target(line.halfedges.back(), tm) == first && get(degree, first) == 2;
    lines.push_back(std::move(line));
  };
  // Open lines start at vertices where they must end; what remains are closed loops.
  for (auto v : vertices(tm)) {
    if (halfedge(v, tm) == GT::null_halfedge())
      continue;
    for (halfedge_descriptor h : CGAL::halfedges_around_source(v, tm)) {
      if (get(kind, edge(h, tm)) < 0 || get(visited, edge(h, tm)))
        continue;
      if (continuation(opposite(h, tm)) == GT::null_halfedge())
        trace(h);
    }
  }
  for (auto e : edges(tm))
    if (get(kind, e) >= 0 && !get(visited, e))
      trace(halfedge(e, tm));
  return lines;
}

template <typename TriangleMesh>
std::vector<Feature_line<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>>
feature_lines(const TriangleMesh& tm, const Feature_line_options& options) {
  return feature_lines(
      tm, options, [](auto) { return 0; }, CGAL::parameters::default_values());
}

template <typename TriangleMesh, typename HalfedgeDescriptor, typename NamedParameters>
std::vector<typename Smoothest_field_solver<TriangleMesh>::Constraint>
feature_alignment_constraints(const TriangleMesh& tm,
                              const std::vector<Feature_line<HalfedgeDescriptor>>& lines,
                              const std::vector<Feature_alignment>& alignment,
                              const Feature_alignment_options& options, const NamedParameters& np) {
  using Vector = typename Smoothest_field_solver<TriangleMesh>::Vector_3;
  std::vector<typename Smoothest_field_solver<TriangleMesh>::Constraint> out;
  // No lines, no frames: they take 0.1 s at 100k vertices.
  if (lines.empty() || alignment.empty() ||
      (alignment.size() != 1 && alignment.size() != lines.size()))
    return out;
  const internal::Vertex_frames<TriangleMesh> frames(tm, np);
  auto vector_of = [&](HalfedgeDescriptor h) {
    return frames.point(frames.index(target(h, tm))) - frames.point(frames.index(source(h, tm)));
  };
  auto unit_direction = [&](HalfedgeDescriptor h) {
    const internal::Vec3 d = vector_of(h);
    const double len = internal::norm(d);
    return len > 0 ? (1 / len) * d : d;
  };
  const double radius = options.tightest_radius;
  std::vector<double> along, turn; // per vertex source(h_k): arc length and turning angle there
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const Feature_line<HalfedgeDescriptor>& line = lines[l];
    const Feature_alignment a = alignment.size() == 1 ? alignment[0] : alignment[l];
    const std::size_t m = line.halfedges.size();
    if (radius > 0 && m > 0) {
      along.assign(m, 0);
      turn.assign(m, 0);
      for (std::size_t k = 0; k < m; ++k) {
        if (k > 0)
          along[k] = along[k - 1] + internal::norm(vector_of(line.halfedges[k - 1]));
        if (k > 0 || line.closed) {
          const double c = internal::dot(unit_direction(line.halfedges[(k + m - 1) % m]),
                                         unit_direction(line.halfedges[k]));
          turn[k] = std::acos(std::max(-1.0, std::min(1.0, c)));
        }
      }
    }
    const double length =
        radius > 0 && m > 0 ? along[m - 1] + internal::norm(vector_of(line.halfedges[m - 1])) : 0;
    // Whether the line turns by more than a radian over the stretch `radius` long centred on the
    // source of halfedge k (a closed line read around; an open one up to its ends).
    auto in_tight_bend = [&](std::size_t k) {
      if (!(radius > 0))
        return false;
      double turned = turn[k];
      for (int side : {-1, 1})
        for (std::size_t step = 1; step < m; ++step) {
          if (!line.closed && (side < 0 ? step > k : k + step >= m))
            break;
          const std::size_t j = side < 0 ? (k + m - step) % m : (k + step) % m;
          double d = std::abs(along[j] - along[k]);
          if (line.closed)
            d = std::min(d, length - d);
          if (d > 0.5 * radius)
            break;
          turned += turn[j];
        }
      return turned > 1;
    };
    for (std::size_t k = line.closed ? 0 : 1; k < m; ++k) {
      if (in_tight_bend(k))
        continue;
      const HalfedgeDescriptor in = line.halfedges[(k + m - 1) % m], out_h = line.halfedges[k];
      const auto v = source(out_h, tm);
      const std::size_t i = frames.index(v);
      internal::Vec3 t = unit_direction(in) + unit_direction(out_h);
      if (a == Feature_alignment::perpendicular)
        t = internal::cross(frames.normal(i), t);
      out.push_back({v, Vector(t[0], t[1], t[2]), options.kind, options.weight});
    }
  }
  return out;
}

} // namespace tessera
