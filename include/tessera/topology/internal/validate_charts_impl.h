// The bodies of validate_charts() and validate_uv_layout() (tessera/topology/validate_charts.h):
// the charts against the surface, the seams and corners, the sides and their pairing, the side
// words, and the expected shapes; the texture layout's signed areas. Included at the end of the
// public header.
#pragma once

#include <tessera/topology/validate_charts.h>

#include <tessera/topology/internal/schema_word.h>

#include <CGAL/Curves_on_surface_topology.h>
#include <CGAL/Path_on_surface.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace tessera {
namespace internal {

// Connected components of the faces of a FaceGraph (indices in face order), and their count.
template <typename FaceGraph>
std::size_t face_components(const FaceGraph& g, std::vector<std::size_t>& component) {
  const auto fim = CGAL::get_initialized_face_index_map(g);
  const std::vector<typename boost::graph_traits<FaceGraph>::face_descriptor> fs(faces(g).begin(),
                                                                                 faces(g).end());
  component.assign(fs.size(), std::size_t(-1));
  std::size_t n = 0;
  std::vector<std::size_t> stack;
  for (std::size_t s = 0; s < fs.size(); ++s) {
    if (component[s] != std::size_t(-1))
      continue;
    component[s] = n;
    stack.assign(1, s);
    while (!stack.empty()) {
      const auto f = fs[stack.back()];
      stack.pop_back();
      for (auto h : CGAL::halfedges_around_face(halfedge(f, g), g)) {
        const auto o = face(opposite(h, g), g);
        if (o == boost::graph_traits<FaceGraph>::null_face())
          continue;
        const std::size_t i = get(fim, o);
        if (component[i] == std::size_t(-1)) {
          component[i] = n;
          stack.push_back(i);
        }
      }
    }
    ++n;
  }
  return n;
}

// The halfedge of face f of tm from s to t; null when f has none.
template <typename PolygonMesh>
typename boost::graph_traits<PolygonMesh>::halfedge_descriptor
halfedge_of_face(const PolygonMesh& tm,
                 typename boost::graph_traits<PolygonMesh>::face_descriptor f,
                 typename boost::graph_traits<PolygonMesh>::vertex_descriptor s,
                 typename boost::graph_traits<PolygonMesh>::vertex_descriptor t) {
  for (auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm))
    if (source(h, tm) == s && target(h, tm) == t)
      return h;
  return boost::graph_traits<PolygonMesh>::null_halfedge();
}

// Up to `at_most` ids, comma-separated, then how many there are in all.
inline std::string join_ids(const std::vector<std::size_t>& ids, std::size_t at_most = 8) {
  std::string s;
  for (std::size_t i = 0; i < ids.size() && i < at_most; ++i)
    s += (i ? ", " : "") + std::to_string(ids[i]);
  if (ids.size() > at_most)
    s += ", ... (" + std::to_string(ids.size()) + " in all)";
  return s;
}

} // namespace internal

