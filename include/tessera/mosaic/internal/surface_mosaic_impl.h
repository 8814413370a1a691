// The implementation of `Surface_mosaic` (tessera/mosaic/surface_mosaic.h): its set-up, the
// optimization (eq. 3's forces in the tiles' charts, the moves along the surface, the neighbour
// lists, teleportation) and its results. The start is in surface_mosaic_start_impl.h, the
// separation that follows the optimization in surface_mosaic_separation_impl.h. Internal: the
// public header holds the types and the documented entry points; nothing here is meant to be
// called directly.
#pragma once

#include <tessera/mosaic/surface_mosaic.h>

#include <tessera/fields/singularities.h>
#include <tessera/internal/parallel.h>
#include <tessera/mosaic/internal/error_diffusion.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace tessera {

template <typename TriangleMesh, typename NamedParameters>
template <typename VertexFieldMap>
Surface_mosaic<TriangleMesh, NamedParameters>::Surface_mosaic(
    const TriangleMesh& tm, const VertexFieldMap& field,
    const std::vector<Feature_line<halfedge_descriptor>>& features,
    const Surface_mosaic_options& options, const NamedParameters& np)
    : tm_(tm), options_(options), vpm_(internal::vertex_point_map(tm, np)) {
  setup(field, features, np);
}

template <typename TriangleMesh, typename NamedParameters>
std::size_t Surface_mosaic<TriangleMesh, NamedParameters>::iterate(std::size_t k) {
  if (status_ != Mosaic_status::ok)
    return 0;
  const auto t0 = Clock::now();
  std::size_t done = 0;
  for (; done < k && !stats_.converged; ++done) {
    const std::size_t it = stats_.iterations;
    if (options_.teleport_every > 0 && it >= options_.teleport_after &&
        (it - options_.teleport_after) % options_.teleport_every == 0 && it > 0)
      stats_.teleported += teleport();
    if (window_pos_.size() != pos_.size()) {
      window_pos_ = pos_;
      window_iterations_ = 0;
    }
    step();
    ++stats_.iterations;
    const bool may_stop = options_.teleport_every == 0 || it > options_.teleport_after;
    if (stats_.mean_displacement.back() < options_.tolerance && may_stop)
      stats_.converged = true;
    // The tiles' net move over the last `stop_window` iterations: where they only jitter (pushed
    // back and forth by about half a percent of the spacing on organic meshes, two percent beside
    // feature walls), the mean displacement of each iteration levels off at that jitter, and
    // stopped only where it dipped below the tolerance: 77-103 iterations on the bull and the cow,
    // the cap of 150 on fandisk with its creases, for no visible change after some 25.
    if (++window_iterations_ == stop_window) {
      const std::size_t n = pos_.size();
      double net = 0;
      for (std::size_t i = 0; i < n; ++i)
        net += internal::norm(pos_[i] - window_pos_[i]) / size_at(points_[i]);
      net /= double(std::max<std::size_t>(n, 1)) * layout_.spacing * double(stop_window);
      stats_.net_displacement.push_back(net);
      if (net < options_.tolerance && may_stop)
        stats_.converged = true;
      window_pos_ = pos_;
      window_iterations_ = 0;
    }
    if (options_.progress)
      options_.progress({"iterations", stats_.iterations, options_.max_iterations});
  }
  stats_.seconds_optimization += seconds(t0, Clock::now());
  stats_.charts = atlas_->size();
  stats_.failed_charts = atlas_->failed();
  return done;
}

template <typename TriangleMesh, typename NamedParameters>
void Surface_mosaic<TriangleMesh, NamedParameters>::run() {
  if (stats_.iterations < options_.max_iterations)
    iterate(options_.max_iterations - stats_.iterations);
  separate_tiles();
  clear_features();
}

template <typename TriangleMesh, typename NamedParameters>
std::size_t Surface_mosaic<TriangleMesh, NamedParameters>::teleport() {
  if (status_ != Mosaic_status::ok || points_.empty())
    return 0;
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  refresh_neighbors(true);
  const std::vector<std::uint32_t> hole_faces = largest_holes(knn_, 0.85, points_.size());
  // Tiles of the closest pairs: cells overlapping by more than a quarter of their side.
  std::vector<std::pair<double, std::uint32_t>> crowded;
  for (std::uint32_t i = 0; i < points_.size(); ++i)
    if (nearest_.size() == points_.size() &&
        nearest_[i] < manhattan_distance(0.75 * layout_.spacing, 0))
      crowded.push_back({nearest_[i], i});
  std::sort(crowded.begin(), crowded.end());
  std::vector<char> taken(points_.size(), 0);
  std::size_t moved = 0;
  for (const auto& c : crowded) {
    if (moved == hole_faces.size())
      break;
    const std::uint32_t i = c.second;
    if (taken[i] || taken[nearest_index_[i]])
      continue;
    taken[i] = taken[nearest_index_[i]] = 1;
    const std::uint32_t f = hole_faces[moved++];
    points_[i] = internal::Surface_point{f, {{1.0 / 3, 1.0 / 3, 1.0 / 3}}};
    pos_[i] = s.position(points_[i]);
    chart_[i] = atlas_->chart_index_of(f);
    if (gain_.size() == points_.size()) {
      gain_[i] = 1;
      last_move_[i] = internal::Vec3{{0, 0, 0}};
    }
  }
  if (moved > 0)
    refresh_neighbors(true);
  return moved;
}

