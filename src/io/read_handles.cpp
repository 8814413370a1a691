// tessera::read_deformation_handles (see tessera/io/read_handles.h).
#include <tessera/io/read_handles.h>

#include "json_fields.h"

#include <fstream>

namespace tessera {
namespace {

using io_internal::Bad_field;
using io_internal::read_number;
using io_internal::read_triple;

/// `j[key]` when `j` is an object holding it, else null (so a missing field reads as ill-typed).
const nlohmann::json& field(const nlohmann::json& j, const char* key) {
  static const nlohmann::json none;
  return j.is_object() && j.contains(key) ? j[key] : none;
}

Vertex_selection read_selection(const nlohmann::json& j, const std::string& what) {
  Vertex_selection s;
  if (j.contains("vertices")) {
    if (!j["vertices"].is_array())
      throw Bad_field(what + ": \"vertices\" must be an array of vertex indices");
    for (const auto& i : j["vertices"]) {
      if (!i.is_number_integer() || i.get<long long>() < 0)
        throw Bad_field(what + ": \"vertices\" must hold indices >= 0");
      s.indices.push_back(std::size_t(i.get<long long>()));
    }
  } else if (j.contains("sphere")) {
    s.kind = Vertex_selection::Kind::sphere;
    s.center = read_triple(field(j["sphere"], "center"), what + ": sphere center");
    s.radius = read_number(field(j["sphere"], "radius"), what + ": sphere radius");
  } else if (j.contains("box")) {
    s.kind = Vertex_selection::Kind::box;
    s.min = read_triple(field(j["box"], "min"), what + ": box min");
    s.max = read_triple(field(j["box"], "max"), what + ": box max");
  } else {
    throw Bad_field(what + " needs \"vertices\", \"sphere\" or \"box\"");
  }
  return s;
}

Handles_read_result read_json(const nlohmann::json& j) {
  Handles_read_result r;
  if (!j.is_object() || !j.contains("handles") || !j["handles"].is_array() || j["handles"].empty())
    throw Bad_field("expected an object with a non-empty \"handles\" array");
  if (j.contains("region")) {
    if (!j["region"].is_object())
      throw Bad_field("region must be an object");
    r.region = read_selection(j["region"], "region");
  }
  const double degrees = std::acos(-1.0) / 180;
  for (std::size_t i = 0; i < j["handles"].size(); ++i) {
    const auto& h = j["handles"][i];
    const std::string what = "handle " + std::to_string(i);
    if (!h.is_object())
      throw Bad_field(what + " must be an object");
    Deformation_handle handle;
    handle.vertices = read_selection(h, what);
    Handle_transform& t = handle.transform;
    if (h.contains("translate"))
      t.translation = read_triple(h["translate"], what + ": translate");
    if (h.contains("rotate")) {
      t.axis = read_triple(field(h["rotate"], "axis"), what + ": rotate axis");
      t.angle = degrees * read_number(field(h["rotate"], "degrees"), what + ": rotate degrees");
    }
    if (h.contains("twist")) {
      t.axis = read_triple(field(h["twist"], "axis"), what + ": twist axis");
      t.twist = degrees * read_number(field(h["twist"], "degrees_per_unit"),
                                      what + ": twist degrees_per_unit");
    }
    if (h.contains("scale")) {
      t.scale = read_number(h["scale"], what + ": scale");
      if (!(t.scale > 0))
        throw Bad_field(what + ": scale must be positive");
    }
    if (h.contains("center")) {
      t.center = read_triple(h["center"], what + ": center");
      t.has_center = true;
    }
    r.handles.push_back(handle);
  }
  return r;
}

} // namespace

Handles_read_result read_deformation_handles(std::istream& in) {
  return io_internal::parse_and_read<Handles_read_result>(in, Handles_read_status::not_json,
                                                          Handles_read_status::bad_field,
                                                          "not valid JSON", read_json);
}

Handles_read_result read_deformation_handles(const std::string& path) {
  std::ifstream in(path);
  if (!in) {
    Handles_read_result failed;
    failed.status = Handles_read_status::cannot_open;
    failed.message = "cannot open " + path;
    return failed;
  }
  return read_deformation_handles(in);
}

} // namespace tessera
