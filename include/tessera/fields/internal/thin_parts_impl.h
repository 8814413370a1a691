// The girth and axis estimate behind thin_part_constraints() (see thin_parts.h).
#pragma once

#include <tessera/fields/internal/vertex_frames.h>
#include <tessera/internal/named_parameters.h>
#include <tessera/internal/parallel.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace tessera::internal {

/// (λ2 − λ3) / λ1 of the normal covariance of a cylinder of radius 1 over the part of it within
/// distance ρ of a point (the patch's faces are those whose centroids lie in the ball): the normal
/// at angle φ from the point's is (cos φ, sin φ, 0) and the ball's axial extent there is
/// √(ρ² − (2 sin(φ/2))²).
inline double cylinder_normal_spread(double rho) {
  constexpr int steps = 512;
  const double pi = std::acos(-1.0);
  double along = 0, across = 0;
  for (int k = 0; k < steps; ++k) {
    const double phi = -pi + (k + 0.5) * 2 * pi / steps;
    const double chord = 2 * std::sin(phi / 2);
    const double w = std::sqrt(std::max(0.0, rho * rho - chord * chord));
    along += w * std::cos(phi) * std::cos(phi);
    across += w * std::sin(phi) * std::sin(phi);
  }
  return along > 0 ? std::min(along, across) / std::max(along, across) : 0;
}

/// Tiles around a cylinder whose patch of radius `radius_over_spacing` spacings has normal spread
/// `q`: the radius ρ with cylinder_normal_spread(ρ) = q, then 2π · radius_over_spacing / ρ. The
/// spread grows with ρ; it is tabulated once over ρ ∈ [0.001, 2.5] and inverted by binary search
/// and linear interpolation (a bisection on the integral cost 41 integrals per sample, most of
/// the estimate's time). Beyond ρ = 2.5 the patch wraps the part and the spread is within 1.5 % of
/// 1, too close to tell girths apart: thinner parts read as that girth.
inline double tiles_around_from_spread(double q, double radius_over_spacing) {
  constexpr std::size_t n = 2048;
  constexpr double lo = 1e-3, hi = 2.5;
  static const std::vector<double> spread = [] {
    std::vector<double> t(n);
    for (std::size_t k = 0; k < n; ++k)
      t[k] = cylinder_normal_spread(lo + (hi - lo) * double(k) / double(n - 1));
    return t;
  }();
  const double pi = std::acos(-1.0);
  if (!(q > 1e-6))
    return std::numeric_limits<double>::infinity();
  if (spread.back() <= q)
    return 2 * pi * radius_over_spacing / hi;
  const std::size_t k =
      std::size_t(std::upper_bound(spread.begin(), spread.end(), q) - spread.begin());
  double rho = lo;
  if (k > 0) {
    const double t = (q - spread[k - 1]) / (spread[k] - spread[k - 1]);
    rho = lo + (hi - lo) * (double(k - 1) + t) / double(n - 1);
  }
  return 2 * pi * radius_over_spacing / rho;
}