template <typename TriangleMesh, typename NamedParameters>
std::vector<typename Surface_mosaic<TriangleMesh, NamedParameters>::Tile>
Surface_mosaic<TriangleMesh, NamedParameters>::tiles() const {
  std::vector<Tile> out;
  if (status_ != Mosaic_status::ok)
    return out;
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  out.reserve(points_.size());
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const internal::Surface_point& p = points_[i];
    Tile t;
    // A tile is glued flat onto the face its centre lies in.
    t.center = pos_[i];
    t.normal = s.normal(p.face);
    t.x_axis = tile_x_axis(p);
    t.size = {{layout_.tile_size[0] * tile_scale(i, 0), layout_.tile_size[1] * tile_scale(i, 1)}};
    t.face = s.face_of(p.face);
    // Internally corner k is the source of the k-th halfedge from halfedge(face); the tile's
    // coordinates follow vertices_around_face(halfedge(face)), which starts at its target
    // (found by the property sweep: the documented order gave points off the centre).
    t.barycentric = {{p.bary[1], p.bary[2], p.bary[0]}};
    t.region = s.region(p.face);
    t.color = distinct_color(t.region);
    out.push_back(t);
  }
  return out;
}

template <typename TriangleMesh, typename NamedParameters>
typename Surface_mosaic<TriangleMesh, NamedParameters>::Result
Surface_mosaic<TriangleMesh, NamedParameters>::result() const {
  Result r;
  r.status = status_;
  r.message = message_;
  r.layout = layout_;
  r.stats = stats_;
  r.tiles = tiles();
  return r;
}

