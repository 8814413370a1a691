// The short text specifications of feature lines and of how a field meets them, as the command line
// takes them (`--features boundary,crease:40,color`, `--align parallel,3=perpendicular`), parsed
// into `Feature_line_options` and one `Feature_alignment` per line.
#pragma once

#include <tessera/fields/feature_lines.h>
#include <tessera/fields/internal/spec_tokens.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

namespace tessera {

enum class Spec_status {
  ok,
  invalid ///< `message` names the bad entry
};

struct Feature_spec_result {
  Spec_status status = Spec_status::ok;
  std::string message;
  Feature_line_options options;
  explicit operator bool() const { return status == Spec_status::ok; }
};

struct Alignment_spec_result {
  Spec_status status = Spec_status::ok;
  std::string message;
  /// One alignment per feature line.
  std::vector<Feature_alignment> alignment;
  explicit operator bool() const { return status == Spec_status::ok; }
};

/// "boundary", "crease" or "crease:ANGLE" (degrees, in (0, 180)), "color", comma-separated: the
/// feature lines to find. Features not named are off.
inline Feature_spec_result parse_feature_spec(const std::string& spec) {
  Feature_spec_result r;
  r.options.boundary = false;
  r.options.color_boundaries = false;
  auto fail = [&](std::string message) {
    r.status = Spec_status::invalid;
    r.message = std::move(message);
    return r;
  };
  for (const std::string& f : internal::split_spec(spec, ',')) {
    if (f == "boundary") {
      r.options.boundary = true;
    } else if (f == "color") {
      r.options.color_boundaries = true;
    } else if (f.rfind("crease", 0) == 0) {
      r.options.creases = true;
      if (f.size() > 6) {
        if (f[6] != ':')
          return fail("write crease:ANGLE (degrees)");
        const std::string angle = f.substr(7);
        std::istringstream in(angle);
        double degrees = 0;
        if (angle.empty() || !(in >> degrees) || !in.eof())
          return fail("'" + angle.substr(0, 40) + "' is not an angle in degrees");
        if (!(degrees > 0 && degrees < 180))
          return fail("the crease angle must be between 0 and 180 degrees");
        r.options.crease_angle_degrees = degrees;
      }
    } else {
      return fail("unknown feature '" + f.substr(0, 40) + "' (boundary, crease:ANGLE, color)");
    }
  }
  return r;
}

/// "parallel", "perpendicular", or a default followed by LINE=ALIGNMENT entries
/// ("parallel,3=perpendicular"), for `lines` feature lines (all parallel unless said otherwise).
inline Alignment_spec_result parse_alignment_spec(const std::string& spec, std::size_t lines) {
  Alignment_spec_result r;
  r.alignment.assign(lines, Feature_alignment::parallel);
  auto fail = [&](std::string message) {
    r.status = Spec_status::invalid;
    r.message = std::move(message);
    r.alignment.clear();
    return r;
  };
  auto parse = [](const std::string& s, Feature_alignment& a) {
    if (s == "parallel")
      a = Feature_alignment::parallel;
    else if (s == "perpendicular")
      a = Feature_alignment::perpendicular;
    else
      return false;
    return true;
  };
  for (const std::string& entry : internal::split_spec(spec, ',')) {
    Feature_alignment a = Feature_alignment::parallel;
    const auto eq = entry.find('=');
    if (eq == std::string::npos) {
      if (!parse(entry, a))
        return fail("'" + entry.substr(0, 40) + "' is neither parallel nor perpendicular");
      std::fill(r.alignment.begin(), r.alignment.end(), a);
      continue;
    }
    std::size_t line = 0;
    if (!internal::spec_index(entry.substr(0, eq), line))
      return fail("'" + entry.substr(0, 40) + "' does not start with a line number");
    if (line >= lines)
      return fail("line " + std::to_string(line) + " does not exist (" + std::to_string(lines) +
                  " feature lines, see feature_lines.json)");
    if (!parse(entry.substr(eq + 1), a))
      return fail("'" + entry.substr(eq + 1, 40) + "' is neither parallel nor perpendicular");
    r.alignment[line] = a;
  }
  return r;
}

} // namespace tessera
