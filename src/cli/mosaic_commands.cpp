// tessera mosaic: a surface mosaic (Lai, Hu, Martin 2006) of equal tiles laid along the smoothest
// field that follows the feature lines, written as tiles.json, a coloured tiles.ply, report.json
// and a picture.
#include "choices.h"
#include "commands.h"
#include "field_input.h"
#include "mesh_input.h"
#include "output_dir.h"

#include <tessera/fields.h>
#include <tessera/io.h>
#include <tessera/io/image.h>
#include <tessera/io/mosaic_reports.h>
#include <tessera/mosaic.h>
#include <tessera/render.h>
#include <tessera/types.h>

#include <CGAL/IO/Color.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh/IO/PLY.h>
#include <boost/property_map/function_property_map.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <type_traits>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

namespace tessera::cli {
namespace {

using Tile = Mosaic_tile<Mesh::Face_index>;
using Clock = std::chrono::steady_clock;

// `x` with `digits` significant digits, or with `digits` decimals when `fixed`.
std::string number(double x, int digits = 6, bool fixed = false) {
  std::ostringstream s;
  if (fixed)
    s << std::fixed;
  s << std::setprecision(digits) << x;
  return s.str();
}

// Where the tiles' colours come from (--colors).
Tile_color_source color_source(const Mosaic_arguments& a) {
  return parse_choice(tile_color_source_names, a.colors, "--colors");
}

// The library's options from the arguments; `by_count` and `aspect_given` say which of --tiles and
// --aspect were on the command line.
Surface_mosaic_options mosaic_options(const Mosaic_arguments& a) {
  const bool by_count = a.tiles_given, aspect_given = a.aspect_given;
  const bool by_size = !a.tile_size.empty();
  if (by_size == by_count)
    throw User_error("give either --tile-size LX[,LY] or --tiles N (exactly one of them)");
  Surface_mosaic_options o;
  if (by_size) {
    if (aspect_given)
      throw User_error("--aspect goes with --tiles; with --tile-size give both sides, LX,LY");
    for (double l : a.tile_size)
      if (!(l > 0) || !std::isfinite(l))
        throw User_error("--tile-size: a side must be a positive number (got " + number(l) + ")");
    o.tiles.tile_size = {{a.tile_size[0], a.tile_size.size() > 1 ? a.tile_size[1] : 0}};
  } else {
    if (a.tiles < 1)
      throw User_error("--tiles must be a positive number of tiles (got " +
                       std::to_string(a.tiles) + ")");
    if (!(a.aspect > 0) || !std::isfinite(a.aspect))
      throw User_error("--aspect must be a positive number (got " + number(a.aspect) + ")");
    o.tiles.tile_count = std::size_t(a.tiles);
    o.tiles.aspect = a.aspect;
  }
  if (!(a.grout >= 0 && a.grout < 1))
    throw User_error("--grout must be in [0, 1) (got " + number(a.grout) + ")");
  o.tiles.grout = a.grout;
  if (!(a.tile_scale_smoothing >= 0 && a.tile_scale_smoothing <= 1))
    throw User_error("--tile-scale-smoothing must be in [0, 1] (got " +
                     number(a.tile_scale_smoothing) + ")");
  if (a.iterations < 0)
    throw User_error("--iterations must not be negative (got " + std::to_string(a.iterations) +
                     ")");
  o.max_iterations = std::size_t(a.iterations);
  // One name table per choice (tessera/mosaic/mosaic_names.h) for parsing and messages.
  o.energy = parse_choice(mosaic_energy_names, a.energy, "--energy");
  o.initialization = parse_choice(mosaic_initialization_names, a.start, "--start");
  o.count = parse_choice(mosaic_count_names, a.count, "--count");
  if (!a.texture.empty() && color_source(a) != Tile_color_source::texture)
    throw User_error("--texture goes with --colors texture");
  // Set here, not left to the library, because the field is solved before the mosaic.
  o.symmetry = mosaic_field_symmetry(o.tiles);
  if (a.teleport)
    o.teleport_every = 10;
  o.seed = a.seed;
  return o;
}

// The tile sizes and spacing of `o` on `mesh` (with a tile size field, those the tiles would have
// without it).
Mosaic_layout tiles_layout(const Surface_mosaic_options& o, const Mesh& mesh) {
  Mosaic_layout layout;
  if (auto why = mosaic_layout(o.tiles, CGAL::Polygon_mesh_processing::area(mesh), layout))
    throw User_error(*why);
  return layout;
}

// Each tile one coloured polygon, lifted off the surface by 0.02 × its shorter side so that it
// shows above the mesh when a viewer opens both.
bool write_tiles_ply(const std::string& path, const std::vector<Tile>& tiles) {
  Mesh polygons;
  auto color = polygons.add_property_map<Mesh::Face_index, CGAL::IO::Color>("f:color").first;
  for (const Tile& t : tiles) {
    const auto outline = tile_polygon(t, 0.02 * std::min(t.size[0], t.size[1]));
    if (outline.size() < 3)
      continue;
    std::vector<Mesh::Vertex_index> corners;
    for (const auto& p : outline)
      corners.push_back(polygons.add_vertex(Point_3(p[0], p[1], p[2])));
    const Mesh::Face_index f = polygons.add_face(corners);
    const auto c = tile_rgb(t.color);
    if (f != Mesh::null_face())
      color[f] = CGAL::IO::Color((unsigned char)c[0], (unsigned char)c[1], (unsigned char)c[2]);
  }
  std::ofstream out(path, std::ios::binary);
  CGAL::IO::set_binary_mode(out);
  const bool written = CGAL::IO::write_PLY(out, polygons);
  out.close();
  return written && !out.fail();
}

} // namespace

// The model's colours a mosaic can take (`--colors mesh` or `texture`): the mesh file's face
// colours, or an OBJ's texture coordinates with its image (`--texture`, else the MTL's map_Kd).
struct Model_colors {
  std::vector<Color> face_colors; // by face index of the mosaic's mesh
  Uv_layout<Mesh> layout;
  Rgb_image texture;
};

Model_colors read_model_colors(const Mosaic_arguments& a, Tile_color_source source,
                               const Mesh& mesh) {
  Model_colors m;
  if (source == Tile_color_source::mesh) {
    auto color = get(CGAL::dynamic_face_property_t<CGAL::IO::Color>(), mesh);
    const Color_regions_result r = read_face_colors(a.mesh, mesh, color);
    if (!r)
      throw User_error(r.message + " (--colors mesh takes the tiles' colours from them)");
    for (auto f : faces(mesh)) {
      const CGAL::IO::Color c = get(color, f);
      m.face_colors.push_back(Color{c.red() / 255.0, c.green() / 255.0, c.blue() / 255.0});
    }
  } else if (source == Tile_color_source::texture) {
    const Cutting_read_result r = read_obj_with_uvs(a.mesh, m.layout);
    if (!r)
      throw User_error(a.mesh + ": " + r.message +
                       " (--colors texture needs an OBJ with texture coordinates)");
    if (!CGAL::is_triangle_mesh(m.layout.charts))
      CGAL::Polygon_mesh_processing::triangulate_faces(m.layout.charts);
    std::string image = a.texture;
    if (image.empty()) {
      const auto named = read_obj_texture_path(a.mesh);
      if (!named)
        throw User_error(a.mesh + ": no texture image (no map_Kd in its material library); give "
                                  "one with --texture IMAGE");
      image = *named;
    }
    Image_read_result ir = read_image(image);
    if (!ir)
      throw User_error(ir.message + " (the texture of --colors texture)");
    m.texture = std::move(ir.image);
  }
  return m;
}

// Each tile's colour averaged over its footprint (tessera/mosaic/tile_colors.h).
void color_tiles(const Model_colors& m, Tile_color_source source, const Mesh& mesh,
                 std::vector<Tile>& tiles) {
  if (source == Tile_color_source::mesh) {
    auto map = boost::make_function_property_map<Mesh::Face_index>(
        [&](Mesh::Face_index f) { return m.face_colors[std::size_t(f)]; });
    average_tile_colors(tiles, Face_colors<Mesh, decltype(map)>(mesh, map));
  } else if (source == Tile_color_source::texture) {
    const auto& uv = m.layout.uv;
    auto map = boost::make_function_property_map<Mesh::Vertex_index>([&](Mesh::Vertex_index v) {
      return std::array<double, 2>{
          {CGAL::to_double(uv[std::size_t(v)][0]), CGAL::to_double(uv[std::size_t(v)][1])}};
    });
    average_tile_colors(tiles,
                        Texture_colors<Mesh, decltype(map)>(m.layout.charts, map, m.texture));
  }
}

// The per-vertex tile size of --tile-size-field: a text file of one number per vertex, or the name
// of a vertex property of the PLY input; false without one.
template <typename SizeMap>
bool read_tile_size_field(const Mosaic_arguments& a, const Mesh& mesh, SizeMap size) {
  if (a.tile_size_field.empty())
    return false;
  const bool file = std::filesystem::exists(a.tile_size_field);
  if (!file && file_extension(a.mesh) != ".ply")
    throw User_error("--tile-size-field: no file " + a.tile_size_field +
                     " (a vertex property name needs a .ply input)");
  const Vertex_scalars_read_result r =
      file ? read_vertex_scalars_file(a.tile_size_field, mesh, size)
           : read_ply_vertex_scalars(a.mesh, a.tile_size_field, mesh, size);
  if (!r)
    throw User_error(r.message + " (--tile-size-field)");
  return true; // (Surface_mosaic refuses sizes that are not positive, naming the vertex)
}

// The mosaic run() lays, with its stats shown to the progress printer while it runs.
struct Laid_mosaic {
  std::vector<Tile> tiles;
  Mosaic_layout layout;
  Surface_mosaic_stats stats;
};
template <typename Mosaic>
Laid_mosaic lay_mosaic(Mosaic& mosaic, const std::string& mesh_path,
                       const Surface_mosaic_stats*& running) {
  if (mosaic.status() != Mosaic_status::ok)
    throw User_error(mesh_path + ": " + mosaic.message());
  running = &mosaic.stats();
  mosaic.run();
  running = nullptr;
  return {mosaic.tiles(), mosaic.layout(), mosaic.stats()};
}

// Progress on stderr once the command has run for a second: every tenth iteration and the last.
Progress_callback mosaic_progress(const Surface_mosaic_stats*& running,
                                  const std::function<double()>& elapsed) {
  return [&running, elapsed](const Progress& p) {
    const Surface_mosaic_stats* stats = running;
    if (stats == nullptr || !(p.done % 10 == 0 || stats->converged || p.done == p.total) ||
        !(elapsed() > 1))
      return;
    std::cerr << "mosaic: iteration " << p.done << ", mean displacement "
              << number(stats->mean_displacement.back(), 3) << ", energy "
              << number(stats->energy.back(), 6) << ", " << number(elapsed(), 1, true) << " s\n";
  };
}

// The files the command reads, which its output directory must not overwrite.
std::vector<std::string> mosaic_inputs(const Mosaic_arguments& a) {
  std::vector<std::string> inputs{a.mesh};
  for (const std::string& f : field_input_files(a.field))
    inputs.push_back(f);
  if (std::filesystem::is_regular_file(a.tile_size_field))
    inputs.push_back(a.tile_size_field);
  return inputs;
}

using Point_map = Mesh::Property_map<Mesh::Vertex_index, Point_3>;

// The field the tiles follow, into `field`, solved on `points` (the surface smoothed at the tiles'
// scale): by default turned along the parts fewer than a few tiles around and held elsewhere
// (`thin` says what was found); with --no-thin-parts solved once.
Smoothest_field_result mosaic_field(const Mosaic_arguments& a,
                                    const Surface_mosaic_options& options,
                                    const Mosaic_layout& layout, const Mesh& mesh,
                                    const Field_input& in, Field_map field, Point_map points,
                                    std::optional<Thin_part_result<Mesh>>& thin) {
  Smoothest_field_options so;
  so.symmetry = options.symmetry;
  // The field is not carried through the vertices where feature lines end or meet (the solver's
  // edge_is_constrained_map): a CAD part's flat faces keep their edges' direction.
  auto is_line = get(CGAL::dynamic_edge_property_t<bool>(), mesh); // false everywhere
  mark_feature_edges(mesh, in.lines, is_line);
  const auto np = CGAL::parameters::vertex_point_map(points).edge_is_constrained_map(is_line);
  const auto constraints = field_constraints(mesh, in, feature_alignment_options(layout));
  if (!a.thin_parts) {
    const Smoothest_field_result r = smoothest_field(mesh, constraints, field, so, np);
    if (!r)
      throw User_error(r.message);
    return r;
  }
  // On a mesh with creases as feature lines (a CAD part) its curved surfaces are guided too.
  auto r = smoothest_field_with_thin_parts(mesh, constraints, field,
                                           thin_part_options(layout, in.lines), so, np);
  if (!r)
    throw User_error(r.message());
  thin = std::move(r.thin_parts);
  return r.field;
}

// The mosaic laid along `field`, on `points` with --smooth-planes (its tiles' centres then put
// back onto the mesh), with the tile sizes of --tile-size-field in `size` when `sized`.
template <typename FieldMap, typename SizeMap>
Laid_mosaic lay_tiles(const Mosaic_arguments& a, Mesh& mesh, FieldMap field, const Field_input& in,
                      const Surface_mosaic_options& options, Point_map points, bool sized,
                      SizeMap size, const Surface_mosaic_stats*& running) {
  // The tiles' planes: the smoothed surface's with --smooth-planes, else the faces' as read.
  const auto np = CGAL::parameters::vertex_point_map(a.smooth_planes ? points : mesh.points());
  Laid_mosaic laid;
  if (sized) {
    const auto sized_np = np.scalar_map(size);
    Surface_mosaic<Mesh, std::decay_t<decltype(sized_np)>> mosaic(mesh, field, in.lines, options,
                                                                  sized_np);
    laid = lay_mosaic(mosaic, a.mesh, running);
  } else {
    Surface_mosaic<Mesh, std::decay_t<decltype(np)>> mosaic(mesh, field, in.lines, options, np);
    laid = lay_mosaic(mosaic, a.mesh, running);
  }
  place_tiles_on_surface(mesh, laid.tiles);
  return laid;
}

// Remeshes the faces of `mesh` with edges longer than four tile spacings to edges of two, so that
// the field has vertices at the tiles' scale, carries what was read on it (the feature lines, the
// tile sizes in `size` when `sized`, the face colours) and says what it did.
template <typename SizeMap>
Coarse_mesh_refinement<Mesh> refine_for_tiles(const Mosaic_layout& layout, Mesh& mesh,
                                              Field_input& in, bool sized, SizeMap size,
                                              Model_colors& colors) {
  Coarse_mesh_refinement<Mesh> r = refine_coarse_mesh(mesh, coarse_mesh_options(layout), in.lines);
  if (r.left_coarse)
    std::cout << "mesh left coarse: its edges longer than four tile spacings belong to slivers\n";
  if (!r.refined)
    return r;
  std::cout << "mesh refined for the field: faces with edges longer than four tile spacings "
               "remeshed to two, the longest edge "
            << number(r.longest_edge_before, 3) << " -> " << number(r.max_edge_length, 3) << ", "
            << r.vertices_added << " vertices added to " << r.vertices_before << "\n";
  if (sized)
    r.interpolate(size);
  if (!colors.face_colors.empty()) {
    std::vector<Color> refined(num_faces(mesh));
    for (auto f : faces(mesh))
      refined[std::size_t(f)] = colors.face_colors[std::size_t(r.coarse_face(f))];
    colors.face_colors = std::move(refined);
  }
  return r;
}

// tiles.json, tiles.ply, report.json and mosaic.png; returns the files written.
std::vector<std::string>
write_mosaic_outputs(const Output_directory& dir, const std::string& mesh_path, const Mesh& mesh,
                     const std::vector<Tile>& tiles, const Coarse_mesh_refinement<Mesh>& refinement,
                     const Mosaic_report& report, const Mosaic_quality& q) {
  const std::string tiles_json = dir.file("tiles.json"), tiles_ply = dir.file("tiles.ply"),
                    report_file = dir.file("report.json"), png = dir.file("mosaic.png");
  // tiles.json names the input's faces, not those of the refined mesh the tiles were laid on.
  std::vector<Tile> on_input = tiles;
  for (Tile& t : on_input)
    t.face = refinement.coarse_face(t.face);
  write_checked_stream(tiles_json, [&](std::ostream& out) {
    return write_mosaic_tiles_report(out, make_mosaic_tiles_report(on_input));
  });
  write_checked(tiles_ply, [&](const std::string& tmp) { return write_tiles_ply(tmp, tiles); });
  write_checked_stream(report_file,
                       [&](std::ostream& out) { return write_mosaic_report(out, report); });
  Render_scene scene;
  add_mosaic(scene, mesh, tiles);
  Render_options ro;
  ro.edges = Edge_drawing::never;
  ro.title = std::filesystem::path(mesh_path).filename().string() + ": " +
             std::to_string(tiles.size()) + " tiles, coverage " + number(q.coverage, 3, true);
  write_checked(png, [&](const std::string& tmp) { return render_png(scene, tmp, ro); });
  return {tiles_json, tiles_ply, report_file, png};
}

// The summary line: tiles, iterations, the quality figures and what the stages changed.
void print_mosaic(const Laid_mosaic& laid, const Mosaic_quality& q) {
  const Mosaic_layout& layout = laid.layout;
  const Surface_mosaic_stats& stats = laid.stats;
  std::cout << "mosaic: " << laid.tiles.size() << " tiles (l " << number(layout.tile_size[0], 3)
            << " x " << number(layout.tile_size[1], 3) << ", grout " << layout.grout << "), "
            << stats.iterations << " iterations ("
            << (stats.converged ? "converged" : "iteration limit reached") << "), coverage "
            << number(q.coverage, 3, true) << ", overlap " << number(q.overlap, 3, true)
            << ", course drift median " << number(q.course_drift_median, 1, true) << "° (p95 "
            << number(q.course_drift_p95, 1, true) << "°), widest bare patch "
            << number(q.largest_gap, 2, true) << " tiles, " << q.tiles_crossing_features
            << " tiles crossing feature lines";
  if (stats.moved_off_features + stats.cut_at_features + stats.removed_at_features > 0)
    std::cout << " (" << stats.moved_off_features << " moved off them, " << stats.cut_at_features
              << " cut to them, " << stats.removed_at_features << " left out)";
  if (stats.shrunk_tiles > 0)
    std::cout << ", " << stats.shrunk_tiles << " tiles made smaller where the surface is thin";
  if (stats.filled_patches > 0)
    std::cout << ", " << stats.filled_patches << " added in bare patches";
  if (stats.trimmed_tiles > 0)
    std::cout << ", " << stats.trimmed_tiles << " trimmed to fit";
  if (stats.grown_tiles > 0)
    std::cout << ", " << stats.grown_tiles << " grown back into room";
  if (stats.left_out_crowded > 0)
    std::cout << ", " << stats.left_out_crowded << " crowded tiles left out";
  std::cout << "\n";
}

// The lines of the options that were given: --tile-size-field, --thin-parts, --cut-tiles.
void print_mosaic_options(const Mosaic_arguments& a, const std::vector<Tile>& tiles,
                          const std::optional<Thin_part_result<Mesh>>& thin,
                          const Cut_tiles_result& cut) {
  if (!a.tile_size_field.empty()) {
    const auto [small, large] =
        std::minmax_element(tiles.begin(), tiles.end(),
                            [](const Tile& x, const Tile& y) { return x.size[0] < y.size[0]; });
    if (small != tiles.end())
      std::cout << "tile sizes from " << a.tile_size_field << ": sides "
                << number(small->size[0], 3) << " to " << number(large->size[0], 3) << "\n";
  }
  if (thin) {
    const std::size_t parts = thin->guided_vertices - thin->curved_band_vertices;
    if (parts == 0)
      std::cout << "thin parts: none";
    else
      std::cout << "thin parts: the field turned along them at " << parts
                << " vertices, held elsewhere (typically "
                << number(thin->median_guided_tiles_around, 1, true)
                << " tiles around; the thinnest is " << number(thin->fewest_tiles_around, 1, true)
                << ")";
    if (thin->curved_band_vertices > 0)
      std::cout << "; curved bands with no loop around them turned along at "
                << thin->curved_band_vertices << " vertices";
    if (thin->guided_vertices > 0)
      std::cout << " (" << number(100 * thin->guided_area_fraction, 1, true)
                << "% of the area guided)";
    std::cout << "\n";
  }
  if (a.cut_tiles)
    std::cout << "cut tiles: " << cut.tiles_cut << " cut, " << cut.tiles_removed << " removed, "
              << number(100 * cut.fraction_removed, 2) << "% of the tile area cut away\n";
}

// Without --features: the creases at 60° are taken as feature lines (with the open borders) when
// they read as edges of the shape at the tiles' scale (`tile_scale_creases()`), and said which.
Tile_scale_creases read_creases(const Mesh& mesh, const Mosaic_layout& layout,
                                Field_input_arguments& field) {
  const Tile_scale_crease_options co;
  const Tile_scale_creases c = tile_scale_creases(mesh, layout.spacing, co);
  const std::string with_creases = "boundary,crease:" + number(co.angle_degrees);
  if (c.features)
    field.features = with_creases;
  if (c.lines > 0)
    std::cout << "creases: " << c.lines << " lines sharper than " << number(co.angle_degrees)
              << "°, " << number(c.length, 1, true) << " tile spacings long, "
              << number(100 * c.long_share, 0, true) << "% in lines of " << number(co.long_line)
              << " spacings or more: "
              << (c.features ? "edges of the shape, taken as feature lines with the open borders "
                               "(--features boundary leaves them out)"
                             : "folds of the triangulation, not feature lines (--features " +
                                   with_creases + " takes them)")
              << "\n";
  return c;
}

int run_mosaic(const Mosaic_arguments& a) {
  const auto start = Clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  const Surface_mosaic_stats* running = nullptr;
  Surface_mosaic_options options = mosaic_options(a);
  options.progress = mosaic_progress(running, elapsed);
  Mesh_changes changes;
  Mesh mesh = read_input_mesh(a.mesh, a.input, &changes);
  const Tile_color_source colors = color_source(a);
  Model_colors model_colors = read_model_colors(a, colors, mesh);
  // The layout on the area as read: the refinement splits faces in their planes.
  const Mosaic_layout layout = tiles_layout(options, mesh);
  Field_input_arguments field_arguments = a.field;
  std::optional<Tile_scale_creases> creases;
  if (field_arguments.features.empty())
    creases = read_creases(mesh, layout, field_arguments);
  Field_input in = read_field_input(a.mesh, mesh, field_arguments);
  const Output_directory dir(a.out, a.force, mosaic_inputs(a));
  auto size = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  const bool sized = read_tile_size_field(a, mesh, size);
  const Coarse_mesh_refinement<Mesh> refinement =
      refine_for_tiles(layout, mesh, in, sized, size, model_colors);

  const Field_map field =
      mesh.add_property_map<Mesh::Vertex_index, Vector_3>("v:tessera_field").first;
  const Point_map points =
      mesh.add_property_map<Mesh::Vertex_index, Point_3>("v:tessera_tile_scale").first;
  Tile_scale_options scale;
  scale.time = a.tile_scale_smoothing;
  const Tile_scale_result smoothing =
      tile_scale_points(mesh, layout.spacing, in.lines, points, scale);
  if (smoothing.smoothed)
    std::cout << "surface smoothed at the tiles' scale for the field"
              << (a.smooth_planes ? " and the tiles' planes" : "") << ": vertices moved by "
              << number(smoothing.mean_move, 3) << " spacings on average, "
              << number(smoothing.largest_move, 3) << " at most (" << smoothing.iterations
              << " conjugate-gradient iterations)\n";
  else if (a.tile_scale_smoothing > 0)
    std::cout << "surface " << smoothing.message << "\n";
  std::optional<Thin_part_result<Mesh>> thin;
  const Smoothest_field_result fr = mosaic_field(a, options, layout, mesh, in, field, points, thin);
  const double seconds_field = elapsed();

  Laid_mosaic laid = lay_tiles(a, mesh, field, in, options, points, sized, size, running);
  std::vector<Tile>& tiles = laid.tiles;
  color_tiles(model_colors, colors, mesh, tiles);
  const double grout_width = grid_grout_width(laid.layout);
  Cut_tiles_result cut;
  if (a.cut_tiles && !(cut = cut_tiles(tiles, grout_width)))
    throw User_error(cut.message);
  Mosaic_quality_options qo;
  qo.symmetry = options.symmetry;
  const Mosaic_quality q = mosaic_quality(mesh, tiles, field, in.lines, qo);

  Mosaic_report report =
      make_mosaic_report(a.mesh, changes, fr, options.symmetry, in.lines.size(), in.color_regions,
                         laid.layout, laid.stats, q, seconds_field);
  report.options = {a.energy, a.start, a.count, a.colors, a.seed, a.teleport, a.iterations};
  if (creases)
    report.field.creases = Mosaic_report_creases{creases->lines, creases->length,
                                                 creases->long_share, creases->features};
  if (thin)
    report.field.thin_parts = Mosaic_report_thin_parts{
        thin->guided_vertices, thin->curved_band_vertices, thin->guided_area_fraction,
        thin->fewest_tiles_around, thin->median_guided_tiles_around};
  if (refinement.refined)
    report.field.refined_mesh =
        Mosaic_report_refinement{refinement.vertices_before, refinement.vertices_added,
                                 refinement.longest_edge_before, refinement.max_edge_length};
  if (a.cut_tiles)
    report.cut_tiles = Mosaic_report_cut{grout_width, cut};
  const std::vector<std::string> written =
      write_mosaic_outputs(dir, a.mesh, mesh, tiles, refinement, report, q);
  print_mosaic(laid, q);
  print_mosaic_options(a, tiles, thin, cut);
  print_written(with_view(written, dir, a.view, a.mesh));
  return exit_ok;
}

void register_mosaic_commands(CLI::App& app, std::function<int()>& run) {
  auto a = std::make_shared<Mosaic_arguments>();
  auto* cmd = app.add_subcommand(
      "mosaic", "Surface mosaic: equal tiles laid along the smoothest field (Lai et al. 2006)");
  add_mesh_input(cmd, a->mesh, a->input);
  cmd->add_option("--tile-size", a->tile_size,
                  "Tile sides LX[,LY] (square tiles when LY is left out)")
      ->delimiter(',')
      ->expected(1, 2);
  auto* tiles = cmd->add_option("--tiles", a->tiles, "Number of tiles (instead of --tile-size)");
  auto* aspect = cmd->add_option("--aspect", a->aspect, "Tile aspect LX / LY with --tiles")
                     ->capture_default_str();
  cmd->add_option("--grout", a->grout, "Fraction of the surface left to grout, in [0, 1)")
      ->capture_default_str();
  add_field_input(cmd, a->field);
  cmd->add_option("--colors", a->colors,
                  "region (one colour per region between feature lines), mesh (the mesh file's "
                  "face or vertex colours) or texture (an OBJ's texture image through its texture "
                  "coordinates); a tile takes the mean colour of its footprint")
      ->capture_default_str();
  cmd->add_option("--texture", a->texture,
                  "Texture image for --colors texture (default: the map_Kd of the OBJ's MTL)");
  cmd->add_option("--iterations", a->iterations, "Most iterations of the optimization")
      ->capture_default_str();
  cmd->add_flag("--teleport", a->teleport,
                "Every 10 iterations from the 30th, move tiles from crowded places into holes");
  cmd->add_option("--tile-scale-smoothing", a->tile_scale_smoothing,
                  "Solve the field on the surface smoothed at the tiles' scale: time of one step "
                  "of mean curvature flow, in tile spacings squared (0: on the mesh as read)")
      ->capture_default_str();
  cmd->add_flag("--smooth-planes", a->smooth_planes,
                "Lay the tiles on that smoothed surface too, each in the plane of its footprint "
                "(less drift and overlap on bumpy meshes, wider bare patches at tips)");
  cmd->add_flag("--thin-parts,!--no-thin-parts", a->thin_parts,
                "Turn the field along parts fewer than 10 tiles around (legs, horns, tails: the "
                "loop cut across the part), so "
                "that tiles lie along and around them, and keep it elsewhere (the default; "
                "--no-thin-parts leaves the smoothest field as it is)");
  cmd->add_flag("--cut-tiles", a->cut_tiles, "Cut overlapping tiles apart, keeping the grout");
  cmd->add_option("--energy", a->energy, "soft-box, or gaussian-manhattan (Lai et al.'s eq. 2)")
      ->capture_default_str();
  cmd->add_option("--start", a->start,
                  "automatic (position-field, or lattice with --tile-size-field), lattice (rows "
                  "grown along the field from a seed), position-field (a tile at each point of a "
                  "field-aligned lattice solved over the surface) or error-diffusion (Lai et "
                  "al.'s random start)")
      ->capture_default_str();
  cmd->add_option("--count", a->count,
                  "about (the lattice decides: holes a tile wide get one, crowded tiles are left "
                  "out; at most 8 % over N), exact (N tiles, crowded where rows do not fit) or "
                  "at-most (as about, never more than N)")
      ->capture_default_str();
  cmd->add_option("--tile-size-field", a->tile_size_field,
                  "Tile size varying over the surface, relative to --tiles/--tile-size: a text "
                  "file of one positive number per vertex, or the name of a vertex property of "
                  "the PLY input (a smooth field lays better with --start error-diffusion)");
  cmd->add_option("--seed", a->seed, "Seed of the initial layout")->capture_default_str();
  cmd->add_option("--out", a->out, "Output directory")->required();
  cmd->add_flag("--force", a->force, "Write into a non-empty directory Tessera did not create");
  add_view_flag(cmd, a->view);
  cmd->callback([&run, a, tiles, aspect] {
    run = [a, tiles, aspect] {
      a->tiles_given = tiles->count() > 0;
      a->aspect_given = aspect->count() > 0;
      return run_mosaic(*a);
    };
  });
}

} // namespace tessera::cli
