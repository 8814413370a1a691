// Vertex tangent spaces and the discrete Levi-Civita connection between them, after Knöppel, Crane,
// Pinkall, Schröder, "Globally optimal direction fields" (SIGGRAPH 2013), §5.1: corner angles
// rescaled to sum to 2π around interior vertices, transport along edges, holonomy as angle excess
// per face.
#pragma once

#include <CGAL/Kernel_traits.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <tessera/internal/named_parameters.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <utility>
#include <vector>

namespace tessera::internal {

/// A 3D vector in double precision (its own type so that the operators below are found by ADL).
struct Vec3 : std::array<double, 3> {};

inline Vec3 operator-(const Vec3& a, const Vec3& b) {
  return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}};
}
inline Vec3 operator+(const Vec3& a, const Vec3& b) {
  return {{a[0] + b[0], a[1] + b[1], a[2] + b[2]}};
}
inline Vec3 operator*(double s, const Vec3& a) {
  return {{s * a[0], s * a[1], s * a[2]}};
}
inline double dot(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}
inline double norm(const Vec3& a) {
  return std::sqrt(dot(a, a));
}
/// Angle in [0, π] between `a` and `b`; 0 when either vanishes (atan2 never yields NaN here).
inline double angle_between(const Vec3& a, const Vec3& b) {
  return std::atan2(norm(cross(a, b)), dot(a, b));
}

template <typename Vector> Vec3 to_vec3(const Vector& v) {
  return {{CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z())}};
}

/// The connection data every field algorithm shares. Vertex v's tangent space has the orthonormal
/// basis (e1, e2) with e2 = N × e1, N the angle-weighted vertex normal and e1 the projection of the
/// reference outgoing edge; intrinsic angles are measured from that edge, counter-clockwise.
/// A 3D tangent vector at angle ψ in (e1, e2) has intrinsic angle ψ (geometry-central's
/// convention), so rotations about N are rotations of the intrinsic angle.
template <typename TriangleMesh> class Vertex_frames {
public:
  using GT = boost::graph_traits<TriangleMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using face_descriptor = typename GT::face_descriptor;
  using Point = typename boost::property_traits<
      typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type;
  using Kernel = typename CGAL::Kernel_traits<Point>::Kernel;
  using Vector_3 = typename Kernel::Vector_3;

  /// Named parameters: `vertex_point_map`.
  template <typename NamedParameters = CGAL::parameters::Default_named_parameters>
  explicit Vertex_frames(const TriangleMesh& tm,
                         const NamedParameters& np = CGAL::parameters::default_values())
      : tm_(tm), index_(get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm)),
        angle_(get(CGAL::dynamic_halfedge_property_t<double>(), tm)),
        corner_(get(CGAL::dynamic_halfedge_property_t<double>(), tm)) {
    const auto vpm = vertex_point_map(tm, np);
    for (vertex_descriptor v : vertices(tm)) {
      put(index_, v, vertices_.size());
      vertices_.push_back(v);
      points_.push_back(to_vec3(get(vpm, v) - CGAL::ORIGIN));
    }
    const std::size_t n = vertices_.size();
    normal_.assign(n, Vec3{{0, 0, 0}});
    e1_.assign(n, Vec3{{1, 0, 0}});
    angle_sum_.assign(n, 2 * pi());
    border_.assign(n, false);
    fan_map_.assign(n, {});
    for (vertex_descriptor v : vertices_)
      build_vertex(v);
  }

  static double pi() { return std::acos(-1.0); }
  const TriangleMesh& mesh() const { return tm_; }
  std::size_t size() const { return vertices_.size(); }
  std::size_t index(vertex_descriptor v) const { return get(index_, v); }
  vertex_descriptor vertex(std::size_t i) const { return vertices_[i]; }
  const Vec3& point(std::size_t i) const { return points_[i]; }
  const Vec3& normal(std::size_t i) const { return normal_[i]; }
  const Vec3& e1(std::size_t i) const { return e1_[i]; }
  Vec3 e2(std::size_t i) const { return cross(normal_[i], e1_[i]); }
  bool is_border_vertex(std::size_t i) const { return border_[i]; }
  /// Total intrinsic angle around vertex i: 2π inside, the corner-angle sum on the border.
  double angle_sum(std::size_t i) const { return angle_sum_[i]; }

  /// Intrinsic angle of the outgoing halfedge `h` in the frame of source(h).
  double angle(halfedge_descriptor h) const { return get(angle_, h); }
  /// Rescaled corner angle at source(h) in face(h).
  double corner(halfedge_descriptor h) const { return get(corner_, h); }
  /// Angle ρ by which transport along `h` rotates an intrinsic angle from source(h) to target(h).
  double transport(halfedge_descriptor h) const {
    return angle(opposite(h, tm_)) - angle(h) + pi();
  }
  /// Holonomy (angle excess) of face f: sum of its rescaled corner angles minus π. These sum to 2π
  /// χ over a closed surface, which is what makes Poincaré–Hopf hold exactly for face indices.
  double holonomy(face_descriptor f) const {
    double sum = -pi();
    for (halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm_), tm_))
      sum += corner(h);
    return sum;
  }
  double length(halfedge_descriptor h) const {
    return norm(points_[index(target(h, tm_))] - points_[index(source(h, tm_))]);
  }

  /// Power representation |X| e^{i n ψ} of the tangent part of X at vertex i.
  /// The angle in (e1, e2) of the tangent part is taken to an intrinsic angle through the fan:
  /// between two outgoing edges, as far from one to the other as it is between their projections,
  /// so a vector along an edge gets exactly that edge's intrinsic angle. (Across a crease the
  /// tangent plane, the mean of the faces', foreshortens the faces' angles: a line's tangent read
  /// by its projection alone was 1–8° off the angle that the transport gives its edge, which bent
  /// the field across a CAD part's flat faces.) Where the projected fan folds over, the projected
  /// angle is taken as it is.
  std::complex<double> to_power(std::size_t i, const Vec3& x, int n) const {
    const Vec3 e2v = e2(i);
    const double a = dot(x, e1_[i]), b = dot(x, e2v);
    const double r = std::hypot(a, b);
    if (r == 0)
      return {0, 0};
    return std::polar(r, n * along_fan(i, std::atan2(b, a), false));
  }
  /// The representative 3D vector of power vector u at vertex i (angle arg(u)/n, length |u| or 1),
  /// the intrinsic angle taken back through the fan as `to_power` takes it.
  Vec3 from_power(std::size_t i, std::complex<double> u, int n, bool unit) const {
    const double r = std::abs(u);
    if (r == 0)
      return {{0, 0, 0}};
    const double psi = along_fan(i, std::arg(u) / n, true), len = unit ? 1.0 : r;
    return (len * std::cos(psi)) * e1_[i] + (len * std::sin(psi)) * e2(i);
  }

