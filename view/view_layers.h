// Building blocks of view pages (view/view_page.h), shared by `view` (view/view_inputs.h) and the
// --view pages of `fit`, `detect` and `reconstruct` (apps/view_outputs.h): point layers, models
// meshed into mesh layers, legends of scenes and models, residuals.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "datasets/io/scene_file.h"
#include "model/model.h"
#include "view/view_page.h"

namespace implicitfit {

// The box models are meshed in when a page has clouds: the points' box padded by 10% of its
// longest side on every side (a flat cloud still gets a box with volume). False when empty.
bool PaddedBox(const std::vector<Eigen::Vector3d>& points, Eigen::Vector3d* lo,
               Eigen::Vector3d* hi);

ViewLayer PointsLayer(const std::string& name, const std::vector<Eigen::Vector3d>& points);

struct ModelMeshing {
  bool has_box = false;  // mesh over [lo, hi]; otherwise DefaultMeshBox of the model
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();
  int resolution = 100;  // grid cells along the box's longest side
};

// The zero set of `model` (datasets/meshing/model_mesher.h) as a mesh layer; its note gives the
// cell and says when the zero set does not meet the box. Throws std::invalid_argument from the
// mesher (e.g. a grid above its limit).
ViewLayer ModelMeshLayer(const std::string& name, const Model& model, const ModelMeshing& meshing);

// f of the model at every point.
std::vector<double> ModelResiduals(const Model& model, const std::vector<Eigen::Vector3d>& points);

// "cylinder", "union (5 nodes)", "bernstein_mesh"
std::string ModelKindText(const Model& model);
// The root's parameters, "center (1, 2, 3) radius 2.5" (4 significant digits); for a tree, its
// expression size, for Bernstein kinds their degree and control points.
std::string ModelParameterText(const Model& model);

// One legend row per primitive of the scene (name, kind, parameters, points, RMS).
std::vector<LegendEntry> SceneLegend(const Scene& scene);

// Per point: f of its primitive (labels[i] = k), 0 for unassigned points.
std::vector<double> LabelledResiduals(const Scene& scene, const std::vector<int>& labels,
                                      const std::vector<Eigen::Vector3d>& points);

// Labels of a scene's cloud when no labels file is given: each point goes to the primitive of
// smallest |f| among those with |f| <= 3 x (its RMS + 1e-9 x the box diagonal), else -1 (a
// guess: primitives are unbounded; the page's note says so).
std::vector<int> NearestPrimitiveLabels(const Scene& scene,
                                        const std::vector<Eigen::Vector3d>& points);

}  // namespace implicitfit
