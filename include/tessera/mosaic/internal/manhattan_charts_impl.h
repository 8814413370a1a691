// The bodies of `Manhattan_chart_atlas`'s members (tessera/mosaic/manhattan_charts.h): growing a
// chart over faces from its seed (unfolded face by face, stopping at the radius, where the field
// has turned too far or where the chart would close around the surface) and fitting its (u, v) by
// least squares, eq. 5 of Lai et al. Included at the end of the public header.
#pragma once

#include <tessera/mosaic/manhattan_charts.h>

#include <tessera/internal/parallel.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <thread>
#include <vector>

namespace tessera {

template <typename TriangleMesh>
Manhattan_chart_atlas<TriangleMesh>::Manhattan_chart_atlas(
    const internal::Surface_arrays<TriangleMesh>& s,
    const internal::Face_field<TriangleMesh>& field, const Manhattan_chart_options& options)
    : s_(s), field_(field), options_(options), core_(s.number_of_faces(), internal::no_index),
      local_(s.number_of_vertices(), internal::no_index), scratch_(s) {}

template <typename TriangleMesh>
std::uint32_t Manhattan_chart_atlas<TriangleMesh>::chart_index_of(std::uint32_t f) {
  if (core_[f] == internal::no_index)
    grow(f);
  return core_[f];
}

// In three steps, so that the growth (two thirds of the charts' time) runs in parallel too:
// the charts' seeds and cores first, in order (a core is what the chart's growth reaches within
// the core radius, so it does not depend on the faces beyond it); then every chart grown to its
// radius and fitted, independently; last, a core face that the full growth reached by another
// path and turned away (a seam met first from the far side) leaves that core and gets a chart of
// its own as `chart_index_of` would give it.
template <typename TriangleMesh>
std::vector<std::uint32_t>
Manhattan_chart_atlas<TriangleMesh>::chart_indices_of(const std::vector<std::uint32_t>& faces) {
  using namespace internal;
  const std::size_t first = charts_.size();
  std::vector<std::vector<std::uint32_t>> cores;
  Reach reached;
  for (std::uint32_t f : faces) {
    if (core_[f] != no_index)
      continue;
    const std::uint32_t id = std::uint32_t(charts_.size());
    auto chart = std::make_unique<Manhattan_chart>();
    chart->seed_face = f;
    charts_.push_back(std::move(chart));
    reach(f, id, options_.core_radius, scratch_, reached);
    std::vector<std::uint32_t> core;
    for (std::uint32_t g : reached.order)
      if (core_[g] == no_index) {
        core_[g] = id;
        core.push_back(g);
      }
    cores.push_back(std::move(core));
  }
  std::vector<char> failed(charts_.size() - first, 0);
  // Each thread takes every `threads`-th run of 64 charts rather than one contiguous half: charts
  // differ in size along the surface, and with halves one thread waited for the other (at 40k
  // tiles the two halves' fits took 0.53 and 0.68 s).
  const std::size_t count = charts_.size() - first, run = 64;
  const std::size_t threads =
      count >= 16 ? std::max<std::size_t>(1, std::thread::hardware_concurrency()) : 1;
  internal::parallel_blocks(
      threads,
      [&](std::size_t a, std::size_t b) {
        Scratch scratch(s_);
        Reach r;
        std::vector<std::uint32_t> local(s_.number_of_vertices(), no_index);
        for (std::size_t t = a; t < b; ++t)
          for (std::size_t start = t * run; start < count; start += threads * run)
            for (std::size_t c = start; c < std::min(count, start + run); ++c) {
              Manhattan_chart& chart = *charts_[first + c];
              reach(chart.seed_face, std::uint32_t(first + c), options_.radius, scratch, r);
              take(chart, r);
              failed[c] = !fit(chart, local);
            }
      },
      1);
  for (char x : failed)
    failed_ += std::size_t(x);
  for (std::size_t c = 0; c < cores.size(); ++c)
    for (std::uint32_t g : cores[c])
      if (charts_[first + c]->slot(g) == no_index)
        core_[g] = no_index;
  std::vector<std::uint32_t> out;
  out.reserve(faces.size());
  for (std::uint32_t f : faces)
    out.push_back(chart_index_of(f));
  return out;
}

template <typename TriangleMesh>
void Manhattan_chart_atlas<TriangleMesh>::grow(std::uint32_t seed) {
  const std::uint32_t id = std::uint32_t(charts_.size());
  auto chart = std::make_unique<Manhattan_chart>();
  chart->seed_face = seed;
  Reach r;
  reach(seed, id, options_.radius, scratch_, r);
  take(*chart, r);
  const double core = options_.core_radius;
  const internal::Vec3 centre = s_.centroid(seed);
  for (std::uint32_t f : chart->faces)
    if (core_[f] == internal::no_index && internal::norm(s_.centroid(f) - centre) <= core)
      core_[f] = id;
  core_[seed] = id;
  failed_ += std::size_t(!fit(*chart, local_));
  charts_.push_back(std::move(chart));
}

template <typename TriangleMesh>
void Manhattan_chart_atlas<TriangleMesh>::reach(std::uint32_t seed, std::uint32_t id, double radius,
                                                Scratch& g, Reach& out) const {
  using namespace internal;
  const double alpha = 2 * std::acos(-1.0) / field_.symmetry();
  const Vec3 centre = s_.centroid(seed);
  out.order.assign(1, seed);
  out.xs.assign(1, field_.direction(seed));
  std::vector<double>& turned = out.turned;
  turned.assign(1, 0.0);
  g.mark[seed] = id;
  {
    const Vec3 e1 = out.xs[0], e2 = cross(s_.normal(seed), e1);
    for (const std::uint32_t v : s_.corners(seed)) {
      const Vec3 p = s_.vertex_point(v) - centre;
      g.flat[v] = {{dot(p, e1), dot(p, e2)}};
      g.flat_mark[v] = id;
    }
  }
  for (std::size_t head = 0; head < out.order.size() && out.order.size() < options_.max_faces;
       ++head) {
    const std::uint32_t f = out.order[head];
    const Vec3 xf = out.xs[head];
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t n = s_.neighbor(f, k);
      if (n == no_index || g.mark[n] == id)
        continue;
      if (norm(s_.centroid(n) - centre) > radius)
        continue;
      // Unfold n onto f about their edge: angles measured from the edge in each face agree.
      Vec3 e = s_.point(f, (k + 1) % 3) - s_.point(f, k);
      e = (1 / std::max(norm(e), 1e-300)) * e;
      const Vec3& xn = field_.direction(n);
      const double af = std::atan2(dot(cross(s_.normal(f), e), xf), dot(e, xf));
      const double an = std::atan2(dot(cross(s_.normal(n), e), xn), dot(e, xn));
      double d = an - af;
      d -= alpha * std::round(d / alpha);
      const double total = turned[head] + d;
      if (std::abs(total) > options_.max_rotation)
        continue;
      if (!unfold(f, k, n, id, g))
        continue;
      g.mark[n] = id;
      const double a = af + d;
      out.order.push_back(n);
      out.xs.push_back(std::cos(a) * e + std::sin(a) * cross(s_.normal(n), e));
      turned.push_back(total);
    }
  }
}

