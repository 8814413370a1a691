// The body of topology/validate_refinement.h's validate_refinement(): every refined vertex located
// on the original surface, every refined face inside one original face and neither degenerate nor
// inverted, the coverage of each original face summed. Included at the end of the public header.
#pragma once

#include <tessera/topology/validate_refinement.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace tessera {

template <typename TriangleMesh>
Refinement_validation validate_refinement(const TriangleMesh& original, const TriangleMesh& refined,
                                          const Validate_refinement_options& options) {
  using GT = boost::graph_traits<TriangleMesh>;
  using Point = typename boost::property_traits<
      typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type;
  using K = typename CGAL::Kernel_traits<Point>::Kernel;
  using FT = typename K::FT;
  using Point_2 = typename K::Point_2;
  using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<
      Epick, CGAL::AABB_triangle_primitive<
                 Epick, typename std::vector<Epick::Triangle_3>::const_iterator>>>;

  Refinement_validation out;
  out.exact = options.tolerance == 0;
  auto add = [&](Refinement_problem_kind kind, std::string message, std::vector<std::size_t> vs,
                 std::vector<std::size_t> fs, std::vector<std::size_t> ofs) {
    if (out.problem_counts[std::size_t(kind)]++ < options.max_problems_per_kind)
      out.problems.push_back(
          {kind, std::move(message), std::move(vs), std::move(fs), std::move(ofs)});
  };
  if (!CGAL::is_triangle_mesh(original) || !CGAL::is_triangle_mesh(refined)) {
    out.status = Refinement_validation_status::not_triangles;
    out.message = "both meshes must be triangle meshes";
    return out;
  }
  const auto opm = get(CGAL::vertex_point, original);
  const auto rpm = get(CGAL::vertex_point, refined);
  auto approx = [](const Point& p) {
    return Epick::Point_3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  };

  const std::vector<typename GT::face_descriptor> ofaces(faces(original).begin(),
                                                         faces(original).end());
  std::vector<std::array<Point, 3>> otri(ofaces.size());
  std::vector<Epick::Triangle_3> approx_tri(ofaces.size());
  CGAL::Bbox_3 box;
  for (std::size_t i = 0; i < ofaces.size(); ++i) {
    const auto h = halfedge(ofaces[i], original);
    otri[i] = {get(opm, source(h, original)), get(opm, target(h, original)),
               get(opm, target(next(h, original), original))};
    approx_tri[i] = Epick::Triangle_3(approx(otri[i][0]), approx(otri[i][1]), approx(otri[i][2]));
    box += approx_tri[i].bbox();
  }
  const double diagonal =
      std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                CGAL::square(box.zmax() - box.zmin()));
  const double tolerance = options.tolerance * diagonal;
  // Wide enough that double approximations of exact points never miss their face.
  const double search = tolerance + 1e-12 * diagonal;
  Tree tree(approx_tri.cbegin(), approx_tri.cend());
  tree.accelerate_distance_queries();

  // Per original face, the axis its projection keeps the most of, and its projected orientation.
  std::vector<int> drop(ofaces.size());
  std::vector<CGAL::Orientation> oriented(ofaces.size());
  auto project = [](const Point& p, int d) {
    return d == 0 ? Point_2(p.y(), p.z()) : d == 1 ? Point_2(p.z(), p.x()) : Point_2(p.x(), p.y());
  };
  for (std::size_t i = 0; i < ofaces.size(); ++i) {
    const auto n = CGAL::normal(approx_tri[i][0], approx_tri[i][1], approx_tri[i][2]);
    const double a[3] = {std::abs(n.x()), std::abs(n.y()), std::abs(n.z())};
    drop[i] = a[0] >= a[1] && a[0] >= a[2] ? 0 : a[1] >= a[2] ? 1 : 2;
    oriented[i] = CGAL::orientation(project(otri[i][0], drop[i]), project(otri[i][1], drop[i]),
                                    project(otri[i][2], drop[i]));
  }

  // 1. Every refined vertex on the original surface; remember which faces it lies on.
  const std::vector<typename GT::vertex_descriptor> rverts(vertices(refined).begin(),
                                                           vertices(refined).end());
  std::vector<std::vector<std::size_t>> on_faces(rverts.size());
  const auto rvim = CGAL::get_initialized_vertex_index_map(refined);
  std::vector<typename Tree::Primitive_id> hits;
  for (std::size_t v = 0; v < rverts.size(); ++v) {
    const Point& x = get(rpm, rverts[v]);
    const Epick::Point_3 ax = approx(x);
    hits.clear();
    tree.all_intersected_primitives(CGAL::Bbox_3(ax.x() - search, ax.y() - search, ax.z() - search,
                                                 ax.x() + search, ax.y() + search, ax.z() + search),
                                    std::back_inserter(hits));
    bool at_vertex = false, on_edge = false;
    for (auto id : hits) {
      const std::size_t f = std::size_t(id - approx_tri.cbegin());
      const auto& t = otri[f];
      bool on = false;
      if (out.exact) {
        on = typename K::Triangle_3(t[0], t[1], t[2]).has_on(x);
        if (on) {
          at_vertex = at_vertex || x == t[0] || x == t[1] || x == t[2];
          for (int k = 0; k < 3; ++k)
            on_edge = on_edge || typename K::Segment_3(t[k], t[(k + 1) % 3]).has_on(x);
        }
      } else {
        on = CGAL::squared_distance(ax, approx_tri[f]) <= tolerance * tolerance;
        if (on) {
          for (int k = 0; k < 3; ++k) {
            at_vertex =
                at_vertex || CGAL::squared_distance(ax, approx_tri[f][k]) <= tolerance * tolerance;
            on_edge = on_edge ||
                      CGAL::squared_distance(
                          ax, Epick::Segment_3(approx_tri[f][k], approx_tri[f][(k + 1) % 3])) <=
                          tolerance * tolerance;
          }
        }
      }
      if (on)
        on_faces[v].push_back(f);
    }
    if (on_faces[v].empty()) {
      // The distance to the nearest face, in the kernel's arithmetic (exact before the root).
      const auto nearest = tree.closest_point_and_primitive(ax).second;
      const auto& t = otri[std::size_t(nearest - approx_tri.cbegin())];
      std::ostringstream d;
      d.precision(3);
      d << std::sqrt(
          CGAL::to_double(CGAL::squared_distance(x, typename K::Triangle_3(t[0], t[1], t[2]))));
      add(Refinement_problem_kind::off_surface,
          "vertex " + std::to_string(v) + " is off the original surface by " + d.str() +
              (out.exact ? " (tested exactly)" : " (tolerance " + std::to_string(tolerance) + ")"),
          {v}, {}, {});
    } else if (at_vertex)
      ++out.on_original_vertices;
    else if (on_edge)
      ++out.on_original_edges;
    else
      ++out.inside_original_faces;
  }

  // 2. Every refined face inside one original face, turned like it; 3. coverage per original face.
  std::vector<FT> covered(ofaces.size(), FT(0));
  std::size_t fi = 0;
  for (auto rf : faces(refined)) {
    const std::size_t f_id = fi++;
    const auto h = halfedge(rf, refined);
    const typename GT::vertex_descriptor c[3] = {source(h, refined), target(h, refined),
                                                 target(next(h, refined), refined)};
    std::size_t vi[3];
    for (int k = 0; k < 3; ++k)
      vi[k] = get(rvim, c[k]);
    if (on_faces[vi[0]].empty() || on_faces[vi[1]].empty() || on_faces[vi[2]].empty())
      continue;
    std::size_t home = std::size_t(-1);
    for (std::size_t f : on_faces[vi[0]])
      if (std::find(on_faces[vi[1]].begin(), on_faces[vi[1]].end(), f) != on_faces[vi[1]].end() &&
          std::find(on_faces[vi[2]].begin(), on_faces[vi[2]].end(), f) != on_faces[vi[2]].end()) {
        home = f;
        break;
      }
    const std::vector<std::size_t> corners{vi[0], vi[1], vi[2]};
    if (home == std::size_t(-1)) {
      add(Refinement_problem_kind::straddles_faces,
          "face " + std::to_string(f_id) + " lies in no single original face", corners, {f_id}, {});
      continue;
    }
    const Point& a = get(rpm, c[0]);
    const Point& b = get(rpm, c[1]);
    const Point& d = get(rpm, c[2]);
    if (CGAL::collinear(a, b, d)) {
      add(Refinement_problem_kind::degenerate_face,
          "face " + std::to_string(f_id) + " is degenerate", corners, {f_id}, {home});
      continue;
    }
    const int k = drop[home];
    const Point_2 pa = project(a, k), pb = project(b, k), pd = project(d, k);
    if (CGAL::orientation(pa, pb, pd) != oriented[home])
      add(Refinement_problem_kind::inverted_face,
          "face " + std::to_string(f_id) + " is turned against original face " +
              std::to_string(home),
          corners, {f_id}, {home});
    covered[home] += (pb.x() - pa.x()) * (pd.y() - pa.y()) - (pb.y() - pa.y()) * (pd.x() - pa.x());
  }
  // Coverage is only measured when every refined face found its original face.
  const bool all_placed =
      out.problem_counts[std::size_t(Refinement_problem_kind::off_surface)] == 0 &&
      out.problem_counts[std::size_t(Refinement_problem_kind::straddles_faces)] == 0;
  for (std::size_t f = 0; all_placed && f < ofaces.size(); ++f) {
    const int k = drop[f];
    const Point_2 p = project(otri[f][0], k), q = project(otri[f][1], k),
                  r = project(otri[f][2], k);
    const FT area2 = (q.x() - p.x()) * (r.y() - p.y()) - (q.y() - p.y()) * (r.x() - p.x());
    // Within the tolerance, the refined boundary may run off the original edges by `tolerance`:
    // twice the area may then differ by up to twice that times the perimeter.
    double perimeter = 0;
    for (int e = 0; e < 3; ++e)
      perimeter += std::sqrt(CGAL::squared_distance(approx_tri[f][e], approx_tri[f][(e + 1) % 3]));
    const bool equal =
        out.exact ? covered[f] == area2
                  : std::abs(CGAL::to_double(covered[f] - area2)) <=
                        2 * tolerance * perimeter + 1e-9 * std::abs(CGAL::to_double(area2));
    if (!equal)
      add(Refinement_problem_kind::coverage,
          "the refined faces inside original face " + std::to_string(f) + " cover " +
              std::to_string(CGAL::to_double(covered[f] / area2) * 100) + " % of it",
          {}, {}, {f});
  }

  std::size_t total = 0;
  for (std::size_t n : out.problem_counts)
    total += n;
  out.status =
      total == 0 ? Refinement_validation_status::valid : Refinement_validation_status::invalid;
  out.message =
      total == 0 ? std::to_string(rverts.size()) + " vertices on the original surface (" +
                       std::to_string(out.on_original_vertices) + " on its vertices, " +
                       std::to_string(out.on_original_edges) + " on its edges, " +
                       std::to_string(out.inside_original_faces) + " inside its faces), " +
                       std::to_string(fi) + " faces tiling its " + std::to_string(ofaces.size()) +
                       " faces" + (out.exact ? ", exactly" : "")
                 : out.problems.front().message +
                       (total > 1 ? " (and " + std::to_string(total - 1) + " more problems)" : "");
  return out;
}

} // namespace tessera
