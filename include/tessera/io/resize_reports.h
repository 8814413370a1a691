// What `tessera resize` and `tessera deform` write to report.json, for library users: plain report
// structs of a resize, a deformation and their texture-preserving variants, built from the
// library's results (`make_resize_report`, `make_deform_report`, `make_textured_resize_report`,
// `make_textured_deform_report`) with the measures taken around them (`make_stretch_stats`,
// `make_texel_report`), and one JSON writer per kind compiled into Tessera::core (nlohmann-json
// stays private). The keys and their meanings are doc/formats.md's; the CLI writes through these
// and nothing else.
#pragma once

#include <tessera/io/mesh_repair.h>
#include <tessera/resizing/deform.h>
#include <tessera/resizing/method_names.h>
#include <tessera/resizing/resize.h>
#include <tessera/resizing/texels.h>
#include <tessera/resizing/texture_resize.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace tessera {

/// Statistics of the local stretch ratio over a set of vertices (`mean` … `max` are written only
/// when `vertices` > 0).
struct Stretch_stats {
  std::size_t vertices = 0;
  double mean = 0, median = 0, p95 = 0, max = 0;
};

/// The stretch statistics of `values` (e.g. from `local_stretch_ratios()`), non-finite ones left
/// out.
inline Stretch_stats make_stretch_stats(std::vector<double> values) {
  values.erase(
      std::remove_if(values.begin(), values.end(), [](double x) { return !std::isfinite(x); }),
      values.end());
  Stretch_stats s;
  if (values.empty())
    return s;
  std::sort(values.begin(), values.end());
  for (double x : values)
    s.mean += x / double(values.size());
  s.vertices = values.size();
  s.median = values[values.size() / 2];
  s.p95 = values[std::min(values.size() - 1, std::size_t(0.95 * double(values.size())))];
  s.max = values.back();
  return s;
}

/// report.json of `tessera resize` (simple or non-homogeneous).
struct Resize_report {
  std::string mesh, method;
  std::string volume_mesh; ///< "tetgen", "grid" or "none"
  std::size_t volume_vertices = 0, tetrahedra = 0, iterations = 0;
  std::array<double, 3> scale{}, extent_before{}, target_extent{}, extent_after{}, free_stretch{},
      vulnerability_weight{{1, 1, 1}};
  std::string solver;
  double enclosed_volume_before = 0, enclosed_volume_after = 0; ///< NaN (null) when not closed
  bool self_intersections_before = false, self_intersections_after = false;
  Stretch_stats vulnerable, free, simple_scaling_vulnerable, simple_scaling_free;
  double vulnerability_seconds = 0, volume_mesh_seconds = 0, solve_seconds = 0, total_seconds = 0;
  Mesh_changes repairs;
};

/// report.json of `tessera deform` (arap, srarap or spokes).
struct Deform_report {
  std::string mesh, handles, method;
  unsigned iterations = 0;
  std::size_t handle_vertices = 0, region_vertices = 0;
  double max_handle_error = 0;
  bool self_intersections_before = false, self_intersections_after = false;
  double enclosed_volume_before = 0, enclosed_volume_after = 0; ///< NaN (null) when not closed
  Stretch_stats stretch_ratio;
  double preprocess_seconds = 0, deform_seconds = 0, total_seconds = 0;
  Mesh_changes repairs;
};

/// The texels of one surface (`measure_texels()`).
struct Texel_report {
  std::size_t count = 0;
  double median_aspect = 0, median_size = 0, median_spacing = 0;
};

inline Texel_report make_texel_report(const Texel_measure& m) {
  return {m.texels.size(), m.median_aspect, m.median_size, m.median_spacing};
}

/// What every texture-preserving report has: where the texture came from, the pipeline's stages
/// (written as "texture", the texels before and after and the seconds) and the checks around it.
struct Texture_report {
  std::string texture_source; ///< "segmented" or the vertex-id file
  std::size_t regions = 0;
  Texture_preservation_stages stages;
  bool self_intersections_before = false, self_intersections_after = false;
  double segmentation_seconds = 0; ///< finding the texture, before the pipeline
  double total_seconds = 0;
  Mesh_changes repairs;
};

/// report.json of `tessera resize --method textured`.
struct Textured_resize_report {
  Texture_report texture;
  std::string mesh, base_method; ///< base_method: "nonhomogeneous" or "simple"
  std::array<double, 3> scale{}, extent_before{}, target_extent{}, extent_after{};
  /// The input by simple scaling and by non-homogeneous resizing (null when that failed).
  Texel_report simple_scaling;
  std::optional<Texel_report> nonhomogeneous;
};

