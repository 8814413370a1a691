// What `tessera field` writes besides its picture, for library users: singularities.json and
// feature_lines.json as plain report structs built from the library's results
// (`make_singularities_report`, `make_feature_lines_report`) with one JSON writer each compiled
// into Tessera::core (nlohmann-json stays private), and field.csv (`write_field_csv`). The keys and
// their meanings are doc/formats.md's; the CLI writes through these and nothing else.
#pragma once

#include <tessera/fields/feature_lines.h>
#include <tessera/fields/singularities.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <array>
#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace tessera {

/// One singular face: its index (a multiple of 1/symmetry) and its centroid.
struct Singularity_report {
  std::size_t face = 0;
  double index = 0;
  std::array<double, 3> position{};
};

/// The index of one boundary loop, at one of its border halfedges.
struct Boundary_index_report {
  std::size_t halfedge = 0;
  double index = 0;
};

/// singularities.json of `tessera field`: indices as fractions (numerator / symmetry).
struct Singularities_report {
  int symmetry = 1;
  long euler_characteristic = 0;
  double face_index_sum = 0, boundary_index_sum = 0;
  bool poincare_hopf_holds = false;
  std::vector<Singularity_report> singularities;
  std::vector<Boundary_index_report> boundary_loops;
};

/// One feature line: its vertices from the first halfedge's source to the last one's target (a
/// closed line repeats its first vertex at the end).
struct Feature_line_report {
  std::size_t line = 0;
  std::string kind; ///< "boundary", "crease" or "color"
  bool closed = false;
  std::string alignment; ///< "parallel" or "perpendicular"
  std::vector<std::size_t> vertices;
};

/// feature_lines.json of `tessera field` (an array in the file).
struct Feature_lines_report {
  std::vector<Feature_line_report> lines;
};

/// Writes `report` as JSON (indented by 2); false when the stream failed.
bool write_singularities_report(std::ostream& out, const Singularities_report& report);
/// Writes `report` as a JSON array (one key a line); false when the stream failed.
bool write_feature_lines_report(std::ostream& out, const Feature_lines_report& report);

/// The name of a feature kind in feature_lines.json: "boundary", "crease", "color" or "user".
inline const char* feature_kind_name(Feature_kind kind) {
  return kind == Feature_kind::boundary ? "boundary"
         : kind == Feature_kind::crease ? "crease"
         : kind == Feature_kind::user   ? "user"
                                        : "color";
}

/// The report of `field_singularities(tm, …)`: each singular face's position is its centroid.
template <typename TriangleMesh>
Singularities_report make_singularities_report(const TriangleMesh& tm,
                                               const Field_singularities<TriangleMesh>& sing) {
  const double n = sing.symmetry;
  Singularities_report r;
  r.symmetry = sing.symmetry;
  r.euler_characteristic = sing.euler_characteristic;
  r.face_index_sum = double(sing.face_index_sum) / n;
  r.boundary_index_sum = double(sing.boundary_index_sum) / n;
  r.poincare_hopf_holds = sing.poincare_hopf_holds();
  const auto vpm = get(CGAL::vertex_point, tm);
  for (const auto& s : sing.singularities) {
    Singularity_report q;
    q.face = std::size_t(s.face);
    q.index = double(s.numerator) / n;
    for (auto v : CGAL::vertices_around_face(halfedge(s.face, tm), tm)) {
      const auto& p = get(vpm, v);
      for (int c = 0; c < 3; ++c)
        q.position[std::size_t(c)] += CGAL::to_double(p[c]) / 3;
    }
    r.singularities.push_back(q);
  }
  for (const auto& b : sing.boundary_loops)
    r.boundary_loops.push_back({std::size_t(b.halfedge), double(b.numerator) / n});
  return r;
}

/// The report of the feature lines of `tm`, `alignment[l]` saying how the field meets line `l`.
template <typename TriangleMesh>
Feature_lines_report make_feature_lines_report(
    const TriangleMesh& tm,
    const std::vector<
        Feature_line<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>>& lines,
    const std::vector<Feature_alignment>& alignment) {
  Feature_lines_report r;
  for (std::size_t l = 0; l < lines.size(); ++l) {
    Feature_line_report q;
    q.line = l;
    q.kind = feature_kind_name(lines[l].kind);
    q.closed = lines[l].closed;
    q.alignment = l < alignment.size() && alignment[l] == Feature_alignment::perpendicular
                      ? "perpendicular"
                      : "parallel";
    if (!lines[l].halfedges.empty())
      q.vertices.push_back(std::size_t(source(lines[l].halfedges.front(), tm)));
    for (auto h : lines[l].halfedges)
      q.vertices.push_back(std::size_t(target(h, tm)));
    r.lines.push_back(std::move(q));
  }
  return r;
}

/// field.csv: a header line, then per vertex its id, position and field vector (17 digits).
/// Returns false when the stream failed.
template <typename TriangleMesh, typename VertexFieldMap>
bool write_field_csv(std::ostream& out, const TriangleMesh& tm, const VertexFieldMap& field) {
  out << "vertex,x,y,z,field_x,field_y,field_z\n";
  out.precision(17);
  const auto vpm = get(CGAL::vertex_point, tm);
  for (auto v : vertices(tm)) {
    const auto& p = get(vpm, v);
    const auto& f = get(field, v);
    out << std::size_t(v) << "," << p.x() << "," << p.y() << "," << p.z() << "," << f.x() << ","
        << f.y() << "," << f.z() << "\n";
  }
  return bool(out);
}

} // namespace tessera
