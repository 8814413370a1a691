// The bodies of resizing/resize.h's entry points: tetrahedralize(), resize() (simple scaling, or
// the vulnerability, the volume and its solve of Kraevoy et al. 2008) and scale_for_extents().
// Included at the end of the public header.
#pragma once

#include <tessera/resizing/resize.h>

#include <tessera/resizing/internal/surface_soup.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <future>
#include <string>
#include <vector>

namespace tessera {

template <typename TriangleMesh, typename NamedParameters>
Tetrahedralize_result tetrahedralize(const TriangleMesh& tm, const Tetrahedralize_options& options,
                                     const NamedParameters& np) {
  const auto vpm = internal::vertex_point_map(tm, np);
  Tetrahedralize_result result = internal::check_tetrahedralization_input(tm, vpm);
  if (!result)
    return result;
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  internal::surface_soup(tm, vpm, points, triangles);
  return tetrahedralize_surface(points, triangles, options);
}

template <typename TriangleMesh, typename VulnerabilityMap, typename NamedParameters>
Resize_result resize(TriangleMesh& tm, VulnerabilityMap vulnerability,
                     const Resize_options& options, const NamedParameters& np) {
  using Clock = std::chrono::steady_clock;
  const auto vpm = internal::writable_vertex_point_map(tm, np);
  using Point = typename boost::property_traits<decltype(vpm)>::value_type;
  auto seconds = [](Clock::time_point since) {
    return std::chrono::duration<double>(Clock::now() - since).count();
  };
  Resize_result result;
  for (double s : options.scale)
    if (!(s > 0) || !std::isfinite(s)) {
      result.status = Resize_status::invalid_scale;
      result.message = "scale factors must be positive and finite";
      return result;
    }
  if (faces(tm).empty()) {
    result.status = Resize_status::empty_mesh;
    result.message = "the mesh has no faces";
    return result;
  }
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  internal::surface_soup(tm, vpm, points, triangles);
  const CGAL::Bbox_3 box = bounding_box(points);
  for (int d = 0; d < 3; ++d) {
    result.extent_before[std::size_t(d)] = box.max(d) - box.min(d);
    result.target_extent[std::size_t(d)] =
        options.scale[std::size_t(d)] * (box.max(d) - box.min(d));
  }

  std::vector<std::array<double, 3>> moved;
  if (options.method == Resize_method::simple) {
    for (auto v : vertices(tm))
      put(vulnerability, v, std::array<double, 3>{{0, 0, 0}});
    moved = points;
    for (auto& p : moved)
      for (std::size_t c = 0; c < 3; ++c) {
        const double centre = 0.5 * (box.min(int(c)) + box.max(int(c)));
        p[c] = centre + options.scale[c] * (p[c] - centre);
      }
    result.free_stretch = options.scale;
  } else {
    Resize_volume kind = options.volume;
    if (kind == Resize_volume::automatic)
      kind = CGAL::is_closed(tm) && CGAL::is_triangle_mesh(tm) ? Resize_volume::tetgen
                                                               : Resize_volume::grid;
    result.volume = kind;
    auto start = Clock::now();
    if (kind == Resize_volume::tetgen) {
      const Tetrahedralize_result checked = internal::check_tetrahedralization_input(tm, vpm);
      if (!checked) {
        result.status = checked.status == Tetrahedralize_status::not_closed
                            ? Resize_status::not_closed
                        : checked.status == Tetrahedralize_status::self_intersecting
                            ? Resize_status::self_intersecting
                            : Resize_status::empty_mesh;
        result.message = checked.message;
        return result;
      }
    }
    // TetGen and the jet fits are independent: TetGen runs on a thread of its own meanwhile.
    std::future<Tetrahedralize_result> tetrahedralized;
    if (kind == Resize_volume::tetgen)
      tetrahedralized = std::async(std::launch::async, [&] {
        return tetrahedralize_surface(points, triangles, options.tetrahedralize);
      });
    result.vulnerability = compute_vulnerability(tm, vulnerability, options.vulnerability, np);
    if (!result.vulnerability) {
      result.status = result.vulnerability.status == Vulnerability_status::empty_mesh
                          ? Resize_status::empty_mesh
                          : Resize_status::invalid_options;
      result.message = result.vulnerability.message;
      return result;
    }
    std::vector<std::array<double, 3>> values;
    values.reserve(points.size());
    for (auto v : vertices(tm)) {
      std::array<double, 3> w = get(vulnerability, v);
      for (double& x : w)
        x = std::clamp(x * options.vulnerability_weight, 0.0, 1.0);
      values.push_back(w);
    }
    result.vulnerability_seconds = seconds(start);

    Tet_mesh volume;
    if (kind == Resize_volume::tetgen) {
      Tetrahedralize_result done = tetrahedralized.get();
      if (!done) {
        result.status = Resize_status::tetgen_failed;
        result.message = done.message;
        return result;
      }
      volume = std::move(done.mesh);
    } else {
      volume = grid_tet_mesh(points, options.grid);
    }
    result.volume_vertices = volume.points.size();
    result.tetrahedra = volume.tets.size();
    // Grid vertices farther than a cell's diagonal from the model get no vulnerability: empty
    // space takes the stretch.
    double falloff = 0;
    if (volume.embedded()) {
      const auto& q = volume.tets.front();
      double diagonal = 0;
      for (std::size_t c = 0; c < 3; ++c)
        diagonal += std::pow(volume.points[q[0]][c] - volume.points[q[3]][c], 2);
      falloff = 2 * std::sqrt(diagonal);
    }
    const auto volume_values = carry_to_volume(volume, points, values, falloff);
    result.volume_seconds = seconds(start);

    start = Clock::now();
    Volume_resize_options solve = options.solve;
    solve.scale = options.scale;
    const Volume_resize_result solved = resize_volume(volume, volume_values, solve);
    result.solve_seconds = seconds(start);
    result.solver = solved.solver;
    result.iterations = solved.iterations;
    result.free_stretch = solved.free_stretch;
    result.vulnerability_weight = solved.vulnerability_weight;
    if (!solved) {
      result.status = solved.status == Volume_resize_status::invalid_options
                          ? Resize_status::invalid_options
                          : Resize_status::solve_failed;
      result.message = solved.message;
      return result;
    }
    moved = volume.surface_positions(solved.points);
  }
  const CGAL::Bbox_3 after = bounding_box(moved);
  for (int d = 0; d < 3; ++d)
    result.extent_after[std::size_t(d)] = after.max(d) - after.min(d);
  std::size_t i = 0;
  for (auto v : vertices(tm)) {
    const auto& p = moved[i++];
    put(vpm, v, Point(p[0], p[1], p[2]));
  }
  return result;
}

template <typename TriangleMesh, typename NamedParameters>
Scale_for_extents_result scale_for_extents(const TriangleMesh& tm,
                                           const std::array<double, 3>& extents,
                                           const NamedParameters& np) {
  Scale_for_extents_result result;
  auto fail = [&](Resize_status status, std::string message) {
    result.status = status;
    result.message = std::move(message);
    return result;
  };
  if (vertices(tm).empty())
    return fail(Resize_status::empty_mesh, "the mesh has no vertices");
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(tm, np);
  for (int c = 0; c < 3; ++c) {
    const double wanted = extents[std::size_t(c)], extent = box.max(c) - box.min(c);
    if (!(wanted > 0) || !std::isfinite(wanted))
      return fail(Resize_status::invalid_scale, "extents must be positive numbers");
    if (!(extent > 0))
      return fail(Resize_status::invalid_scale, "the mesh is flat along axis " + std::to_string(c));
    result.scale[std::size_t(c)] = wanted / extent;
  }
  return result;
}

template <typename TriangleMesh, typename NamedParameters>
Resize_result resize(TriangleMesh& tm, const Resize_options& options, const NamedParameters& np) {
  return resize(tm, get(CGAL::dynamic_vertex_property_t<std::array<double, 3>>(), tm), options, np);
}

} // namespace tessera
