// The implementation of synthesize_texture() (tessera/resizing/texture_synthesis.h): the templates
// (a vertex's nearby triangles projected into its tangent frame and resampled on a square grid),
// the distance from the region's border, and the coarse-to-fine expectation–maximization. Included
// by texture_synthesis.h after the types it uses (Texture_synthesis_options,
// Texture_synthesis_result, …); nothing here is meant to be called directly.
#pragma once

#include <tessera/internal/named_parameters.h>
#include <tessera/internal/parallel.h>
#include <tessera/resizing/internal/fairing_impl.h>
#include <tessera/resizing/texels.h>
#include <tessera/topology/internal/graph_search.h>

#include <CGAL/Epick_d.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Search_traits_d.h>
#include <CGAL/property_map.h>

#include <boost/iterator/counting_iterator.hpp>

#include <Eigen/Dense>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <random>
#include <string>
#include <unordered_map>
#include <vector>

namespace tessera {
namespace internal {

/// A template sample: the detail at a grid point is w·(h[v0], h[v1], h[v2]); v0 == npos when the
/// grid point falls on no projected triangle.
struct Template_sample {
  static constexpr std::uint32_t npos = std::uint32_t(-1);
  std::array<std::uint32_t, 3> v{{npos, npos, npos}};
  std::array<float, 3> w{{0, 0, 0}};
};

/// Templates of a mesh: the tangent frame of each vertex and, for the vertices asked for, the
/// barycentric coordinates of each grid point on the triangles projected into that frame.
template <typename TriangleMesh, typename VertexPointMap> class Template_sampler {
public:
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;

  Template_sampler(const TriangleMesh& tm, VertexPointMap vpm, const std::array<double, 3>& axis)
      : tm_(tm), vpm_(vpm), index_(get(CGAL::dynamic_vertex_property_t<std::uint32_t>(), tm)),
        face_index_(get(CGAL::dynamic_face_property_t<std::uint32_t>(), tm)) {
    namespace PMP = CGAL::Polygon_mesh_processing;
    for (vertex_descriptor v : vertices(tm)) {
      put(index_, v, std::uint32_t(points_.size()));
      vertices_.push_back(v);
      const auto p = get(vpm, v);
      points_.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
      const auto n = PMP::compute_vertex_normal(v, tm, CGAL::parameters::vertex_point_map(vpm));
      Eigen::Vector3d normal(CGAL::to_double(n.x()), CGAL::to_double(n.y()),
                             CGAL::to_double(n.z()));
      frames_.push_back(tangent_frame(normal, axis));
    }
    for (face_descriptor f : faces(tm))
      put(face_index_, f, faces_++);
  }

  /// Per-thread working memory of `sample`.
  struct Scratch {
    std::vector<std::uint32_t> stamp;
    std::uint32_t counter = 0;
    std::vector<face_descriptor> stack;
  };

  std::uint32_t index(vertex_descriptor v) const { return get(index_, v); }
  vertex_descriptor vertex(std::uint32_t i) const { return vertices_[i]; }
  const Eigen::Vector3d& point(std::uint32_t i) const { return points_[i]; }
  std::size_t size() const { return points_.size(); }

  /// Appends the (2r + 1)² samples of v's template, spacing d, row by row.
  void sample(vertex_descriptor v, double d, std::size_t r, std::vector<Template_sample>& out) {
    const std::size_t side = 2 * r + 1, first = out.size();
    out.resize(first + side * side);
    sample(v, d, r, out.data() + first, scratch_);
  }

  /// Writes the (2r + 1)² samples of v's template to `out`; reads the mesh only, so threads with
  /// their own `scratch` may sample at once.
  void sample(vertex_descriptor v, double d, std::size_t r, Template_sample* out,
              Scratch& scratch) const {
    const std::size_t side = 2 * r + 1;
    std::fill(out, out + side * side, Template_sample{});
    if (scratch.stamp.size() != faces_) {
      scratch.stamp.assign(faces_, 0);
      scratch.counter = 0;
    }
    const std::uint32_t stamp = ++scratch.counter;
    auto& stack = scratch.stack;
    const std::uint32_t i = get(index_, v);
    const Eigen::Vector3d& p = points_[i];
    const auto& frame = frames_[i];
    // Faces reached across edges from v whose corners come within the template's reach, facing
    // the same side as v (so a thin part's other side is not projected onto this one).
    const double reach = (double(r) + 1.5) * d * std::sqrt(2.0);
    stack.clear();
    for (face_descriptor f : CGAL::faces_around_target(halfedge(v, tm_), tm_))
      if (f != boost::graph_traits<TriangleMesh>::null_face()) {
        scratch.stamp[get(face_index_, f)] = stamp;
        stack.push_back(f);
      }
    while (!stack.empty()) {
      const face_descriptor f = stack.back();
      stack.pop_back();
      std::array<std::uint32_t, 3> ids;
      std::array<Eigen::Vector2d, 3> uv;
      bool near = false;
      int k = 0;
      for (vertex_descriptor w : CGAL::vertices_around_face(halfedge(f, tm_), tm_)) {
        ids[std::size_t(k)] = get(index_, w);
        const Eigen::Vector3d q = points_[ids[std::size_t(k)]] - p;
        uv[std::size_t(k)] = Eigen::Vector2d(q.dot(frame[1]), q.dot(frame[2])) / d;
        near = near || q.norm() < reach;
        ++k;
      }
      const Eigen::Vector3d e1 = points_[ids[1]] - points_[ids[0]],
                            e2 = points_[ids[2]] - points_[ids[0]];
      if (!near || e1.cross(e2).dot(frame[0]) <= 0)
        continue;
      rasterize(ids, uv, r, out);
      for (auto h : CGAL::halfedges_around_face(halfedge(f, tm_), tm_)) {
        const face_descriptor g = face(opposite(h, tm_), tm_);
        if (g != boost::graph_traits<TriangleMesh>::null_face() &&
            scratch.stamp[get(face_index_, g)] != stamp) {
          scratch.stamp[get(face_index_, g)] = stamp;
          stack.push_back(g);
        }
      }
    }
  }

private:
  void rasterize(const std::array<std::uint32_t, 3>& ids, const std::array<Eigen::Vector2d, 3>& uv,
                 std::size_t r, Template_sample* grid) const {
    const double ri = double(r);
    const double lo_u = std::max(-ri, std::ceil(std::min({uv[0].x(), uv[1].x(), uv[2].x()})));
    const double hi_u = std::min(ri, std::floor(std::max({uv[0].x(), uv[1].x(), uv[2].x()})));
    const double lo_v = std::max(-ri, std::ceil(std::min({uv[0].y(), uv[1].y(), uv[2].y()})));
    const double hi_v = std::min(ri, std::floor(std::max({uv[0].y(), uv[1].y(), uv[2].y()})));
    const Eigen::Vector2d a = uv[1] - uv[0], b = uv[2] - uv[0];
    const double det = a.x() * b.y() - a.y() * b.x();
    if (std::abs(det) < 1e-12)
      return;
    const std::size_t side = 2 * r + 1;
    for (double y = lo_v; y <= hi_v; ++y)
      for (double x = lo_u; x <= hi_u; ++x) {
        const Eigen::Vector2d c = Eigen::Vector2d(x, y) - uv[0];
        const double s = (c.x() * b.y() - c.y() * b.x()) / det;
        const double t = (a.x() * c.y() - a.y() * c.x()) / det;
        if (s < -1e-9 || t < -1e-9 || s + t > 1 + 1e-9)
          continue;
        Template_sample& g = grid[std::size_t(y + ri) * side + std::size_t(x + ri)];
        if (g.v[0] != Template_sample::npos)
          continue;
        g.v = ids;
        g.w = {{float(1 - s - t), float(s), float(t)}};
      }
  }

  const TriangleMesh& tm_;
  VertexPointMap vpm_;
  typename boost::property_map<TriangleMesh,
                               CGAL::dynamic_vertex_property_t<std::uint32_t>>::const_type index_;
  typename boost::property_map<
      TriangleMesh, CGAL::dynamic_face_property_t<std::uint32_t>>::const_type face_index_;
  std::uint32_t faces_ = 0;
  std::vector<vertex_descriptor> vertices_;
  std::vector<Eigen::Vector3d> points_;
  std::vector<std::array<Eigen::Vector3d, 3>> frames_;
  Scratch scratch_;
};

/// Distance along `tm`'s edges from its vertices outside `region`, per vertex in the order of
/// `vertices(tm)` (a `Template_sampler`'s indices); infinite everywhere if every vertex is inside.
template <typename TriangleMesh, typename VertexPointMap, typename RegionMap>
std::vector<double> distance_from_outside(const TriangleMesh& tm, VertexPointMap vpm,
                                          RegionMap region) {
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> outside;
  for (auto v : vertices(tm))
    if (!get(region, v))
      outside.push_back(v);
  Mesh_indices<TriangleMesh> indices(tm);
  Shortest_path_tree<TriangleMesh> tree(tm, indices);
  tree.run(outside, [&](auto e) {
    return CGAL::to_double(CGAL::Polygon_mesh_processing::edge_length(
        halfedge(e, tm), tm, CGAL::parameters::vertex_point_map(vpm)));
  });
  std::vector<double> distance;
  distance.reserve(std::size_t(num_vertices(tm)));
  for (auto v : vertices(tm))
    distance.push_back(outside.empty() ? std::numeric_limits<double>::infinity()
                                       : tree.distance(v));
  return distance;
}

/// The body of `synthesize_texture` and, with `sample_vectors` and `target_vectors` (per vertex, in
/// the order of vertices(sample) and vertices(target); the target's read where held and written
/// on the region), of `synthesize_texture_with_vectors` (texture_synthesis.h).
template <typename SampleMesh, typename SampleRegionMap, typename SampleHeightMap,
          typename TargetMesh, typename TargetRegionMap, typename TargetHeightMap,
          typename SampleNamedParameters, typename TargetNamedParameters>
Texture_synthesis_result synthesize_texture_impl(
    const SampleMesh& sample, SampleRegionMap sample_region, SampleHeightMap sample_height,
    const TargetMesh& target, TargetRegionMap target_region, TargetHeightMap target_height,
    const Texture_synthesis_options& options, const SampleNamedParameters& np_sample,
    const TargetNamedParameters& np_target,
    const std::vector<std::array<double, 3>>* sample_vectors = nullptr,
    std::vector<std::array<double, 3>>* target_vectors = nullptr) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using internal::Template_sample;
  const auto sample_vpm = internal::vertex_point_map(sample, np_sample);
  const auto target_vpm = internal::vertex_point_map(target, np_target);
  Texture_synthesis_result result;
  auto fail = [&](Texture_synthesis_status status, std::string message) {
    result.status = status;
    result.message = std::move(message);
    return result;
  };

