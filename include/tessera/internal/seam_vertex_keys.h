// Dense keys of the vertices of a CGAL::Seam_mesh, for the modules that keep per-seam-vertex data
// in plain vectors (the OBJ writer's `vt` numbers, the per-tile parameterization). Not for direct
// use.
#pragma once

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>

#include <algorithm>
#include <cstddef>
#include <utility>

namespace tessera {
namespace internal {

/// A seam-mesh vertex is named by one halfedge of the underlying mesh (the one `target()` returns
/// for all of its halfedges); its key is that halfedge's index, so a vector of `size()` entries
/// holds one slot per seam-mesh vertex (a hash map of seam vertices was a third of the OBJ
/// writer's time). `size()` is one more than the largest halfedge index, which exceeds
/// `num_halfedges()` on a Surface_mesh whose removed elements are not yet collected.
template <typename TriangleMesh> class Seam_vertex_keys {
public:
  explicit Seam_vertex_keys(const TriangleMesh& tm)
      : him_(CGAL::get_initialized_halfedge_index_map(tm)) {
    for (auto h : halfedges(tm))
      size_ = std::max<std::size_t>(size_, std::size_t(get(him_, h)) + 1);
  }
  template <typename SeamVertex> std::size_t operator()(const SeamVertex& v) const {
    return std::size_t(get(him_, v.hd.tmhd));
  }
  std::size_t size() const { return size_; }

private:
  decltype(CGAL::get_initialized_halfedge_index_map(std::declval<const TriangleMesh&>())) him_;
  std::size_t size_ = 0;
};

} // namespace internal
} // namespace tessera