template <typename TriangleMesh, typename NamedParameters>
template <typename VertexFieldMap>
void Surface_mosaic<TriangleMesh, NamedParameters>::setup(
    const VertexFieldMap& field, const std::vector<Feature_line<halfedge_descriptor>>& features,
    const NamedParameters& np) {
  const TriangleMesh& tm = tm_;
  const Surface_mosaic_options& options = options_;
  const auto t0 = Clock::now();
  if (faces(tm).empty())
    return fail(Mosaic_status::empty_mesh, "the mesh has no faces");
  if (!CGAL::is_triangle_mesh(tm))
    return fail(Mosaic_status::not_triangle_mesh, "the mesh is not a triangle mesh");
  symmetry_ = options.symmetry != 0 ? options.symmetry : mosaic_field_symmetry(options.tiles);
  if (symmetry_ != 2 && symmetry_ != 4)
    return fail(Mosaic_status::invalid_options, "the symmetry must be 2 or 4");
  const bool paper = options.energy == Mosaic_energy::gaussian_manhattan;
  const double chart_radius = options.chart_radius > 0 ? options.chart_radius : paper ? 5 : 3;
  const double core_radius = options.chart_core_radius > 0 ? options.chart_core_radius
                             : paper                       ? 2
                                                           : 1.2;
  if (options.neighbors < 1 || !(options.step > 0) || !(options.max_step > 0) ||
      options.chart_radius < 0 || options.chart_core_radius < 0 || core_radius >= chart_radius)
    return fail(Mosaic_status::invalid_options, "neighbors, step, max_step and the chart radii "
                                                "must be positive, the core inside the chart");
  if (!(options.most_over_count >= 0) || !std::isfinite(options.most_over_count))
    return fail(Mosaic_status::invalid_options, "most_over_count must be finite and not negative");
  for (auto v : vertices(tm)) {
    const internal::Vec3 x = internal::to_vec3(get(field, v));
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
      return fail(Mosaic_status::invalid_field, "the field has a non-finite vector");
  }
  surface_ = std::make_unique<internal::Surface_arrays<TriangleMesh>>(tm, vpm_, features);
  double area = surface_->total_area();
  if constexpr (!CGAL::parameters::is_default_parameter<NamedParameters,
                                                        CGAL::internal_np::scalar_t>::value) {
    const auto size_map = CGAL::parameters::get_parameter(np, CGAL::internal_np::scalar_map);
    const internal::Surface_arrays<TriangleMesh>& s = *surface_;
    vertex_size_.resize(s.number_of_vertices());
    for (std::uint32_t v = 0; v < s.number_of_vertices(); ++v) {
      vertex_size_[v] = double(get(size_map, s.vertex_of(v)));
      if (!std::isfinite(vertex_size_[v]) || !(vertex_size_[v] > 0))
        return fail(Mosaic_status::invalid_options,
                    "the tile size field must be positive and finite (vertex " + std::to_string(v) +
                        ")");
    }
    if (options.initialization == Mosaic_initialization::position_field)
      return fail(Mosaic_status::invalid_options,
                  "the position-field start does not take a tile size field");
    // The layout's spacing is that of size 1: N tiles of the local sizes cover the surface.
    area = 0;
    for (std::uint32_t f = 0; f < s.number_of_faces(); ++f)
      area += s.area(f) / std::pow(face_size(f), 2);
    largest_size_ = *std::max_element(vertex_size_.begin(), vertex_size_.end());
  }
  if (auto why = mosaic_layout(options.tiles, area, layout_))
    return fail(Mosaic_status::invalid_options, *why);
  if (layout_.aspect != 1 && symmetry_ == 4)
    return fail(Mosaic_status::invalid_options,
                "rectangular tiles need a 2-symmetric (line) field");
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  face_field_ = std::make_unique<internal::Face_field<TriangleMesh>>(s, field, symmetry_);
  vertex_field_.resize(s.number_of_vertices());
  for (std::uint32_t v = 0; v < s.number_of_vertices(); ++v)
    vertex_field_[v] = internal::to_vec3(get(field, s.vertex_of(v)));
  Manhattan_chart_options co;
  // Charts hold the neighbours of the largest tiles (the pull of smaller ones ends sooner).
  co.radius = chart_radius * layout_.sigma * largest_size_;
  co.core_radius = core_radius * layout_.sigma * largest_size_;
  co.max_rotation = options.max_chart_rotation;
  // A third of the chart radius: a band around a part thinner than the chart meets itself a
  // girth apart, at least a spacing; curvature moves a corner far less (see the option).
  co.seam_tolerance = co.radius / 3;
  atlas_ = std::make_unique<Manhattan_chart_atlas<TriangleMesh>>(s, *face_field_, co);
  reach_ =
      options.feature_reach * std::max(layout_.tile_size[0], layout_.tile_size[1]) * largest_size_;
  if (options.feature_repulsion && !features.empty())
    features_ = std::make_unique<internal::Feature_segments<TriangleMesh>>(s, features, reach_);
  if (options.singularity_tiles) {
    const auto sing = field_singularities(tm, field, symmetry_);
    for (const auto& sg : sing.singularities) {
      const std::uint32_t f = s.id(sg.face);
      virtual_pos_.push_back(s.centroid(f));
      virtual_region_.push_back(s.region(f));
    }
  }
  stats_.regions = s.number_of_regions();
  stats_.virtual_tiles = virtual_pos_.size();
  const auto t1 = Clock::now();
  stats_.seconds_setup = seconds(t0, t1);
  // `automatic`: the position field has one spacing, so a tile size field grows the lattice.
  if (options_.initialization == Mosaic_initialization::automatic)
    options_.initialization = vertex_size_.empty() ? Mosaic_initialization::position_field
                                                   : Mosaic_initialization::lattice;
  if (options_.initialization == Mosaic_initialization::position_field)
    points_ = fit_count(position_field_points());
  else if (options_.initialization == Mosaic_initialization::lattice)
    points_ = lattice_points();
  else {
    // With a size field, the density goes as 1 / size².
    std::vector<double> weight;
    for (std::uint32_t f = 0; f < s.number_of_faces() && !vertex_size_.empty(); ++f)
      weight.push_back(1 / std::pow(face_size(f), 2));
    points_ = internal::error_diffusion_points(s, layout_.tile_count, options.seed, weight);
  }
  // Tiles in Hilbert order (CGAL's median policy, deterministic): each tile's neighbours then
  // lie close in memory, and so do the charts they are looked up in. The forces and the
  // separation read a neighbour's face, barycentric coordinates and chart coordinates per pair,
  // and in the start's order (rows grown breadth first) those were cache misses.
  {
    std::vector<CGAL::Epick::Point_3> at;
    at.reserve(points_.size());
    for (const internal::Surface_point& p : points_) {
      const internal::Vec3 q = s.position(p);
      at.emplace_back(q[0], q[1], q[2]);
    }
    std::vector<std::size_t> order(points_.size());
    for (std::size_t i = 0; i < order.size(); ++i)
      order[i] = i;
    using Point_map = CGAL::Pointer_property_map<CGAL::Epick::Point_3>::type;
    CGAL::hilbert_sort(
        order.begin(), order.end(),
        CGAL::Spatial_sort_traits_adapter_3<CGAL::Epick, Point_map>(CGAL::make_property_map(at)),
        CGAL::Hilbert_sort_median_policy());
    std::vector<internal::Surface_point> sorted;
    sorted.reserve(points_.size());
    pos_.reserve(points_.size());
    for (std::size_t i : order) {
      sorted.push_back(points_[i]);
      pos_.push_back({{at[i].x(), at[i].y(), at[i].z()}});
    }
    points_.swap(sorted);
  }
  std::vector<std::uint32_t> start_faces;
  for (const internal::Surface_point& p : points_)
    start_faces.push_back(p.face);
  chart_ = atlas_->chart_indices_of(start_faces);
  stats_.seconds_initialization = seconds(t1, Clock::now());
  stats_.charts = atlas_->size();
}