template <typename PolygonMesh, typename ChartMesh>
Cutting_validation validate_charts(
    const PolygonMesh& tm, const ChartMesh& charts,
    const std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>& chart_to_mesh,
    const Validate_charts_options& options) {
  using GT = boost::graph_traits<PolygonMesh>;
  using CT = boost::graph_traits<ChartMesh>;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using chart_halfedge = typename CT::halfedge_descriptor;
  Cutting_validation out;
  auto add = [&](Cutting_problem_kind kind, std::string message, std::vector<std::size_t> vs = {},
                 std::vector<std::size_t> fs = {}) {
    out.problems.push_back({kind, std::move(message), std::move(vs), std::move(fs)});
  };
  auto finish = [&] {
    out.status = out.problems.empty() ? Cutting_validation_status::valid
                                      : Cutting_validation_status::invalid;
    if (!out.problems.empty())
      out.message = out.problems.front().message;
    else
      out.message = std::to_string(out.charts.size()) + " chart(s), all disks; " +
                    std::to_string(out.seam_edges) + " seam edges, " +
                    std::to_string(out.corner_vertices) + " corner vertices";
    return out;
  };

  const auto vim = CGAL::get_initialized_vertex_index_map(tm);
  const auto fim = CGAL::get_initialized_face_index_map(tm);
  const auto cvim = CGAL::get_initialized_vertex_index_map(charts);
  const auto cfim = CGAL::get_initialized_face_index_map(charts);
  const std::vector<typename GT::face_descriptor> tm_faces(faces(tm).begin(), faces(tm).end());
  const std::vector<typename GT::vertex_descriptor> tm_vertices(vertices(tm).begin(),
                                                                vertices(tm).end());

  // 1. The charts copy the surface: same faces, each face's corners in the same cyclic order.
  if (num_faces(charts) != tm_faces.size() || chart_to_mesh.size() != num_vertices(charts)) {
    add(Cutting_problem_kind::mismatch, "the charts have " + std::to_string(num_faces(charts)) +
                                            " faces and " + std::to_string(num_vertices(charts)) +
                                            " vertices (" + std::to_string(chart_to_mesh.size()) +
                                            " mapped) for " + std::to_string(tm_faces.size()) +
                                            " faces of the surface");
    return finish();
  }
  auto origin = [&](typename CT::vertex_descriptor v) { return chart_to_mesh[get(cvim, v)]; };
  // The surface halfedge a chart halfedge copies (null when its face's corners do not match).
  auto to_mesh = [&](chart_halfedge ch) {
    return internal::halfedge_of_face(tm, tm_faces[get(cfim, face(ch, charts))],
                                      origin(source(ch, charts)), origin(target(ch, charts)));
  };
  for (auto cf : faces(charts)) {
    const std::size_t i = get(cfim, cf);
    bool same = degree(cf, charts) == degree(tm_faces[i], tm);
    for (chart_halfedge ch : CGAL::halfedges_around_face(halfedge(cf, charts), charts))
      same = same && to_mesh(ch) != GT::null_halfedge();
    if (!same)
      add(Cutting_problem_kind::mismatch,
          "chart face " + std::to_string(i) + " does not copy the corners of surface face " +
              std::to_string(i),
          {}, {i});
  }
  if (!out.problems.empty())
    return finish();
  // Two chart faces glued along an edge must be neighbours across that edge on the surface.
  for (auto ce : edges(charts)) {
    const chart_halfedge ch = halfedge(ce, charts), co = opposite(ch, charts);
    if (is_border(ch, charts) || is_border(co, charts))
      continue;
    if (opposite(to_mesh(ch), tm) != to_mesh(co)) {
      const std::size_t f = get(cfim, face(ch, charts));
      add(Cutting_problem_kind::mismatch,
          "chart face " + std::to_string(f) +
              " is glued to a face that is not its neighbour on the surface",
          {}, {f, std::size_t(get(cfim, face(co, charts)))});
    }
  }
  if (!out.problems.empty())
    return finish();

  // 2. The seams: surface edges whose two faces are apart in the charts. Cut degree counts seams
  // and the surface's own border; corners are where it is not 2, or marked.
  std::vector<char> on_seam(num_halfedges(tm), 0); // by halfedge: a chart boundary runs along it
  const auto him = CGAL::get_initialized_halfedge_index_map(tm);
  std::vector<std::size_t> cut_degree(tm_vertices.size(), 0);
  for (auto ch : halfedges(charts)) {
    if (!is_border(ch, charts))
      continue;
    const halfedge_descriptor h = to_mesh(opposite(ch, charts));
    on_seam[get(him, h)] = 1;
    ++cut_degree[get(vim, source(h, tm))];
    ++cut_degree[get(vim, target(h, tm))];
    if (!is_border(opposite(h, tm), tm))
      ++out.seam_edges; // counted from each side: halved below
  }
  out.seam_edges /= 2;
  // Each seam edge was counted from both of its sides, each border edge once.
  for (std::size_t i = 0; i < tm_vertices.size(); ++i) {
    std::size_t border = 0;
    for (halfedge_descriptor h : CGAL::halfedges_around_target(halfedge(tm_vertices[i], tm), tm))
      border += is_border_edge(h, tm) ? 1 : 0;
    cut_degree[i] = (cut_degree[i] - border) / 2 + border;
  }
  std::vector<char> corner(tm_vertices.size(), 0);
  for (std::size_t i = 0; i < tm_vertices.size(); ++i)
    corner[i] = cut_degree[i] > 0 && cut_degree[i] != 2;
  for (std::size_t i : options.marked_corners)
    if (i < corner.size() && cut_degree[i] > 0)
      corner[i] = 1;
  for (char c : corner)
    out.corner_vertices += c ? 1 : 0;
  std::vector<std::size_t> dangling;
  for (std::size_t i = 0; i < tm_vertices.size(); ++i)
    if (cut_degree[i] == 1)
      dangling.push_back(i);
  if (!dangling.empty() && options.expect != Expected_cutting::disks)
    add(Cutting_problem_kind::dangling_seam,
        std::to_string(dangling.size()) + " seam(s) end inside the surface, at vertices " +
            internal::join_ids(dangling),
        dangling);

  // 3. Charts: components, Euler characteristic, boundary loops.
  std::vector<std::size_t> chart_of_face;
  const std::size_t n_charts = internal::face_components(charts, chart_of_face);
  out.charts.assign(n_charts, {});
  for (std::size_t f = 0; f < chart_of_face.size(); ++f)
    ++out.charts[chart_of_face[f]].faces;
  auto chart_of = [&](chart_halfedge h) {
    const auto f = is_border(h, charts) ? face(opposite(h, charts), charts) : face(h, charts);
    return chart_of_face[get(cfim, f)];
  };
  for (auto v : vertices(charts))
    if (halfedge(v, charts) != CT::null_halfedge())
      ++out.charts[chart_of(halfedge(v, charts))].euler_characteristic;
  for (auto e : edges(charts))
    --out.charts[chart_of(halfedge(e, charts))].euler_characteristic;
  for (auto& c : out.charts)
    c.euler_characteristic += long(c.faces);
  out.chart_of_face = chart_of_face;

  // 4. Walk every boundary loop: split it into sides at the corners, and pair the sides.
  struct Side {
    std::size_t chart;
    std::vector<halfedge_descriptor> halfedges; // surface halfedges with the chart on their left
    bool closed = false; // a whole boundary loop without a corner: it starts anywhere
  };
  std::vector<Side> sides;
  std::vector<char> visited(num_halfedges(charts), 0);
  const auto chim = CGAL::get_initialized_halfedge_index_map(charts);
  for (auto b : halfedges(charts)) {
    if (!is_border(b, charts) || visited[get(chim, b)])
      continue;
    const std::size_t c = chart_of(b);
    ++out.charts[c].boundary_loops;
    // The border loop runs against the chart; its opposites, reversed, run along it.
    std::vector<chart_halfedge> loop;
    for (chart_halfedge h : CGAL::halfedges_around_face(b, charts)) {
      visited[get(chim, h)] = 1;
      loop.push_back(opposite(h, charts));
    }
    std::reverse(loop.begin(), loop.end());
    auto at_corner = [&](chart_halfedge h) {
      return corner[get(vim, origin(source(h, charts)))] != 0;
    };
    // Start at the corner with the smallest chart vertex index, so that the word does not depend
    // on how halfedges happen to be numbered.
    auto first_corner = loop.end();
    for (auto it = loop.begin(); it != loop.end(); ++it)
      if (at_corner(*it) &&
          (first_corner == loop.end() ||
           get(cvim, source(*it, charts)) < get(cvim, source(*first_corner, charts))))
        first_corner = it;
    if (first_corner == loop.end()) { // no corner: the whole loop is one closed side
      sides.push_back({c, {}, true});
      for (chart_halfedge h : loop)
        sides.back().halfedges.push_back(to_mesh(h));
      continue;
    }
    std::rotate(loop.begin(), first_corner, loop.end());
    for (chart_halfedge h : loop) {
      if (at_corner(h)) {
        sides.push_back({c, {}});
        out.charts[c].corners.push_back(get(vim, origin(source(h, charts))));
        out.charts[c].chart_corners.push_back(get(cvim, source(h, charts)));
      }
      sides.back().halfedges.push_back(to_mesh(h));
    }
  }
  for (std::size_t c = 0; c < n_charts; ++c)
    if (!out.charts[c].is_disk())
      add(Cutting_problem_kind::not_a_disk,
          "chart " + std::to_string(c) + " is not a disk (Euler characteristic " +
              std::to_string(out.charts[c].euler_characteristic) + ", " +
              std::to_string(out.charts[c].boundary_loops) + " boundary loops" +
              (out.charts[c].euler_characteristic < 1 ? ": a seam is missing)" : ")"));

  std::map<halfedge_descriptor, std::size_t> side_starting_with;
  // A closed side has no start: each of its halfedges, with its position, finds it.
  std::map<halfedge_descriptor, std::pair<std::size_t, std::size_t>> on_closed_side;
  for (std::size_t s = 0; s < sides.size(); ++s) {
    side_starting_with.emplace(sides[s].halfedges.front(), s);
    if (sides[s].closed)
      for (std::size_t k = 0; k < sides[s].halfedges.size(); ++k)
        on_closed_side.emplace(sides[s].halfedges[k], std::make_pair(s, k));
  }
  std::vector<std::size_t> partner(sides.size(), std::size_t(-1));
  for (std::size_t s = 0; s < sides.size(); ++s) {
    const auto& hs = sides[s].halfedges;
    const std::size_t n = hs.size();
    if (is_border(opposite(hs.front(), tm), tm))
      continue; // along the surface's border: no partner
    // The partner runs the same halfedges backwards: from the opposite of this side's last
    // halfedge, or, for a closed side, from wherever the opposite of its first one lies.
    std::size_t t = std::size_t(-1), shift = 0;
    if (sides[s].closed) {
      const auto it = on_closed_side.find(opposite(hs.front(), tm));
      if (it != on_closed_side.end()) {
        t = it->second.first;
        shift = (it->second.second + 1) % n; // where the partner's walk meets hs.back()
      }
    } else if (const auto it = side_starting_with.find(opposite(hs.back(), tm));
               it != side_starting_with.end()) {
      t = it->second;
    }
    bool reversed = t != std::size_t(-1) && sides[t].halfedges.size() == n &&
                    sides[t].closed == sides[s].closed;
    for (std::size_t k = 0; reversed && k < n; ++k)
      reversed = sides[t].halfedges[(shift + n - 1 - k) % n] == opposite(hs[k], tm);
    if (reversed)
      partner[s] = t;
    else {
      const auto v = get(vim, source(hs.front(), tm));
      add(Cutting_problem_kind::unpaired_side,
          "the side of chart " + std::to_string(sides[s].chart) + " from vertex " +
              std::to_string(v) +
              " has no reversed partner (its seam is cut at a corner on one side only)",
          {std::size_t(v)});
    }
  }

  // A chart bounded by one loop is read from the corner where the most commutators
  // (x y x^-1 y^-1) follow one another, so that a canonical schema prints canonically; on a tie,
  // from the corner with the smallest chart vertex index, where the walk above started.
  std::vector<std::size_t> order(sides.size());
  for (std::size_t s = 0; s < sides.size(); ++s)
    order[s] = s;
  for (std::size_t first = 0; first < sides.size();) {
    const std::size_t c = sides[first].chart;
    std::size_t end = first;
    while (end < sides.size() && sides[end].chart == c)
      ++end;
    const std::size_t n = end - first;
    auto& chart = out.charts[c];
    if (chart.boundary_loops == 1 && chart.corners.size() == n && n >= 4) {
      // The loop's word: a side pair is one letter, forwards at its first side; a side without
      // a partner on the loop is a letter of its own.
      internal::Schema_word loop_word;
      for (std::size_t s = first; s < end; ++s) {
        const std::size_t p = partner[s];
        const bool paired = p != std::size_t(-1) && p >= first && p < end;
        loop_word.push_back({paired ? std::min(s, p) : s, paired && p < s});
      }
      std::size_t best = 0, most = 0;
      for (std::size_t r = 0; r < n; ++r) {
        std::size_t run = 0;
        while (4 * run + 4 <= n && internal::commutator_at(loop_word, r + 4 * run))
          ++run;
        if (run > most) {
          most = run;
          best = r;
        }
      }
      std::rotate(order.begin() + long(first), order.begin() + long(first + best),
                  order.begin() + long(end));
      std::rotate(chart.corners.begin(), chart.corners.begin() + long(best), chart.corners.end());
      std::rotate(chart.chart_corners.begin(), chart.chart_corners.begin() + long(best),
                  chart.chart_corners.end());
    }
    first = end;
  }

  // Side words, pairs labelled in order of first appearance.
  std::vector<std::size_t> pair_label(sides.size(), std::size_t(-1));
  std::size_t labels = 0;
  for (std::size_t s : order) {
    auto& chart = out.charts[sides[s].chart];
    ++chart.sides;
    std::string w;
    if (is_border(opposite(sides[s].halfedges.front(), tm), tm))
      w = "B";
    else if (partner[s] == std::size_t(-1))
      w = "?";
    else {
      const bool inverse = pair_label[partner[s]] != std::size_t(-1);
      const std::size_t k = inverse ? pair_label[partner[s]] : labels++;
      pair_label[s] = k;
      w = std::string(k % 2 == 0 ? "a" : "b") + std::to_string(k / 2 + 1) + (inverse ? "^-1" : "");
    }
    chart.word += (chart.word.empty() ? "" : " ") + w;
  }

  // 5. Expected shapes.
  if (options.expect == Expected_cutting::quads)
    for (std::size_t c = 0; c < n_charts; ++c) {
      const auto& corners = out.charts[c].corners;
      if (corners.size() == 4)
        continue;
      // A T-junction is a corner where the chart's boundary runs on nearly straight: of a chart
      // with more than four corners, name the flattest extra ones, with their angle inside the
      // chart.
      std::vector<std::pair<double, std::size_t>> angles;
      for (std::size_t v : corners) {
        double angle = 0;
        for (halfedge_descriptor h :
             CGAL::halfedges_around_target(halfedge(tm_vertices[v], tm), tm)) {
          if (is_border(h, tm) || chart_of_face[get(fim, face(h, tm))] != c)
            continue;
          const auto& p = get(CGAL::vertex_point, tm, target(h, tm));
          const auto& a = get(CGAL::vertex_point, tm, source(h, tm));
          const auto& b = get(CGAL::vertex_point, tm, target(next(h, tm), tm));
          double u[3], w[3];
          for (int d = 0; d < 3; ++d) {
            u[d] = CGAL::to_double(a[d] - p[d]);
            w[d] = CGAL::to_double(b[d] - p[d]);
          }
          const double dot = u[0] * w[0] + u[1] * w[1] + u[2] * w[2];
          const double nu = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
          const double nw = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
          if (nu > 0 && nw > 0)
            angle += std::acos(std::clamp(dot / (nu * nw), -1.0, 1.0));
        }
        angles.emplace_back(angle, v);
      }
      std::sort(angles.begin(), angles.end(), [](const auto& x, const auto& y) {
        return std::abs(x.first - M_PI) < std::abs(y.first - M_PI);
      });
      std::string flat;
      std::vector<std::size_t> where;
      for (std::size_t i = 0; corners.size() > 4 && i < corners.size() - 4; ++i) {
        flat += (i ? ", " : "") + std::to_string(angles[i].second) + " (" +
                std::to_string(int(std::lround(angles[i].first * 180 / M_PI))) + " deg)";
        where.push_back(angles[i].second);
      }
      add(Cutting_problem_kind::not_a_quad,
          "chart " + std::to_string(c) + " has " + std::to_string(corners.size()) +
              " corners where a quad has 4" +
              (flat.empty() ? std::string()
                            : "; likely T-junctions (its flattest corners) at vertices " + flat),
          where.empty() ? corners : where);
    }
  if (options.expect == Expected_cutting::schema) {
    std::vector<std::size_t> component_of_face;
    const std::size_t n_components = internal::face_components(tm, component_of_face);
    std::vector<std::vector<std::size_t>> charts_of(n_components);
    std::vector<long> chi(n_components, 0);
    std::vector<std::size_t> border_loops(n_components, 0);
    for (std::size_t f = 0; f < component_of_face.size(); ++f) {
      auto& list = charts_of[component_of_face[f]];
      if (std::find(list.begin(), list.end(), chart_of_face[f]) == list.end())
        list.push_back(chart_of_face[f]);
      ++chi[component_of_face[f]];
    }
    auto component_of = [&](halfedge_descriptor h) {
      return component_of_face[get(fim, face(is_border(h, tm) ? opposite(h, tm) : h, tm))];
    };
    for (auto v : tm_vertices)
      if (halfedge(v, tm) != GT::null_halfedge())
        ++chi[component_of(halfedge(v, tm))];
    for (auto e : edges(tm))
      --chi[component_of(halfedge(e, tm))];
    std::vector<char> seen(num_halfedges(tm), 0);
    for (auto h : halfedges(tm))
      if (is_border(h, tm) && !seen[get(him, h)]) {
        ++border_loops[component_of(h)];
        for (auto g : CGAL::halfedges_around_face(h, tm))
          seen[get(him, g)] = 1;
      }
    for (std::size_t k = 0; k < n_components; ++k) {
      const long genus = (2 - chi[k] - long(border_loops[k])) / 2;
      const std::string where =
          "surface component " + std::to_string(k) + " (genus " + std::to_string(genus) + ")";
      if (charts_of[k].size() != 1) {
        add(Cutting_problem_kind::not_a_schema, where + " is cut into " +
                                                    std::to_string(charts_of[k].size()) +
                                                    " charts, not one polygon");
        continue;
      }
      const auto& chart = out.charts[charts_of[k].front()];
      if (border_loops[k] != 0 || genus == 0)
        continue;
      const bool one_basepoint =
          !chart.corners.empty() &&
          std::all_of(chart.corners.begin(), chart.corners.end(),
                      [&](std::size_t v) { return v == chart.corners.front(); });
      if (!one_basepoint || chart.sides != std::size_t(4 * genus)) {
        std::vector<std::size_t> distinct = chart.corners;
        std::sort(distinct.begin(), distinct.end());
        distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
        add(Cutting_problem_kind::not_a_schema,
            where + ": a schema has " + std::to_string(4 * genus) +
                " sides at one basepoint, this chart " + std::to_string(chart.sides) +
                " sides with corners at " + std::to_string(distinct.size()) + " vertices (" +
                internal::join_ids(distinct) + ")",
            distinct);
      }
    }
    if (options.check_loops_non_contractible) {
      CGAL::Surface_mesh_topology::Curves_on_surface_topology<PolygonMesh> cst(tm);
      for (const Side& s : sides) {
        if (source(s.halfedges.front(), tm) != target(s.halfedges.back(), tm))
          continue;
        if (is_border(opposite(s.halfedges.front(), tm), tm))
          continue;
        CGAL::Surface_mesh_topology::Path_on_surface<PolygonMesh> path(tm);
        for (halfedge_descriptor h : s.halfedges)
          path.push_back(h);
        if (cst.is_contractible(path)) {
          const auto v = get(vim, source(s.halfedges.front(), tm));
          add(Cutting_problem_kind::contractible_loop,
              "the side of chart " + std::to_string(s.chart) + " from vertex " + std::to_string(v) +
                  " is a contractible loop",
              {std::size_t(v)});
        }
      }
    }
  }
  return finish();
}