/// Per-vertex girth (in tiles around) and axis, measured on patches one spacing wide around
/// samples half a spacing apart. With `slice_up_to` > 0, a sample whose normal spread reads fewer
/// than twice that many tiles around has its girth measured instead as the length of the loop the
/// plane through it across the axis cuts from the surface: that loop's length when it closes
/// within `slice_up_to` spacings, infinite when it does not (it runs into a border, or around more
/// than a thin part).
template <typename TriangleMesh> class Thin_part_estimator {
public:
  using GT = boost::graph_traits<TriangleMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using face_descriptor = typename GT::face_descriptor;
  using Vector_3 = typename Vertex_frames<TriangleMesh>::Vector_3;

  struct Estimate {
    double tiles_around = std::numeric_limits<double>::infinity();
    /// What the normal spread alone reads (equal to `tiles_around` where nothing was sliced).
    double spread_tiles_around = std::numeric_limits<double>::infinity();
    Vector_3 axis{0, 0, 0};
    bool axis_valid = false;
    /// A third of the incident faces' area.
    double area = 0;
  };

  template <typename NamedParameters>
  Thin_part_estimator(const TriangleMesh& tm, double spacing, double radius,
                      const NamedParameters& np, double slice_up_to = 0)
      : tm_(tm), spacing_(spacing), radius_(radius), slice_up_to_(slice_up_to),
        vertex_index_(get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm)),
        face_index_(get(CGAL::dynamic_face_property_t<std::size_t>(), tm)) {
    const auto vpm = vertex_point_map(tm, np);
    for (vertex_descriptor v : vertices(tm)) {
      put(vertex_index_, v, vertices_.size());
      vertices_.push_back(v);
      points_.push_back(to_vec3(get(vpm, v) - CGAL::ORIGIN));
    }
    for (face_descriptor f : faces(tm)) {
      put(face_index_, f, faces_.size());
      faces_.push_back(f);
    }
    centroid_.resize(faces_.size());
    normal_.resize(faces_.size());
    area_.resize(faces_.size());
    vertex_normal_.assign(vertices_.size(), Vec3{{0, 0, 0}});
    estimate_.resize(vertices_.size());
    for (std::size_t f = 0; f < faces_.size(); ++f) {
      Vec3 c{{0, 0, 0}}, n{{0, 0, 0}};
      std::array<std::size_t, 3> corner{};
      int k = 0;
      for (vertex_descriptor v : CGAL::vertices_around_face(halfedge(faces_[f], tm), tm)) {
        if (k < 3)
          corner[std::size_t(k)] = get(vertex_index_, v);
        c = c + points_[get(vertex_index_, v)];
        ++k;
      }
      if (k >= 3)
        n = cross(points_[corner[1]] - points_[corner[0]], points_[corner[2]] - points_[corner[0]]);
      const double twice_area = norm(n);
      centroid_[f] = (1.0 / std::max(k, 1)) * c;
      area_[f] = std::isfinite(twice_area) ? 0.5 * twice_area : 0;
      normal_[f] = twice_area > 0 && std::isfinite(twice_area) ? (1 / twice_area) * n : Vec3{};
      for (vertex_descriptor v : CGAL::vertices_around_face(halfedge(faces_[f], tm), tm)) {
        const std::size_t i = get(vertex_index_, v);
        vertex_normal_[i] = vertex_normal_[i] + area_[f] * normal_[f];
        estimate_[i].area += area_[f] / std::max(k, 1);
      }
    }
  }

  void estimate() {
    // Samples, half a spacing apart: each takes the vertices near it that no earlier one took.
    std::vector<std::size_t> owner(vertices_.size(), none), samples;
    std::vector<std::size_t> patch;
    std::vector<char> seen(faces_.size(), 0);
    for (std::size_t i = 0; i < vertices_.size(); ++i) {
      if (owner[i] != none || halfedge(vertices_[i], tm_) == GT::null_halfedge())
        continue;
      owner[i] = samples.size();
      grow_patch(i, 0.5 * std::min(spacing_, radius_), seen, patch);
      for (std::size_t f : patch)
        for (vertex_descriptor v : CGAL::vertices_around_face(halfedge(faces_[f], tm_), tm_)) {
          std::size_t& o = owner[get(vertex_index_, v)];
          if (o == none)
            o = samples.size();
        }
      samples.push_back(i);
    }
    // The samples' patches are measured in parallel.
    std::vector<double> tiles(samples.size(), std::numeric_limits<double>::infinity());
    std::vector<double> spread(samples.size(), std::numeric_limits<double>::infinity());
    std::vector<char> sliced(samples.size(), 0);
    std::vector<Vec3> axis(samples.size(), Vec3{{0, 0, 0}});
    parallel_blocks(samples.size(), [&](std::size_t first, std::size_t last) {
      std::vector<char> mark(faces_.size(), 0);
      std::vector<std::size_t> faces;
      for (std::size_t s = first; s < last; ++s) {
        grow_patch(samples[s], radius_, mark, faces);
        Eigen::Matrix3d c = Eigen::Matrix3d::Zero();
        for (std::size_t f : faces) {
          const Eigen::Vector3d n(normal_[f][0], normal_[f][1], normal_[f][2]);
          c += area_[f] * n * n.transpose();
        }
        if (!(c.trace() > 0) || !std::isfinite(c.trace()))
          continue;
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(c);
        const Eigen::Vector3d lambda = eigen.eigenvalues(); // ascending
        tiles[s] =
            tiles_around_from_spread((lambda[1] - lambda[0]) / lambda[2], radius_ / spacing_);
        const Eigen::Vector3d a = eigen.eigenvectors().col(0);
        axis[s] = Vec3{{a[0], a[1], a[2]}};
        // Sliced only where the axis lies along the surface (as for a guide, below): where it
        // points out of it (a tip, or a patch too round to have an axis) the plane touches the
        // surface at the sample and would cut a loop around nothing.
        spread[s] = tiles[s];
        if (slice_up_to_ > 0 && tiles[s] < 2 * slice_up_to_ &&
            norm(along_surface(axis[s], vertex_normal_[samples[s]])) > 0.5) {
          tiles[s] = sliced_girth(samples[s], axis[s], slice_up_to_ * spacing_) / spacing_;
          sliced[s] = 1;
        }
      }
    });
    for (std::size_t i = 0; i < vertices_.size(); ++i) {
      if (owner[i] == none)
        continue;
      Estimate& e = estimate_[i];
      e.tiles_around = tiles[owner[i]];
      e.spread_tiles_around = spread[owner[i]];
      if (slice_up_to_ == 0 || sliced[owner[i]]) // with slicing, only loops are thin parts
        fewest_ = std::min(fewest_, e.tiles_around);
      const Vec3 t = along_surface(axis[owner[i]], vertex_normal_[i]);
      const double tl = norm(t);
      e.axis_valid = tl > 0.5;
      if (e.axis_valid)
        e.axis = Vector_3(t[0] / tl, t[1] / tl, t[2] / tl);
    }
  }

  const Estimate& at(vertex_descriptor v) const { return estimate_[get(vertex_index_, v)]; }
  double fewest_tiles_around() const { return fewest_; }