// Keeps the tiles i with keep[i]; the neighbour lists are renumbered (or, when there are none
// yet, built on their next use).
template <typename TriangleMesh, typename NamedParameters>
void Surface_mosaic<TriangleMesh, NamedParameters>::remove_tiles(const std::vector<char>& keep) {
  const std::size_t n = points_.size(), nk = options_.neighbors;
  // The neighbour lists stay, renumbered, with the left-out tiles taken out (the separation
  // leaves out a few tiles a round; querying every list again took 0.05 s a round at 40k tiles).
  // Each list then holds its k nearest less those left out, padded at the end; the next refresh
  // queries again the lists of tiles that moved, as it does for any list.
  const bool lists = neighbors_.size() == n * nk && built_pos_.size() == n;
  std::vector<std::uint32_t> index(n + virtual_pos_.size(), internal::no_index);
  std::size_t k = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (keep[i]) {
      index[i] = std::uint32_t(k);
      points_[k] = points_[i], pos_[k] = pos_[i], chart_[k] = chart_[i];
      if (!scale_.empty())
        scale_[k] = scale_[i];
      if (lists)
        built_pos_[k] = built_pos_[i];
      ++k;
    }
  for (std::size_t v = 0; v < virtual_pos_.size(); ++v) // virtual tiles follow the tiles
    index[n + v] = std::uint32_t(k + v);
  if (lists) {
    std::size_t row = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (!keep[i])
        continue;
      std::size_t m = 0;
      for (std::size_t e = 0; e < nk; ++e) {
        const std::uint32_t j = neighbors_[i * nk + e];
        if (j == internal::no_index)
          break;
        if (index[j] != internal::no_index)
          neighbors_[row * nk + m++] = index[j];
      }
      for (; m < nk; ++m)
        neighbors_[row * nk + m] = internal::no_index;
      ++row;
    }
    neighbors_.resize(k * nk), built_pos_.resize(k);
  }
  points_.resize(k), pos_.resize(k), chart_.resize(k);
  if (!scale_.empty())
    scale_.resize(k);
  if (lists)
    forget_tile_state();
  else
    forget_neighbors();
}

// After tiles were added or removed: the per-tile state of the optimization and the neighbour
// lists no longer match the tiles; they are rebuilt on their next use.
template <typename TriangleMesh, typename NamedParameters>
void Surface_mosaic<TriangleMesh, NamedParameters>::forget_neighbors() {
  forget_tile_state();
  built_pos_.clear(), neighbors_.clear();
  knn_.reset({});
}

// The optimization's per-tile state (steps, gains, nearest neighbours), rebuilt on its next use.
template <typename TriangleMesh, typename NamedParameters>
void Surface_mosaic<TriangleMesh, NamedParameters>::forget_tile_state() {
  last_move_.clear(), gain_.clear(), nearest_.clear(), nearest_index_.clear();
}

