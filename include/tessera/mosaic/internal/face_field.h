// Face_field: a mosaic's direction field per face (Lai, Hu, Martin, "Surface Mosaics" §4.3, X_T of
// eq. 5), which the Manhattan charts fit their coordinates to and the surface mosaic orients its
// tiles by. Included by tessera/mosaic/manhattan_charts.h.
#pragma once

#include <tessera/mosaic/internal/surface_arrays.h>

#include <cmath>
#include <complex>
#include <cstdint>
#include <vector>

namespace tessera::internal {

/// The field per face: one of its n directions, X_T, a unit vector in the face's plane. Computed
/// from a vertex field by averaging the corners' power vectors e^{inθ} in the face's frame.
template <typename TriangleMesh> class Face_field {
public:
  template <typename VertexFieldMap>
  Face_field(const Surface_arrays<TriangleMesh>& s, const VertexFieldMap& field, int symmetry)
      : symmetry_(symmetry == 4 ? 4 : 2), x_(s.number_of_faces()) {
    for (std::uint32_t f = 0; f < s.number_of_faces(); ++f) {
      const Vec3 n = s.normal(f);
      Vec3 e1 = s.point(f, 1) - s.point(f, 0);
      const double l = norm(e1);
      e1 = l > 0 ? (1 / l) * e1 : Vec3{{1, 0, 0}};
      const Vec3 e2 = cross(n, e1);
      std::complex<double> sum = 0;
      for (int k = 0; k < 3; ++k) {
        const Vec3 x = to_vec3(get(field, s.vertex_of(s.corners(f)[k])));
        const double a = std::atan2(dot(x, e2), dot(x, e1));
        if (norm(x) > 0)
          sum += std::polar(1.0, symmetry_ * a);
      }
      const double angle = std::abs(sum) > 0 ? std::arg(sum) / symmetry_ : 0;
      x_[f] = std::cos(angle) * e1 + std::sin(angle) * e2;
    }
  }
  int symmetry() const { return symmetry_; }
  /// One of the face's n field directions (unit, in the face's plane).
  const Vec3& direction(std::uint32_t f) const { return x_[f]; }

private:
  int symmetry_;
  std::vector<Vec3> x_;
};

} // namespace tessera::internal