private:
  static constexpr std::size_t none = std::size_t(-1);
  using halfedge_descriptor = typename GT::halfedge_descriptor;

  // The part of the unit axis a along the surface whose normal is n (of any length): its length
  // is 1 on a tube's side and falls to 0 where the axis points out of the surface; zero when n is.
  static Vec3 along_surface(const Vec3& a, const Vec3& n) {
    const double nl = norm(n);
    if (!(nl > 0))
      return Vec3{{0, 0, 0}};
    const Vec3 u = (1 / nl) * n;
    return a - dot(a, u) * u;
  }

  // The length of the loop that the plane through vertex i with normal `axis` cuts from the
  // surface, traced from i's faces across one face at a time; infinite when it runs into a border
  // or past `bound`. A vertex on the plane counts as above it, so every triangle the plane crosses
  // has exactly two crossed edges and the crossed edges form disjoint loops and border-to-border
  // chains. (CGAL::Polygon_mesh_slicer cuts the plane's section of the whole mesh: on a model's
  // leg the same plane crosses its body and other legs too. Slicing each vertex with it took
  // 0.35–8.7 s on the organic meshes of doc/mosaic.md.)
  double sliced_girth(std::size_t i, const Vec3& axis, double bound) const {
    const double infinite = std::numeric_limits<double>::infinity();
    const Vec3& o = points_[i];
    auto height = [&](halfedge_descriptor h) {
      return dot(points_[get(vertex_index_, target(h, tm_))] - o, axis);
    };
    auto crossed = [&](halfedge_descriptor h) {
      return (height(h) >= 0) != (height(prev(h, tm_)) >= 0);
    };
    auto crossing = [&](halfedge_descriptor h) {
      const double a = height(prev(h, tm_)), b = height(h);
      const Vec3& p = points_[get(vertex_index_, source(h, tm_))];
      const Vec3& q = points_[get(vertex_index_, target(h, tm_))];
      return p + (a / (a - b)) * (q - p);
    };
    // The other crossed edge of h's face, walking on from h.
    auto exit = [&](halfedge_descriptor h) {
      for (halfedge_descriptor g = next(h, tm_); g != h; g = next(g, tm_))
        if (crossed(g))
          return g;
      return h;
    };
    // A face around i that the plane crosses (i lies on the plane, so it touches several).
    halfedge_descriptor first = GT::null_halfedge();
    for (halfedge_descriptor h : CGAL::halfedges_around_target(halfedge(vertices_[i], tm_), tm_)) {
      if (is_border(h, tm_))
        continue;
      for (halfedge_descriptor g : CGAL::halfedges_around_face(h, tm_))
        if (crossed(g)) {
          first = g;
          break;
        }
      if (first != GT::null_halfedge())
        break;
    }
    if (first == GT::null_halfedge())
      return infinite;
    halfedge_descriptor out = exit(first);
    double length = norm(crossing(out) - crossing(first));
    // Each step enters the next face through the edge the last one left by; the steps are bounded
    // by the length, and by the number of halfedges when the mesh is degenerate.
    for (std::size_t steps = 0; steps < num_halfedges(tm_) && length <= bound; ++steps) {
      const halfedge_descriptor in = opposite(out, tm_);
      if (is_border(in, tm_))
        return infinite;
      if (in == first) // back in the first face; a loop of no length is around nothing
        return length > 0 ? length : infinite;
      out = exit(in);
      if (out == in)
        return infinite;
      length += norm(crossing(out) - crossing(in));
    }
    return infinite;
  }

  // The faces around vertex i whose centroids lie within `radius` of it, connected through edges
  // (breadth-first from i's faces). `mark` is left all zero.
  void grow_patch(std::size_t i, double radius, std::vector<char>& mark,
                  std::vector<std::size_t>& patch) const {
    patch.clear();
    const Vec3& p = points_[i];
    const double r2 = radius * radius;
    auto within = [&](std::size_t f) {
      const Vec3 d = centroid_[f] - p;
      return dot(d, d) <= r2;
    };
    for (face_descriptor f : CGAL::faces_around_target(halfedge(vertices_[i], tm_), tm_)) {
      if (f == GT::null_face())
        continue;
      const std::size_t k = get(face_index_, f);
      if (!mark[k]) {
        mark[k] = 1;
        patch.push_back(k); // the vertex's own faces always count, however large
      }
    }
    for (std::size_t next = 0; next < patch.size(); ++next)
      for (face_descriptor g : CGAL::faces_around_face(halfedge(faces_[patch[next]], tm_), tm_)) {
        if (g == GT::null_face())
          continue;
        const std::size_t k = get(face_index_, g);
        if (!mark[k] && within(k)) {
          mark[k] = 1;
          patch.push_back(k);
        }
      }
    for (std::size_t f : patch)
      mark[f] = 0;
  }

  const TriangleMesh& tm_;
  double spacing_, radius_, slice_up_to_;
  decltype(get(CGAL::dynamic_vertex_property_t<std::size_t>(),
               std::declval<const TriangleMesh&>())) vertex_index_;
  decltype(get(CGAL::dynamic_face_property_t<std::size_t>(),
               std::declval<const TriangleMesh&>())) face_index_;
  std::vector<vertex_descriptor> vertices_;
  std::vector<face_descriptor> faces_;
  std::vector<Vec3> points_, centroid_, normal_, vertex_normal_;
  std::vector<double> area_;
  std::vector<Estimate> estimate_;
  double fewest_ = std::numeric_limits<double>::infinity();
};

} // namespace tessera::internal