// The reached faces sorted by id, with their matched frames.
template <typename TriangleMesh>
void Manhattan_chart_atlas<TriangleMesh>::take(Manhattan_chart& chart, const Reach& r) const {
  std::vector<std::uint32_t> perm(r.order.size());
  for (std::uint32_t i = 0; i < perm.size(); ++i)
    perm[i] = i;
  std::sort(perm.begin(), perm.end(),
            [&](std::uint32_t a, std::uint32_t b) { return r.order[a] < r.order[b]; });
  chart.faces.resize(r.order.size());
  chart.frame.resize(r.order.size());
  for (std::size_t i = 0; i < perm.size(); ++i) {
    const std::uint32_t f = r.order[perm[i]];
    chart.faces[i] = f;
    chart.frame[i] = {{r.xs[perm[i]], internal::cross(s_.normal(f), r.xs[perm[i]])}};
  }
}

template <typename TriangleMesh>
bool Manhattan_chart_atlas<TriangleMesh>::unfold(std::uint32_t f, int k, std::uint32_t g,
                                                 std::uint32_t id, Scratch& scratch) const {
  using namespace internal;
  const auto& cf = s_.corners(f);
  const std::uint32_t a = cf[k], b = cf[(k + 1) % 3], o = cf[(k + 2) % 3];
  std::uint32_t c = no_index;
  for (const std::uint32_t v : s_.corners(g))
    if (v != a && v != b)
      c = v;
  if (c == no_index)
    return false;
  const Vec3 ab = s_.vertex_point(b) - s_.vertex_point(a);
  const Vec3 ac = s_.vertex_point(c) - s_.vertex_point(a);
  const double l2 = dot(ab, ab);
  if (!(l2 > 0))
    return false;
  auto& flat = scratch.flat;
  auto& flat_mark = scratch.flat_mark;
  const double t = dot(ac, ab) / l2, h = norm(ac - t * ab) / std::sqrt(l2);
  const std::array<double, 2>& pa = flat[a];
  const std::array<double, 2> d{{flat[b][0] - pa[0], flat[b][1] - pa[1]}};
  const double side = d[0] * (flat[o][1] - pa[1]) - d[1] * (flat[o][0] - pa[0]) > 0 ? -1.0 : 1.0;
  const std::array<double, 2> pc{
      {pa[0] + t * d[0] - side * h * d[1], pa[1] + t * d[1] + side * h * d[0]}};
  if (flat_mark[c] == id)
    return !(options_.seam_tolerance > 0) ||
           std::hypot(pc[0] - flat[c][0], pc[1] - flat[c][1]) <= options_.seam_tolerance;
  flat[c] = pc;
  flat_mark[c] = id;
  return true;
}