private:
  // Angle `a` (radians) taken from the projection's angles to the intrinsic ones (`back`: the
  // other way) by the piecewise-linear map through the fan's edges (`fan_map_`); unchanged at a
  // vertex without one.
  double along_fan(std::size_t i, double a, bool back) const {
    const std::vector<std::array<double, 2>>& m = fan_map_[i];
    if (m.empty())
      return a;
    const int from = back ? 1 : 0, to = back ? 0 : 1;
    const double two_pi = 2 * pi();
    a = std::fmod(a, two_pi);
    if (a < 0)
      a += two_pi;
    // m runs from (0, 0) to (2π, 2π), increasing in both.
    const auto it = std::upper_bound(
        m.begin(), m.end(), a, [&](double x, const auto& p) { return x < p[std::size_t(from)]; });
    if (it == m.begin() || it == m.end())
      return a;
    const auto& p = *(it - 1);
    const auto& q = *it;
    const double span = q[std::size_t(from)] - p[std::size_t(from)];
    const double t = span > 0 ? (a - p[std::size_t(from)]) / span : 0;
    return p[std::size_t(to)] + t * (q[std::size_t(to)] - p[std::size_t(to)]);
  }

  // The fan's (projected angle, intrinsic angle) pairs at vertex i, from (0, 0) to (2π, 2π), or
  // none where the projected edges do not turn one way around the normal.
  void build_fan_map(std::size_t i, const std::vector<halfedge_descriptor>& fan) {
    auto dir = [&](halfedge_descriptor h) { return points_[index(target(h, tm_))] - points_[i]; };
    const Vec3 e2v = e2(i);
    std::vector<std::array<double, 2>> m;
    const double two_pi = 2 * pi();
    for (halfedge_descriptor h : fan) {
      const Vec3 d = dir(h);
      double phi = std::atan2(dot(d, e2v), dot(d, e1_[i]));
      if (phi < 0)
        phi += two_pi;
      if (m.empty())
        phi = 0; // the reference edge, e1's own
      else if (!(phi > m.back()[0]) || !(get(angle_, h) > m.back()[1]))
        return; // folded, or a degenerate corner: no map
      m.push_back({{phi, get(angle_, h)}});
    }
    if (m.back()[0] >= two_pi || m.back()[1] >= two_pi)
      return;
    m.push_back({{two_pi, two_pi}});
    fan_map_[i] = std::move(m);
  }

  // Outgoing halfedges of v in counter-clockwise order; on the border the first one is the border
  // edge whose face lies to its left, so the fan's angles run from 0 to the corner-angle sum.
  std::vector<halfedge_descriptor> outgoing_fan(vertex_descriptor v, bool& border) const {
    std::vector<halfedge_descriptor> fan;
    border = true;
    if (halfedge(v, tm_) == GT::null_halfedge())
      return fan;
    halfedge_descriptor start = opposite(halfedge(v, tm_), tm_);
    border = false;
    for (halfedge_descriptor h : CGAL::halfedges_around_source(start, tm_))
      if (is_border(opposite(h, tm_), tm_) && !is_border(h, tm_)) {
        start = h;
        border = true;
        break;
      }
    halfedge_descriptor h = start;
    do {
      fan.push_back(h);
      if (is_border(h, tm_))
        break;
      h = opposite(prev(h, tm_), tm_);
    } while (h != start);
    return fan;
  }

  void build_vertex(vertex_descriptor v) {
    const std::size_t i = index(v);
    bool border = false;
    const std::vector<halfedge_descriptor> fan = outgoing_fan(v, border);
    border_[i] = border;
    if (fan.empty())
      return; // isolated vertex: default frame
    auto dir = [&](halfedge_descriptor h) { return points_[index(target(h, tm_))] - points_[i]; };
    std::vector<double> corners;
    Vec3 normal{{0, 0, 0}};
    for (halfedge_descriptor h : fan) {
      if (is_border(h, tm_))
        continue;
      const Vec3 a = dir(h), b = dir(opposite(prev(h, tm_), tm_));
      const double alpha = angle_between(a, b);
      corners.push_back(alpha);
      const Vec3 fn = cross(a, b);
      const double len = norm(fn);
      if (len > 0)
        normal = normal + (alpha / len) * fn;
    }
    double total = 0;
    for (double c : corners)
      total += c;
    // Rescale inside so the angles close up (Knöppel et al. §5.1); a star of degenerate triangles
    // gets equal corners.
    if (total == 0) {
      for (double& c : corners)
        c = (border ? pi() : 2 * pi()) / double(corners.size());
      total = border ? pi() : 2 * pi();
    }
    const double scale = border ? 1.0 : 2 * pi() / total;
    double a = 0, sum = 0;
    for (std::size_t k = 0; k < fan.size(); ++k) {
      put(angle_, fan[k], a);
      if (k < corners.size()) {
        put(corner_, fan[k], corners[k] * scale);
        a += corners[k] * scale;
        sum += corners[k] * scale;
      }
    }
    angle_sum_[i] = border ? sum : 2 * pi();

    const double nl = norm(normal);
    normal_[i] = nl > 0 ? (1 / nl) * normal : Vec3{{0, 0, 1}};
    const Vec3 ref = dir(fan.front());
    Vec3 t = ref - dot(ref, normal_[i]) * normal_[i];
    if (norm(t) < 1e-12 * (norm(ref) + 1e-300)) {
      const Vec3 axis = std::abs(normal_[i][0]) < 0.9 ? Vec3{{1, 0, 0}} : Vec3{{0, 1, 0}};
      t = cross(normal_[i], axis);
    }
    e1_[i] = (1 / norm(t)) * t;
    build_fan_map(i, fan);
  }

  template <typename T>
  using Vertex_map =
      decltype(get(CGAL::dynamic_vertex_property_t<T>(), std::declval<const TriangleMesh&>()));
  template <typename T>
  using Halfedge_map =
      decltype(get(CGAL::dynamic_halfedge_property_t<T>(), std::declval<const TriangleMesh&>()));

  const TriangleMesh& tm_;
  Vertex_map<std::size_t> index_;
  Halfedge_map<double> angle_, corner_;
  std::vector<vertex_descriptor> vertices_;
  std::vector<Vec3> points_, normal_, e1_;
  std::vector<std::vector<std::array<double, 2>>> fan_map_;
  std::vector<double> angle_sum_;
  std::vector<bool> border_;
};

} // namespace tessera::internal
