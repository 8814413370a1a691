// The pipeline behind resize_preserving_texture() and deform_preserving_texture()
// (tessera/resizing/texture_resize.h): segmentation, base and detail, the base's change, remeshing,
// synthesis, and the result written back into the caller's mesh. Included by texture_resize.h after
// the types it uses (Texture_preservation_options, Texture_preservation_stages, …); nothing here is
// meant to be called directly.
#pragma once

#include <tessera/internal/named_parameters.h>
#include <tessera/resizing/internal/texture_remesh.h>
#include <tessera/resizing/laplacian_detail.h>
#include <tessera/resizing/texels.h>
#include <tessera/resizing/texture_detail.h>
#include <tessera/resizing/texture_segmentation.h>
#include <tessera/resizing/texture_separation.h>
#include <tessera/resizing/texture_synthesis.h>

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/property_map/function_property_map.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace tessera {
namespace internal {

// Empties a mesh but keeps its property maps (the caller's output maps): Surface_mesh's clear()
// would remove them.
template <typename Mesh, typename = void> struct Has_clear_keeping_maps : std::false_type {};
template <typename Mesh>
struct Has_clear_keeping_maps<
    Mesh, std::void_t<decltype(std::declval<Mesh&>().clear_without_removing_property_maps())>>
    : std::true_type {};

template <typename Mesh> void clear_keeping_maps(Mesh& tm) {
  if constexpr (Has_clear_keeping_maps<Mesh>::value)
    tm.clear_without_removing_property_maps();
  else
    CGAL::clear(tm);
}

/// The pipeline, with the base's change as `change_base(Texture_work_mesh&)`, which returns
/// {ok, message}. Writes the result into `tm` and its maps; leaves `tm` as it was on failure.
template <typename TriangleMesh, typename TextureMap, typename BaseMap, typename HeightMap,
          typename NamedParameters, typename ChangeBase>
Texture_preservation_status
preserve_texture(TriangleMesh& tm, TextureMap is_texture, BaseMap base_point, HeightMap height,
                 const Texture_preservation_options& options, const NamedParameters& np,
                 ChangeBase&& change_base, Texture_preservation_stages& stages,
                 std::string& message) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  using Clock = std::chrono::steady_clock;
  using M = Texture_work_mesh;
  using Point = M::Point;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using Status = Texture_preservation_status;
  const auto start = Clock::now();
  auto lap = [](Clock::time_point& since) {
    const auto now = Clock::now();
    const double s = std::chrono::duration<double>(now - since).count();
    since = now;
    return s;
  };
  auto fail = [&](Status status, std::string why) {
    message = std::move(why);
    return status;
  };
  const auto vpm = internal::writable_vertex_point_map(tm, np);
  if (faces(tm).empty())
    return fail(Status::empty_mesh, "the mesh has no faces");
  if (!CGAL::is_triangle_mesh(tm))
    return fail(Status::not_triangle_mesh, "texture preservation needs a triangle mesh");

  // The work mesh: the input in doubles, vertices in the order of vertices(tm).
  M input;
  std::vector<vertex_descriptor> originals;
  {
    auto index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
    for (vertex_descriptor v : vertices(tm)) {
      put(index, v, originals.size());
      originals.push_back(v);
      const auto& p = get(vpm, v);
      input.add_vertex(
          Point(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())));
    }
    for (face_descriptor f : faces(tm)) {
      std::vector<M::Vertex_index> corners;
      for (vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, tm), tm))
        corners.push_back(M::Vertex_index(M::size_type(get(index, v))));
      if (input.add_face(corners) == M::null_face())
        return fail(Status::not_triangle_mesh, "the mesh is not a manifold surface");
    }
  }
  stages.vertices_before = input.number_of_vertices();
  auto texture = input.add_property_map<M::Vertex_index, bool>("v:tessera_texture", false).first;
  Clock::time_point since = start;
  if (options.region == Texture_region_source::given) {
    for (std::size_t i = 0; i < originals.size(); ++i)
      texture[M::Vertex_index(M::size_type(i))] = bool(get(is_texture, originals[i]));
  } else {
    auto region = input.add_property_map<M::Vertex_index, std::size_t>("v:tessera_region", 0).first;
    stages.segmentation = segment_texture(input, region, texture, options.segmentation);
    input.remove_property_map(region);
    if (!stages.segmentation)
      return fail(Status::segmentation_failed, "segmentation: " + stages.segmentation.message);
  }
  stages.segmentation_seconds = lap(since);
  for (M::Vertex_index v : input.vertices())
    stages.texture_vertices_before += texture[v] ? 1 : 0;
  // Area of the faces whose corners are all `marked(v)`, at `point(v)`.
  auto texture_area = [](const M& m, const auto& marked, const auto& point) {
    double area = 0;
    for (M::Face_index f : m.faces()) {
      std::array<Point, 3> p;
      std::size_t k = 0;
      bool inside = true;
      for (M::Vertex_index v : CGAL::vertices_around_face(m.halfedge(f), m)) {
        inside = inside && marked(v);
        p[k++] = point(v);
      }
      if (inside)
        area += std::sqrt(CGAL::squared_area(p[0], p[1], p[2]));
    }
    return area;
  };
  stages.texture_area_before = texture_area(
      input, [&](M::Vertex_index v) { return bool(texture[v]); },
      [&](M::Vertex_index v) { return input.point(v); });

  // Several textures (§3.4): each is synthesized from its own sample at its own period.
  auto part =
      input.add_property_map<M::Vertex_index, std::size_t>("v:tessera_texture_part", no_texture_id)
          .first;
  stages.separation = separate_textures(input, texture, part, options.separation);
  if (!stages.separation)
    return fail(Status::no_texture, "no vertex is texture");
  const std::size_t parts = stages.separation.textures.size();
  stages.separation_seconds = lap(since);

  // Base and detail.
  auto base = input.add_property_map<M::Vertex_index, Point>("v:tessera_base").first;
  auto detail = input.add_property_map<M::Vertex_index, double>("v:tessera_detail", 0).first;
  Detail_extraction_options extraction = options.extraction;
  if (!(extraction.texel_period > 0) && stages.segmentation.period.period > 0)
    extraction.texel_period = stages.segmentation.period.period;
  // One low pass takes the detail off all textures: at the longest of their periods, so the
  // coarsest texture's texels leave the base too (at a shorter one they stay in it, in part, and
  // would be stretched with it).
  if (parts > 1) {
    double longest = 0;
    for (const Separated_texture& t : stages.separation.textures)
      longest = std::max(longest, t.period.period);
    if (extraction.texel_period > 0 || longest > 0)
      extraction.texel_period = std::max(extraction.texel_period, longest);
  }
  stages.extraction = extract_detail(input, texture, base, detail, extraction);
  if (stages.extraction.status == Detail_extraction_status::no_texture)
    return fail(Status::no_texture, "no vertex is texture");
  if (!stages.extraction)
    return fail(Status::extraction_failed, "detail extraction: " + stages.extraction.message);
  const bool laplacian = options.detail == Detail_representation::laplacian_coordinates;
  Laplacian_detail_options frames;
  frames.reference_axis = options.synthesis.reference_axis;
  using Vector_detail = std::array<double, 3>;
  if (laplacian) {
    auto delta = input
                     .add_property_map<M::Vertex_index, Vector_detail>("v:tessera_laplacian_detail",
                                                                       Vector_detail{{0, 0, 0}})
                     .first;
    stages.laplacian_extraction = extract_laplacian_detail(input, base, delta, frames);
    if (!stages.laplacian_extraction)
      return fail(Status::extraction_failed,
                  "Laplacian-coordinate detail: " + stages.laplacian_extraction.message);
  }
  stages.extraction_seconds = lap(since);
  stages.texel_height_threshold = options.texel_threshold * stages.extraction.max_height;
  stages.texels_before =
      measure_texels(input, input.points(), detail, stages.texel_height_threshold);
  stages.input_detail.resize(originals.size());
  for (std::size_t i = 0; i < originals.size(); ++i)
    stages.input_detail[i] = detail[M::Vertex_index(M::size_type(i))];
  // A detail map that is 0 off texture t.
  auto detail_of = [](const auto& ids, const auto& heights, std::size_t t) {
    return boost::make_function_property_map<M::Vertex_index, double>(
        [ids, heights, t](M::Vertex_index v) { return ids[v] == t ? double(heights[v]) : 0.0; });
  };
  stages.textures.resize(parts);
  for (std::size_t t = 0; t < parts; ++t) {
    Texture_part_stages& p = stages.textures[t];
    p.pieces = stages.separation.textures[t].pieces;
    p.vertices_before = stages.separation.textures[t].vertices;
    p.area_before = stages.separation.textures[t].area;
    p.texels_before = parts == 1 ? stages.texels_before
                                 : measure_texels(input, input.points(), detail_of(part, detail, t),
                                                  stages.texel_height_threshold);
  }
  {
    double length = 0;
    std::size_t count = 0;
    for (M::Edge_index e : input.edges()) {
      const M::Halfedge_index h = input.halfedge(e);
      if (texture[input.source(h)] && texture[input.target(h)]) {
        length += std::sqrt(CGAL::squared_distance(base[input.source(h)], base[input.target(h)]));
        ++count;
      }
    }
    if (count == 0)
      return fail(Status::no_texture, "the texture has no edge");
    stages.texture_edge_length = length / double(count);
  }

  // The sample: the input's base with its detail. The target: the same base, changed.
  M sample = input;
  for (M::Vertex_index v : sample.vertices())
    sample.point(v) = base[v];
  M target = sample;
  {
    const std::pair<bool, std::string> changed = change_base(target);
    stages.base_seconds = lap(since);
    if (!changed.first)
      return fail(Status::base_failed, changed.second);
  }
  auto target_texture = target.property_map<M::Vertex_index, bool>("v:tessera_texture").first;
  auto target_detail = target.property_map<M::Vertex_index, double>("v:tessera_detail").first;
  {
    auto copied_base = target.property_map<M::Vertex_index, Point>("v:tessera_base").first;
    target.remove_property_map(copied_base);
  }
  auto free = target.add_property_map<M::Vertex_index, bool>("v:tessera_free", false).first;
  auto target_part =
      target.property_map<M::Vertex_index, std::size_t>("v:tessera_texture_part").first;
  if (options.remeshing_iterations > 0) {
    stages.remeshing =
        remesh_texture_region(target, target_texture, target_detail, free, target_part,
                              stages.texture_edge_length, options.remeshing_iterations);
  } else {
    for (M::Vertex_index v : target.vertices()) {
      bool inside = !target.is_border(v);
      for (M::Vertex_index w : CGAL::vertices_around_target(target.halfedge(v), target))
        inside = inside && target_texture[w];
      free[v] = inside && target_texture[v];
      stages.remeshing.free_vertices += free[v] ? 1 : 0;
    }
  }
  for (M::Vertex_index v : target.vertices())
    if (free[v])
      target_detail[v] = 0;
  // The Laplacian-coordinate detail is held at 0 off the synthesized vertices: the
  // reconstruction holds those vertices' positions, so only the free ones' δ is read.
  M::Property_map<M::Vertex_index, Vector_detail> sample_delta, target_delta;
  if (laplacian) {
    sample_delta =
        sample.property_map<M::Vertex_index, Vector_detail>("v:tessera_laplacian_detail").first;
    target_delta =
        target.property_map<M::Vertex_index, Vector_detail>("v:tessera_laplacian_detail").first;
    for (M::Vertex_index v : target.vertices())
      target_delta[v] = Vector_detail{{0, 0, 0}};
  }
  stages.remeshing_seconds = lap(since);

  auto sample_texture = sample.property_map<M::Vertex_index, bool>("v:tessera_texture").first;
  auto sample_detail = sample.property_map<M::Vertex_index, double>("v:tessera_detail").first;
  auto sample_part =
      sample.property_map<M::Vertex_index, std::size_t>("v:tessera_texture_part").first;
  // Each texture from its own sample, onto its own part of the target, at its own period; the
  // other parts' details are held meanwhile.
  auto sample_region =
      sample.add_property_map<M::Vertex_index, bool>("v:tessera_sample_part").first;
  auto target_region =
      target.add_property_map<M::Vertex_index, bool>("v:tessera_target_part").first;
  double squared_mismatch = 0;
  for (std::size_t t = 0; t < parts; ++t) {
    Texture_part_stages& p = stages.textures[t];
    for (M::Vertex_index v : sample.vertices())
      sample_region[v] = sample_texture[v] && (parts == 1 || sample_part[v] == t);
    for (M::Vertex_index v : target.vertices())
      target_region[v] = free[v] && (parts == 1 || target_part[v] == t);
    Texture_synthesis_options synthesis = options.synthesis;
    if (!(synthesis.texel_period > 0))
      synthesis.texel_period = parts > 1 && stages.separation.textures[t].period.period > 0
                                   ? stages.separation.textures[t].period.period
                                   : stages.extraction.texel_period;
    if (!(synthesis.border_fade > 0))
      synthesis.border_fade = 0.25 * synthesis.texel_period;
    p.period = synthesis.texel_period;
    p.synthesis = laplacian
                      ? synthesize_texture_with_vectors(sample, sample_region, sample_detail,
                                                        sample_delta, target, target_region,
                                                        target_detail, target_delta, synthesis)
                      : synthesize_texture(sample, sample_region, sample_detail, target,
                                           target_region, target_detail, synthesis);
    p.synthesis_seconds = lap(since);
    stages.synthesis_seconds += p.synthesis_seconds;
    if (!p.synthesis) {
      stages.synthesis = p.synthesis;
      return fail(Status::synthesis_failed,
                  parts == 1 ? "synthesis: " + p.synthesis.message
                             : "synthesis of texture " + std::to_string(t + 1) + " of " +
                                   std::to_string(parts) + " (period " + std::to_string(p.period) +
                                   "): " + p.synthesis.message);
    }
    if (t == 0)
      stages.synthesis = p.synthesis;
    else {
      stages.synthesis.sample_templates += p.synthesis.sample_templates;
      stages.synthesis.target_vertices += p.synthesis.target_vertices;
      stages.synthesis.iterations += p.synthesis.iterations;
    }
    squared_mismatch +=
        double(p.synthesis.target_vertices) * p.synthesis.rms_mismatch * p.synthesis.rms_mismatch;
  }
  if (parts > 1 && stages.synthesis.target_vertices > 0)
    stages.synthesis.rms_mismatch =
        std::sqrt(squared_mismatch / double(stages.synthesis.target_vertices));
  sample.remove_property_map(sample_region);
  target.remove_property_map(target_region);

  // The result: the changed base displaced by the detail along its normals, written into tm.
  auto normal =
      target
          .add_property_map<M::Vertex_index,
                            CGAL::Exact_predicates_inexact_constructions_kernel::Vector_3>(
              "v:tessera_normal")
          .first;
  PMP::compute_vertex_normals(target, normal);
  auto displaced = target.add_property_map<M::Vertex_index, Point>("v:tessera_displaced").first;
  for (M::Vertex_index v : target.vertices())
    displaced[v] = target.point(v) + target_detail[v] * normal[v];
  if (laplacian) {
    // Eqs. 10–11: the synthesized vertices rebuilt from their δ, the others held where the
    // displacement put them; their detail is then the result's offset along the base's normal.
    frames.anchor_wavelength = options.anchor_periods * stages.extraction.texel_period;
    stages.reconstruction = reconstruct_from_laplacian_detail(target, free, target.points(),
                                                              target_delta, displaced, frames);
    if (!stages.reconstruction)
      return fail(Status::synthesis_failed, "reconstruction: " + stages.reconstruction.message);
    for (M::Vertex_index v : target.vertices())
      if (free[v])
        target_detail[v] = (displaced[v] - target.point(v)) * normal[v];
    target.remove_property_map(target_delta);
    stages.reconstruction_seconds = lap(since);
  }
  stages.texels_after =
      measure_texels(target, displaced, target_detail, stages.texel_height_threshold);
  stages.texture_area_after = texture_area(
      target, [&](M::Vertex_index v) { return bool(target_texture[v]); },
      [&](M::Vertex_index v) { return displaced[v]; });
  for (std::size_t t = 0; t < parts; ++t) {
    Texture_part_stages& p = stages.textures[t];
    auto in_part = [&](M::Vertex_index v) {
      return target_texture[v] && (parts == 1 || target_part[v] == t);
    };
    for (M::Vertex_index v : target.vertices())
      p.vertices_after += in_part(v) ? 1 : 0;
    p.area_after =
        parts == 1 ? stages.texture_area_after
                   : texture_area(target, in_part, [&](M::Vertex_index v) { return displaced[v]; });
    p.texels_after =
        parts == 1 ? stages.texels_after
                   : measure_texels(target, displaced, detail_of(target_part, target_detail, t),
                                    stages.texel_height_threshold);
  }
  clear_keeping_maps(tm);
  const auto out_vpm = internal::writable_vertex_point_map(tm, np);
  using Out_point = typename boost::property_traits<decltype(out_vpm)>::value_type;
  using Base_point = typename boost::property_traits<BaseMap>::value_type;
  // The target's indices are contiguous (its garbage was collected), so made[v] is v's copy.
  std::vector<vertex_descriptor> made;
  made.reserve(target.number_of_vertices());
  for (M::Vertex_index v : target.vertices()) {
    const vertex_descriptor w = add_vertex(tm);
    const Point &p = displaced[v], &b = target.point(v);
    put(out_vpm, w, Out_point(p.x(), p.y(), p.z()));
    put(is_texture, w, target_texture[v]);
    put(base_point, w, Base_point(b.x(), b.y(), b.z()));
    put(height, w, target_detail[v]);
    stages.texture_vertices_after += target_texture[v] ? 1 : 0;
    made.push_back(w);
  }
  for (M::Face_index f : target.faces()) {
    std::array<vertex_descriptor, 3> corners;
    std::size_t k = 0;
    for (M::Vertex_index v : CGAL::vertices_around_face(target.halfedge(f), target))
      corners[k++] = made[std::size_t(v)];
    CGAL::Euler::add_face(corners, tm);
  }
  stages.vertices_after = made.size();
  stages.total_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return Status::ok;
}

} // namespace internal
} // namespace tessera