  // Grid spacing from the sample region's mean triangle area; the period from its texels.
  double region_area = 0;
  std::size_t region_faces = 0;
  for (auto f : faces(sample)) {
    bool inside = true;
    for (auto v : CGAL::vertices_around_face(halfedge(f, sample), sample))
      inside = inside && get(sample_region, v);
    if (!inside)
      continue;
    region_area +=
        CGAL::to_double(PMP::face_area(f, sample, CGAL::parameters::vertex_point_map(sample_vpm)));
    ++region_faces;
  }
  if (region_faces == 0)
    return fail(Texture_synthesis_status::empty_sample, "the sample has no texture triangle");
  const double d = options.grid_spacing > 0 ? options.grid_spacing
                                            : std::sqrt(2 * region_area / double(region_faces));
  double peak = 0; // the sample's largest detail
  for (auto v : vertices(sample))
    if (get(sample_region, v))
      peak = std::max(peak, std::abs(double(get(sample_height, v))));
  std::size_t r = options.template_radius;
  if (r == 0) {
    // The period: the given one, or √(area / texels) when that is longer (texels long in one
    // direction, such as ridges, repeat at the given period across and need templates that
    // see a good length of them).
    auto raised = get(CGAL::dynamic_vertex_property_t<double>(), sample);
    for (auto v : vertices(sample))
      put(raised, v, get(sample_region, v) ? double(get(sample_height, v)) : 0.0);
    const Texel_measure texels = measure_texels(sample, sample_vpm, raised, 0.25 * peak);
    const double counted =
        texels.texels.empty() ? 4 * d : std::sqrt(region_area / double(texels.texels.size()));
    const double period = std::max(options.texel_period, counted);
    r = std::size_t(std::clamp(std::ceil(0.5 * period / d), 2.0, 12.0));
  }
  result.grid_spacing = d;
  result.template_radius = r;
  const std::size_t side = 2 * r + 1, dims = side * side;
  // A template's row: its (2r + 1)² details, then (guided) as many region indicators times
  // `guide`.
  const double guide = options.border_guidance * peak;

