// JSON writers of the resize reports (tessera/io/resize_reports.h): report.json of `tessera resize`
// and `tessera deform` and of their texture-preserving variants, in the CLI and in a library
// user's code alike.
#include <tessera/io/resize_reports.h>

#include "report_json.h"

#include <nlohmann/json.hpp>

namespace tessera {
namespace {

nlohmann::json stretch_json(const Stretch_stats& s) {
  if (s.vertices == 0)
    return {{"vertices", 0}};
  return {{"vertices", s.vertices},
          {"mean", s.mean},
          {"median", s.median},
          {"p95", s.p95},
          {"max", s.max}};
}

nlohmann::json texel_json(const Texel_report& t) {
  return {{"count", t.count},
          {"median_aspect", t.median_aspect},
          {"median_size", t.median_size},
          {"median_spacing", t.median_spacing}};
}

nlohmann::json texel_json(const std::optional<Texel_report>& t) {
  return t ? texel_json(*t) : nlohmann::json();
}

// One object per texture (`separate_textures`), largest first.
nlohmann::json textures_json(const Texture_preservation_stages& s) {
  nlohmann::json out = nlohmann::json::array();
  for (const Texture_part_stages& p : s.textures)
    out.push_back({{"pieces", p.pieces},
                   {"vertices_before", p.vertices_before},
                   {"vertices_after", p.vertices_after},
                   {"area_before", p.area_before},
                   {"area_after", p.area_after},
                   {"period", p.period},
                   {"texels_before", texel_json(make_texel_report(p.texels_before))},
                   {"texels_after", texel_json(make_texel_report(p.texels_after))},
                   {"grid_spacing", p.synthesis.grid_spacing},
                   {"template_radius", p.synthesis.template_radius},
                   {"sample_templates", p.synthesis.sample_templates},
                   {"synthesis_seconds", p.synthesis_seconds}});
  return out;
}

nlohmann::json stages_json(const Texture_preservation_stages& s) {
  return {{"texture_vertices_before", s.texture_vertices_before},
          {"texture_vertices_after", s.texture_vertices_after},
          {"texture_area_before", s.texture_area_before},
          {"texture_area_after", s.texture_area_after},
          {"vertices_before", s.vertices_before},
          {"vertices_after", s.vertices_after},
          {"segmentation",
           {{"period", s.segmentation.period.period},
            {"periodic", s.segmentation.period.periodic},
            {"peak_strength", s.segmentation.period.peak_strength},
            {"lobe", s.segmentation.period.lobe},
            {"coarser_periods", s.segmentation.coarser_periods},
            {"radius", s.segmentation.ring_radius},
            {"texture_vertices", s.segmentation.texture_vertices}}},
          {"separation", {{"pieces", s.separation.pieces}, {"scraps", s.separation.scraps}}},
          {"textures", textures_json(s)},
          {"extraction",
           {{"iterations", s.extraction.iterations},
            {"max_height", s.extraction.max_height},
            {"mean_edge_length", s.extraction.mean_edge_length}}},
          {"remeshing",
           {{"edge_length", s.texture_edge_length},
            {"region_faces", s.remeshing.region_faces},
            {"free_vertices", s.remeshing.free_vertices},
            {"border_vertices_added", s.remeshing.border_vertices_added}}},
          {"synthesis",
           {{"grid_spacing", s.synthesis.grid_spacing},
            {"template_radius", s.synthesis.template_radius},
            {"sample_templates", s.synthesis.sample_templates},
            {"target_vertices", s.synthesis.target_vertices},
            {"iterations", s.synthesis.iterations},
            {"rms_mismatch", s.synthesis.rms_mismatch}}}};
}

// The keys every texture-preserving report has; "texels" gets the comparison's figures added.
nlohmann::json texture_json(const Texture_report& t) {
  const Texture_preservation_stages& s = t.stages;
  return {{"texture_source", t.texture_source},
          {"regions", t.regions},
          {"texture", stages_json(s)},
          {"texels",
           {{"height_threshold", s.texel_height_threshold},
            {"input", texel_json(make_texel_report(s.texels_before))},
            {"textured", texel_json(make_texel_report(s.texels_after))}}},
          {"self_intersections_before", t.self_intersections_before},
          {"self_intersections_after", t.self_intersections_after},
          {"seconds",
           {{"extraction", s.extraction_seconds},
            {"separation", s.separation_seconds},
            {"base", s.base_seconds},
            {"remeshing", s.remeshing_seconds},
            {"synthesis", s.synthesis_seconds},
            {"pipeline", s.total_seconds},
            {"total", t.total_seconds},
            {"segmentation", t.segmentation_seconds}}},
          {"repairs", io_internal::repairs_json(t.repairs)},
          {"method", "textured"}};
}

} // namespace

bool write_resize_report(std::ostream& out, const Resize_report& r) {
  const nlohmann::json j{{"mesh", r.mesh},
                         {"method", r.method},
                         {"volume_mesh", r.volume_mesh},
                         {"volume_vertices", r.volume_vertices},
                         {"tetrahedra", r.tetrahedra},
                         {"scale", r.scale},
                         {"extent_before", r.extent_before},
                         {"target_extent", r.target_extent},
                         {"extent_after", r.extent_after},
                         {"free_stretch", r.free_stretch},
                         {"vulnerability_weight", r.vulnerability_weight},
                         {"iterations", r.iterations},
                         {"solver", r.solver},
                         {"enclosed_volume_before", r.enclosed_volume_before},
                         {"enclosed_volume_after", r.enclosed_volume_after},
                         {"self_intersections_before", r.self_intersections_before},
                         {"self_intersections_after", r.self_intersections_after},
                         {"stretch_ratio",
                          {{"vulnerable", stretch_json(r.vulnerable)},
                           {"free", stretch_json(r.free)},
                           {"simple_scaling_vulnerable", stretch_json(r.simple_scaling_vulnerable)},
                           {"simple_scaling_free", stretch_json(r.simple_scaling_free)}}},
                         {"seconds",
                          {{"vulnerability", r.vulnerability_seconds},
                           {"volume_mesh", r.volume_mesh_seconds},
                           {"solve", r.solve_seconds},
                           {"total", r.total_seconds}}},
                         {"repairs", io_internal::repairs_json(r.repairs)}};
  return io_internal::dump(out, j);
}

bool write_deform_report(std::ostream& out, const Deform_report& r) {
  const nlohmann::json j{{"mesh", r.mesh},
                         {"handles", r.handles},
                         {"method", r.method},
                         {"iterations", r.iterations},
                         {"handle_vertices", r.handle_vertices},
                         {"region_vertices", r.region_vertices},
                         {"max_handle_error", r.max_handle_error},
                         {"self_intersections_before", r.self_intersections_before},
                         {"self_intersections_after", r.self_intersections_after},
                         {"enclosed_volume_before", r.enclosed_volume_before},
                         {"enclosed_volume_after", r.enclosed_volume_after},
                         {"stretch_ratio", stretch_json(r.stretch_ratio)},
                         {"seconds",
                          {{"preprocess", r.preprocess_seconds},
                           {"deform", r.deform_seconds},
                           {"total", r.total_seconds}}},
                         {"repairs", io_internal::repairs_json(r.repairs)}};
  return io_internal::dump(out, j);
}

bool write_textured_resize_report(std::ostream& out, const Textured_resize_report& r) {
  nlohmann::json j = texture_json(r.texture);
  j.update({{"mesh", r.mesh},
            {"base_method", r.base_method},
            {"scale", r.scale},
            {"extent_before", r.extent_before},
            {"target_extent", r.target_extent},
            {"extent_after", r.extent_after}});
  j["texels"]["simple_scaling"] = texel_json(r.simple_scaling);
  j["texels"]["nonhomogeneous"] = texel_json(r.nonhomogeneous);
  return io_internal::dump(out, j);
}

bool write_textured_deform_report(std::ostream& out, const Textured_deform_report& r) {
  nlohmann::json j = texture_json(r.texture);
  j.update({{"mesh", r.mesh},
            {"handles", r.handles},
            {"iterations", r.iterations},
            {"handle_vertices", r.handle_vertices},
            {"region_vertices", r.region_vertices},
            {"max_handle_error", r.max_handle_error}});
  j["texels"]["arap"] = texel_json(r.arap);
  return io_internal::dump(out, j);
}

} // namespace tessera
