// tessera::write_view_html (see tessera/view/write_view_html.h).
#include <tessera/view/write_view_html.h>

#include "view_assets.h"

#include <nlohmann/json.hpp>

#include <cerrno>
#include <cstring>
#include <fstream>

namespace tessera {
namespace {

using nlohmann::json;

std::string base64(const void* data, std::size_t size) {
  static const char table[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const auto* in = static_cast<const unsigned char*>(data);
  std::string out;
  out.reserve((size + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < size; i += 3) {
    const unsigned n = (in[i] << 16) | (in[i + 1] << 8) | in[i + 2];
    out += {table[n >> 18], table[(n >> 12) & 63], table[(n >> 6) & 63], table[n & 63]};
  }
  if (i + 1 == size) {
    const unsigned n = in[i] << 16;
    out += {table[n >> 18], table[(n >> 12) & 63], '=', '='};
  } else if (i + 2 == size) {
    const unsigned n = (in[i] << 16) | (in[i + 1] << 8);
    out += {table[n >> 18], table[(n >> 12) & 63], table[(n >> 6) & 63], '='};
  }
  return out;
}

template <typename T> std::string base64(const std::vector<T>& v) {
  return base64(v.data(), v.size() * sizeof(T));
}

std::string escape_html(const std::string& text) {
  std::string out;
  for (const char c : text)
    switch (c) {
    case '<':
      out += "&lt;";
      break;
    case '>':
      out += "&gt;";
      break;
    case '&':
      out += "&amp;";
      break;
    case '"':
      out += "&quot;";
      break;
    default:
      out += c;
    }
  return out;
}

/// JSON that may stand inside a <script> element.
std::string script_safe(std::string text) {
  for (std::size_t at = 0; (at = text.find("</", at)) != std::string::npos; at += 3)
    text.replace(at, 2, "<\\/");
  return text;
}

json scene_json(const View_scene& scene) {
  json meshes = json::array(), segments = json::array(), points = json::array();
  for (const View_mesh_layer& m : scene.meshes) {
    json layer = {{"name", m.name},
                  {"positions", base64(m.positions)},
                  {"triangles", base64(m.triangles)},
                  {"colour", m.colour},
                  {"element_kind", m.element_kind},
                  {"lit", m.lit},
                  {"pickable", m.pickable},
                  {"hover_vertex", m.hover_vertex},
                  {"visible", m.visible}};
    if (!m.triangle_colours.empty())
      layer["triangle_colours"] = base64(m.triangle_colours);
    if (!m.vertex_colours.empty())
      layer["vertex_colours"] = base64(m.vertex_colours);
    if (!m.element_ids.empty())
      layer["element_ids"] = base64(m.element_ids);
    if (!m.element_figures.empty())
      layer["element_figures"] = m.element_figures;
    if (!m.texture.pixels.empty())
      layer["texture"] = {{"width", m.texture.width},
                          {"height", m.texture.height},
                          {"pixels", base64(m.texture.pixels)},
                          {"coordinates", base64(m.texture_coordinates)}};
    meshes.push_back(std::move(layer));
  }
  for (const View_segment_layer& s : scene.segments)
    segments.push_back({{"name", s.name},
                        {"segments", base64(s.segments)},
                        {"colour", s.colour},
                        {"visible", s.visible}});
  for (const View_point_layer& p : scene.points)
    points.push_back({{"name", p.name},
                      {"positions", base64(p.positions)},
                      {"labels", p.labels},
                      {"colour", p.colour},
                      {"visible", p.visible}});
  return {{"title", scene.title},     {"kind", scene.kind}, {"version", tessera_version()},
          {"sources", scene.sources}, {"meshes", meshes},   {"segments", segments},
          {"points", points},         {"flat", scene.flat}};
}

std::string data_url(const char* script) {
  return "data:text/javascript;base64," + base64(script, std::strlen(script));
}

// Errors are collected before any module runs, so that a failed import shows up too.
const char* const error_trap = R"(window.tesseraErrors = [];
window.addEventListener('error', (e) => window.tesseraErrors.push(String(e.message || e)));
window.addEventListener('unhandledrejection', (e) => window.tesseraErrors.push(String(e.reason)));
const tesseraConsoleError = console.error.bind(console);
console.error = (...args) => { window.tesseraErrors.push(args.join(' ')); tesseraConsoleError(...args); };
)";

const char* const style = R"(body { margin: 0; overflow: hidden; font: 13px sans-serif; }
#panel { position: absolute; top: 8px; left: 8px; background: #fffc; padding: 6px 10px; max-width: 40%; }
#panel label { display: block; }
#sources { color: #555; font-size: 11px; }
#hover { position: absolute; bottom: 8px; left: 8px; background: #fffc; padding: 2px 6px; }
#tessera-summary { display: none; }
.tag { position: absolute; left: 0; top: 0; font-size: 11px; color: #222; pointer-events: none; }
)";

} // namespace

std::string tessera_version() {
  return TESSERA_VERSION;
}

std::string view_html(const View_scene& scene) {
  const json imports = {
      {"imports",
       {{"three", data_url(view_assets::three_module)},
        {"three/addons/controls/OrbitControls.js", data_url(view_assets::orbit_controls)}}}};
  std::string sources;
  for (const std::string& s : scene.sources)
    sources += (sources.empty() ? "" : ", ") + escape_html(s);
  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>";
  html += escape_html(scene.title) + "</title>\n<style>\n" + style + "</style>\n<script>\n" +
          error_trap + "</script>\n<script type=\"importmap\">\n" + imports.dump() +
          "\n</script>\n</head>\n<body>\n<div id=\"panel\"><b>" + escape_html(scene.title) +
          "</b><div id=\"sources\">from " + sources + "<br>Tessera " + tessera_version() +
          ", three.js " + view_assets::three_version +
          " (MIT licence)</div><div id=\"layers\"></div></div>\n<div id=\"hover\"></div>\n"
          "<pre id=\"tessera-summary\"></pre>\n<script type=\"application/json\" "
          "id=\"tessera-data\">" +
          script_safe(scene_json(scene).dump()) + "</script>\n<script type=\"module\">\n" +
          view_assets::page_script + "</script>\n</body>\n</html>\n";
  return html;
}

View_result write_view_html(const View_scene& scene, const std::string& path) {
  const std::string html = view_html(scene);
  std::ofstream out(path, std::ios::binary);
  errno = 0;
  if (out)
    out.write(html.data(), static_cast<std::streamsize>(html.size()));
  out.close();
  if (!out)
    return {View_status::cannot_write,
            "cannot write " + path + (errno ? std::string(": ") + std::strerror(errno) : "")};
  return {};
}

} // namespace tessera