  internal::Template_sampler<SampleMesh, decltype(sample_vpm)> sample_sampler(
      sample, sample_vpm, options.reference_axis);
  std::vector<double> sample_values(sample_sampler.size(), 0);
  std::vector<char> sample_inside(sample_sampler.size(), 0);
  for (auto v : vertices(sample)) {
    sample_values[sample_sampler.index(v)] = double(get(sample_height, v));
    sample_inside[sample_sampler.index(v)] = get(sample_region, v) ? 1 : 0;
  }
  internal::Template_sampler<TargetMesh, decltype(target_vpm)> target_sampler(
      target, target_vpm, options.reference_axis);
  constexpr std::size_t fixed = std::size_t(-1);
  std::vector<std::size_t> unknown(target_sampler.size(), fixed);
  std::vector<double> h(target_sampler.size(), 0);
  std::vector<std::uint32_t> owners;
  for (auto v : vertices(target)) {
    const std::uint32_t i = target_sampler.index(v);
    h[i] = double(get(target_height, v));
    if (get(target_region, v)) {
      unknown[i] = owners.size();
      owners.push_back(i);
    }
  }
  const std::size_t n = owners.size();
  result.target_vertices = n;
  if (n == 0)
    return fail(Texture_synthesis_status::empty_target, "the target has no texture vertex");
  std::mt19937 random(options.random_seed);

