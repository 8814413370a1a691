// The canonical polygonal schema on a mesh: the cut-and-paste moves planned on the schema's word
// (internal/schema_word.h) carried out on an M-tiling. A move's diagonal is the shortest cutting
// path between two corners of the disk (Alg. 4's search, after the local refinements that let a
// path through); gluing is removing the seams of the glued side pair. Included by
// topology/cut_graph.h's implementation; not for direct use.
#pragma once

#include <tessera/topology/edge_cost.h>
#include <tessera/topology/internal/cutting_path_search.h>
#include <tessera/topology/internal/schema_word.h>
#include <tessera/topology/internal/tile_refinement.h>
#include <tessera/topology/m_tiling.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace tessera {
namespace internal {

/// What making one component's schema canonical did.
template <typename TriangleMesh> struct Canonical_schema_outcome {
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  bool ok = false;
  std::string message;
  /// Cut-and-paste moves made (each one new loop cut and one removed).
  std::size_t moves = 0;
  std::size_t added_vertices = 0;
  /// The first halfedge of the side where the canonical word starts (a1).
  halfedge_descriptor first_side;
  /// Commutators in the final word (the genus when `ok`).
  std::size_t commutators = 0;
};

/// The word of a polygon given by its sides (halfedge paths in boundary order, the polygon on
/// their left): a side and the side that runs along it backwards are one letter, forwards where
/// it is met first; a side along the mesh border is a letter of its own. `forward[l]` receives
/// letter l's forward side. False when a side not on the border has no reversed partner.
template <typename TriangleMesh, typename Path>
bool read_schema_word(const TriangleMesh& tm, const std::vector<Path>& sides, Schema_word& word,
                      std::vector<Path>& forward) {
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  std::map<halfedge_descriptor, std::size_t> side_starting_with;
  for (std::size_t s = 0; s < sides.size(); ++s)
    if (!sides[s].empty())
      side_starting_with.emplace(sides[s].front(), s);
  std::vector<std::size_t> letter_of_side(sides.size(), std::size_t(-1));
  word.clear();
  forward.clear();
  for (std::size_t s = 0; s < sides.size(); ++s) {
    if (letter_of_side[s] != std::size_t(-1)) {
      word.push_back({letter_of_side[s], true});
      continue;
    }
    const Path& hs = sides[s];
    if (hs.empty())
      return false;
    letter_of_side[s] = forward.size();
    word.push_back({forward.size(), false});
    forward.push_back(hs);
    if (is_border(opposite(hs.front(), tm), tm))
      continue;
    const auto partner = side_starting_with.find(opposite(hs.back(), tm));
    if (partner == side_starting_with.end() || partner->second <= s ||
        sides[partner->second].size() != hs.size())
      return false;
    letter_of_side[partner->second] = letter_of_side[s];
  }
  return true;
}

/// `Cut_polygon::word`: the text of `read_schema_word`, or empty when a side is unpaired.
template <typename TriangleMesh, typename Path>
std::string polygon_word(const TriangleMesh& tm, const std::vector<Path>& sides) {
  Schema_word word;
  std::vector<Path> forward;
  return read_schema_word(tm, sides, word, forward) ? word_text(word) : std::string();
}

/// Brings the polygon of the tile containing `component_face` (a disk cut by a polygonal schema)
/// into canonical form a1 b1 a1^-1 b1^-1 … by cut-and-paste, refining `tm` locally where a diagonal
/// needs room. The tiling follows every change; edge costs of new edges are set from
/// `cost_options`. `genus` is the component's genus: the word must end with that many commutators.
template <typename TriangleMesh, typename EdgeCostMap, typename VertexPointMap>
Canonical_schema_outcome<TriangleMesh>
make_schema_canonical(TriangleMesh& tm, M_tiling<TriangleMesh>& tiling,
                      typename boost::graph_traits<TriangleMesh>::face_descriptor component_face,
                      long genus, EdgeCostMap cost, const Edge_cost_options& cost_options,
                      VertexPointMap vpm) {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  using Path = std::vector<halfedge_descriptor>;
  Canonical_schema_outcome<TriangleMesh> out;
  auto fail = [&](std::string why) {
    out.ok = false;
    out.message = "canonical schema: " + std::move(why);
    return out;
  };

  // The word of the polygon: each side pair is one letter, its forward side the first met.
  const auto tile = tiling.tiles_without_faces()[tiling.tile_of(component_face)];
  if (tile.boundaries.size() != 1 || tile.genus != 0)
    return fail("the component is not cut into one disk");
  std::vector<Path> forward; // letter -> its forward side's halfedges
  std::vector<Path> sides;
  for (const auto& side : tile.sides)
    sides.push_back(side.halfedges);
  Schema_word word;
  if (!read_schema_word(tm, sides, word, forward))
    return fail("a side has no reversed partner");
  const Canonical_plan plan = plan_canonical_schema(word, forward.size());
  if (plan.commutators != std::size_t(genus))
    return fail("the word " + word_text(word) + " does not normalize to " + std::to_string(genus) +
                " commutators (its corners are not all one vertex)");

  // The halfedge arriving at corner i (where side w[i] starts): the end of side w[i - 1].
  const auto corner = [&](const Schema_word& w, std::size_t i) {
    const Signed_letter& s = w[(i + w.size() - 1) % w.size()];
    return s.inverse ? opposite(forward[s.letter].front(), tm) : forward[s.letter].back();
  };
  std::vector<vertex_descriptor> added;
  // One search for all moves. It keeps the cut's vertices blocked across runs and reads them all
  // again when the cut did not just grow (here: after the glued loop's seams are removed).
  std::optional<Cutting_path_search<TriangleMesh, VertexPointMap>> search;
  const auto absorb = [&] {
    tiling.absorb_refinement();
    for (vertex_descriptor v : added)
      for (halfedge_descriptor h : CGAL::halfedges_around_target(v, tm))
        put(cost, edge(h, tm),
            edge_cost(edge(h, tm), tm, cost_options, CGAL::parameters::vertex_point_map(vpm)));
    if (search)
      search->refresh(added);
    out.added_vertices += added.size();
    added.clear();
  };
  bool chords_split = false;
  for (const Cut_and_paste_move& move : plan.moves) {
    const halfedge_descriptor from = corner(word, move.from), to = corner(word, move.to);
    // Room for the diagonal: the chords of the disk (once: afterwards each new diagonal's chords
    // are split right after its cut, and removing seams makes no chord) and narrow wedges at its
    // two corners.
    if (!chords_split) {
      const auto now = tiling.tiles_without_faces()[tiling.tile_of(component_face)];
      if (split_tile_chords(tm, tiling, tile_corners(tiling, now), added, vpm) > 0)
        absorb();
      chords_split = true;
    }
    if (open_narrow_wedges(tm, tiling, {from, to}, added, vpm))
      absorb();
    if (!search)
      search.emplace(
          tiling, 1, [&](auto e) { return double(get(cost, e)); }, vpm);
    search->run({from}, {to});
    const auto best = search->best_arrival(to, [](std::size_t) { return true; });
    if (!best.found())
      return fail("no diagonal found between two corners of the disk");
    const Path diagonal = search->path(best);
    if (tiling.cut(diagonal) != Cut_path_status::ok)
      return fail("a diagonal could not be cut");
    // The diagonal runs from corner `from` to corner `to` with piece 2 (w[to, from)) on its left,
    // which is how cut_and_paste reads the new letter forwards.
    forward.push_back(diagonal);
    std::vector<vertex_descriptor> inner;
    for (std::size_t i = 0; i + 1 < diagonal.size(); ++i)
      inner.push_back(target(diagonal[i], tm));
    if (split_chords_at(tm, tiling, inner, added, vpm) > 0)
      absorb();
    tiling.uncut(forward[move.glue]);
    word = cut_and_paste(word, move);
    ++out.moves;
  }

  // The polygon on the mesh must read as the planned word, up to where its boundary starts.
  const auto final_tile = tiling.tiles_without_faces()[tiling.tile_of(component_face)];
  std::map<halfedge_descriptor, Signed_letter> letter_starting_with;
  for (const Signed_letter& s : word)
    letter_starting_with.emplace(
        s.inverse ? opposite(forward[s.letter].back(), tm) : forward[s.letter].front(), s);
  Schema_word on_mesh;
  for (const auto& side : final_tile.sides) {
    const auto it = letter_starting_with.find(side.halfedges.front());
    if (it == letter_starting_with.end())
      return fail("a side of the final polygon is not a planned side");
    on_mesh.push_back(it->second);
  }
  if (final_tile.boundaries.size() != 1 || on_mesh.size() != word.size())
    return fail("the final polygon is not the planned disk");
  std::size_t shift = 0;
  while (shift < word.size() && on_mesh[shift] != word.front())
    ++shift;
  for (std::size_t i = 0; i < word.size(); ++i)
    if (shift == word.size() || on_mesh[(shift + i) % word.size()] != word[i])
      return fail("the final polygon reads " + word_text(on_mesh) + ", planned " + word_text(word));
  const Signed_letter& first = word[plan.first_commutator];
  out.first_side =
      first.inverse ? opposite(forward[first.letter].back(), tm) : forward[first.letter].front();
  out.commutators = plan.commutators;
  out.ok = true;
  return out;
}

} // namespace internal
} // namespace tessera
