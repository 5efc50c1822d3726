// The HTML report's embedded scripts and style: three.js and its orbit controls (from npm, read
// into the binary at build time) and the viewer's own code (viewer.js, viewer.css).
#pragma once

#include <string_view>

namespace envcrust::cli::html {

/// Whether three.js was found when envcrust was built (scripts/setup.sh installs it with npm
/// into third_party/node_modules); without it the assets below are empty.
bool has_three_js();

/// three/build/three.module.min.js: an ES module with no imports.
std::string_view three_module_js();

/// three/examples/jsm/controls/OrbitControls.js: an ES module importing from 'three'.
std::string_view orbit_controls_js();

/// viewer.js: the page's module script (reads the data blocks, builds the scene).
std::string_view viewer_js();

/// viewer.css: the page's style.
std::string_view viewer_css();

}  // namespace envcrust::cli::html
