// Deformation by handles (the seed paper's Figs. 12-13: scale + rotation, scale + twist) through
// CGAL's Surface_mesh_deformation: handle vertices are moved by a transform and reach their targets
// exactly, the region of interest follows as rigidly as possible (ARAP, Sorkine and Alexa 2007;
// spokes and rims, Chao et al. 2010; smoothed rotation-enhanced ARAP, Levi and Gotsman 2015), the
// rest of the mesh stays where it is.
#pragma once

#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace tessera {

enum class Deformation_method { arap, spokes_and_rims, smoothed_arap };

/// Vertices chosen by index (in the order of `vertices(tm)`), inside a sphere, or inside an
/// axis-aligned box.
struct Vertex_selection {
  enum class Kind { indices, sphere, box };
  Kind kind = Kind::indices;
  std::vector<std::size_t> indices;
  std::array<double, 3> center{{0, 0, 0}};
  double radius = 0;
  std::array<double, 3> min{{0, 0, 0}}, max{{0, 0, 0}};
};

/// p ↦ c + t + R_twist(p)·R·(s·(p − c)): a uniform scale s about the centre c, a rotation by
/// `angle` (radians) about `axis` through c, a twist that adds `twist` radians per unit of length
/// along the axis (measured from c), then a translation t. The centre is the handle's centroid
/// unless given.
struct Handle_transform {
  std::array<double, 3> translation{{0, 0, 0}};
  std::array<double, 3> axis{{0, 0, 1}};
  double angle = 0;
  double twist = 0;
  double scale = 1;
  bool has_center = false;
  std::array<double, 3> center{{0, 0, 0}};

  std::array<double, 3> apply(const std::array<double, 3>& p, const std::array<double, 3>& c) const;
};

struct Deformation_handle {
  Vertex_selection vertices;
  Handle_transform transform;
};

struct Deformation_options {
  Deformation_method method = Deformation_method::arap;
  /// Local/global iterations of CGAL's solver and its energy tolerance (0 for none).
  unsigned int iterations = 5;
  double tolerance = 1e-4;
  /// Vertices that may move (handles are added to it); none for the whole mesh. Vertices outside it
  /// stay where they are.
  std::optional<Vertex_selection> region_of_interest;
};

enum class Deformation_status {
  ok,
  empty_mesh,
  /// A handle selects no vertex, or an index is out of range.
  empty_handle,
  /// CGAL's preprocessing (the factorization of its Laplacian) failed, e.g. a region of interest
  /// with no fixed vertex and no handle in one of its components.
  preprocess_failed
};

struct Deformation_result {
  Deformation_status status = Deformation_status::ok;
  std::string message;
  std::size_t handle_vertices = 0;
  std::size_t region_vertices = 0;
  /// Largest distance between a handle vertex and its target after the deformation (0 up to
  /// rounding: handles are hard constraints).
  double max_handle_error = 0;
  double preprocess_seconds = 0, deform_seconds = 0;
  explicit operator bool() const { return status == Deformation_status::ok; }
};

/// The vertices of `tm` that `selection` picks (indices past the end are dropped, and counted in
/// `out_of_range` when given).
template <typename TriangleMesh, typename VertexPointMap>
std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>
select_vertices(const TriangleMesh& tm, VertexPointMap vpm, const Vertex_selection& selection,
                std::size_t* out_of_range = nullptr) {
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> all(
      vertices(tm).begin(), vertices(tm).end());
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> out;
  if (selection.kind == Vertex_selection::Kind::indices) {
    std::size_t bad = 0;
    for (std::size_t i : selection.indices) {
      if (i < all.size())
        out.push_back(all[i]);
      else
        ++bad;
    }
    if (out_of_range)
      *out_of_range = bad;
    return out;
  }
  for (auto v : all) {
    const auto& p = get(vpm, v);
    const double x[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    bool inside = true;
    if (selection.kind == Vertex_selection::Kind::sphere) {
      double d2 = 0;
      for (std::size_t c = 0; c < 3; ++c)
        d2 += (x[c] - selection.center[c]) * (x[c] - selection.center[c]);
      inside = d2 <= selection.radius * selection.radius;
    } else {
      for (std::size_t c = 0; c < 3; ++c)
        inside = inside && x[c] >= selection.min[c] && x[c] <= selection.max[c];
    }
    if (inside)
      out.push_back(v);
  }
  return out;
}

} // namespace tessera

