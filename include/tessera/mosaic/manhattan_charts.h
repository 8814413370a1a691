// Local charts for the Manhattan distance on a surface (Lai, Hu, Martin, "Surface Mosaics"
// §4.2–4.3): a chart is grown over faces from a seed by breadth-first search until it leaves a ball
// of radius about 5σ or the field has turned too far, and parameterized by the least-squares fit of
// eq. 5, min Σ_T A_T (|∇u − X_T|² + |∇v − Y_T|²), so that u runs along the field and v across it.
// The Manhattan distance of two points of a chart is then measured along the directions at 45° to
// the field.
#pragma once

#include <tessera/mosaic/internal/face_field.h>
#include <tessera/mosaic/internal/surface_arrays.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace tessera {

/// The Manhattan distance of Lai et al. §4.2 between two points whose difference is (du, dv) in a
/// chart (u along the field, v across it), for tiles of aspect η = l_x / l_y: lengths along u are
/// divided by √η and along v multiplied by √η, then measured along the two directions at 45° to the
/// field, |x′ + y′|/√2 + |x′ − y′|/√2 = √2·max(|x′|, |y′|). Its balls are squares aligned with the
/// field, so the 8 neighbours of a tile in a field-aligned grid are equidistant from it (the
/// paper's Fig. 2).
inline double manhattan_distance(double du, double dv, double aspect = 1) {
  const double s = std::sqrt(aspect);
  return std::sqrt(2.0) * std::max(std::abs(du / s), std::abs(dv * s));
}

/// Options of the chart atlas.
struct Manhattan_chart_options {
  /// Charts stop growing at faces whose centroid is farther than this from the seed (Lai et al.:
  /// 5σ).
  double radius = 1;
  /// Faces within this distance of a chart's seed take it as their chart ("core"); a tile uses the
  /// chart of its face, so its neighbours up to `radius − core_radius` away are inside that chart.
  double core_radius = 0.4;
  /// Charts also stop where the field, unfolded from the seed face by face, has turned more than
  /// this (radians; Lai et al.: π/2): near a singularity the field cannot be fitted by one (u, v).
  double max_rotation = 1.5707963267948966;
  /// Charts also stop where they would close around the surface: each face is unfolded into the
  /// plane across the edge it was reached by, and a face whose free corner lands farther than this
  /// from where another path put that corner is left out. Around a part thinner than the chart
  /// (a leg, a tail, a tube) the two fronts meet a girth apart; a least-squares fit of a band
  /// that closes on itself squeezes the distances around it (the gradient of v cannot integrate
  /// to the girth around the loop). Curvature alone moves a corner by far less (the angle defect
  /// enclosed times the distance). 0 never stops a chart there.
  double seam_tolerance = 0;
  /// Safety cap on the faces of one chart.
  std::size_t max_faces = 200000;
};

/// A chart: the faces it covers (dense face ids, sorted), the (u, v) of each face's corners from
/// the eq. 5 fit, and the field frame (X_T, Y_T) each face was fitted to (X_T rotated by a multiple
/// of 2π/n so that it turns least from the seed's).
struct Manhattan_chart {
  std::vector<std::uint32_t> faces;
  std::vector<std::array<std::array<double, 2>, 3>> uv;
  std::vector<std::array<internal::Vec3, 2>> frame;
  std::uint32_t seed_face = 0;

  /// Slot of dense face f in this chart, or `internal::no_index`.
  std::uint32_t slot(std::uint32_t f) const {
    const auto it = std::lower_bound(faces.begin(), faces.end(), f);
    return it != faces.end() && *it == f ? std::uint32_t(it - faces.begin()) : internal::no_index;
  }
  std::array<double, 2> uv_at(std::uint32_t slot, const std::array<double, 3>& b) const {
    const auto& c = uv[slot];
    return {{b[0] * c[0][0] + b[1] * c[1][0] + b[2] * c[2][0],
             b[0] * c[0][1] + b[1] * c[1][1] + b[2] * c[2][1]}};
  }
};

