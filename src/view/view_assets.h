// The scripts a `tessera view` page inlines, embedded at configure time
// (cmake/EmbedViewAssets.cmake): three.js's module build and OrbitControls from web/node_modules
// (MIT licence), and the page's own script src/view/view_page.js.
#pragma once

namespace tessera::view_assets {

extern const char* const three_module;
extern const char* const orbit_controls;
extern const char* const page_script;
/// The three.js version of web/package-lock.json.
extern const char* const three_version;

} // namespace tessera::view_assets
