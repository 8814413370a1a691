// What reading a mesh file may repair, and the record of what it did repair: the policy of
// `read_mesh()` and the counts it reports, shared by the reader and its internal repair step.
#pragma once

#include <cstddef>
#include <string>

namespace tessera {

/// What `read_mesh()` may change in a file to make it a valid surface. None of these changes moves
/// a point: they merge, split, drop or reorder vertices and faces.
enum class Mesh_repair {
  /// Refuse any change (polygon triangulation is governed by `Read_mesh_options::triangulate`).
  none,
  /// Merge duplicated points, drop unused vertices and degenerate or duplicated faces, split faces
  /// that pass through one vertex twice, reorient inconsistently oriented faces and split pinched
  /// vertices. Edges shared by more than two faces are refused.
  safe,
  /// `safe`, and also split edges shared by more than two faces (CGAL's `orient_polygon_soup`).
  all
};

/// What reading changed in the file's faces and vertices (all zero for a clean file).
struct Mesh_changes {
  std::size_t merged_vertices = 0;  ///< points equal to an earlier point, merged into it
  std::size_t removed_vertices = 0; ///< vertices no face uses
  std::size_t split_faces = 0;      ///< faces passing through one vertex twice, split
  std::size_t removed_faces = 0;    ///< degenerate or duplicated faces dropped
  std::size_t reoriented_faces = 0; ///< faces reversed to agree with their neighbours
  /// Vertices whose faces form several fans, split (with `Mesh_repair::all`, the ends of split
  /// edges count too).
  std::size_t pinched_vertices = 0;
  std::size_t non_manifold_edges = 0; ///< edges of more than two faces, split (`Mesh_repair::all`)
  /// True when any count is non-zero: vertex ids then differ from the file's.
  bool any() const {
    return merged_vertices + removed_vertices + split_faces + removed_faces + reoriented_faces +
               pinched_vertices + non_manifold_edges >
           0;
  }
  /// The non-zero counts as one phrase, e.g. "3 faces reoriented, 1 pinched vertex split".
  std::string to_string() const {
    std::string out;
    auto add = [&](std::size_t n, const char* one, const char* many, const char* what) {
      if (n == 0)
        return;
      if (!out.empty())
        out += ", ";
      out += std::to_string(n) + " " + (n == 1 ? one : many) + " " + what;
    };
    add(merged_vertices, "duplicated point", "duplicated points", "merged");
    add(removed_vertices, "unused vertex", "unused vertices", "removed");
    add(split_faces, "face through a vertex twice", "faces through a vertex twice", "split");
    add(removed_faces, "degenerate or duplicated face", "degenerate or duplicated faces",
        "removed");
    add(reoriented_faces, "face", "faces", "reoriented");
    add(pinched_vertices, "pinched vertex", "pinched vertices", "split");
    add(non_manifold_edges, "edge of more than two faces", "edges of more than two faces", "split");
    return out;
  }
};

} // namespace tessera
