// The inputs of `implicitfit view INPUT...` (docs/view.md) as the layers of one page, in the
// order given:
//   clouds  any format ReadCloudFile takes (datasets/clouds/cloud_file.h); labels (.xyzl, PLY
//           "label") colour them by primitive, residuals (PLY "residual") by residual; with a
//           model among the inputs and no residuals of its own, a cloud gets f of that model;
//   scenes  detect's JSON (datasets/io/scene_file.h): drawn as the scene's cloud coloured by
//           primitive, with a legend (kind, parameters, points, RMS). The cloud is a cloud input
//           of the scene's point count when there is one (e.g. the segmented PLY of
//           `detect --ply`), else the scene's "cloud" path (as given, else beside the scene
//           file). Labels: that cloud's own, else --labels, else the nearest primitive
//           (NearestPrimitiveLabels, said in the layer's note);
//   models  any model JSON, meshed (view/view_layers.h) in the padded box of the page's clouds,
//           or, without clouds, in the model's default mesh box;
//   meshes  PLY files with faces (datasets/meshing/mesh_file.h).
// Every input is read before anything is returned: a missing or unreadable one throws
// InputError naming it (so that no page is written).
#pragma once

#include <string>
#include <vector>

#include "view/view_page.h"

namespace implicitfit {

struct ViewInputOptions {
  std::string labels;     // --labels: one label a line for the first scene's cloud
  int resolution = 100;   // model meshes: grid cells along the box's longest side
  bool has_box = false;   // --box: mesh models in [box_min, box_max] instead
  Eigen::Vector3d box_min = Eigen::Vector3d::Zero(), box_max = Eigen::Vector3d::Zero();
  double residual_scale = 0.0;  // > 0: the colour map's saturation for every cloud
  bool quiet = false;           // no progress on stderr
};

ViewPage ReadViewInputs(const std::vector<std::string>& inputs, const ViewInputOptions& options);

}  // namespace implicitfit
