// Deformation by handles (the seed paper's Figs. 12-13: scale + rotation, scale + twist) through
// CGAL's Surface_mesh_deformation: handle vertices are moved by a transform and reach their targets
// exactly, the region of interest follows as rigidly as possible (ARAP, Sorkine and Alexa 2007;
// spokes and rims, Chao et al. 2010; smoothed rotation-enhanced ARAP, Levi and Gotsman 2015), the
// rest of the mesh stays where it is.
#pragma once

#include <tessera/internal/named_parameters.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
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
                std::size_t* out_of_range = nullptr);

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
                  const NamedParameters& np = CGAL::parameters::default_values());

} // namespace tessera

#include <tessera/resizing/internal/deform_impl.h>
