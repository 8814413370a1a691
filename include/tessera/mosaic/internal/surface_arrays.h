// Dense, double-precision copies of what the mosaic stages read from a triangle mesh over and over
// (corner positions, face frames, areas, adjacency, regions between feature lines), built once so
// the inner loops touch flat arrays instead of walking halfedges through property maps.
#pragma once

#include <tessera/fields/feature_lines.h>
#include <tessera/fields/internal/vertex_frames.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/property_map.h>

#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace tessera::internal {

inline constexpr std::uint32_t no_index = std::uint32_t(-1);

/// A point on the surface: a face (dense id) and barycentric coordinates in it.
struct Surface_point {
  std::uint32_t face = 0;
  std::array<double, 3> bary{{1.0 / 3, 1.0 / 3, 1.0 / 3}};
};

/// The field interpolated at barycentric coordinates `b` of a face from its corners' vectors `x`,
/// as an angle in the frame (e1, e2): the power average Σ b_k e^{inθ_k} (zero vectors left out),
/// its argument divided by n. False when the average vanishes (a singular point).
inline bool interpolated_field_angle(const std::array<Vec3, 3>& x, const std::array<double, 3>& b,
                                     const Vec3& e1, const Vec3& e2, int n, double& angle) {
  std::complex<double> sum = 0;
  for (int k = 0; k < 3; ++k)
    if (norm(x[k]) > 0)
      sum += b[k] * std::polar(1.0, n * std::atan2(dot(x[k], e2), dot(x[k], e1)));
  if (!(std::abs(sum) > 0))
    return false;
  angle = std::arg(sum) / n;
  return true;
}

