// Validation that a refined triangle mesh (a quadrangulation's surface after local refinement, or
// any mesh said to be a subdivision of another) lies on the original surface and tiles it: every
// refined vertex on an original vertex, edge or face; every refined face inside one original face,
// neither degenerate nor inverted; and the refined faces inside each original face add up to it.
// With an exact kernel (CGAL::Epeck) read from text without rounding and a zero tolerance, every
// test is exact.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace tessera {

struct Validate_refinement_options {
  /// Largest distance from the original surface, relative to its bounding-box diagonal, at which a
  /// refined vertex still counts as on it; coverage sums compare with the same relative tolerance.
  /// 0 asks for exact tests: the answer is then exact when the kernel's constructions are
  /// (CGAL::Epeck), and with CGAL::Epick holds for the coordinates as doubles.
  double tolerance = 1e-9;
  /// Problems kept per kind (all are counted).
  std::size_t max_problems_per_kind = 20;
};

enum class Refinement_problem_kind {
  /// A refined vertex on no original face.
  off_surface,
  /// A refined face whose corners lie on no common original face.
  straddles_faces,
  degenerate_face,
  /// A refined face turned against the original face it lies in.
  inverted_face,
  /// The refined faces inside an original face do not add up to its area.
  coverage
};
constexpr std::size_t refinement_problem_kinds = 5;

/// One problem; ids are indices in the refined mesh's vertex or face order, `original_faces` in the
/// original's face order.
struct Refinement_problem {
  Refinement_problem_kind kind;
  std::string message;
  std::vector<std::size_t> vertices;
  std::vector<std::size_t> faces;
  std::vector<std::size_t> original_faces;
};

enum class Refinement_validation_status { valid, invalid, not_triangles };

struct Refinement_validation {
  Refinement_validation_status status = Refinement_validation_status::valid;
  std::string message;
  /// Refined vertices that coincide with an original vertex, lie inside an original edge, or
  /// inside an original face.
  std::size_t on_original_vertices = 0, on_original_edges = 0, inside_original_faces = 0;
  /// Whether the tests were exact (tolerance 0).
  bool exact = false;
  std::array<std::size_t, refinement_problem_kinds> problem_counts{};
  std::vector<Refinement_problem> problems;
  explicit operator bool() const { return status == Refinement_validation_status::valid; }
};

/// Checks that `refined` is a refinement of `original` (both triangle meshes with the same point
/// type). Candidate faces are found with a CGAL::AABB_tree on double approximations; the tests
/// themselves use the meshes' kernel.
template <typename TriangleMesh>
Refinement_validation validate_refinement(const TriangleMesh& original, const TriangleMesh& refined,
                                          const Validate_refinement_options& options = {});

} // namespace tessera

#include <tessera/topology/internal/validate_refinement_impl.h>
