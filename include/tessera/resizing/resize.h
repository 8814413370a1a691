// Resizing a triangle mesh along chosen axes: simple scaling, or non-homogeneous resizing (Kraevoy,
// Sheffer, Shamir, Cohen-Or, SIGGRAPH Asia 2008) that lets straight, axis-parallel parts take the
// stretch and keeps curved parts in proportion. The surface is embedded in a volume (TetGen for
// closed surfaces, the protective grid otherwise), the volume is resized, the surface follows.
#pragma once

#include <tessera/internal/named_parameters.h>
#include <tessera/resizing/internal/surface_soup.h>
#include <tessera/resizing/tet_mesh.h>
#include <tessera/resizing/volume_resize.h>
#include <tessera/resizing/vulnerability.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <future>
#include <string>
#include <vector>

namespace tessera {

enum class Resize_method {
  /// Coordinates multiplied by the scale factors: round parts become ellipsoids.
  simple,
  /// Kraevoy et al.'s: stretch where the model is free, uniform scale where it is vulnerable.
  nonhomogeneous
};

/// The volume the surface is resized in.
enum class Resize_volume {
  /// TetGen for closed surfaces, the grid otherwise.
  automatic,
  /// The surface's interior by TetGen; needs a closed surface without self-intersections.
  tetgen,
  /// Kraevoy's protective grid around the model; works for any surface.
  grid
};

struct Resize_options {
  /// Target size of the bounding box along x, y, z as a factor of the current one.
  std::array<double, 3> scale{{1, 1, 1}};
  Resize_method method = Resize_method::nonhomogeneous;
  Resize_volume volume = Resize_volume::automatic;
  /// Factor on every vulnerability (0 gives the simple scaling's shape back, through the volume).
  double vulnerability_weight = 1;
  Vulnerability_options vulnerability;
  Tetrahedralize_options tetrahedralize;
  Grid_tet_mesh_options grid;
  /// Anchor μ, iterations and tolerance of the solve (its `scale` is set from `scale`).
  Volume_resize_options solve;
};

enum class Resize_status {
  ok,
  empty_mesh,
  /// A scale factor is not positive and finite.
  invalid_scale,
  /// An option of the vulnerability or of the solve is out of range (the message says which).
  invalid_options,
  /// The TetGen volume was asked for a surface that is not closed.
  not_closed,
  self_intersecting,
  tetgen_failed,
  /// The volume could not be solved: its matrix could not be factored (or it was empty).
  solve_failed
};

struct Resize_result {
  Resize_status status = Resize_status::ok;
  std::string message;
  Resize_volume volume = Resize_volume::automatic;
  std::size_t volume_vertices = 0;
  std::size_t tetrahedra = 0;
  std::size_t iterations = 0;
  std::array<double, 3> free_stretch{{1, 1, 1}};
  std::array<double, 3> extent_before{{0, 0, 0}};
  std::array<double, 3> target_extent{{0, 0, 0}};
  std::array<double, 3> extent_after{{0, 0, 0}};
  Vulnerability_result vulnerability;
  std::string solver;
  /// Wall-clock seconds: the vulnerability, the volume mesh (its TetGen part overlaps the
  /// vulnerability, on another thread, and is counted from the same start), the solve.
  double vulnerability_seconds = 0, volume_seconds = 0, solve_seconds = 0;
  explicit operator bool() const { return status == Resize_status::ok; }
};

/// Tetrahedralizes the interior of a closed triangle mesh with TetGen, after checking what would
/// make TetGen fail or crash: a border, a face that is not a triangle, a self-intersection
/// (`CGAL::Polygon_mesh_processing::does_self_intersect`). The volume's first vertices are the
/// mesh's, in the order of `vertices(tm)`.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Tetrahedralize_result
tetrahedralize(const TriangleMesh& tm, const Tetrahedralize_options& options = {},
               const NamedParameters& np = CGAL::parameters::default_values()) {
  const auto vpm = internal::vertex_point_map(tm, np);
  Tetrahedralize_result result = internal::check_tetrahedralization_input(tm, vpm);
  if (!result)
    return result;
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  internal::surface_soup(tm, vpm, points, triangles);
  return tetrahedralize_surface(points, triangles, options);
}

/// Resizes `tm` in place (its `vertex_point_map`) so its bounding box becomes `options.scale`
/// times the current one, writing each vertex's vulnerability along x, y, z into `vulnerability`
/// (a vertex property map of `std::array<double, 3>`; zeros for the simple method). On failure
/// the mesh is left as it was.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh, typename VulnerabilityMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Resize_result resize(TriangleMesh& tm, VulnerabilityMap vulnerability,
                     const Resize_options& options = {},
                     const NamedParameters& np = CGAL::parameters::default_values()) {
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

/// Scale factors for `Resize_options::scale` that give a mesh's bounding box chosen extents.
struct Scale_for_extents_result {
  /// `invalid_scale` when an extent is not positive and finite or the mesh is flat along an axis
  /// given an extent (the message names the axis); `empty_mesh` without vertices.
  Resize_status status = Resize_status::ok;
  std::string message;
  std::array<double, 3> scale{{1, 1, 1}};
  explicit operator bool() const { return status == Resize_status::ok; }
};

/// The factors by which `tm`'s bounding box (`CGAL::Polygon_mesh_processing::bbox`) becomes
/// `extents` along x, y and z: what `tessera resize --size X,Y,Z` resizes by.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Scale_for_extents_result
scale_for_extents(const TriangleMesh& tm, const std::array<double, 3>& extents,
                  const NamedParameters& np = CGAL::parameters::default_values()) {
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

/// As above, with the vulnerability in a scratch map.
template <typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Resize_result resize(TriangleMesh& tm, const Resize_options& options = {},
                     const NamedParameters& np = CGAL::parameters::default_values()) {
  return resize(tm, get(CGAL::dynamic_vertex_property_t<std::array<double, 3>>(), tm), options, np);
}

} // namespace tessera
