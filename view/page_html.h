// The HTML of a view page (docs/view.md): view/page.html with three.js, view/viewer.js and the
// page's data inlined, so that it opens without network access. The data is one JSON object:
//   {"title", "options", "notes", "centre", "box_min", "box_max",
//    "layers": [points: {"type": "points", "name", "note", "count", "origin", "extent",
//                        "positions": base64 uint16 x 3 (position = origin + extent * q / 65535),
//                        "labels": {"type": "int16"|"int32", "data": base64}, "legend": [...],
//                        "residuals": base64 float32, "residual_scale", "colour", ...},
//               mesh:   {"type": "mesh", "name", "origin", "vertices": base64 float32 x 3
//                        (relative to origin), "normals": base64 int8 x 3 (n * 127),
//                        "triangles": base64 uint32 x 3, "triangle_count", "colour"}]}
// Positions are quantised to 16 bits over the layer's box (1/65535 of its size: far below what a
// screen shows) so that a page holds 10^6 labelled points with residuals in about 16 MB
// (12 bytes a point before base64's 4/3). Everything is placed relative to the centre of the
// page's box, so survey-sized coordinates keep their precision in float32.
#pragma once

#include <string>

#include "view/view_page.h"

namespace implicitfit {

// Throws std::invalid_argument when a layer's labels or residuals do not match its points, or
// a mesh's triangles index past its vertices.
std::string PageHtml(const ViewPage& page);

// PageHtml written atomically (datasets/io/atomic_file.h): the page is complete or absent.
void WritePage(const ViewPage& page, const std::string& path);

// "&", "<", ">", '"' and "'" as HTML entities (for text placed in HTML).
std::string HtmlEscape(const std::string& text);

}  // namespace implicitfit