template <typename TriangleMesh, typename NamedParameters>
double Surface_mosaic<TriangleMesh, NamedParameters>::seconds(Clock::time_point a,
                                                              Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

template <typename TriangleMesh, typename NamedParameters>
void Surface_mosaic<TriangleMesh, NamedParameters>::fail(Mosaic_status s, std::string m) {
  status_ = s;
  message_ = std::move(m);
}

template <typename TriangleMesh, typename NamedParameters>
internal::Vec3
Surface_mosaic<TriangleMesh, NamedParameters>::tangent(const internal::Vec3& x,
                                                       const internal::Vec3& normal) {
  const internal::Vec3 t = x - internal::dot(x, normal) * normal;
  const double l = internal::norm(t);
  if (l > 1e-12)
    return (1 / l) * t;
  const internal::Vec3 a =
      std::abs(normal[0]) < 0.9 ? internal::Vec3{{1, 0, 0}} : internal::Vec3{{0, 1, 0}};
  const internal::Vec3 b = internal::cross(normal, a);
  return (1 / internal::norm(b)) * b;
}

// Rebuilds the k-nearest lists when some tile has moved far enough since its list was built to
// change them (an eighth of the spacing), or every 10 iterations. Only the lists that can have
// changed are queried again (`requery_neighbors()`), unless `force`.
template <typename TriangleMesh, typename NamedParameters>
void Surface_mosaic<TriangleMesh, NamedParameters>::refresh_neighbors(bool force, bool periodic) {
  if (!force && knn_.size() > 0 && moved_since_refresh_ < 0.25 * layout_.spacing &&
      (!periodic || iterations_since_refresh_ < 10)) {
    ++iterations_since_refresh_;
    return;
  }
  const std::size_t n = points_.size(), k = options_.neighbors;
  std::vector<internal::Vec3> all = pos_;
  all.insert(all.end(), virtual_pos_.begin(), virtual_pos_.end());
  knn_.reset(all);
  const bool whole = force || built_pos_.size() != n || neighbors_.size() != n * k;
  std::vector<std::uint32_t> query;
  if (whole) {
    neighbors_.assign(n * k, internal::no_index);
    built_pos_.resize(n);
    query.resize(n);
    for (std::uint32_t i = 0; i < n; ++i)
      query[i] = i;
  } else {
    query = movers();
  }
  requery_neighbors(query);
  if (!whole) {
    // A tile that moved can have left the lists it was in, and entered those of the tiles now
    // near it (the tiles in its own new list: nearness is about symmetric): those are queried
    // again too. Every other list holds tiles that moved less than the threshold.
    std::vector<char> mover(n, 0), again(n, 0);
    for (const std::uint32_t i : query)
      mover[i] = 1;
    for (const std::uint32_t i : query)
      for (std::size_t m = 0; m < k; ++m) {
        const std::uint32_t j = neighbors_[i * k + m];
        if (j < n && !mover[j])
          again[j] = 1;
      }
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t m = 0; m < k && !mover[i] && !again[i]; ++m) {
        const std::uint32_t j = neighbors_[i * k + m];
        if (j < n && mover[j])
          again[i] = 1;
      }
    std::vector<std::uint32_t> second;
    for (std::uint32_t i = 0; i < n; ++i)
      if (again[i])
        second.push_back(i);
    requery_neighbors(second);
  }
  // The threshold holds against each tile's position when its list was last built.
  double largest = 0;
  for (std::size_t i = 0; i < n; ++i)
    largest = std::max(largest, internal::norm(pos_[i] - built_pos_[i]) / size_at(points_[i]));
  moved_since_refresh_ = 2 * largest;
  iterations_since_refresh_ = 0;
}

// The tiles that moved more than a sixteenth of the spacing since their lists were built (half the
// refresh threshold: the lists of those below it stay).
template <typename TriangleMesh, typename NamedParameters>
std::vector<std::uint32_t> Surface_mosaic<TriangleMesh, NamedParameters>::movers() const {
  std::vector<std::uint32_t> out;
  for (std::uint32_t i = 0; i < points_.size(); ++i)
    if (internal::norm(pos_[i] - built_pos_[i]) / size_at(points_[i]) > 0.0625 * layout_.spacing)
      out.push_back(i);
  return out;
}

// Queries the k-nearest lists of `tiles` in the current tree, on every core.
template <typename TriangleMesh, typename NamedParameters>
void Surface_mosaic<TriangleMesh, NamedParameters>::requery_neighbors(
    const std::vector<std::uint32_t>& tiles) {
  const std::size_t k = options_.neighbors;
  internal::parallel_blocks(tiles.size(), [&](std::size_t first, std::size_t last) {
    for (std::size_t t = first; t < last; ++t) {
      const std::uint32_t i = tiles[t];
      std::size_t m = 0;
      knn_.nearest(pos_[i], k + 1, [&](std::size_t j, double) {
        if (j != i && m < k)
          neighbors_[i * k + m++] = std::uint32_t(j);
      });
      for (; m < k; ++m)
        neighbors_[i * k + m] = internal::no_index;
      built_pos_[i] = pos_[i];
    }
  });
}

// The size field at face f's centroid.
template <typename TriangleMesh, typename NamedParameters>
double Surface_mosaic<TriangleMesh, NamedParameters>::face_size(std::uint32_t f) const {
  return size_at(internal::Surface_point{f, {{1.0 / 3, 1.0 / 3, 1.0 / 3}}});
}

// The size field at p (1 without one).
template <typename TriangleMesh, typename NamedParameters>
double
Surface_mosaic<TriangleMesh, NamedParameters>::size_at(const internal::Surface_point& p) const {
  if (vertex_size_.empty())
    return 1;
  const auto& c = surface_->corners(p.face);
  return p.bary[0] * vertex_size_[c[0]] + p.bary[1] * vertex_size_[c[1]] +
         p.bary[2] * vertex_size_[c[2]];
}

