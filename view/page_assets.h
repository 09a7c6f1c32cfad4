// The assets of a view page, embedded at build time (view/embed_assets.cmake): the HTML
// template view/page.html with its markers, the viewer view/viewer.js, and three.js r111 with its
// OrbitControls from Debian's libjs-three (MIT licence), inlined into every page so that it
// opens without network access. ThreeJs() and OrbitControlsJs() are empty in a build without
// libjs-three (PageHtml then refuses).
#pragma once

#include <string_view>

namespace implicitfit {

std::string_view PageTemplate();
std::string_view ViewerScript();
std::string_view ThreeJs();
std::string_view OrbitControlsJs();

}  // namespace implicitfit