  using Kernel_d = CGAL::Epick_d<CGAL::Dynamic_dimension_tag>;
  using Point_d = Kernel_d::Point_d;
  using Base_traits = CGAL::Search_traits_d<Kernel_d>;
  using Point_map = CGAL::Pointer_property_map<Point_d>::type;
  using Traits = CGAL::Search_traits_adapter<std::size_t, Point_map, Base_traits>;
  using Distance =
      CGAL::Distance_adapter<std::size_t, Point_map, CGAL::Euclidean_distance<Base_traits>>;
  using Search = CGAL::Orthogonal_k_neighbor_search<Traits, Distance>;

  // Coarse to fine, as texture optimization does: templates of the same (2r + 1)² samples at
  // spacing 2^level·d, so the coarse levels span several texels and settle their layout and the
  // fine level their shape. Each level starts from the one before, the coarsest from random
  // sample patches.
  const std::size_t levels = std::max<std::size_t>(1, options.levels);
  const std::vector<double> sample_border =
      internal::distance_from_outside(sample, sample_vpm, sample_region);
  // The distribution the details are given after each level (see the histogram matching below):
  // the sample's texture vertices beyond the border fade's width from its border, sorted.
  std::vector<double> region_values;
  for (auto v : vertices(sample))
    if (get(sample_region, v) && sample_border[sample_sampler.index(v)] >= options.border_fade)
      region_values.push_back(double(get(sample_height, v)));
  std::sort(region_values.begin(), region_values.end());
  std::vector<Template_sample> grid;
  // The finest level's whole sample templates, row by row (carrying vectors only).
  std::vector<Template_sample> whole_grid;
  std::vector<std::array<double, 3>> vectors;
  if (target_vectors)
    vectors = *target_vectors;
  const std::size_t most_iterations = levels * options.iterations;
  report_progress(options.progress, "synthesis iterations", 0, most_iterations);
  for (std::size_t level = levels; level-- > 0;) {
    const double spacing = d * double(std::size_t(1) << level);
    const bool coarsest = level + 1 == levels;
    // The region's outline guides the coarse levels, which settle where the texels go; the
    // finest level, which shapes them, matches the texture alone. A stretched outline keeps the
    // old phase in its small wiggles (lobes at the ends of ridges, twice as far apart after a 2×
    // stretch), and matched at the fine level they cut the new ridges short (aspect 11.3 → 8.9);
    // at the coarse spacing they fall between grid samples.
    const bool guided = options.border_guidance > 0 && (level > 0 || levels == 1);
    const std::size_t width = guided ? 2 * dims : dims;

    // Sample templates: every texture vertex whose template lies wholly inside the texture region
    // (a template reaching past it would teach the target the untextured surface).
    // Templates are sampled in parallel (each to its own block), then kept in vertex order.
    std::vector<double> rows;
    {
      // Candidates: texture vertices at least 0.9 of the template's half width from the
      // region's border (those nearer cannot hold a whole template), and at level k one in 4^k
      // of them (drawn at random, seeded): a template twice as coarse needs four times fewer
      // positions to cover the texture's phases, and sampling it reaches four times more faces.
      std::vector<typename boost::graph_traits<SampleMesh>::vertex_descriptor> candidates;
      std::bernoulli_distribution keep(1.0 / double(std::size_t(1) << (2 * level)));
      const double clearance = guided ? 0.0 : 0.9 * double(r) * spacing;
      for (auto v : vertices(sample))
        if (get(sample_region, v) && sample_border[sample_sampler.index(v)] >= clearance &&
            (level == 0 || keep(random)))
          candidates.push_back(v);
      grid.assign(candidates.size() * dims, Template_sample{});
      std::vector<char> whole(candidates.size(), 0);
      internal::parallel_blocks(
          candidates.size(),
          [&](std::size_t first, std::size_t last) {
            typename decltype(sample_sampler)::Scratch scratch;
            for (std::size_t c = first; c < last; ++c) {
              Template_sample* tpl = grid.data() + c * dims;
              sample_sampler.sample(candidates[c], spacing, r, tpl, scratch);
              // Guided, a template may reach past the region's border (its indicators say
              // where); it must lie on the surface all the same.
              whole[c] = std::none_of(tpl, tpl + dims, [&](const Template_sample& g) {
                return g.v[0] == Template_sample::npos ||
                       (!guided && (!sample_inside[g.v[0]] || !sample_inside[g.v[1]] ||
                                    !sample_inside[g.v[2]]));
              });
            }
          },
          16);
      if (level == 0)
        whole_grid.clear();
      for (std::size_t c = 0; c < candidates.size(); ++c) {
        if (!whole[c])
          continue;
        const Template_sample* tpl = grid.data() + c * dims;
        if (level == 0 && sample_vectors)
          whole_grid.insert(whole_grid.end(), tpl, tpl + dims);
        for (const Template_sample* g = tpl; g != tpl + dims; ++g)
          rows.push_back(g->w[0] * sample_values[g->v[0]] + g->w[1] * sample_values[g->v[1]] +
                         g->w[2] * sample_values[g->v[2]]);
        if (guided)
          for (const Template_sample* g = tpl; g != tpl + dims; ++g)
            rows.push_back(guide *
                           (g->w[0] * sample_inside[g->v[0]] + g->w[1] * sample_inside[g->v[1]] +
                            g->w[2] * sample_inside[g->v[2]]));
      }
    }
    const std::size_t m = rows.size() / width;
    if (m == 0) {
      if (level > 0)
        continue; // the region is too small for this level's templates: start finer
      return fail(Texture_synthesis_status::empty_sample,
                  "no texture vertex of the sample has a whole template inside its texture "
                  "region: the region is narrower than a template (half width " +
                      std::to_string(double(r) * spacing) + ", " + std::to_string(r) +
                      " grid steps); try a template_radius of " +
                      std::to_string(std::max<std::size_t>(2, r / 2)) + " (--texel-period " +
                      std::to_string(double(r) * spacing) + " on the command line)");
    }
    result.sample_templates = m;
    const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>
        templates(rows.data(), Eigen::Index(m), Eigen::Index(width));

    // Principal components of the sample templates: the search runs on the first few.
    // The covariance comes from at most 2048 templates drawn at random: its cost grows with the
    // rows times dims² (3 GFLOP for 11k templates of 23² samples, a second; 0.15 s this way),
    // and the leading components of a texture's templates are well estimated by a few thousand.
    const Eigen::RowVectorXd mean = templates.colwise().mean();
    const Eigen::MatrixXd centred = templates.rowwise() - mean;
    Eigen::MatrixXd covariance;
    if (m > 2048) {
      std::vector<std::size_t> rows_drawn(m);
      std::iota(rows_drawn.begin(), rows_drawn.end(), std::size_t(0));
      std::shuffle(rows_drawn.begin(), rows_drawn.end(), random);
      Eigen::MatrixXd drawn(2048, Eigen::Index(width));
      for (Eigen::Index k = 0; k < 2048; ++k)
        drawn.row(k) = centred.row(Eigen::Index(rows_drawn[std::size_t(k)]));
      covariance = drawn.transpose() * drawn;
    } else {
      covariance = centred.transpose() * centred;
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> pca(covariance);
    const Eigen::Index p = Eigen::Index(std::min(options.search_dimensions, width));
    const Eigen::MatrixXd basis = pca.eigenvectors().rightCols(p);
    const Eigen::MatrixXd reduced = centred * basis;
    std::vector<Point_d> sample_points;
    sample_points.reserve(m);
    for (std::size_t i = 0; i < m; ++i) {
      const Eigen::RowVectorXd row = reduced.row(Eigen::Index(i));
      sample_points.emplace_back(int(p), row.data(), row.data() + p);
    }
    const Point_map point_map = CGAL::make_property_map(sample_points);
    typename Search::Tree tree(boost::counting_iterator<std::size_t>(0),
                               boost::counting_iterator<std::size_t>(m),
                               typename Search::Tree::Splitter(), Traits(point_map));
    tree.build();

    // Template centres: templates at every vertex would average (2r + 1)² of them at each point
    // and blur the result; as texture optimization does, keep centres about a quarter of a
    // template apart (a point then lies in about 16 of them), picked in a random order.
    std::vector<std::uint32_t> centres;
    {
      std::vector<std::uint32_t> order = owners;
      std::shuffle(order.begin(), order.end(), random);
      const double apart = std::max(spacing, 0.5 * double(r) * spacing);
      auto cell_of = [&](const Eigen::Vector3d& x) {
        return std::array<std::int64_t, 3>{{std::int64_t(std::floor(x[0] / apart)),
                                            std::int64_t(std::floor(x[1] / apart)),
                                            std::int64_t(std::floor(x[2] / apart))}};
      };
      auto key = [](const std::array<std::int64_t, 3>& c) {
        return (c[0] * 73856093) ^ (c[1] * 19349663) ^ (c[2] * 83492791);
      };
      std::unordered_multimap<std::int64_t, std::uint32_t> taken;
      for (std::uint32_t i : order) {
        const Eigen::Vector3d& x = target_sampler.point(i);
        const auto c = cell_of(x);
        bool near = false;
        for (std::int64_t dx = -1; dx <= 1 && !near; ++dx)
          for (std::int64_t dy = -1; dy <= 1 && !near; ++dy)
            for (std::int64_t dz = -1; dz <= 1 && !near; ++dz) {
              const auto range = taken.equal_range(key({{c[0] + dx, c[1] + dy, c[2] + dz}}));
              for (auto it = range.first; it != range.second && !near; ++it)
                near = (target_sampler.point(it->second) - x).norm() < apart;
            }
        if (near)
          continue;
        taken.emplace(key(c), i);
        centres.push_back(i);
      }
    }
    const std::size_t count = centres.size();
    grid.assign(count * dims, Template_sample{});
    internal::parallel_blocks(
        count,
        [&](std::size_t first, std::size_t last) {
          typename decltype(target_sampler)::Scratch scratch;
          for (std::size_t t = first; t < last; ++t)
            target_sampler.sample(target_sampler.vertex(centres[t]), spacing, r,
                                  grid.data() + t * dims, scratch);
        },
        16);
    // Grid samples on the surface around the region (all three corners held) are left out, as
    // samples off the surface are: sample templates are texture throughout, so matching the
    // smooth surface there pulled the texels near the border out of their lattice.
    // Guided, they stay: the sample templates reach past their border too.
    if (!guided)
      for (Template_sample& g : grid)
        if (g.v[0] != Template_sample::npos && unknown[g.v[0]] == fixed &&
            unknown[g.v[1]] == fixed && unknown[g.v[2]] == fixed)
          g = Template_sample{};
    std::vector<double> held(grid.size(), 0);
    for (std::size_t g = 0; g < grid.size(); ++g)
      if (grid[g].v[0] != Template_sample::npos)
        for (std::size_t a = 0; a < 3; ++a)
          if (unknown[grid[g].v[a]] == fixed)
            held[g] += grid[g].w[a] * h[grid[g].v[a]];

    if (coarsest) {
      // Start (as texture optimization does) from random sample patches: each centre in turn
      // pastes a random sample template over the unknowns it reaches that no earlier one did,
      // each grid value going to the nearest corner of its triangle.
      // The patches come from templates wholly inside the sample's region (guided, the others
      // would paste their bare border into the middle of the target).
      std::vector<std::size_t> sources;
      for (std::size_t i = 0; i < m; ++i)
        if (!guided || templates.row(Eigen::Index(i)).rightCols(Eigen::Index(dims)).minCoeff() >=
                           guide * (1 - 1e-6))
          sources.push_back(i);
      if (sources.empty())
        for (std::size_t i = 0; i < m; ++i)
          sources.push_back(i);
      std::uniform_int_distribution<std::size_t> pick(0, sources.size() - 1);
      std::vector<bool> covered(n, false);
      std::vector<std::size_t> pasted;
      for (std::size_t t = 0; t < count; ++t) {
        const std::size_t source = sources[pick(random)];
        const Template_sample* tpl = grid.data() + t * dims;
        pasted.clear();
        for (std::size_t g = 0; g < dims; ++g) {
          const Template_sample& s = tpl[g];
          if (s.v[0] == Template_sample::npos)
            continue;
          const std::size_t a = std::size_t(std::max_element(s.w.begin(), s.w.end()) - s.w.begin());
          const std::size_t u = unknown[s.v[a]];
          if (u == fixed || covered[u])
            continue;
          h[s.v[a]] = templates(Eigen::Index(source), Eigen::Index(g));
          pasted.push_back(u);
        }
        for (std::size_t u : pasted)
          covered[u] = true;
      }
    }

    // Eq. 8, reweighted as texture optimization does (each template's weight ‖x − z‖^(0.8 − 2),
    // so a few bad matches do not blur the rest): Σ over templates and grid samples of
    // ω(w·h − s)² in the unknowns, the held details on the right-hand side. The pattern is
    // analysed once per level.
    // The pattern is built once per level; each iteration only refills its values: every
    // (grid sample, corner, corner) product of unknowns has its slot in the matrix's values.
    std::vector<double> weight(count, 1.0);
    Eigen::SparseMatrix<double> normal_matrix{Eigen::Index(n), Eigen::Index(n)};
    std::vector<std::size_t> slot; // per product, in the order `assemble` visits them
    {
      std::vector<Eigen::Triplet<double>> entries;
      for (const Template_sample& s : grid) {
        if (s.v[0] == Template_sample::npos)
          continue;
        for (std::size_t a = 0; a < 3; ++a)
          if (unknown[s.v[a]] != fixed)
            for (std::size_t b = 0; b < 3; ++b)
              if (unknown[s.v[b]] != fixed)
                entries.emplace_back(Eigen::Index(unknown[s.v[a]]), Eigen::Index(unknown[s.v[b]]),
                                     1.0);
      }
      // A small pull towards the current details keeps unknowns no grid sample lands on
      // determined.
      for (std::size_t i = 0; i < n; ++i)
        entries.emplace_back(Eigen::Index(i), Eigen::Index(i), 1.0);
      normal_matrix.setFromTriplets(entries.begin(), entries.end());
      normal_matrix.makeCompressed();
      slot.reserve(entries.size());
      const double* values = normal_matrix.valuePtr();
      for (const Eigen::Triplet<double>& e : entries)
        slot.push_back(std::size_t(&normal_matrix.coeffRef(e.row(), e.col()) - values));
    }
    auto assemble = [&] {
      double* values = normal_matrix.valuePtr();
      std::fill(values, values + normal_matrix.nonZeros(), 0.0);
      std::size_t k = 0;
      for (std::size_t g = 0; g < grid.size(); ++g) {
        const Template_sample& s = grid[g];
        if (s.v[0] == Template_sample::npos)
          continue;
        const double omega = weight[g / dims];
        for (std::size_t a = 0; a < 3; ++a)
          if (unknown[s.v[a]] != fixed)
            for (std::size_t b = 0; b < 3; ++b)
              if (unknown[s.v[b]] != fixed)
                values[slot[k++]] += omega * double(s.w[a]) * double(s.w[b]);
      }
      for (std::size_t i = 0; i < n; ++i)
        values[slot[k++]] += 1e-6;
    };
    assemble();
    // The M-step's matrix changes with the weights every iteration, while the details change
    // little: conjugate gradients from the current details (Jacobi preconditioned, the matrix is
    // a sum of interpolation stencils and well conditioned) take a few dozen products where an
    // LDLᵀ refactorization took 40 ms per iteration at 35k unknowns.
    Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> solver;
    solver.setTolerance(1e-6);
    // The coarse levels only settle where texels go: a rough solve (at most 50 products) is
    // enough there, and at spacing 4d most unknowns lie in few grid samples' triangles, which
    // makes the exact solve slow to converge (seconds at 35k unknowns).
    if (level > 0)
      solver.setMaxIterations(50);

    std::vector<std::size_t> match(count, m);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(Eigen::Index(n));
    for (std::size_t iteration = 0; iteration < options.iterations; ++iteration) {
      // E-step: the nearest sample template of each target template. Grid samples that fell off
      // the target take the sample mean, so they add nothing to the distance in principal
      // components.
      // The matches are independent (the tree is only read): in parallel, one slot per template.
      std::vector<std::size_t> best(count, m), valid(count, 0);
      std::vector<double> distance(count, 0);
      internal::parallel_blocks(
          count,
          [&](std::size_t first, std::size_t last) {
            Eigen::VectorXd query = Eigen::VectorXd::Zero(Eigen::Index(width));
            std::vector<double> coordinates(static_cast<std::size_t>(p));
            for (std::size_t t = first; t < last; ++t) {
              const Template_sample* tpl = grid.data() + t * dims;
              for (std::size_t g = 0; g < dims; ++g) {
                const Template_sample& s = tpl[g];
                query[Eigen::Index(g)] =
                    s.v[0] == Template_sample::npos
                        ? mean[Eigen::Index(g)]
                        : s.w[0] * h[s.v[0]] + s.w[1] * h[s.v[1]] + s.w[2] * h[s.v[2]];
                if (guided)
                  query[Eigen::Index(dims + g)] =
                      s.v[0] == Template_sample::npos
                          ? mean[Eigen::Index(dims + g)]
                          : guide * (s.w[0] * (unknown[s.v[0]] != fixed) +
                                     s.w[1] * (unknown[s.v[1]] != fixed) +
                                     s.w[2] * (unknown[s.v[2]] != fixed));
              }
              const Eigen::VectorXd projected = basis.transpose() * (query - mean.transpose());
              std::copy(projected.data(), projected.data() + p, coordinates.begin());
              const Point_d q(int(p), coordinates.begin(), coordinates.end());
              Search search(tree, q, 1, 0, true, Distance(point_map));
              best[t] = search.begin()->first;
              for (std::size_t g = 0; g < dims; ++g)
                if (tpl[g].v[0] != Template_sample::npos) {
                  const double e =
                      query[Eigen::Index(g)] - templates(Eigen::Index(best[t]), Eigen::Index(g));
                  distance[t] += e * e;
                  ++valid[t];
                }
            }
          },
          16);
      std::size_t changed = 0, counted = 0;
      double mismatch = 0;
      rhs.setZero();
      for (std::size_t t = 0; t < count; ++t) {
        const Template_sample* tpl = grid.data() + t * dims;
        changed += best[t] != match[t];
        match[t] = best[t];
        mismatch += distance[t];
        counted += valid[t];
        weight[t] = std::pow(std::sqrt(distance[t] / double(std::max<std::size_t>(valid[t], 1))) +
                                 1e-3 * peak,
                             0.8 - 2);
        // M-step's right-hand side: Σ ω w_a (s_g − held_g) over the unknown corners.
        for (std::size_t g = 0; g < dims; ++g) {
          const Template_sample& s = tpl[g];
          if (s.v[0] == Template_sample::npos)
            continue;
          const double value =
              templates(Eigen::Index(best[t]), Eigen::Index(g)) - held[t * dims + g];
          for (std::size_t a = 0; a < 3; ++a)
            if (unknown[s.v[a]] != fixed)
              rhs[Eigen::Index(unknown[s.v[a]])] += weight[t] * s.w[a] * value;
        }
      }
      result.rms_mismatch = counted > 0 ? std::sqrt(mismatch / double(counted)) : 0;
      ++result.iterations;
      report_progress(options.progress, "synthesis iterations", result.iterations, most_iterations);
      // Texture optimization settles long before every match is final: the last few changes
      // move the mismatch by under 0.1 % per iteration. Stop once at most 2 % of the templates
      // changed their match.
      if (double(changed) <= 0.02 * double(count))
        break;
      // M-step: the details that best agree with the matched templates.
      assemble();
      solver.compute(normal_matrix);
      for (std::size_t i = 0; i < n; ++i)
        rhs[Eigen::Index(i)] += 1e-6 * h[owners[i]];
      Eigen::VectorXd guess(Eigen::Index(n), 1);
      for (std::size_t i = 0; i < n; ++i)
        guess[Eigen::Index(i)] = h[owners[i]];
      const Eigen::VectorXd solved = solver.solveWithGuess(rhs, guess);
      if (solver.info() != Eigen::Success && !(level > 0 && solver.info() == Eigen::NoConvergence))
        return fail(Texture_synthesis_status::solve_failed,
                    "the synthesis' least-squares solve failed");
      for (std::size_t i = 0; i < n; ++i)
        h[owners[i]] = solved[Eigen::Index(i)];
    }
    // Least squares average the overlapping matches, which lowers the peaks and fills the
    // valleys a little at every iteration (texels come out a tenth smaller at the measure's
    // threshold). As Kopf et al. (2007) do in texture optimization, the details are then given
    // the sample's distribution: each unknown keeps its rank and takes the sample's value at
    // that rank: the sample's texture vertices beyond the border fade's width from its border
    // (the target's band that wide is faded out after, and the sample's is cut by the border).
    // Not only those a template's half width inside: that interior can end through the outer
    // texels' centres, where the base faired under a wide texture is lower than in its middle,
    // and holds lower details than the texture (doc/resizing.md, the two-lattice plate).
    if (options.match_histogram && !region_values.empty()) {
      std::vector<std::size_t> rank(n);
      std::iota(rank.begin(), rank.end(), std::size_t(0));
      std::sort(rank.begin(), rank.end(),
                [&](std::size_t a, std::size_t b) { return h[owners[a]] < h[owners[b]]; });
      for (std::size_t k = 0; k < n; ++k)
        h[owners[rank[k]]] = region_values[std::min(
            region_values.size() - 1,
            std::size_t((double(k) + 0.5) / double(n) * double(region_values.size())))];
    }
    // The vectors carried: the finest level's last matches averaged as eq. 8 averages the
    // details, with the same weights, one solve per component; no grid sample pulls an unknown
    // off 0 by itself.
    if (level == 0 && sample_vectors) {
      assemble();
      solver.compute(normal_matrix);
      for (std::size_t c = 0; c < 3; ++c) {
        rhs.setZero();
        for (std::size_t t = 0; t < count; ++t) {
          if (match[t] >= m)
            continue;
          for (std::size_t g = 0; g < dims; ++g) {
            const Template_sample& s = grid[t * dims + g];
            const Template_sample& from = whole_grid[match[t] * dims + g];
            if (s.v[0] == Template_sample::npos || from.v[0] == Template_sample::npos)
              continue;
            double value = 0;
            for (std::size_t a = 0; a < 3; ++a) {
              value += from.w[a] * (*sample_vectors)[from.v[a]][c];
              if (unknown[s.v[a]] == fixed)
                value -= s.w[a] * vectors[s.v[a]][c];
            }
            for (std::size_t a = 0; a < 3; ++a)
              if (unknown[s.v[a]] != fixed)
                rhs[Eigen::Index(unknown[s.v[a]])] += weight[t] * s.w[a] * value;
          }
        }
        const Eigen::VectorXd solved = solver.solve(rhs);
        if (solver.info() != Eigen::Success)
          return fail(Texture_synthesis_status::solve_failed,
                      "the least-squares solve of the carried vectors failed");
        for (std::size_t i = 0; i < n; ++i)
          vectors[owners[i]][c] = solved[Eigen::Index(i)];
      }
    }
  }
  // The finest level, unguided, fills the region to its border: fragments of texels the border
  // still cuts are faded out over `border_fade` (smoothstep of the distance along the edges from
  // the vertices around the region).
  std::vector<double> fade(target_sampler.size(), 1.0);
  if (options.border_fade > 0) {
    const std::vector<double> around =
        internal::distance_from_outside(target, target_vpm, target_region);
    for (std::size_t i = 0; i < fade.size(); ++i) {
      const double t = std::min(1.0, around[i] / options.border_fade);
      fade[i] = t * t * (3 - 2 * t);
    }
  }
  for (auto v : vertices(target))
    if (get(target_region, v)) {
      const std::uint32_t i = target_sampler.index(v);
      put(target_height, v, fade[i] * h[i]);
      if (target_vectors)
        for (std::size_t c = 0; c < 3; ++c)
          (*target_vectors)[i][c] = fade[i] * vectors[i][c];
    }
  report_progress(options.progress, "synthesis iterations", most_iterations, most_iterations);
  return result;
}

} // namespace internal
} // namespace tessera