// Tile i's side along `axis` over the layout's: the size field at its centre, times its
// shrinking and trimming.
template <typename TriangleMesh, typename NamedParameters>
double Surface_mosaic<TriangleMesh, NamedParameters>::tile_scale(std::size_t i, int axis) const {
  return size_at(points_[i]) * (i < scale_.size() ? scale_[i][axis] : 1.0);
}

// (du, dv) from tile j to tile i in tile i's chart, or in j's chart when i's does not hold j, or
// else in i's tangent frame.
template <typename TriangleMesh, typename NamedParameters>
std::array<double, 2> Surface_mosaic<TriangleMesh, NamedParameters>::chart_difference(
    std::uint32_t i, std::uint32_t j, const Manhattan_chart& ci, const std::array<double, 2>& uvi,
    const std::array<internal::Vec3, 2>& frame) const {
  const internal::Surface_point& pj = points_[j];
  const std::uint32_t sj = ci.slot(pj.face);
  if (sj != internal::no_index) {
    const auto uvj = ci.uv_at(sj, pj.bary);
    return {{uvi[0] - uvj[0], uvi[1] - uvj[1]}};
  }
  const Manhattan_chart& cj = atlas_->chart(chart_[j]);
  const std::uint32_t si = cj.slot(points_[i].face);
  if (si != internal::no_index) {
    const auto a = cj.uv_at(si, points_[i].bary), b = cj.uv_at(cj.slot(pj.face), pj.bary);
    return {{a[0] - b[0], a[1] - b[1]}};
  }
  const internal::Vec3 d = pos_[i] - pos_[j];
  return {{internal::dot(d, frame[0]), internal::dot(d, frame[1])}};
}

// A tile's x axis: the power average of its face corners' field at its centre, in the face's
// plane, started from the face's direction.
template <typename TriangleMesh, typename NamedParameters>
internal::Vec3
Surface_mosaic<TriangleMesh, NamedParameters>::tile_x_axis(const internal::Surface_point& p) const {
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  const internal::Vec3 normal = s.normal(p.face);
  const internal::Vec3 e1 = tangent(face_field_->direction(p.face), normal);
  const internal::Vec3 e2 = internal::cross(normal, e1);
  const auto& c = s.corners(p.face);
  double a = 0;
  internal::interpolated_field_angle(
      {{vertex_field_[c[0]], vertex_field_[c[1]], vertex_field_[c[2]]}}, p.bary, e1, e2, symmetry_,
      a);
  return std::cos(a) * e1 + std::sin(a) * e2;
}

// With the soft-box energy feature lines are walls (a mirror image hardly pushes a tile that sits
// on the line, the energy being flat near zero distance): a tile whose cell (the tile and half
// the grout around it) crosses the closest line of its region moves straight away from it until
// the cell touches the line, so the tile's edge stays half a grout width off it (Lai et al.
// §5.2).
template <typename TriangleMesh, typename NamedParameters>
void Surface_mosaic<TriangleMesh, NamedParameters>::keep_off_features(std::uint32_t i) {
  if (!features_)
    return;
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  const double root = std::sqrt(layout_.aspect);
  // A tile near two lines (a corner of a region) may be pushed from one towards the other: a few
  // passes.
  for (int pass = 0; pass < 4; ++pass) {
    internal::Surface_point& p = points_[i];
    const internal::Vec3 at = s.position(p);
    internal::Vec3 q;
    if (!features_->near(p.face) || !features_->closest(s.region(p.face), at, q))
      return;
    internal::Vec3 away = at - q;
    const double depth = internal::norm(away);
    if (!(depth > 1e-9 * layout_.spacing))
      away = s.centroid(p.face) - q; // on the line: into the face
    // In the tile's own axes (those `tiles()` writes), not its chart's: near a line the field
    // turns, and a few degrees between the two would let a corner of the tile over the line.
    const internal::Vec3 x = tile_x_axis(p);
    const std::array<internal::Vec3, 2> frame{{x, internal::cross(s.normal(p.face), x)}};
    const double nu = internal::dot(away, frame[0]), nv = internal::dot(away, frame[1]);
    const double l = std::sqrt(nu * nu + nv * nv);
    if (!(l > 0))
      return;
    // Half the cell's extent along the line's normal (cell sides s·√η along u, s/√η along v),
    // less what the separation shrank or trimmed off the tile: a full cell's distance pushed
    // tiles trimmed beside a crease back onto their neighbours at every pass, and those pairs
    // were most of a CAD part's overlap (oblong: tiles cut to a quarter or more overlapping the
    // next one in bands 1.4 tiles wide).
    const std::array<double, 2> scale =
        i < scale_.size() ? scale_[i] : std::array<double, 2>{{1, 1}};
    const double cell_u = root * layout_.spacing - (1 - scale[0]) * layout_.tile_size[0],
                 cell_v = layout_.spacing / root - (1 - scale[1]) * layout_.tile_size[1];
    const double half = 0.5 * size_at(p) * (cell_u * std::abs(nu) + cell_v * std::abs(nv)) / l;
    if (depth >= half)
      return;
    p = s.walk(p, ((half - depth) / l) * (nu * frame[0] + nv * frame[1])).p;
    chart_[i] = atlas_->chart_index_of(p.face);
  }
}

