// Planar mosaic pictures with cairo (image surfaces for PNG, SVG surfaces for vector output).
#include <tessera/mosaic/draw_planar_mosaic.h>

#include <cairo-svg.h>
#include <cairo.h>

#include <cmath>
#include <memory>

namespace tessera {
namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

Render_result failed(Render_status status, std::string message) {
  Render_result r;
  r.status = status;
  r.message = std::move(message);
  return r;
}

using Surface = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;
using Context = std::unique_ptr<cairo_t, decltype(&cairo_destroy)>;

void tile_path(cairo_t* cr, const Planar_tile& t, Planar_tile_shape shape) {
  cairo_save(cr);
  cairo_translate(cr, t.x + 0.5, t.y + 0.5); // pixel centres are at integer coordinates
  cairo_rotate(cr, t.angle);
  if (shape == Planar_tile_shape::ellipse) {
    cairo_scale(cr, t.width / 2, t.height / 2);
    cairo_arc(cr, 0, 0, 1, 0, 2 * M_PI);
  } else {
    cairo_rectangle(cr, -t.width / 2, -t.height / 2, t.width, t.height);
  }
  cairo_restore(cr);
}

} // namespace

Render_result draw_planar_mosaic(const std::vector<Planar_tile>& tiles, int width, int height,
                                 const std::string& path, const Planar_drawing_options& options) {
  if (width <= 0 || height <= 0)
    return failed(Render_status::empty_scene, "nothing to draw");
  if (!(options.scale > 0) || width * options.scale > 32767 || height * options.scale > 32767)
    return failed(Render_status::invalid_scene, "the picture would be too large");
  const bool svg = ends_with(path, ".svg");
  if (!svg && !ends_with(path, ".png"))
    return failed(Render_status::write_failed, "the picture must end in .png or .svg: " + path);
  const double W = std::ceil(width * options.scale), H = std::ceil(height * options.scale);
  Surface surface(svg ? cairo_svg_surface_create(path.c_str(), W, H)
                      : cairo_image_surface_create(CAIRO_FORMAT_RGB24, int(W), int(H)),
                  cairo_surface_destroy);
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
    return failed(Render_status::write_failed, "cannot create " + path);
  Context cr(cairo_create(surface.get()), cairo_destroy);
  cairo_scale(cr.get(), options.scale, options.scale);
  cairo_set_source_rgb(cr.get(), options.grout.r, options.grout.g, options.grout.b);
  cairo_paint(cr.get());
  for (const Planar_tile& t : tiles) {
    tile_path(cr.get(), t, options.shape);
    cairo_set_source_rgb(cr.get(), t.color[0] / 255.0, t.color[1] / 255.0, t.color[2] / 255.0);
    cairo_fill(cr.get());
  }
  cr.reset();
  cairo_surface_flush(surface.get());
  const cairo_status_t st =
      svg ? (cairo_surface_finish(surface.get()), cairo_surface_status(surface.get()))
          : cairo_surface_write_to_png(surface.get(), path.c_str());
  if (st != CAIRO_STATUS_SUCCESS)
    return failed(Render_status::write_failed,
                  "cannot write " + path + ": " + cairo_status_to_string(st));
  return {};
}

Render_result draw_planar_field(const Rgb_image& image, const Planar_field& field,
                                const Gray_image& edge_mask, const std::string& path,
                                const Planar_drawing_options& options) {
  const double scale = options.scale, spacing = options.stroke_spacing;
  if (image.empty() || field.width != image.width || field.height != image.height)
    return failed(Render_status::invalid_scene, "the field and the image differ in size");
  if (!ends_with(path, ".png"))
    return failed(Render_status::write_failed, "the picture must end in .png: " + path);
  if (!(scale > 0) || image.width * scale > 32767 || image.height * scale > 32767)
    return failed(Render_status::invalid_scene, "the picture would be too large");
  const int w = image.width, h = image.height;
  Surface faded(cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h), cairo_surface_destroy);
  Surface surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, int(std::ceil(w * scale)),
                                             int(std::ceil(h * scale))),
                  cairo_surface_destroy);
  if (cairo_surface_status(faded.get()) != CAIRO_STATUS_SUCCESS ||
      cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
    return failed(Render_status::write_failed,
                  "cannot create a picture of " + std::to_string(w) + " x " + std::to_string(h));
  // The image at 40% over white, so the strokes stand out; edge pixels in red.
  unsigned char* data = cairo_image_surface_get_data(faded.get());
  const int stride = cairo_image_surface_get_stride(faded.get());
  const bool edges = edge_mask.width == w && edge_mask.height == h;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      auto* px = reinterpret_cast<std::uint32_t*>(data + std::ptrdiff_t(y) * stride) + x;
      const auto c = image.at(x, y);
      auto fade = [](std::uint8_t v) { return std::uint32_t(153 + v * 0.4); };
      *px = edges && edge_mask.at(x, y) ? 0xd01010u
                                        : (fade(c[0]) << 16) | (fade(c[1]) << 8) | fade(c[2]);
    }
  cairo_surface_mark_dirty(faded.get());
  Context cr(cairo_create(surface.get()), cairo_destroy);
  cairo_scale(cr.get(), scale, scale);
  cairo_set_source_surface(cr.get(), faded.get(), 0, 0);
  cairo_pattern_set_filter(cairo_get_source(cr.get()), CAIRO_FILTER_NEAREST);
  cairo_paint(cr.get());
  cairo_set_source_rgb(cr.get(), 0.05, 0.15, 0.45);
  cairo_set_line_width(cr.get(), std::max(1.0 / scale, spacing / 12));
  cairo_set_line_cap(cr.get(), CAIRO_LINE_CAP_ROUND);
  const double step = std::max(spacing, 4.0), half = 0.4 * step;
  const int strokes = options.shape == Planar_tile_shape::square ? 2 : 1;
  for (double y = step / 2; y < h; y += step)
    for (double x = step / 2; x < w; x += step) {
      const double a = field.angle_at(int(x), int(y));
      for (int k = 0; k < strokes; ++k) {
        const double b = a + k * M_PI / 2, len = k == 0 ? half : 0.6 * half;
        cairo_move_to(cr.get(), x + 0.5 - len * std::cos(b), y + 0.5 - len * std::sin(b));
        cairo_line_to(cr.get(), x + 0.5 + len * std::cos(b), y + 0.5 + len * std::sin(b));
      }
    }
  cairo_stroke(cr.get());
  cr.reset();
  const cairo_status_t st = cairo_surface_write_to_png(surface.get(), path.c_str());
  if (st != CAIRO_STATUS_SUCCESS)
    return failed(Render_status::write_failed,
                  "cannot write " + path + ": " + cairo_status_to_string(st));
  return {};
}

} // namespace tessera
