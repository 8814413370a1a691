// tessera resize and tessera deform: non-homogeneous resizing (Kraevoy et al. 2008) through a
// TetGen volume or the protective grid, and deformation by handles through CGAL's
// Surface_mesh_deformation; each writes the result mesh, a picture from one view and report.json.
#include "choices.h"
#include "commands.h"
#include "mesh_input.h"
#include "output_dir.h"
#include "progress_printer.h"

#include <tessera/io.h>
#include <tessera/io/read_handles.h>
#include <tessera/io/read_vertex_set.h>
#include <tessera/io/resize_reports.h>
#include <tessera/render.h>
#include <tessera/resizing.h>
#include <tessera/resizing/method_names.h>
#include <tessera/resizing/texture_resize.h>
#include <tessera/types.h>

#include <CGAL/IO/Color.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh/IO/PLY.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>

namespace tessera::cli {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Clock = std::chrono::steady_clock;
using P3 = std::array<double, 3>;

// The texture-preserving variants' own options (--method textured).
struct Texture_arguments {
  std::string regions = "auto", base = "nonhomogeneous", detail = "normal";
  double sample_size = 0, texel_period = 0;
  std::size_t em_iterations = 30;
};

struct Resize_arguments {
  std::string mesh, out, method = "nonhomogeneous", volume = "auto";
  std::vector<double> scale, size;
  double vulnerability_weight = 1;
  bool force = false, view = false;
  Mesh_input_flags input;
  Texture_arguments texture;
};

struct Deform_arguments {
  std::string mesh, out, handles, method = "arap";
  unsigned iterations = 5;
  bool force = false, view = false;
  Mesh_input_flags input;
  Texture_arguments texture;
};

bool self_intersects(const Mesh& m) {
  return PMP::does_self_intersect(m);
}

double enclosed_volume(const Mesh& m) {
  return CGAL::is_closed(m) ? std::abs(PMP::volume(m)) : std::nan("");
}

// The picture, written whole or not at all.
void write_picture(const Render_scene& scene, const std::string& path, const std::string& title,
                   Render_options ro = {}) {
  ro.edges = Edge_drawing::never;
  ro.title = title;
  write_checked(path, [&](const std::string& p) { return render_png(scene, p, ro); });
}

// A mesh with its vertex colours ("v:color") as binary PLY.
bool write_colored_ply(const std::string& path, const Mesh& mesh) {
  std::ofstream out(path, std::ios::binary);
  const bool written = CGAL::IO::write_PLY(out, mesh);
  out.close();
  return written && !out.fail();
}

// --- Texture-preserving resizing and deformation (--method textured) -------------------------

using Texture_map = Mesh::Property_map<Mesh::Vertex_index, bool>;

Texture_preservation_options texture_options(const Texture_arguments& t) {
  if (!(t.sample_size >= 0) || !std::isfinite(t.sample_size))
    throw User_error("--sample-size must be a number >= 0 (vertices in one texel)");
  if (t.em_iterations == 0)
    throw User_error("--em-iterations must be at least 1");
  if (!(t.texel_period >= 0) || !std::isfinite(t.texel_period))
    throw User_error("--texel-period must be a length >= 0 (0: read from the surface)");
  Texture_preservation_options o;
  o.region = Texture_region_source::given; // the CLI segments or reads the region first
  o.segmentation.sample_size = t.sample_size;
  o.segmentation.texel_period = t.texel_period;
  o.extraction.texel_period = t.texel_period;
  o.synthesis.texel_period = t.texel_period;
  o.synthesis.iterations = t.em_iterations;
  o.detail = parse_choice(detail_representation_names, t.detail, "--detail");
  return o;
}

// The input's texture (segmented, or read from a vertex-id file) and its detail over the base
// (the library's, filled in by `take_input_detail` after the run), which the texel figures of
// simple scaling and non-homogeneous resizing measure.
struct Input_texture {
  Texture_map texture;
  Mesh::Property_map<Mesh::Vertex_index, double> detail;
  Mesh::Property_map<Mesh::Vertex_index, std::size_t> region;
  std::size_t regions = 0;
  std::string source;
  Texture_segmentation_result segmentation;
};

Input_texture find_texture(Mesh& mesh, const Texture_arguments& t, Texture_preservation_options& o,
                           const std::string& name) {
  Input_texture in;
  in.texture = mesh.add_property_map<Mesh::Vertex_index, bool>("v:tessera_is_texture", false).first;
  in.region = mesh.add_property_map<Mesh::Vertex_index, std::size_t>("v:tessera_region", 0).first;
  if (t.regions == "auto") {
    const Texture_segmentation_result s =
        segment_texture(mesh, in.region, in.texture, o.segmentation);
    if (!s)
      throw User_error(name + ": " + s.message);
    if (s.texture_vertices == 0)
      throw User_error(name + ": no geometric texture found (no region's curvature varies enough; "
                              "mark it with --texture-regions FILE)");
    in.regions = s.regions.size();
    in.source = "segmented";
    in.segmentation = s;
    o.extraction.texel_period = s.period.period; // the pipeline fairs at the scale found here
  } else {
    const Vertex_set_read_result r = read_vertex_set_file(t.regions, mesh, in.texture);
    if (!r)
      throw User_error(r.message);
    for (auto v : vertices(mesh))
      in.region[v] = in.texture[v] ? 1 : 0;
    in.regions = 2;
    in.source = t.regions;
  }
  in.detail = mesh.add_property_map<Mesh::Vertex_index, double>("v:tessera_detail", 0).first;
  return in;
}

// Per vertex, the detail height as a colour: blue below the base, white on it, red above, scaled
// by the largest height.
std::vector<Color> height_colors(const Mesh& m,
                                 const Mesh::Property_map<Mesh::Vertex_index, double>& height) {
  double peak = 0;
  for (auto v : vertices(m))
    peak = std::max(peak, std::abs(height[v]));
  std::vector<Color> out;
  for (auto v : vertices(m))
    out.push_back(diverging_color(0.5 + 0.5 * height[v] / std::max(peak, 1e-300)));
  return out;
}

// The result's texture vertices and its colours by detail height, its maps found by name: the
// library replaced the mesh, and the maps taken before belong to the one replaced.
Texture_map result_texture(const Mesh& result) {
  return result.property_map<Mesh::Vertex_index, bool>("v:tessera_is_texture").first;
}
std::vector<Color> result_height_colors(const Mesh& result) {
  return height_colors(result,
                       result.property_map<Mesh::Vertex_index, double>("v:tessera_height").first);
}

// The result, its base and the input's regions; the comparison picture (input first, sharing the
// input's connectivity, the textured result last).
void write_textured_outputs(const Output_directory& dir, const std::string& result_name,
                            const Mesh& input, const Input_texture& in, const Mesh& result,
                            const Comparison_scene& picture, const std::string& title,
                            std::vector<std::string>& written) {
  const std::string result_file = dir.file(result_name), base_file = dir.file("base.off"),
                    ply = dir.file("regions.ply"),
                    png = dir.file(result_name.substr(0, result_name.find('.')) + ".png");
  write_checked(result_file, [&](const std::string& p) { return write_mesh(p, result); });
  {
    Mesh base = result;
    auto b = result.property_map<Mesh::Vertex_index, Point_3>("v:tessera_base").first;
    for (auto v : vertices(base))
      base.point(v) = b[v];
    write_checked(base_file, [&](const std::string& p) { return write_mesh(p, base); });
  }
  {
    Mesh colored = input;
    auto color = colored.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
    for (auto v : vertices(colored))
      color[v] = in.texture[v] ? CGAL::IO::Color(200, 40, 40) : CGAL::IO::Color(200, 200, 205);
    write_checked(ply, [&](const std::string& p) { return write_colored_ply(p, colored); });
  }
  write_picture(picture.scene, png,
                title + (picture.offset_axis == 2 ? ", top to bottom" : ", bottom to top"),
                picture.view);
  written.insert(written.end(), {result_file, base_file, ply, png});
}

// The part every texture-preserving report has.
Texture_report texture_report(const Input_texture& in, const Texture_preservation_stages& stages,
                              bool intersected_before, bool intersects_after, double find_seconds,
                              Clock::time_point start, const Mesh_changes& changes) {
  Texture_report report;
  report.texture_source = in.source;
  report.regions = in.regions;
  report.stages = stages;
  report.stages.segmentation = in.segmentation; // the CLI segments before the pipeline runs
  report.self_intersections_before = intersected_before;
  report.self_intersections_after = intersects_after;
  report.segmentation_seconds = find_seconds;
  report.total_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  report.repairs = changes;
  return report;
}

// `report` into `path`, whole or not at all.
template <typename Report, typename Write>
void write_report(const std::string& path, const Report& report, Write write) {
  write_checked_stream(path, [&](std::ostream& out) { return write(out, report); });
}

// One line: each texture's period, texels and spacing before and after; with Laplacian
// coordinates, a second one: the vertices rebuilt from them.
void print_textures(const Texture_preservation_stages& s) {
  std::cout << "textures: " << s.textures.size();
  for (std::size_t t = 0; t < s.textures.size(); ++t) {
    const Texture_part_stages& p = s.textures[t];
    std::cout << (t ? "; " : " (") << "period " << p.period << ": " << p.texels_before.texels.size()
              << " -> " << p.texels_after.texels.size() << " texels, spacing "
              << p.texels_before.median_spacing << " -> " << p.texels_after.median_spacing;
  }
  std::cout << (s.textures.empty() ? "\n" : ")\n");
  if (s.reconstruction.vertices > 0)
    std::cout << "detail: laplacian, " << s.reconstruction.vertices
              << " vertices rebuilt from their Laplacian coordinates in "
              << s.reconstruction_seconds << " s\n";
}

// The common start of `resize --method textured` and `deform --method textured`: the input's
// texture and detail, and a copy of the input with the maps the library fills.
struct Textured_run {
  Input_texture in;
  double find_seconds = 0;
  Mesh input, result;
  Texture_map texture;
  Mesh::Property_map<Mesh::Vertex_index, Point_3> base;
  Mesh::Property_map<Mesh::Vertex_index, double> height;
  std::vector<Color> input_colors;
};

// Fills `run` in place: the maps of `run.in` belong to `run.input` and must not outlive it.
void start_textured(Textured_run& run, Mesh mesh, const Texture_arguments& t,
                    Texture_preservation_options& o, const std::string& name) {
  run.input = std::move(mesh);
  const auto found_at = Clock::now();
  run.in = find_texture(run.input, t, o, name);
  run.find_seconds = std::chrono::duration<double>(Clock::now() - found_at).count();
  run.result = run.input;
  run.texture = run.result.property_map<Mesh::Vertex_index, bool>("v:tessera_is_texture").first;
  run.base = run.result.add_property_map<Mesh::Vertex_index, Point_3>("v:tessera_base").first;
  run.height = run.result.add_property_map<Mesh::Vertex_index, double>("v:tessera_height", 0).first;
}

// The input's detail as the library extracted it (at the longest period when there are several
// textures), and the input's colours by it.
void take_input_detail(Textured_run& run, const Texture_preservation_stages& stages) {
  std::size_t i = 0;
  for (auto v : vertices(run.input))
    run.in.detail[v] = i < stages.input_detail.size() ? stages.input_detail[i++] : 0.0;
  run.input_colors = height_colors(run.input, run.in.detail);
}

int run_textured_resize(const Resize_arguments& a, Resize_options options, Mesh mesh,
                        const Mesh_changes& changes, const Output_directory& dir,
                        Clock::time_point start) {
  Texture_resize_options o;
  o.texture = texture_options(a.texture);
  o.texture.synthesis.progress = options.solve.progress;
  options.method = parse_choice(resize_method_names, a.texture.base, "--base");
  o.resize = options;
  Textured_run run;
  start_textured(run, std::move(mesh), a.texture, o.texture, a.mesh);
  const Input_texture& in = run.in;
  const Mesh &input = run.input, &result = run.result;
  const Texture_resize_result r =
      resize_preserving_texture(run.result, run.texture, run.base, run.height, o);
  if (!r)
    throw User_error(a.mesh + ": " + r.message);
  take_input_detail(run, r.stages);

  // The same input by simple scaling and by non-homogeneous resizing, for comparison.
  const Resize_comparison<Mesh> compared =
      texture_resize_comparison(input, result, result_texture(result), options,
                                {run.input_colors, result_height_colors(result)});
  if (!compared)
    throw User_error(a.mesh + ": " + compared.message);
  const double threshold = r.stages.texel_height_threshold;
  const Mesh& simple = compared.simple_scaling;
  const Texel_measure simple_texels = measure_texels(simple, simple.points(), in.detail, threshold);
  const bool intersected_before = self_intersects(input),
             intersects_after = self_intersects(result);

  std::vector<std::string> written;
  write_textured_outputs(dir, "resized.off", input, in, result, compared.picture,
                         std::filesystem::path(a.mesh).filename().string() +
                             ": input, simple scaling, non-homogeneous, texture-preserving "
                             "(colour: detail height)",
                         written);
  const std::string report_file = dir.file("report.json");
  Textured_resize_report report = make_textured_resize_report(a.mesh, options, r);
  report.texture = texture_report(in, r.stages, intersected_before, intersects_after,
                                  run.find_seconds, start, changes);
  report.simple_scaling = make_texel_report(simple_texels);
  if (const std::optional<Mesh>& n = compared.nonhomogeneous)
    report.nonhomogeneous =
        make_texel_report(measure_texels(*n, n->points(), in.detail, threshold));
  write_report(report_file, report, write_textured_resize_report);
  written.push_back(report_file);
  const Texel_measure &b = r.stages.texels_before, &t = r.stages.texels_after;
  std::cout << "resize: textured (" << report.base_method << " base), " << b.texels.size()
            << " texels -> " << t.texels.size() << ", median aspect " << b.median_aspect << " -> "
            << t.median_aspect << " (simple scaling " << simple_texels.median_aspect
            << "), median size " << b.median_size << " -> " << t.median_size << ", "
            << r.stages.vertices_before << " -> " << r.stages.vertices_after << " vertices"
            << (intersects_after && !intersected_before ? ", NEW SELF-INTERSECTIONS" : "") << "\n";
  print_textures(r.stages);
  print_written(with_view(written, dir, a.view, a.mesh));
  return exit_ok;
}

// The library's options from the arguments but the scale factors, which --size takes from the
// mesh (scale_factors); refuses what is out of range.
// --method: the texture-preserving variant ("textured", the base resized by --base's method), or
// a method of the library's table.
constexpr const char* textured_method = "textured";
bool is_textured(const std::string& method) {
  return method == textured_method;
}

Resize_options resize_options(const Resize_arguments& a) {
  if (a.scale.empty() == a.size.empty())
    throw User_error("give either --scale SX,SY,SZ or --size X,Y,Z (exactly one of them)");
  const std::vector<double>& given = a.scale.empty() ? a.size : a.scale;
  if (given.size() != 3)
    throw User_error(std::string(a.scale.empty() ? "--size" : "--scale") +
                     " takes three numbers, X,Y,Z");
  for (double x : given)
    if (!(x > 0) || !std::isfinite(x))
      throw User_error("scale factors and sizes must be positive numbers");
  Resize_options options;
  if (!is_textured(a.method))
    options.method = parse_choice(resize_method_names, a.method, "method", "", {textured_method});
  options.volume = parse_choice(resize_volume_names, a.volume, "volume");
  if (!(a.vulnerability_weight >= 0) || !std::isfinite(a.vulnerability_weight))
    throw User_error("--vulnerability-weight must be a number >= 0");
  options.vulnerability_weight = a.vulnerability_weight;
  return options;
}

// --scale as given, or the factors that give the mesh's bounding box the extents of --size.
std::array<double, 3> scale_factors(const Resize_arguments& a, const Mesh& mesh) {
  if (a.size.empty())
    return {{a.scale[0], a.scale[1], a.scale[2]}};
  const Scale_for_extents_result r = scale_for_extents(mesh, {{a.size[0], a.size[1], a.size[2]}});
  if (!r)
    throw User_error("--size: " + r.message + "; use --scale");
  return r.scale;
}

// The input coloured by the vulnerability each vertex resisted the resize with.
bool write_vulnerability_ply(const std::string& path, const Mesh& input,
                             const std::vector<double>& resisted) {
  Mesh colored = input;
  auto color = colored.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
  std::size_t i = 0;
  for (auto v : vertices(colored)) {
    const Color c = diverging_color(resisted[i++]);
    color[v] = CGAL::IO::Color((unsigned char)(255 * c.r), (unsigned char)(255 * c.g),
                               (unsigned char)(255 * c.b));
  }
  return write_colored_ply(path, colored);
}

// resized.off, vulnerability.ply, resize.png and report.json, which gets the command's time last;
// returns the files written.
std::vector<std::string> write_resize_outputs(const Output_directory& dir, const std::string& name,
                                              const Mesh& input, const Mesh& resized,
                                              const std::vector<double>& resisted,
                                              const Comparison_scene& picture,
                                              Resize_report& report, Clock::time_point start) {
  const std::string resized_file = dir.file("resized.off"), ply = dir.file("vulnerability.ply"),
                    png = dir.file("resize.png"), report_file = dir.file("report.json");
  write_checked(resized_file, [&](const std::string& p) { return write_mesh(p, resized); });
  write_checked(ply,
                [&](const std::string& p) { return write_vulnerability_ply(p, input, resisted); });
  write_picture(picture.scene, png,
                std::filesystem::path(name).filename().string() + ": input, simple scaling, " +
                    report.method + " (colour: vulnerability)",
                picture.view);
  report.total_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  write_report(report_file, report, write_resize_report);
  return {resized_file, ply, png, report_file};
}

void print_resize(const Resize_result& r, const Resize_report& report) {
  std::cout << "resize: " << report.method << ", extent " << r.extent_after[0] << " x "
            << r.extent_after[1] << " x " << r.extent_after[2] << " (target " << r.target_extent[0]
            << " x " << r.target_extent[1] << " x " << r.target_extent[2] << ")";
  if (report.vulnerable.vertices > 0)
    std::cout << ", stretch ratio in vulnerable parts median " << report.vulnerable.median
              << ", p95 " << report.vulnerable.p95 << " (simple scaling "
              << report.simple_scaling_vulnerable.median << ", "
              << report.simple_scaling_vulnerable.p95 << ")";
  for (std::size_t d = 0; d < 3; ++d)
    if (r.vulnerability_weight[d] < 1)
      std::cout << ", too little free along "
                << "xyz"[d] << ": vulnerability weighed by " << r.vulnerability_weight[d];
  std::cout << (report.self_intersections_after && !report.self_intersections_before
                    ? ", NEW SELF-INTERSECTIONS"
                    : "")
            << "\n";
}

int run_resize(const Resize_arguments& a) {
  const auto start = Clock::now();
  Resize_options options = resize_options(a);
  Progress_printer printer;
  options.solve.progress = printer.callback();
  Mesh_changes changes;
  Mesh mesh = read_input_mesh(a.mesh, a.input, &changes);
  const Output_directory dir(a.out, a.force, {a.mesh});
  const Mesh input = mesh;
  options.scale = scale_factors(a, mesh);
  if (is_textured(a.method))
    return run_textured_resize(a, options, mesh, changes, dir, start);
  auto vulnerability =
      mesh.add_property_map<Mesh::Vertex_index, P3>("v:tessera_vulnerability").first;
  const Resize_result r = resize(mesh, vulnerability, options);
  if (!r)
    throw User_error(a.mesh + ": " + r.message);

  // Local stretch in vulnerable and free regions (vulnerability along a resized axis ≥ 0.5),
  // against simple scaling's; the result coloured by the vulnerability its vertices resisted with.
  const Stretch_by_vulnerability stretch =
      stretch_by_vulnerability(mesh, input.points(), mesh.points(), vulnerability, options.scale);
  std::vector<Color> colors;
  for (double w : stretch.resisted)
    colors.push_back(diverging_color(w));
  const Resize_comparison<Mesh> compared = resize_comparison(input, mesh, options, {{}, colors});
  if (!compared)
    throw User_error(a.mesh + ": " + compared.message);
  const Stretch_by_vulnerability simple_stretch = stretch_by_vulnerability(
      mesh, input.points(), compared.simple_scaling.points(), vulnerability, options.scale);

  Resize_report report = make_resize_report(a.mesh, options, r, changes);
  report.enclosed_volume_before = enclosed_volume(input);
  report.enclosed_volume_after = enclosed_volume(mesh);
  report.self_intersections_before = self_intersects(input);
  report.self_intersections_after = self_intersects(mesh);
  report.vulnerable = make_stretch_stats(stretch.vulnerable);
  report.free = make_stretch_stats(stretch.free);
  report.simple_scaling_vulnerable = make_stretch_stats(simple_stretch.vulnerable);
  report.simple_scaling_free = make_stretch_stats(simple_stretch.free);
  const std::vector<std::string> written = write_resize_outputs(
      dir, a.mesh, input, mesh, stretch.resisted, compared.picture, report, start);
  print_resize(r, report);
  print_written(with_view(written, dir, a.view, a.mesh));
  return exit_ok;
}

std::vector<Deformation_handle> read_handles(const std::string& path,
                                             std::optional<Vertex_selection>& region) {
  Handles_read_result r = read_deformation_handles(path);
  if (!r)
    throw User_error(r.status == Handles_read_status::cannot_open ? r.message
                                                                  : path + ": " + r.message);
  if (r.region)
    region = r.region;
  return std::move(r.handles);
}

int run_textured_deform(const Deform_arguments& a, const Deformation_options& options,
                        const std::vector<Deformation_handle>& handles, Mesh mesh,
                        const Mesh_changes& changes, const Output_directory& dir,
                        Clock::time_point start) {
  Texture_deform_options o;
  o.texture = texture_options(a.texture);
  Progress_printer printer;
  o.texture.synthesis.progress = printer.callback();
  o.deformation = options;
  Textured_run run;
  start_textured(run, std::move(mesh), a.texture, o.texture, a.mesh);
  const Input_texture& in = run.in;
  const Mesh &input = run.input, &result = run.result;
  const Texture_deform_result r =
      deform_preserving_texture(run.result, handles, run.texture, run.base, run.height, o);
  if (!r)
    throw User_error((r.status == Texture_preservation_status::base_failed ? a.handles : a.mesh) +
                     ": " + r.message);
  take_input_detail(run, r.stages);
  // The input deformed as it is (ARAP), for comparison.
  Mesh plain = input;
  const bool plain_ok = bool(deform_by_handles(plain, handles, options));
  const double threshold = r.stages.texel_height_threshold;
  const Texel_measure plain_texels = measure_texels(plain, plain.points(), in.detail, threshold);
  const bool intersected_before = self_intersects(input),
             intersects_after = self_intersects(result);
  std::vector<Mesh_state> states{mesh_state(input, run.input_colors)};
  if (plain_ok)
    states.push_back(mesh_state(plain, run.input_colors));
  const Comparison_scene picture = texture_comparison_scene(
      input, states, result, result_texture(result), result_height_colors(result));
  std::vector<std::string> written;
  write_textured_outputs(dir, "deformed.off", input, in, result, picture,
                         std::filesystem::path(a.mesh).filename().string() +
                             ": input, ARAP, texture-preserving (colour: detail height)",
                         written);
  const std::string report_file = dir.file("report.json");
  Textured_deform_report report = make_textured_deform_report(a.mesh, a.handles, a.iterations, r);
  report.texture = texture_report(in, r.stages, intersected_before, intersects_after,
                                  run.find_seconds, start, changes);
  if (plain_ok)
    report.arap = make_texel_report(plain_texels);
  write_report(report_file, report, write_textured_deform_report);
  written.push_back(report_file);
  const Texel_measure &b = r.stages.texels_before, &t = r.stages.texels_after;
  std::cout << "deform: textured, " << r.deformation.handle_vertices << " handle vertices, "
            << b.texels.size() << " texels -> " << t.texels.size() << ", median aspect "
            << b.median_aspect << " -> " << t.median_aspect << " (ARAP alone "
            << plain_texels.median_aspect << "), median size " << b.median_size << " -> "
            << t.median_size
            << (intersects_after && !intersected_before ? ", NEW SELF-INTERSECTIONS" : "") << "\n";
  print_textures(r.stages);
  print_written(with_view(written, dir, a.view, a.mesh));
  return exit_ok;
}

int run_deform(const Deform_arguments& a) {
  const auto start = Clock::now();
  Deformation_options options;
  // textured: ARAP on the base, the texture synthesized anew.
  const bool textured = is_textured(a.method);
  options.method =
      textured ? Deformation_method::arap
               : parse_choice(deformation_method_names, a.method, "method", "", {textured_method});
  options.iterations = a.iterations;
  const std::vector<Deformation_handle> handles =
      read_handles(a.handles, options.region_of_interest);
  Mesh_changes changes;
  Mesh mesh = read_input_mesh(a.mesh, a.input, &changes);
  const Output_directory dir(a.out, a.force, {a.mesh, a.handles});
  if (textured)
    return run_textured_deform(a, options, handles, mesh, changes, dir, start);
  const Mesh input = mesh;
  const Deformation_result r = deform_by_handles(mesh, handles, options);
  if (!r)
    throw User_error(a.handles + ": " + r.message);
  const bool intersected_before = self_intersects(input), intersects_after = self_intersects(mesh);
  auto ratio = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  local_stretch_ratios(mesh, input.points(), mesh.points(), ratio);
  std::vector<double> ratios;
  for (auto v : vertices(mesh))
    ratios.push_back(get(ratio, v));

  const std::string deformed_file = dir.file("deformed.off"), png = dir.file("deform.png"),
                    report_file = dir.file("report.json");
  write_checked(deformed_file, [&](const std::string& p) { return write_mesh(p, mesh); });
  Render_scene scene;
  add_mesh_states(scene, mesh, {mesh_state(input), mesh_state(mesh)}, 0);
  Deform_report report = make_deform_report(a.mesh, a.handles, options, r, changes);
  write_picture(scene, png,
                std::filesystem::path(a.mesh).filename().string() + ": input, deformed (" +
                    report.method + ")");
  report.self_intersections_before = intersected_before;
  report.self_intersections_after = intersects_after;
  report.enclosed_volume_before = enclosed_volume(input);
  report.enclosed_volume_after = enclosed_volume(mesh);
  report.stretch_ratio = make_stretch_stats(ratios);
  report.total_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  write_report(report_file, report, write_deform_report);
  std::cout << "deform: " << report.method << ", " << r.handle_vertices << " handle vertices, "
            << r.region_vertices << " free to move, handles off their targets by at most "
            << r.max_handle_error
            << (intersects_after && !intersected_before ? ", NEW SELF-INTERSECTIONS" : "") << "\n";
  print_written(with_view({deformed_file, png, report_file}, dir, a.view, a.mesh));
  return exit_ok;
}

void add_texture_options(CLI::App* cmd, Texture_arguments& t) {
  cmd->add_option("--texture-regions", t.regions,
                  "With --method textured: auto (found by segmentation) or a file of texture "
                  "vertex ids")
      ->capture_default_str();
  cmd->add_option("--sample-size", t.sample_size,
                  "With --method textured: vertices in one texel, which sets the segmentation's "
                  "radius instead of the texel period (0: from the period)")
      ->capture_default_str();
  cmd->add_option("--texel-period", t.texel_period,
                  "With --method textured: distance between neighbouring texels in model units "
                  "(0: read from the surface; the report gives the one found)")
      ->capture_default_str();
  cmd->add_option("--em-iterations", t.em_iterations,
                  "With --method textured: E-M iterations per level of the synthesis")
      ->capture_default_str();
  cmd->add_option("--detail", t.detail,
                  "With --method textured: how the detail is carried to the new base, " +
                      internal::enum_name_list(detail_representation_names) +
                      " (normal: an offset along the base's normal; laplacian: Laplacian "
                      "coordinates in the base's frames and a Poisson reconstruction)")
      ->capture_default_str();
}

} // namespace