template <typename ChartMesh, typename FT>
Cutting_validation validate_uv_layout(const ChartMesh& charts,
                                      const std::vector<std::array<FT, 2>>& uv,
                                      const std::vector<Pinched_texture_vertex>& pinched) {
  Cutting_validation out;
  const auto cvim = CGAL::get_initialized_vertex_index_map(charts);
  std::vector<std::size_t> chart_of_face;
  const std::size_t n_charts = internal::face_components(charts, chart_of_face);
  out.charts.assign(n_charts, {});
  std::vector<FT> area2;
  std::vector<FT> total(n_charts, FT(0));
  std::size_t f = 0;
  for (auto cf : faces(charts)) {
    FT a(0);
    for (auto h : CGAL::halfedges_around_face(halfedge(cf, charts), charts)) {
      const auto& p = uv[get(cvim, source(h, charts))];
      const auto& q = uv[get(cvim, target(h, charts))];
      a += p[0] * q[1] - p[1] * q[0];
    }
    area2.push_back(a);
    total[chart_of_face[f]] += a;
    ++out.charts[chart_of_face[f]].faces;
    ++f;
  }
  std::size_t mirrored = 0;
  for (std::size_t c = 0; c < n_charts; ++c)
    mirrored += CGAL::sign(total[c]) == CGAL::NEGATIVE ? 1 : 0;
  std::vector<std::size_t> degenerate, inverted;
  for (std::size_t i = 0; i < area2.size(); ++i) {
    const CGAL::Sign s = CGAL::sign(area2[i]);
    if (s == CGAL::ZERO)
      degenerate.push_back(i);
    else if (s != CGAL::sign(total[chart_of_face[i]]))
      inverted.push_back(i);
  }
  if (!degenerate.empty())
    out.problems.push_back(
        {Cutting_problem_kind::degenerate_uv_face,
         std::to_string(degenerate.size()) +
             " face(s) with zero area in the texture layout: " + internal::join_ids(degenerate),
         {},
         degenerate});
  if (!inverted.empty())
    out.problems.push_back({Cutting_problem_kind::inverted_uv_face,
                            std::to_string(inverted.size()) +
                                " face(s) turned against their chart in the texture layout: " +
                                internal::join_ids(inverted),
                            {},
                            inverted});
  if (!pinched.empty()) {
    // The chart of each chart vertex: that of any face around it.
    std::vector<std::size_t> chart_of_vertex(num_vertices(charts), std::size_t(-1));
    const auto cfim = CGAL::get_initialized_face_index_map(charts);
    for (auto cf : faces(charts))
      for (auto v : CGAL::vertices_around_face(halfedge(cf, charts), charts))
        chart_of_vertex[get(cvim, v)] = chart_of_face[get(cfim, cf)];
    for (const Pinched_texture_vertex& x : pinched) {
      std::vector<std::size_t> touching;
      for (std::size_t cv : x.chart_vertices)
        if (cv < chart_of_vertex.size() && chart_of_vertex[cv] != std::size_t(-1))
          touching.push_back(chart_of_vertex[cv]);
      std::sort(touching.begin(), touching.end());
      const bool itself = std::adjacent_find(touching.begin(), touching.end()) != touching.end();
      touching.erase(std::unique(touching.begin(), touching.end()), touching.end());
      out.notes.push_back(
          {Cutting_problem_kind::pinched_texture_vertex,
           "texture vertex v " + std::to_string(x.vertex + 1) + "/vt " +
               std::to_string(x.texture_coordinate + 1) + " (1-based, as in the file) joins " +
               std::to_string(x.chart_vertices.size()) + " fans that share no edge: " +
               (touching.size() == 1
                    ? "chart " + std::to_string(touching.front()) + " touches itself there"
                    : "charts " + internal::join_ids(touching) +
                          (itself ? " (one of them twice)" : "") + " touch there"),
           {x.vertex},
           {}});
    }
  }
  out.status =
      out.problems.empty() ? Cutting_validation_status::valid : Cutting_validation_status::invalid;
  out.message =
      out.problems.empty()
          ? std::to_string(n_charts) + " chart(s) without folds or zero-area faces" +
                (mirrored ? " (" + std::to_string(mirrored) + " mirrored as a whole)" : "")
          : out.problems.front().message;
  return out;
}

} // namespace tessera