// One iteration of eq. 3: every force from the current positions, then every move. Both loops
// run over the tiles in parallel (forces read the positions of the last iteration; projections
// touch one tile each); charts, which grow lazily, and the feature walls follow serially.
template <typename TriangleMesh, typename NamedParameters>
void Surface_mosaic<TriangleMesh, NamedParameters>::step() {
  refresh_neighbors(false);
  const std::size_t n = points_.size();
  const double cap = options_.max_step * layout_.spacing;
  std::vector<internal::Vec3> move(n);
  std::vector<double> energy(n, 0.0);
  if (last_move_.size() != n) {
    last_move_.assign(n, internal::Vec3{{0, 0, 0}});
    gain_.assign(n, 1.0);
  }
  nearest_.assign(n, std::numeric_limits<double>::infinity());
  nearest_index_.assign(n, 0);
  internal::parallel_blocks(n, [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i) {
      internal::Vec3 m = force(std::uint32_t(i), energy[i]);
      // A tile pushed back and forth between two neighbours (its move reverses) halves its own
      // step; one that keeps going regains it. Without this, crowded tiles oscillate for ever.
      if (internal::dot(m, last_move_[i]) < 0)
        gain_[i] *= 0.5;
      else
        gain_[i] = std::min(1.0, 1.25 * gain_[i]);
      m = gain_[i] * m;
      const double l = internal::norm(m), most = cap * size_at(points_[i]);
      if (l > most)
        m = (most / l) * m;
      move[i] = m;
    }
  });
  last_move_ = move;
  const double total = move_by(move);
  double sum = 0;
  for (double e : energy)
    sum += e;
  stats_.energy.push_back(sum);
  stats_.mean_displacement.push_back(n > 0 ? total / double(n) / layout_.spacing : 0);
}