template <typename TriangleMesh>
bool Manhattan_chart_atlas<TriangleMesh>::fit(Manhattan_chart& chart,
                                              std::vector<std::uint32_t>& local) const {
  using namespace internal;
  std::vector<std::uint32_t> vertices;
  for (std::uint32_t f : chart.faces)
    for (std::uint32_t v : s_.corners(f))
      if (local[v] == no_index) {
        local[v] = std::uint32_t(vertices.size());
        vertices.push_back(v);
      }
  const std::uint32_t fixed = local[s_.corners(chart.seed_face)[0]];
  // Free unknowns: every local vertex but the fixed one.
  auto unknown = [fixed](std::uint32_t l) { return l < fixed ? l : l - 1; };
  const Eigen::Index n = Eigen::Index(vertices.size()) - 1;
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(chart.faces.size() * 9);
  // The right-hand sides b_u and b_v, one column each.
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(std::max<Eigen::Index>(n, 0), 2);
  double scale = 0;
  for (std::size_t i = 0; i < chart.faces.size(); ++i) {
    const std::uint32_t f = chart.faces[i];
    const double area = s_.area(f);
    if (!(area > 0))
      continue;
    std::array<Vec3, 3> grad;
    for (int k = 0; k < 3; ++k)
      grad[k] = (1 / (2 * area)) *
                cross(s_.normal(f), s_.point(f, (k + 2) % 3) - s_.point(f, (k + 1) % 3));
    for (int a = 0; a < 3; ++a) {
      const std::uint32_t la = local[s_.corners(f)[a]];
      if (la == fixed)
        continue;
      b(unknown(la), 0) += area * dot(grad[a], chart.frame[i][0]);
      b(unknown(la), 1) += area * dot(grad[a], chart.frame[i][1]);
      for (int b = 0; b < 3; ++b) {
        const std::uint32_t lb = local[s_.corners(f)[b]];
        if (lb == fixed)
          continue;
        const double w = area * dot(grad[a], grad[b]);
        triplets.emplace_back(unknown(la), unknown(lb), w);
        scale = std::max(scale, std::abs(w));
      }
    }
  }
  Eigen::MatrixXd uv = Eigen::MatrixXd::Zero(std::max<Eigen::Index>(n, 0), 2);
  bool solved = true;
  if (n > 0) {
    // Vertices reached only through degenerate faces would leave the matrix singular: a vanishing
    // diagonal term keeps it definite without moving the others.
    for (Eigen::Index i = 0; i < n; ++i)
      triplets.emplace_back(i, i, 1e-12 * scale + 1e-300);
    Eigen::SparseMatrix<double> K(n, n);
    K.setFromTriplets(triplets.begin(), triplets.end());
    const auto factor_and_solve = [&](auto& ldlt) {
      ldlt.compute(K);
      if (ldlt.info() == Eigen::Success)
        uv = ldlt.solve(b);
      return ldlt.info() == Eigen::Success;
    };
    // A chart has some 60 unknowns where a tile spans a few faces: a fill-reducing ordering
    // costs more than the fill it saves (the fits at 200k triangles and 40k tiles: 0.49 s with
    // AMD, 0.30 s without). On a fine mesh under few tiles it has hundreds (about 900 at 200k
    // triangles and 3000 tiles), and without one the charts took 6.0 s instead of 1.1 s.
    bool factored = false;
    if (n <= 128) {
      Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>>
          ldlt;
      factored = factor_and_solve(ldlt);
    } else {
      Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt; // AMD ordering
      factored = factor_and_solve(ldlt);
    }
    if (!factored || !uv.allFinite()) {
      uv.setZero();
      solved = false;
    }
  }
  chart.uv.resize(chart.faces.size());
  for (std::size_t i = 0; i < chart.faces.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t l = local[s_.corners(chart.faces[i])[k]];
      chart.uv[i][k] = l == fixed ? std::array<double, 2>{{0, 0}}
                                  : std::array<double, 2>{{uv(unknown(l), 0), uv(unknown(l), 1)}};
    }
  for (std::uint32_t v : vertices)
    local[v] = no_index;
  return solved;
}

} // namespace tessera