#include <tessera/internal/named_parameters.h>
#include <tessera/resizing/internal/deform_with.h>

namespace tessera {

/// Deforms `tm` in place: each handle's vertices go to their transformed positions, the region of
/// interest (every other vertex by default) follows by `options.method`, and vertices outside it
/// stay. A handle with the identity transform pins its vertices. `TriangleMesh` needs internal
/// vertex and halfedge indices (as `CGAL::Surface_mesh` has).
///
/// Scale: ARAP keeps each cell's rotation and penalizes any change of size, so a scaled handle
/// stretches the region between it and the fixed part like rubber; to grow a part in proportion,
/// resize (resize.h) and use handles for rotation, twist and placement.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Deformation_result
deform_by_handles(TriangleMesh& tm, const std::vector<Deformation_handle>& handles,
                  const Deformation_options& options = {},
                  const NamedParameters& np = CGAL::parameters::default_values()) {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  const auto vpm = internal::writable_vertex_point_map(tm, np);
  Deformation_result result;
  if (faces(tm).empty()) {
    result.status = Deformation_status::empty_mesh;
    result.message = "the mesh has no faces";
    return result;
  }
  std::vector<std::vector<vertex_descriptor>> selected;
  std::vector<Handle_transform> transforms;
  for (std::size_t h = 0; h < handles.size(); ++h) {
    std::size_t out_of_range = 0;
    selected.push_back(select_vertices(tm, vpm, handles[h].vertices, &out_of_range));
    transforms.push_back(handles[h].transform);
    if (selected.back().empty() || out_of_range > 0) {
      result.status = Deformation_status::empty_handle;
      result.message = "handle " + std::to_string(h) +
                       (out_of_range > 0 ? " has " + std::to_string(out_of_range) +
                                               " vertex indices out of range"
                                         : " selects no vertex");
      return result;
    }
  }
  std::vector<vertex_descriptor> region;
  if (options.region_of_interest)
    region = select_vertices(tm, vpm, *options.region_of_interest);
  else
    region.assign(vertices(tm).begin(), vertices(tm).end());
  switch (options.method) {
  case Deformation_method::spokes_and_rims:
    return internal::deform_with<CGAL::SPOKES_AND_RIMS>(tm, vpm, region, selected, transforms,
                                                        options);
  case Deformation_method::smoothed_arap:
    return internal::deform_with<CGAL::SRE_ARAP>(tm, vpm, region, selected, transforms, options);
  default:
    return internal::deform_with<CGAL::ORIGINAL_ARAP>(tm, vpm, region, selected, transforms,
                                                      options);
  }
}

inline std::array<double, 3> Handle_transform::apply(const std::array<double, 3>& p,
                                                     const std::array<double, 3>& c) const {
  std::array<double, 3> d{(p[0] - c[0]) * scale, (p[1] - c[1]) * scale, (p[2] - c[2]) * scale};
  double n = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  const std::array<double, 3> k = n > 0
                                      ? std::array<double, 3>{axis[0] / n, axis[1] / n, axis[2] / n}
                                      : std::array<double, 3>{0, 0, 1};
  const double along = (p[0] - c[0]) * k[0] + (p[1] - c[1]) * k[1] + (p[2] - c[2]) * k[2];
  const double theta = angle + twist * along;
  // Rodrigues' rotation of d about k by theta.
  const double cs = std::cos(theta), sn = std::sin(theta);
  const double kd = k[0] * d[0] + k[1] * d[1] + k[2] * d[2];
  const std::array<double, 3> kxd{k[1] * d[2] - k[2] * d[1], k[2] * d[0] - k[0] * d[2],
                                  k[0] * d[1] - k[1] * d[0]};
  std::array<double, 3> out{};
  for (std::size_t i = 0; i < 3; ++i)
    out[i] = c[i] + translation[i] + d[i] * cs + kxd[i] * sn + k[i] * kd * (1 - cs);
  return out;
}

} // namespace tessera
