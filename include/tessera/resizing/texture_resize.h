// Resizing and deformation that preserve a geometric texture (Chen and Meng, "Anisotropic resizing
// and deformation preserving geometric textures", SPM 2009 / CAD 2010): find the texture
// (texture_segmentation.h), split the surface into a smooth base and a detail along its normals
// (texture_detail.h), resize or deform the base (resize.h, deform.h), remesh the stretched texture
// region to the input's edge length, and synthesize the detail anew on it from the input's
// (texture_synthesis.h), so each texel keeps its shape and size and the new room gets more texels.
#pragma once

#include <tessera/resizing/deform.h>
#include <tessera/resizing/internal/texture_remesh.h>
#include <tessera/resizing/laplacian_detail.h>
#include <tessera/resizing/resize.h>
#include <tessera/resizing/texels.h>
#include <tessera/resizing/texture_detail.h>
#include <tessera/resizing/texture_segmentation.h>
#include <tessera/resizing/texture_separation.h>
#include <tessera/resizing/texture_synthesis.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace tessera {

/// Where the texture is.
enum class Texture_region_source {
  /// Found by `segment_texture` (mean shift on curvature statistics).
  segment,
  /// Read from the caller's `is_texture` map.
  given
};

/// The stages around the base's resize or deformation, shared by both.
struct Texture_preservation_options {
  Texture_region_source region = Texture_region_source::segment;
  Texture_segmentation_options segmentation;
  Detail_extraction_options extraction;
  /// How the detail goes from the input to the changed base: a displacement along the base's
  /// normal (the conference version), or Laplacian coordinates in the base's frames carried by the
  /// synthesis and a Poisson reconstruction (the journal version, laplacian_detail.h).
  Detail_representation detail = Detail_representation::normal_displacement;
  /// With Laplacian coordinates: the reconstruction's soft constraints hold the waves longer than
  /// this many texel periods to the synthesized displacement (`anchor_wavelength`; 0: the Poisson
  /// solve alone, which integrates the synthesis' errors into broad swells).
  double anchor_periods = 2;
  /// How the texture splits into textures synthesized each from its own sample, with its own
  /// period (§3.4).
  Texture_separation_options separation;
  Texture_synthesis_options synthesis;
  /// Rounds of isotropic remeshing of the resized texture region (to the input's edge length
  /// there); 0 synthesizes on the stretched triangles as they are.
  unsigned remeshing_iterations = 3;
  /// Texels are measured (texels.h) where the detail exceeds this fraction of the input's largest
  /// detail.
  double texel_threshold = 0.2;
};

struct Texture_resize_options {
  /// The base's resize: target scale, simple or non-homogeneous, its volume.
  Resize_options resize;
  Texture_preservation_options texture;
};

struct Texture_deform_options {
  Deformation_options deformation;
  Texture_preservation_options texture;
};

enum class Texture_preservation_status {
  ok,
  empty_mesh,
  not_triangle_mesh,
  /// `segment_texture` failed (its result says why).
  segmentation_failed,
  /// No vertex is texture, or the texture has no triangle.
  no_texture,
  extraction_failed,
  /// The base's resize or deformation failed (its result says why).
  base_failed,
  synthesis_failed
};

/// One of several textures (`separate_textures`) through the pipeline.
struct Texture_part_stages {
  /// Connected pieces of the texture region it holds.
  std::size_t pieces = 0;
  std::size_t vertices_before = 0, vertices_after = 0;
  double area_before = 0, area_after = 0;
  /// The period its synthesis used: its own (`Separated_texture::period`) when there are several
  /// textures, the surface's otherwise.
  double period = 0;
  /// Its texels (the stages' measure restricted to it), before and after.
  Texel_measure texels_before, texels_after;
  Texture_synthesis_result synthesis;
  double synthesis_seconds = 0;
};

/// Figures of the stages around the base's change.
struct Texture_preservation_stages {
  Texture_segmentation_result segmentation;
  Detail_extraction_result extraction;
  Texture_separation_result separation;
  internal::Texture_region_remeshing remeshing;
  /// The synthesis of all textures: with several, the sample templates, target vertices and
  /// iterations summed over them, the mismatch their RMS over the target vertices, grid spacing
  /// and template radius those of the largest texture.
  Texture_synthesis_result synthesis;
  /// `Detail_representation::laplacian_coordinates`: the extraction of δ on the input and the
  /// Poisson reconstruction of the result (its `vertices`: the vertices solved for).
  Laplacian_detail_result laplacian_extraction, reconstruction;
  /// Per texture, in the order of `separation.textures` (largest first).
  std::vector<Texture_part_stages> textures;
  std::size_t vertices_before = 0, vertices_after = 0;
  std::size_t texture_vertices_before = 0, texture_vertices_after = 0;
  /// Area of the triangles whose corners are all texture, before (on the input) and after.
  double texture_area_before = 0, texture_area_after = 0;
  /// Per input vertex, in the order of `vertices(tm)` before the call: its detail height over
  /// the base faired at the extraction's period (0 off the texture), which `texels_before`
  /// measures.
  std::vector<double> input_detail;
  /// Texels of the input (detail over the input) and of the result (detail over the changed base),
  /// measured at the same height threshold.
  Texel_measure texels_before, texels_after;
  double texel_height_threshold = 0;
  /// The input's mean edge length in the texture region, which the remeshing aims at.
  double texture_edge_length = 0;
  /// Wall-clock seconds per stage.
  double segmentation_seconds = 0, extraction_seconds = 0, separation_seconds = 0, base_seconds = 0,
         remeshing_seconds = 0, synthesis_seconds = 0, reconstruction_seconds = 0,
         total_seconds = 0;
};

