// tessera::read_control_vectors (see tessera/io/read_control_vectors.h).
#include <tessera/io/read_control_vectors.h>

#include "json_fields.h"

#include <fstream>

namespace tessera {
namespace {

using io_internal::Bad_field;
using io_internal::read_triple;

std::size_t read_index(const nlohmann::json& j, const std::string& what) {
  if (!j.is_number_integer() || j.get<long long>() < 0)
    throw Bad_field(what + " must be an index >= 0");
  return std::size_t(j.get<long long>());
}

Control_vectors_read_result read_json(const nlohmann::json& doc) {
  if (!doc.is_object() || !doc.contains("controls") || !doc["controls"].is_array())
    throw Bad_field("expected an object with a \"controls\" array");
  Control_vectors_read_result r;
  for (std::size_t k = 0; k < doc["controls"].size(); ++k) {
    const auto& c = doc["controls"][k];
    const std::string where = "control " + std::to_string(k);
    if (!c.is_object() || !c.contains("direction"))
      throw Bad_field(where + " needs a \"direction\"");
    Control_vector v;
    v.direction = read_triple(c["direction"], where + ": \"direction\"");
    if (c.contains("weight")) {
      if (!c["weight"].is_number() || !(c["weight"].get<double>() > 0) ||
          !std::isfinite(c["weight"].get<double>()))
        throw Bad_field(where + ": \"weight\" must be a positive number");
      v.weight = c["weight"].get<double>();
    }
    if (c.contains("vertex")) {
      v.index = read_index(c["vertex"], where + ": \"vertex\"");
    } else if (c.contains("face")) {
      v.location = Control_vector::Location::face;
      v.index = read_index(c["face"], where + ": \"face\"");
      if (c.contains("barycentric"))
        v.barycentric = read_triple(c["barycentric"], where + ": \"barycentric\"");
    } else {
      throw Bad_field(where + " needs a \"vertex\" or a \"face\"");
    }
    r.controls.push_back(v);
  }
  return r;
}

} // namespace

Control_vectors_read_result read_control_vectors(std::istream& in) {
  return io_internal::parse_and_read<Control_vectors_read_result>(
      in, Control_vectors_read_status::not_json, Control_vectors_read_status::bad_field,
      "malformed JSON", read_json);
}

Control_vectors_read_result read_control_vectors(const std::string& path) {
  std::ifstream in(path);
  if (!in) {
    Control_vectors_read_result failed;
    failed.status = Control_vectors_read_status::cannot_open;
    failed.message = "cannot open control file";
    return failed;
  }
  return read_control_vectors(in);
}

} // namespace tessera