/// Charts grown on demand: `chart_index_of(f)` returns the chart whose core holds face f, growing a
/// new chart seeded at f when none does. Charts depend only on the mesh and the field, so they are
/// kept for the whole optimization (the per-face chart flags of Lai et al. §4.3).
template <typename TriangleMesh> class Manhattan_chart_atlas {
public:
  /// An atlas with no chart yet over `s`, for `field` (both must outlive it).
  Manhattan_chart_atlas(const internal::Surface_arrays<TriangleMesh>& s,
                        const internal::Face_field<TriangleMesh>& field,
                        const Manhattan_chart_options& options);

  /// The index of the chart whose core holds dense face f, grown and fitted now when none does.
  std::uint32_t chart_index_of(std::uint32_t f);
  /// `chart_index_of` for many faces at once: the charts' seeds and cores are chosen in order as
  /// `chart_index_of` would choose them (a core is what the chart's growth reaches within the core
  /// radius), then the charts are grown to their radius and fitted in parallel.
  std::vector<std::uint32_t> chart_indices_of(const std::vector<std::uint32_t>& faces);
  const Manhattan_chart& chart(std::uint32_t c) const { return *charts_[c]; }
  std::size_t size() const { return charts_.size(); }
  /// Charts whose least-squares system could not be solved (left with u = v = 0; tiles in them fall
  /// back to the tangent-plane distance).
  std::size_t failed() const { return failed_; }

private:
  // Per-growth marks: which chart last reached each face, and each vertex's place in the plane of
  // the chart last grown over it (`unfold()`) with that chart's id. One set per thread.
  struct Scratch {
    explicit Scratch(const internal::Surface_arrays<TriangleMesh>& s)
        : mark(s.number_of_faces(), internal::no_index), flat(s.number_of_vertices()),
          flat_mark(s.number_of_vertices(), internal::no_index) {}
    std::vector<std::uint32_t> mark;
    std::vector<std::array<double, 2>> flat;
    std::vector<std::uint32_t> flat_mark;
  };
  // What a growth reached: faces in breadth-first order, each with its matched field direction
  // and the field's turn from the seed.
  struct Reach {
    std::vector<std::uint32_t> order;
    std::vector<internal::Vec3> xs;
    std::vector<double> turned;
  };

  // Grows the chart seeded at face `seed`, its core and its fit, now.
  void grow(std::uint32_t seed);

  // The faces reached from `seed` breadth first, unfolded face by face, up to `radius` from its
  // centroid, until the field has turned `max_rotation` or the unfolding meets itself; marked
  // with `id` in `scratch`.
  void reach(std::uint32_t seed, std::uint32_t id, double radius, Scratch& scratch,
             Reach& out) const;
  // Writes what was reached into `chart` (faces sorted by index, with their frames).
  void take(Manhattan_chart& chart, const Reach& r) const;

  // Unfolds face g, reached from face f across f's edge from corner k to k + 1, into chart `id`'s
  // plane: places its free corner on the far side of that edge, at the same place along and off
  // it as in space. False (g stays out) when another path put that corner farther than
  // `seam_tolerance` away.
  bool unfold(std::uint32_t f, int k, std::uint32_t g, std::uint32_t id, Scratch& scratch) const;

  // Eq. 5 of Lai et al.: the normal equations K u = b_u, K v = b_v, K the cotangent stiffness
  // matrix, with the seed face's first corner fixed at (0, 0). `local` maps mesh vertices to chart
  // unknowns (all `no_index` on entry and on return). False when the system could not be solved.
  bool fit(Manhattan_chart& chart, std::vector<std::uint32_t>& local) const;

  const internal::Surface_arrays<TriangleMesh>& s_;
  const internal::Face_field<TriangleMesh>& field_;
  Manhattan_chart_options options_;
  std::vector<std::unique_ptr<Manhattan_chart>> charts_;
  std::vector<std::uint32_t> core_, local_;
  Scratch scratch_;
  std::size_t failed_ = 0;
};

} // namespace tessera

#include <tessera/mosaic/internal/manhattan_charts_impl.h>