struct Texture_resize_result {
  Texture_preservation_status status = Texture_preservation_status::ok;
  std::string message;
  Resize_result resize;
  Texture_preservation_stages stages;
  explicit operator bool() const { return status == Texture_preservation_status::ok; }
};

struct Texture_deform_result {
  Texture_preservation_status status = Texture_preservation_status::ok;
  std::string message;
  Deformation_result deformation;
  Texture_preservation_stages stages;
  explicit operator bool() const { return status == Texture_preservation_status::ok; }
};

} // namespace tessera

#include <tessera/resizing/internal/texture_resize_impl.h>

namespace tessera {

/// Resizes `tm` so its bounding box becomes `options.resize.scale` times the current one while
/// its geometric texture keeps the size and shape of its texels: the base is resized by
/// `options.resize.method` and the texture synthesized anew on it. `tm` is replaced by the result
/// (new vertices and faces in the texture region; elsewhere the same vertices, in order, on the
/// resized base). Per output vertex: whether it is texture (`is_texture`, also read as the input's
/// texture when `options.texture.region` is `given`), its base position (`base_point`) and its
/// detail along the base's normal (`height`; with Laplacian coordinates, the result's offset from
/// the base along it). On failure `tm` is left as it was.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh, typename TextureMap, typename BaseMap, typename HeightMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Texture_resize_result
resize_preserving_texture(TriangleMesh& tm, TextureMap is_texture, BaseMap base_point,
                          HeightMap height, const Texture_resize_options& options = {},
                          const NamedParameters& np = CGAL::parameters::default_values()) {
  Texture_resize_result result;
  result.status = internal::preserve_texture(
      tm, is_texture, base_point, height, options.texture, np,
      [&](internal::Texture_work_mesh& base) {
        auto vulnerability = get(CGAL::dynamic_vertex_property_t<std::array<double, 3>>(), base);
        // The base is smooth at the texels' scale, not below it: what is left of them after
        // fairing (a few per cent of their height, more at the region's border) must not make
        // the texture region look curved, so the jets are fitted over rings reaching a texel
        // period (P/e rings for edges of length e), at most 6, and over a disc one period across
        // where that is more (k rings of a regular triangulation reach k·e·√3/2 in every
        // direction: P/(√3·e) rings). A tube with a band of bumps then stretches its band
        // nearly as much as the rest (area 1.96x for a 2x stretch, 1.84x with 2-ring jets). With
        // 6 rings for a period of 20 edges, the rims of a coarse texture stayed rigid: on a plate
        // with lattices of 0.25 and 0.4 stretched 2x, the coarse region grew 1.5x and the fine
        // one 2.4x (10 rings: 1.86x and 2.1x; 20 rings: 1.97x and 2.03x, three times as slow).
        // Wide rings are thinned (fit_vertex_jets).
        Resize_options resize_options = options.resize;
        const Texture_preservation_stages& s = result.stages;
        if (s.extraction.texel_period > 0 && s.texture_edge_length > 0) {
          const double edges = s.extraction.texel_period / s.texture_edge_length;
          const double rings =
              std::max(std::min(std::ceil(edges), 6.0), std::ceil(edges / std::sqrt(3.0)));
          resize_options.vulnerability.rings = std::max(resize_options.vulnerability.rings,
                                                        std::size_t(std::clamp(rings, 1.0, 24.0)));
        }
        result.resize = resize(base, vulnerability, resize_options);
        // The input may bound a volume while its faired base does not (on a thin part the
        // fairing can pull opposite sides through each other): the grid takes any surface.
        if (result.resize.status == Resize_status::self_intersecting &&
            resize_options.volume == Resize_volume::automatic) {
          resize_options.volume = Resize_volume::grid;
          result.resize = resize(base, vulnerability, resize_options);
        }
        return std::make_pair(bool(result.resize),
                              "resizing the base (the surface with its texture faired away): " +
                                  result.resize.message);
      },
      result.stages, result.message);
  return result;
}

/// Deforms `tm` by `handles` (deform.h: vertex ids refer to `tm` as given) while its geometric
/// texture keeps its texels' size and shape: the base is deformed and the texture synthesized
/// anew on it. Outputs and failure as `resize_preserving_texture`.
///
/// Named parameters: `vertex_point_map`.
template <typename TriangleMesh, typename TextureMap, typename BaseMap, typename HeightMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Texture_deform_result
deform_preserving_texture(TriangleMesh& tm, const std::vector<Deformation_handle>& handles,
                          TextureMap is_texture, BaseMap base_point, HeightMap height,
                          const Texture_deform_options& options = {},
                          const NamedParameters& np = CGAL::parameters::default_values()) {
  Texture_deform_result result;
  result.status = internal::preserve_texture(
      tm, is_texture, base_point, height, options.texture, np,
      [&](internal::Texture_work_mesh& base) {
        result.deformation = deform_by_handles(base, handles, options.deformation);
        return std::make_pair(bool(result.deformation),
                              "deforming the base (the surface with its texture faired away): " +
                                  result.deformation.message);
      },
      result.stages, result.message);
  return result;
}

} // namespace tessera