void register_resize_commands(CLI::App& app, std::function<int()>& run) {
  auto a = std::make_shared<Resize_arguments>();
  auto* cmd = app.add_subcommand(
      "resize", "Resize along axes, keeping curved parts in proportion (Kraevoy et al. 2008)");
  add_mesh_input(cmd, a->mesh, a->input);
  cmd->add_option("--scale", a->scale, "Factors SX,SY,SZ on the bounding box")->delimiter(',');
  cmd->add_option("--size", a->size, "Target bounding box X,Y,Z (instead of --scale)")
      ->delimiter(',');
  cmd->add_option("--method", a->method,
                  "nonhomogeneous (curved parts keep their proportions), simple (plain scaling) "
                  "or textured (a geometric texture keeps its texels' size and spacing: its "
                  "region is segmented, a smooth base faired out under it and resized, and the "
                  "texture synthesized again on the new base from the input; the texels' scale "
                  "is read from the surface)")
      ->capture_default_str();
  cmd->add_option("--volume", a->volume,
                  "auto (TetGen for closed surfaces, the grid otherwise), tetgen or grid")
      ->capture_default_str();
  cmd->add_option("--vulnerability-weight", a->vulnerability_weight,
                  "Factor on the vulnerability (0 behaves like simple scaling)")
      ->capture_default_str();
  add_texture_options(cmd, a->texture);
  cmd->add_option("--base", a->texture.base,
                  "With --method textured: how the base is resized, " +
                      internal::enum_name_list(resize_method_names))
      ->capture_default_str();
  cmd->add_option("--out", a->out, "Output directory")->required();
  cmd->add_flag("--force", a->force, "Write into a non-empty directory Tessera did not create");
  add_view_flag(cmd, a->view);
  cmd->callback([&run, a] { run = [a] { return run_resize(*a); }; });

  auto d = std::make_shared<Deform_arguments>();
  auto* dc = app.add_subcommand(
      "deform", "Deform by handles as rigidly as possible (CGAL's Surface_mesh_deformation)");
  add_mesh_input(dc, d->mesh, d->input);
  dc->add_option("--handles", d->handles, "JSON file of handles (see doc/resizing.md)")->required();
  dc->add_option("--method", d->method,
                 "arap, srarap (smoothed rotation-enhanced ARAP), spokes, or textured (ARAP on the "
                 "base, texture synthesized anew)")
      ->capture_default_str();
  add_texture_options(dc, d->texture);
  dc->add_option("--iterations", d->iterations, "Iterations of the solver")->capture_default_str();
  dc->add_option("--out", d->out, "Output directory")->required();
  dc->add_flag("--force", d->force, "Write into a non-empty directory Tessera did not create");
  add_view_flag(dc, d->view);
  dc->callback([&run, d] { run = [d] { return run_deform(*d); }; });
}

} // namespace tessera::cli
