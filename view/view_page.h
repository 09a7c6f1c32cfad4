// What a view page shows (docs/view.md): layers drawn over each other, each a point cloud or a
// triangle mesh, with the page's title, default options and notes. The commands fill it
// (view/view_inputs.h reads the user's files; apps/view_outputs.h builds the pages of `fit`,
// `detect` and `reconstruct`), view/page_html.h turns it into the HTML page.
#pragma once

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "datasets/meshing/model_mesher.h"

namespace implicitfit {

// One row of a layer's primitive legend: label k of the layer's points is legend[k].
struct LegendEntry {
  std::string name;        // "p0"
  std::string kind;        // "cylinder"
  std::string parameters;  // "point (1, 2, 3) axis (0, 0, 1) radius 2.5"
  int points = -1;         // < 0: not shown
  double rms = -1.0;       // < 0: not shown
};

struct ViewLayer {
  std::string name;  // shown in the panel (usually the file name)
  std::string note;  // shown after it, e.g. "labels: nearest primitive"
  bool is_mesh = false;

  // A points layer (is_mesh false).
  std::vector<Eigen::Vector3d> points;
  std::vector<int> labels;        // empty, or one per point: index into legend, -1 none
  std::vector<double> residuals;  // empty, or one per point (e.g. f of a model)
  double residual_scale = 0.0;    // the colour map saturates at +-scale; 0: 95th pct of |r|
  std::string residual_title;     // heading of the colour bar ("Residual f" when empty)
  std::string residual_note;      // what the residual is, e.g. "f of the fitted cylinder"
  std::string colour;             // first colour mode: "primitive", "residual", "plain"; "": the
                                  // first the layer has, in that order
  std::string legend_title;       // heading of the primitive legend ("Primitives" when empty)
  std::vector<LegendEntry> legend;

  // A mesh layer (is_mesh true); normals may be empty (computed by the page).
  TriangleMesh mesh;
  std::string mesh_colour;  // CSS colour; "": one of the page's mesh colours
};

struct ViewPage {
  std::string title;
  std::vector<ViewLayer> layers;
  // The page's default options (keys of docs/view.md: clip, az, el, zoom, color, hide, ui,
  // size, ...); the URL fragment overrides them.
  std::map<std::string, std::string> options;
  std::vector<std::string> notes;  // lines shown under the legends
  // Point layers above this many points are thinned to every k-th point (noted in the layer).
  size_t max_points = 2000000;
};

}  // namespace implicitfit