// Eq. 3's force on tile i (times the step t), in its tangent plane; adds i's pair energies to
// `energy` and records its nearest neighbour in the Manhattan metric.
template <typename TriangleMesh, typename NamedParameters>
internal::Vec3 Surface_mosaic<TriangleMesh, NamedParameters>::force(std::uint32_t i,
                                                                    double& energy) {
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  const std::size_t n = points_.size();
  const bool paper = options_.energy == Mosaic_energy::gaussian_manhattan;
  const double sigma2 = layout_.sigma * layout_.sigma, two_sigma2 = 2 * sigma2,
               sigma4 = sigma2 * sigma2;
  const double root = std::sqrt(layout_.aspect);
  const internal::Surface_point& p = points_[i];
  const Manhattan_chart& chart = atlas_->chart(chart_[i]);
  const std::uint32_t slot = chart.slot(p.face);
  const auto uvi = chart.uv_at(slot, p.bary);
  const std::array<internal::Vec3, 2>& frame = chart.frame[slot];
  const std::uint32_t region = s.region(p.face);
  double fx = 0, fy = 0;
  internal::Vec3 f3{{0, 0, 0}};
  // One neighbour at (du, dv) from tile i in i's chart, the pair's mean size h (of the size
  // field; the energy is that of tiles of size 1 at (du, dv) / h): its energy and its push on i.
  const double hi = size_at(p);
  auto add = [&](double du, double dv, double h) {
    const double x = du / (root * h), y = dv * root / h;
    const double d = manhattan_distance(x, y);
    if (paper) {
      const double e = std::exp(-d * d / two_sigma2); // eq. 2
      fx += h * x * e;                                // eq. 3
      fy += h * y * e;
      energy += e;
    } else {
      const double x2 = x * x, y2 = y * y;
      const double e = std::exp(-2 * (x2 * x2 + y2 * y2) / sigma4);
      fx += h * x * x2 * e / sigma2; // −σ²/8 ∇e
      fy += h * y * y2 * e / sigma2;
      energy += e;
      // Cells (a tile with the grout around it, a spacing wide) that overlap push apart along
      // the axis of least overlap, each by half of it times `separation`: the soft box alone
      // lets crowded rows settle with the tiles overlapping by a few percent.
      const double ox = layout_.spacing - std::abs(x), oy = layout_.spacing - std::abs(y);
      if (options_.separation > 0 && ox > 0 && oy > 0) {
        if (ox < oy)
          fx += (x >= 0 ? 0.5 : -0.5) * h * options_.separation * ox;
        else
          fy += (y >= 0 ? 0.5 : -0.5) * h * options_.separation * oy;
      }
    }
    return d;
  };
  for (std::size_t m = 0; m < options_.neighbors; ++m) {
    const std::uint32_t j = neighbors_[i * options_.neighbors + m];
    if (j == internal::no_index)
      break;
    if (j >= n) { // a virtual tile at a singularity: Euclidean distance
      if (virtual_region_[j - n] != region)
        continue;
      const internal::Vec3 d = pos_[i] - virtual_pos_[j - n];
      const double r2 = internal::dot(d, d) / (hi * hi);
      const double e = paper ? std::exp(-r2 / two_sigma2) : std::exp(-2 * r2 * r2 / sigma4);
      f3 = f3 + (paper ? e : e * r2 / sigma2) * d;
      energy += e;
      continue;
    }
    // Tiles of another region, or facing away (the other side of a thin part), do not interact.
    if (s.region(points_[j].face) != region ||
        internal::dot(s.normal(points_[j].face), s.normal(p.face)) < -0.5)
      continue;
    const auto d = chart_difference(i, j, chart, uvi, frame);
    const double dist =
        add(d[0], d[1], vertex_size_.empty() ? 1 : 0.5 * (hi + size_at(points_[j])));
    if (dist < nearest_[i]) {
      nearest_[i] = dist;
      nearest_index_[i] = j;
    }
  }
  // Feature lines with the paper's energy: repulsion from the mirror image across the closest
  // line (Lai et al. §5.2). With the soft-box energy they are walls (`keep_off_features`).
  internal::Vec3 q;
  if (paper && features_ && features_->near(p.face) && features_->closest(region, pos_[i], q) &&
      internal::norm(pos_[i] - q) < reach_) {
    const internal::Vec3 d = 2.0 * (pos_[i] - q);
    add(internal::dot(d, frame[0]), internal::dot(d, frame[1]), hi);
  }
  const internal::Vec3 normal = s.normal(p.face);
  return options_.step * ((fx * root) * frame[0] + (fy / root) * frame[1] +
                          (f3 - internal::dot(f3, normal) * normal));
}

// Walks every tile by `move` along its region (`Surface_arrays::walk`: a closest-point
// projection of the moved point, as before, took a fifth of the run on 200k triangles and could
// land on the far side of a thin part), then off the
// feature lines; returns the summed displacement on the surface, each in units of its tile's
// size.
template <typename TriangleMesh, typename NamedParameters>
double
Surface_mosaic<TriangleMesh, NamedParameters>::move_by(const std::vector<internal::Vec3>& move) {
  const internal::Surface_arrays<TriangleMesh>& s = *surface_;
  const std::size_t n = points_.size();
  const bool paper = options_.energy == Mosaic_energy::gaussian_manhattan;
  internal::parallel_blocks(n, [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i)
      if (move[i][0] != 0 || move[i][1] != 0 || move[i][2] != 0) // (the separation's idle tiles)
        points_[i] = s.walk(points_[i], move[i]).p;
  });
  double total = 0, largest = 0;
  const bool built = built_pos_.size() == n;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (move[i][0] == 0 && move[i][1] == 0 && move[i][2] == 0)
      continue; // not moved: its chart, walls and position stand
    chart_[i] = atlas_->chart_index_of(points_[i].face);
    if (!paper)
      keep_off_features(i);
    const internal::Vec3 next = s.position(points_[i]);
    // In units of the tile's size (with a size field, the stopping rule and the neighbour
    // lists' refresh hold for small and large tiles alike).
    const double d = internal::norm(next - pos_[i]) / size_at(points_[i]);
    total += d;
    pos_[i] = next;
    // How far the tile is from where the neighbour lists were built: no pair's distance has
    // changed by more than twice the largest of these (summing each pass's largest move, as
    // before, rebuilt the lists every second pass of the separation, where tiles jitter in
    // place: a fifth of its time).
    largest = std::max(largest, built ? internal::norm(next - built_pos_[i]) / size_at(points_[i])
                                      : std::numeric_limits<double>::infinity());
  }
  moved_since_refresh_ = std::max(moved_since_refresh_, 2 * largest);
  return total;
}

} // namespace tessera

// The start and the separation, in files of their own.
#include <tessera/mosaic/internal/surface_mosaic_separation_impl.h>
#include <tessera/mosaic/internal/surface_mosaic_start_impl.h>