template <typename TriangleMesh> class Surface_arrays {
public:
  using GT = boost::graph_traits<TriangleMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using face_descriptor = typename GT::face_descriptor;

  /// `feature_edges` marks, by halfedge, the edges no tile may cross (feature lines); faces
  /// connected across other edges form one region.
  template <typename VertexPointMap>
  Surface_arrays(const TriangleMesh& tm, VertexPointMap vpm,
                 const std::vector<Feature_line<halfedge_descriptor>>& features)
      : tm_(tm), vertex_id_(get(CGAL::dynamic_vertex_property_t<std::uint32_t>(), tm)),
        face_id_(get(CGAL::dynamic_face_property_t<std::uint32_t>(), tm)) {
    for (vertex_descriptor v : vertices(tm)) {
      put(vertex_id_, v, std::uint32_t(vertices_.size()));
      vertices_.push_back(v);
      points_.push_back(to_vec3(get(vpm, v) - CGAL::ORIGIN));
    }
    for (face_descriptor f : faces(tm)) {
      put(face_id_, f, std::uint32_t(faces_.size()));
      faces_.push_back(f);
    }
    const std::size_t nf = faces_.size();
    corners_.resize(nf);
    neighbors_.resize(nf);
    across_.resize(nf);
    normal_.resize(nf);
    area_.resize(nf);
    auto is_feature = get(CGAL::dynamic_edge_property_t<bool>(), tm);
    for (auto e : edges(tm))
      put(is_feature, e, false);
    for (const auto& line : features)
      for (halfedge_descriptor h : line.halfedges)
        put(is_feature, edge(h, tm), true);
    for (std::size_t f = 0; f < nf; ++f) {
      halfedge_descriptor h = halfedge(faces_[f], tm);
      for (int k = 0; k < 3; ++k, h = next(h, tm)) {
        corners_[f][k] = get(vertex_id_, target(prev(h, tm), tm));
        // neighbors_[f][k]: the face across the edge opposite corner k+2, i.e. from corner k to
        // k+1.
        const halfedge_descriptor o = opposite(h, tm);
        neighbors_[f][k] = is_border(o, tm) || get(is_feature, edge(h, tm))
                               ? no_index
                               : get(face_id_, face(o, tm));
        across_[f][k] = is_border(o, tm) ? no_index : get(face_id_, face(o, tm));
      }
      const Vec3 n = cross(point(f, 1) - point(f, 0), point(f, 2) - point(f, 0));
      area_[f] = norm(n) / 2;
      normal_[f] = area_[f] > 0 ? (1 / (2 * area_[f])) * n : Vec3{{0, 0, 1}};
      total_area_ += area_[f];
    }
    // Regions: faces connected across edges that are neither borders nor features.
    auto region = get(CGAL::dynamic_face_property_t<std::size_t>(), tm);
    regions_ = CGAL::Polygon_mesh_processing::connected_components(
        tm, region, CGAL::parameters::edge_is_constrained_map(is_feature));
    region_.resize(nf);
    for (std::size_t f = 0; f < nf; ++f)
      region_[f] = std::uint32_t(get(region, faces_[f]));
    // Connected components (faces joined across any edge but a border), per region: regions
    // of different components share no edge, so only a surface that runs into itself (patches
    // that overlap at their seams, sheets that intersect) brings them together.
    auto component = get(CGAL::dynamic_face_property_t<std::size_t>(), tm);
    CGAL::Polygon_mesh_processing::connected_components(tm, component);
    region_component_.assign(regions_, 0);
    for (std::size_t f = 0; f < nf; ++f)
      region_component_[region_[f]] = std::uint32_t(get(component, faces_[f]));
  }

  const TriangleMesh& mesh() const { return tm_; }
  std::size_t number_of_faces() const { return faces_.size(); }
  std::size_t number_of_vertices() const { return vertices_.size(); }
  std::size_t number_of_regions() const { return regions_; }
  face_descriptor face_of(std::uint32_t f) const { return faces_[f]; }
  vertex_descriptor vertex_of(std::uint32_t v) const { return vertices_[v]; }
  std::uint32_t id(face_descriptor f) const { return get(face_id_, f); }
  std::uint32_t id(vertex_descriptor v) const { return get(vertex_id_, v); }
  const std::array<std::uint32_t, 3>& corners(std::uint32_t f) const { return corners_[f]; }
  /// Face across the edge from corner k to corner k+1, or `no_index` on a border or feature line.
  std::uint32_t neighbor(std::uint32_t f, int k) const { return neighbors_[f][k]; }
  /// Face across that edge ignoring feature lines (`no_index` only on a border).
  std::uint32_t across(std::uint32_t f, int k) const { return across_[f][k]; }
  const Vec3& point(std::uint32_t f, int k) const { return points_[corners_[f][k]]; }
  const Vec3& vertex_point(std::uint32_t v) const { return points_[v]; }
  const Vec3& normal(std::uint32_t f) const { return normal_[f]; }
  double area(std::uint32_t f) const { return area_[f]; }
  double total_area() const { return total_area_; }
  std::uint32_t region(std::uint32_t f) const { return region_[f]; }
  /// Whether regions a and b belong to different connected components of the surface.
  bool apart(std::uint32_t a, std::uint32_t b) const {
    return region_component_[a] != region_component_[b];
  }

  Vec3 position(const Surface_point& p) const {
    return p.bary[0] * point(p.face, 0) + p.bary[1] * point(p.face, 1) +
           p.bary[2] * point(p.face, 2);
  }
  Vec3 centroid(std::uint32_t f) const {
    return (1.0 / 3) * (point(f, 0) + point(f, 1) + point(f, 2));
  }

  /// Where a walk on the surface ends, and whether it stopped early at a border or feature line.
  struct Walk {
    Surface_point p;
    bool blocked = false;
    double short_by = 0; ///< the length not walked, when blocked
  };

  /// Walks from `from` by the tangent vector `d` (projected into the start face's plane) along
  /// the surface: straight within a face, and across an edge turned about it into the next face's
  /// plane (the two faces unfolded into one plane), so the length walked is |d| however the
  /// surface bends. A walk stops on a border or feature line edge (`blocked`). Moving a tile this
  /// way keeps it on its own sheet: a step towards the closest point of the surface could land on
  /// the far side of a part thinner than the step.
  Walk walk(const Surface_point& from, const Vec3& d) const {
    std::uint32_t f = from.face;
    Vec3 x = position(from);
    Vec3 r = d - dot(d, normal(f)) * normal(f);
    std::array<double, 3> b = from.bary;
    // A walk crosses about |d| / (edge length) faces; the bound only stops a walk that circles
    // a vertex in degenerate faces.
    for (int crossings = 0; crossings < 256; ++crossings) {
      const std::array<double, 3> t = barycentric_unclamped(f, x + r);
      int exit = -1;
      double first = 1;
      for (int k = 0; k < 3; ++k)
        if (t[k] < 0) {
          // The segment x → x + r leaves the face where corner k's coordinate reaches zero.
          const double at = b[k] / (b[k] - t[k]);
          if (at < first || exit < 0)
            first = at, exit = k;
        }
      if (exit < 0)
        return {Surface_point{f, clamped(t)}, false, 0};
      first = std::clamp(first, 0.0, 1.0);
      x = x + first * r;
      r = (1 - first) * r;
      // The edge opposite corner `exit` runs from corner exit+1 to exit+2.
      const int k = (exit + 1) % 3;
      const std::uint32_t g = neighbor(f, k);
      if (g == no_index)
        return {Surface_point{f, barycentric(f, x)}, true, norm(r)};
      Vec3 e = point(f, (k + 1) % 3) - point(f, k);
      const double l = norm(e);
      if (l > 0)
        e = (1 / l) * e;
      // The rotation about e taking f's normal to g's takes n_f × e to n_g × e.
      r = dot(r, e) * e + dot(r, cross(normal(f), e)) * cross(normal(g), e);
      f = g;
      b = barycentric(f, x);
      x = position(Surface_point{f, b});
    }
    return {Surface_point{f, b}, false, 0};
  }

  /// Barycentric coordinates of q (projected onto face f's plane), not clamped.
  std::array<double, 3> barycentric_unclamped(std::uint32_t f, const Vec3& q) const {
    const Vec3 a = point(f, 0), b = point(f, 1), c = point(f, 2);
    const Vec3 v0 = b - a, v1 = c - a, v2 = q - a;
    const double d00 = dot(v0, v0), d01 = dot(v0, v1), d11 = dot(v1, v1), d20 = dot(v2, v0),
                 d21 = dot(v2, v1);
    const double den = d00 * d11 - d01 * d01;
    if (!(std::abs(den) > 0))
      return {{1.0 / 3, 1.0 / 3, 1.0 / 3}};
    const double y = (d11 * d20 - d01 * d21) / den, z = (d00 * d21 - d01 * d20) / den;
    return {{1 - y - z, y, z}};
  }

  /// Barycentric coordinates of q (projected onto face f's plane), clamped into the triangle.
  std::array<double, 3> barycentric(std::uint32_t f, const Vec3& q) const {
    return clamped(barycentric_unclamped(f, q));
  }

private:
  static std::array<double, 3> clamped(std::array<double, 3> t) {
    for (double& c : t)
      c = std::max(c, 0.0);
    const double s = t[0] + t[1] + t[2];
    if (!(s > 0))
      return {{1.0 / 3, 1.0 / 3, 1.0 / 3}};
    return {{t[0] / s, t[1] / s, t[2] / s}};
  }

  const TriangleMesh& tm_;
  decltype(get(CGAL::dynamic_vertex_property_t<std::uint32_t>(),
               std::declval<const TriangleMesh&>())) vertex_id_;
  decltype(get(CGAL::dynamic_face_property_t<std::uint32_t>(),
               std::declval<const TriangleMesh&>())) face_id_;
  std::vector<vertex_descriptor> vertices_;
  std::vector<face_descriptor> faces_;
  std::vector<Vec3> points_;
  std::vector<std::array<std::uint32_t, 3>> corners_, neighbors_, across_;
  std::vector<Vec3> normal_;
  std::vector<double> area_;
  std::vector<std::uint32_t> region_, region_component_;
  std::size_t regions_ = 0;
  double total_area_ = 0;
};

} // namespace tessera::internal
