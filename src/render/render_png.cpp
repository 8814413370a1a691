// Offscreen rendering of a Render_scene with cairo: orthographic projection, painter's order over
// triangles, polyline segments and points together, so cuts behind the surface stay hidden;
// supersampled 2x (see render_png).
#include <tessera/render/scene.h>

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace tessera {
namespace {

using Vec = std::array<double, 3>;

Vec sub(const Vec& a, const Vec& b) {
  return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}};
}
double dot(const Vec& a, const Vec& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec cross(const Vec& a, const Vec& b) {
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}
Vec normalized(const Vec& a) {
  const double n = std::sqrt(dot(a, a));
  return n > 0 ? Vec{{a[0] / n, a[1] / n, a[2] / n}} : a;
}
bool finite(const Vec& a) {
  return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]);
}

struct Primitive {
  enum Kind { triangle, segment, point } kind;
  std::size_t index; // triangle index, polyline index, or point index
  std::size_t sub;   // segment index within its polyline
  double depth;      // larger is farther from the eye
};

} // namespace

Color distinct_color(std::size_t i) {
  const double golden = 0.618033988749895;
  const double h = std::fmod(0.11 + golden * double(i), 1.0) * 6.0;
  const double s = (i % 3 == 2) ? 0.45 : 0.65, v = (i % 2 == 1) ? 0.8 : 0.95;
  const int sector = int(h) % 6;
  const double f = h - std::floor(h), p = v * (1 - s), q = v * (1 - s * f),
               t = v * (1 - s * (1 - f));
  switch (sector) {
  case 0:
    return {v, t, p};
  case 1:
    return {q, v, p};
  case 2:
    return {p, v, t};
  case 3:
    return {p, q, v};
  case 4:
    return {t, p, v};
  default:
    return {v, p, q};
  }
}

