// Writes a View_scene as one self-contained HTML page: three.js (MIT licence, embedded in the
// library at build time from web/node_modules) inlined as an import map of data: URLs, the
// geometry as base64 binary buffers, orbit controls, a checkbox per layer and hover ids. The page
// opens offline from file:// and exposes `window.tesseraSummary` (also as JSON in
// `<pre id="tessera-summary">`) with per-layer drawn counts and any script errors.
#pragma once

#include <tessera/view/view_scene.h>

#include <string>

namespace tessera {

enum class View_status {
  ok,
  /// The result directory (or report file) does not exist.
  not_found,
  /// The directory holds no files of a command Tessera knows.
  unknown_result_kind,
  /// A file of the result could not be read (the message names it).
  bad_file,
  /// The page could not be written.
  cannot_write
};

/// Status of reading a scene or writing a page.
struct View_result {
  View_status status = View_status::ok;
  /// One line naming the file at fault; empty when ok.
  std::string message;
  explicit operator bool() const { return status == View_status::ok; }
};

/// The Tessera version written into pages ("0.1.0").
std::string tessera_version();

/// The page for `scene` as a string.
std::string view_html(const View_scene& scene);

/// Writes `view_html(scene)` to `path` (overwriting it: the caller decides whether it may).
View_result write_view_html(const View_scene& scene, const std::string& path);

} // namespace tessera
