// What the JSON readers of tessera/io share (internal to Tessera::core, not installed): the error a
// field of the wrong type or value raises, checked numbers and triples, and the parse-then-read
// wrapper that turns every failure into a status and a message.
#pragma once

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <istream>
#include <stdexcept>
#include <string>

namespace tessera::io_internal {

/// A field that is not what the format says: caught once, in `parse_and_read`.
struct Bad_field : std::runtime_error {
  using std::runtime_error::runtime_error;
};

inline std::array<double, 3> read_triple(const nlohmann::json& j, const std::string& what) {
  if (!j.is_array() || j.size() != 3)
    throw Bad_field(what + " must be an array of three numbers");
  std::array<double, 3> p{};
  for (std::size_t c = 0; c < 3; ++c) {
    if (!j[c].is_number() || !std::isfinite(j[c].get<double>()))
      throw Bad_field(what + " must be an array of three finite numbers");
    p[c] = j[c].get<double>();
  }
  return p;
}

inline double read_number(const nlohmann::json& j, const std::string& what) {
  if (!j.is_number() || !std::isfinite(j.get<double>()))
    throw Bad_field(what + " must be a finite number");
  return j.get<double>();
}

/// Parses `in` as JSON and reads the document with `read` (which throws `Bad_field`). A parse
/// error gives a result with status `not_json` and "`prefix` (the parser's message)"; a bad field,
/// or a type `read` did not foresee, status `bad_field` and the field's message.
template <typename Result, typename Status, typename Read>
Result parse_and_read(std::istream& in, Status not_json, Status bad_field,
                      const std::string& prefix, Read&& read) {
  Result failed;
  nlohmann::json doc;
  try {
    in >> doc;
  } catch (const nlohmann::json::exception& e) {
    failed.status = not_json;
    failed.message = prefix + " (" + std::string(e.what()) + ")";
    return failed;
  }
  try {
    return read(doc);
  } catch (const Bad_field& e) {
    failed.message = e.what();
  } catch (const nlohmann::json::exception& e) {
    failed.message = e.what();
  }
  failed.status = bad_field;
  return failed;
}

} // namespace tessera::io_internal
