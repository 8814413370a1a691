// The connected pieces of a texture region (vertices joined along edges whose ends are both in
// it), shared by the segmentation's closing at coarser scales
// (internal/texture_segmentation_impl.h) and by separate_textures (texture_separation.h).
#pragma once

#include <tessera/internal/index_sets.h>

#include <cstddef>
#include <vector>

namespace tessera::internal {

constexpr std::size_t no_piece = std::size_t(-1);

/// Per vertex (by `index`), the piece of the vertices where `inside` is nonzero, numbered in the
/// order of their first vertex by index (`no_piece` outside); `count` receives the vertices per
/// piece.
template <typename TriangleMesh, typename VertexIndexMap>
std::vector<std::size_t> texture_pieces(const TriangleMesh& tm, VertexIndexMap index,
                                        const std::vector<char>& inside,
                                        std::vector<std::size_t>& count) {
  const std::size_t n = inside.size();
  internal::Index_sets sets(n);
  for (auto e : edges(tm)) {
    const std::size_t a = get(index, source(halfedge(e, tm), tm)),
                      b = get(index, target(halfedge(e, tm), tm));
    if (inside[a] && inside[b])
      sets.unite(a, b);
  }
  std::vector<std::size_t> piece(n, no_piece), root_piece(n, no_piece);
  count.clear();
  for (std::size_t i = 0; i < n; ++i)
    if (inside[i]) {
      const std::size_t r = sets.find(i);
      if (root_piece[r] == no_piece) {
        root_piece[r] = count.size();
        count.push_back(0);
      }
      piece[i] = root_piece[r];
      ++count[piece[i]];
    }
  return piece;
}

} // namespace tessera::internal
