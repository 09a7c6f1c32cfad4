// Pictures of view pages (docs/view.md: `view --png`): headless Chromium (Debian's chromium)
// opens the page, draws it with WebGL through SwiftShader (no GPU needed) and writes a PNG:
//   chromium --headless --no-sandbox --disable-gpu --enable-unsafe-swiftshader
//            --use-angle=swiftshader --disable-background-networking --disable-component-update
//            --disable-sync --no-first-run --user-data-dir=<new empty folder>
//            --screenshot=FILE --window-size=W,H file:///PAGE#FRAGMENT
// The page draws once while it loads (view/viewer.js), before Chromium takes the screenshot.
// Chromium runs in its own process group, with a deadline; the group is killed when it ends or
// times out, and its scratch folder (profile, log, picture) is removed.
#pragma once

#include <string>

namespace implicitfit {

struct ScreenshotOptions {
  int width = 1000, height = 750;  // pixels
  std::string fragment;            // the URL fragment without '#' (docs/view.md keys)
  double timeout_seconds = 120.0;
};

// $IMPLICITFIT_CHROMIUM when set, else the first of chromium, chromium-browser, google-chrome,
// google-chrome-stable found on PATH; "" when none is there.
std::string FindChromium();

// FindChromium, or InputError saying that Chromium is missing and where it was looked for.
std::string RequireChromium();

// Writes the picture of the page at page_path to png_path (atomically). Throws
// std::runtime_error, with the end of Chromium's log, when it fails, times out or writes no PNG.
void ScreenshotPage(const std::string& chromium, const std::string& page_path,
                    const std::string& png_path, const ScreenshotOptions& options);

// The same for a page given as its HTML (written to the scratch folder first).
void ScreenshotHtml(const std::string& chromium, const std::string& html,
                    const std::string& png_path, const ScreenshotOptions& options);

}  // namespace implicitfit