Render_result render_png(const Render_scene& scene, const std::string& path,
                         const Render_options& options) {
  Render_result result;
  if (scene.triangles.empty() && scene.polylines.empty() && scene.points.empty()) {
    result.status = Render_status::empty_scene;
    result.message = "nothing to draw";
    return result;
  }
  for (const auto& t : scene.triangles)
    for (std::size_t v : t)
      if (v >= scene.positions.size()) {
        result.status = Render_status::invalid_scene;
        result.message = "a triangle refers to a position that does not exist";
        return result;
      }
  if (!scene.triangle_depth_bias.empty() &&
      scene.triangle_depth_bias.size() != scene.triangles.size()) {
    result.status = Render_status::invalid_scene;
    result.message = "triangle_depth_bias must be empty or hold one distance per triangle";
    return result;
  }
  if (!scene.triangle_colors.empty() && scene.triangle_colors.size() != scene.triangles.size()) {
    result.status = Render_status::invalid_scene;
    result.message = "triangle_colors must be empty or hold one colour per triangle";
    return result;
  }

  // Camera frame: w towards the eye, u to the right, v up on screen.
  const Vec w = normalized(options.eye_direction);
  Vec up = options.up;
  if (std::abs(dot(normalized(up), w)) > 0.99)
    up = {{0, 1, 0}};
  if (std::abs(dot(normalized(up), w)) > 0.99)
    up = {{1, 0, 0}};
  const Vec u = normalized(cross(up, w));
  const Vec v = cross(w, u);

  double umin = std::numeric_limits<double>::max(), umax = -umin, vmin = umin, vmax = -umin;
  auto extend = [&](const Vec& p) {
    if (!finite(p))
      return;
    umin = std::min(umin, dot(p, u));
    umax = std::max(umax, dot(p, u));
    vmin = std::min(vmin, dot(p, v));
    vmax = std::max(vmax, dot(p, v));
  };
  for (const auto& t : scene.triangles)
    for (std::size_t k : t)
      extend(scene.positions[k]);
  for (const auto& l : scene.polylines)
    for (const auto& p : l.points)
      extend(p);
  for (const auto& p : scene.points)
    extend(p.position);
  if (umin > umax) {
    result.status = Render_status::invalid_scene;
    result.message = "no finite coordinates to draw";
    return result;
  }
  const double margin = 0.06;
  const double su = std::max(umax - umin, 1e-12), sv = std::max(vmax - vmin, 1e-12);
  const double scale =
      std::min(options.width * (1 - 2 * margin) / su, options.height * (1 - 2 * margin) / sv);
  const double cu = (umin + umax) / 2, cv = (vmin + vmax) / 2;
  auto screen = [&](const Vec& p, double& x, double& y) {
    x = options.width / 2.0 + (dot(p, u) - cu) * scale;
    y = options.height / 2.0 - (dot(p, v) - cv) * scale;
  };
  // Lines and points sit on the surface: pull them slightly towards the eye so the faces they lie
  // on do not hide them, while faces genuinely in front still do.
  const double bias = 2.0 / scale;

  std::vector<Primitive> prims;
  prims.reserve(scene.triangles.size() + scene.points.size());
  for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
    const auto& t = scene.triangles[i];
    const double d = -(dot(scene.positions[t[0]], w) + dot(scene.positions[t[1]], w) +
                       dot(scene.positions[t[2]], w)) /
                     3;
    prims.push_back({Primitive::triangle, i, 0,
                     d - (scene.triangle_depth_bias.empty() ? 0.0 : scene.triangle_depth_bias[i])});
  }
  for (std::size_t i = 0; i < scene.polylines.size(); ++i)
    for (std::size_t s = 0; s + 1 < scene.polylines[i].points.size(); ++s) {
      const double d =
          -(dot(scene.polylines[i].points[s], w) + dot(scene.polylines[i].points[s + 1], w)) / 2;
      prims.push_back({Primitive::segment, i, s, d - bias});
    }
  for (std::size_t i = 0; i < scene.points.size(); ++i)
    prims.push_back({Primitive::point, i, 0, -dot(scene.points[i].position, w) - 2 * bias});
  std::sort(prims.begin(), prims.end(),
            [](const Primitive& a, const Primitive& b) { return a.depth > b.depth; });

  // Triangles are filled without antialiasing on a surface of twice the size, which is then
  // averaged down: cairo's antialiased fill of each small triangle, and the stroke in its own
  // colour that closed the hairline gaps antialiasing leaves between faces, cost 1.6-3x as much for
  // the same picture (a 53k-face quadrangulation with its tile borders: 0.50 -> 0.30 s; the
  // 77k-face surface of the Foundation benchmark: 0.29 -> 0.10 s). Pictures of more than
  // `supersampled_pixels` are drawn at their size (their pixels are small already).
  constexpr long supersampled_pixels = 4L << 20;
  const int factor = long(options.width) * options.height <= supersampled_pixels ? 2 : 1;
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, factor * options.width,
                                                        factor * options.height);
  cairo_surface_set_device_scale(surface, factor, factor);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, options.background.r, options.background.g, options.background.b);
  cairo_paint(cr);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);

  const bool draw_edges =
      options.edges == Edge_drawing::always ||
      (options.edges == Edge_drawing::automatic && scene.triangles.size() < 6000);
  const Vec light = normalized({{w[0] + 0.3 * u[0] + 0.4 * v[0], w[1] + 0.3 * u[1] + 0.4 * v[1],
                                 w[2] + 0.3 * u[2] + 0.4 * v[2]}});
  for (const Primitive& p : prims) {
    double x, y;
    if (p.kind == Primitive::triangle) {
      const auto& t = scene.triangles[p.index];
      const Vec &a = scene.positions[t[0]], &b = scene.positions[t[1]], &c = scene.positions[t[2]];
      if (!finite(a) || !finite(b) || !finite(c))
        continue;
      const Vec n = normalized(cross(sub(b, a), sub(c, a)));
      const double shade = 0.35 + 0.65 * std::abs(dot(n, light));
      const Color base =
          scene.triangle_colors.empty() ? Color{0.78, 0.8, 0.85} : scene.triangle_colors[p.index];
      screen(a, x, y);
      cairo_move_to(cr, x, y);
      screen(b, x, y);
      cairo_line_to(cr, x, y);
      screen(c, x, y);
      cairo_line_to(cr, x, y);
      cairo_close_path(cr);
      cairo_set_source_rgb(cr, base.r * shade, base.g * shade, base.b * shade);
      // Aliased fills of neighbouring faces meet without gaps.
      cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
      if (!draw_edges) {
        cairo_fill(cr);
        cairo_set_antialias(cr, CAIRO_ANTIALIAS_DEFAULT);
        continue;
      }
      cairo_fill_preserve(cr);
      cairo_set_antialias(cr, CAIRO_ANTIALIAS_DEFAULT);
      cairo_set_source_rgb(cr, base.r * shade * 0.55, base.g * shade * 0.55, base.b * shade * 0.55);
      cairo_set_line_width(cr, 0.6);
      cairo_stroke(cr);
    } else if (p.kind == Primitive::segment) {
      const Render_polyline& l = scene.polylines[p.index];
      const Vec &a = l.points[p.sub], &b = l.points[p.sub + 1];
      if (!finite(a) || !finite(b))
        continue;
      screen(a, x, y);
      cairo_move_to(cr, x, y);
      screen(b, x, y);
      cairo_line_to(cr, x, y);
      cairo_set_source_rgb(cr, l.color.r, l.color.g, l.color.b);
      cairo_set_line_width(cr, l.width);
      cairo_stroke(cr);
    } else {
      const Render_point& pt = scene.points[p.index];
      if (!finite(pt.position))
        continue;
      screen(pt.position, x, y);
      cairo_arc(cr, x, y, pt.radius, 0, 2 * 3.14159265358979);
      cairo_set_source_rgb(cr, pt.color.r, pt.color.g, pt.color.b);
      cairo_fill_preserve(cr);
      cairo_set_source_rgb(cr, 0, 0, 0);
      cairo_set_line_width(cr, 1);
      cairo_stroke(cr);
    }
  }
  if (!options.title.empty()) {
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, 20);
    // A title wider than the picture is set smaller (down to 10 points) rather than cut off.
    cairo_text_extents_t extents;
    cairo_text_extents(cr, options.title.c_str(), &extents);
    const double room = double(options.width) - 32;
    if (extents.x_advance > room && extents.x_advance > 0)
      cairo_set_font_size(cr, std::max(10.0, 20 * room / extents.x_advance));
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    cairo_move_to(cr, 16, 30);
    cairo_show_text(cr, options.title.c_str());
  }
  cairo_destroy(cr);
  if (factor > 1) { // each pixel the mean of its factor x factor samples
    cairo_surface_t* picture =
        cairo_image_surface_create(CAIRO_FORMAT_ARGB32, options.width, options.height);
    cairo_t* down = cairo_create(picture);
    cairo_scale(down, 1.0 / factor, 1.0 / factor);
    cairo_surface_set_device_scale(surface, 1, 1);
    cairo_set_source_surface(down, surface, 0, 0);
    cairo_pattern_set_filter(cairo_get_source(down), CAIRO_FILTER_GOOD);
    cairo_paint(down);
    cairo_destroy(down);
    cairo_surface_destroy(surface);
    surface = picture;
  }
  const cairo_status_t st = cairo_surface_write_to_png(surface, path.c_str());
  cairo_surface_destroy(surface);
  if (st != CAIRO_STATUS_SUCCESS) {
    result.status = Render_status::write_failed;
    result.message = path + ": cannot write PNG (" + cairo_status_to_string(st) + ")";
  }
  return result;
}

} // namespace tessera