/// report.json of `tessera deform --method textured`.
struct Textured_deform_report {
  Texture_report texture;
  std::string mesh, handles;
  unsigned iterations = 0;
  std::size_t handle_vertices = 0, region_vertices = 0;
  double max_handle_error = 0;
  /// The input deformed by ARAP alone (null when that failed).
  std::optional<Texel_report> arap;
};

/// Writes `report` as JSON (one key a line); false when the stream failed.
bool write_resize_report(std::ostream& out, const Resize_report& report);
/// Writes `report` as JSON (one key a line); false when the stream failed.
bool write_deform_report(std::ostream& out, const Deform_report& report);
/// Writes `report` as JSON (one key a line, "method": "textured"); false when the stream failed.
bool write_textured_resize_report(std::ostream& out, const Textured_resize_report& report);
/// Writes `report` as JSON (one key a line, "method": "textured"); false when the stream failed.
bool write_textured_deform_report(std::ostream& out, const Textured_deform_report& report);

/// The name of a volume mesh in the report: "tetgen", "grid" or "none".
inline const char* volume_mesh_name(Resize_volume v) {
  return v == Resize_volume::automatic ? "none" : internal::enum_name(resize_volume_names, v);
}

/// The report of `resize(…, options)` giving `r`; the measures around it (volumes,
/// self-intersections, stretch, total seconds) are set by the caller.
inline Resize_report make_resize_report(const std::string& mesh, const Resize_options& options,
                                        const Resize_result& r, const Mesh_changes& repairs) {
  Resize_report report;
  report.mesh = mesh;
  report.method = internal::enum_name(resize_method_names, options.method);
  report.volume_mesh = volume_mesh_name(r.volume);
  report.volume_vertices = r.volume_vertices;
  report.tetrahedra = r.tetrahedra;
  report.iterations = r.iterations;
  report.scale = options.scale;
  report.extent_before = r.extent_before;
  report.target_extent = r.target_extent;
  report.extent_after = r.extent_after;
  report.free_stretch = r.free_stretch;
  report.vulnerability_weight = r.vulnerability_weight;
  report.solver = r.solver;
  report.vulnerability_seconds = r.vulnerability_seconds;
  report.volume_mesh_seconds = r.volume_seconds;
  report.solve_seconds = r.solve_seconds;
  report.repairs = repairs;
  return report;
}

/// The report of `deform_by_handles(…, options)` giving `r`; the measures around it are set by the
/// caller.
inline Deform_report make_deform_report(const std::string& mesh, const std::string& handles,
                                        const Deformation_options& options,
                                        const Deformation_result& r, const Mesh_changes& repairs) {
  Deform_report report;
  report.mesh = mesh;
  report.handles = handles;
  report.method = internal::enum_name(deformation_method_names, options.method);
  report.iterations = options.iterations;
  report.handle_vertices = r.handle_vertices;
  report.region_vertices = r.region_vertices;
  report.max_handle_error = r.max_handle_error;
  report.preprocess_seconds = r.preprocess_seconds;
  report.deform_seconds = r.deform_seconds;
  report.repairs = repairs;
  return report;
}

/// The report of `resize_preserving_texture(…)` giving `r` (the texture part's checks and seconds
/// are set by the caller).
inline Textured_resize_report make_textured_resize_report(const std::string& mesh,
                                                          const Resize_options& options,
                                                          const Texture_resize_result& r) {
  Textured_resize_report report;
  report.texture.stages = r.stages;
  report.mesh = mesh;
  report.base_method = internal::enum_name(resize_method_names, options.method);
  report.scale = options.scale;
  report.extent_before = r.resize.extent_before;
  report.target_extent = r.resize.target_extent;
  report.extent_after = r.resize.extent_after;
  return report;
}

/// The report of `deform_preserving_texture(…)` giving `r` (the texture part's checks and seconds
/// are set by the caller).
inline Textured_deform_report make_textured_deform_report(const std::string& mesh,
                                                          const std::string& handles,
                                                          unsigned iterations,
                                                          const Texture_deform_result& r) {
  Textured_deform_report report;
  report.texture.stages = r.stages;
  report.mesh = mesh;
  report.handles = handles;
  report.iterations = iterations;
  report.handle_vertices = r.deformation.handle_vertices;
  report.region_vertices = r.deformation.region_vertices;
  report.max_handle_error = r.deformation.max_handle_error;
  return report;
}

} // namespace tessera
