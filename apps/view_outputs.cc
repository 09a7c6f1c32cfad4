#include "apps/view_outputs.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "datasets/clouds/cloud_file.h"
#include "datasets/clouds/ply_writer.h"
#include "view/page_html.h"
#include "view/view_layers.h"

namespace implicitfit {
namespace {

std::string FileName(const std::string& path) {
  return std::filesystem::path(path).filename().string();
}

std::string Figure(const char* format, double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, v);
  return buffer;
}

// The model meshed in the padded box of the points, as a layer named `name`.
ViewLayer MeshOverPoints(const std::string& name, const Model& model,
                         const std::vector<Eigen::Vector3d>& points) {
  ModelMeshing meshing;
  meshing.has_box = PaddedBox(points, &meshing.lo, &meshing.hi);
  return ModelMeshLayer(name, model, meshing);
}

}  // namespace

void WriteDetectionView(const CloudDetection& d, const std::string& page_path) {
  ViewPage page;
  page.title = "detect " + d.scene.cloud;
  ViewLayer layer = PointsLayer(FileName(d.scene.cloud), d.cloud.points);
  layer.labels = d.result.labels;
  layer.labels.resize(layer.points.size(), -1);
  layer.residuals = d.result.residuals;
  layer.residuals.resize(layer.points.size(), 0.0);
  layer.residual_note = "f of each point's primitive";
  layer.legend = SceneLegend(d.scene);
  layer.colour = "primitive";
  page.layers.push_back(std::move(layer));
  page.notes.push_back(std::to_string(d.scene.primitives.size()) + " primitives, " +
                       std::to_string(d.scene.unassigned) + " of " +
                       std::to_string(d.scene.points) + " points unassigned; threshold " +
                       Figure("%.4g", d.result.threshold) + ", spacing " +
                       Figure("%.4g", d.result.spacing));
  WritePage(page, page_path);
}

void WriteReconstructionView(const CloudReconstruction& job, const std::string& cloud_path,
                             const std::string& page_path) {
  const SolidReconstruction& r = job.result;
  const std::vector<Eigen::Vector3d>& points = job.cloud.points;
  ViewPage page;
  page.title = "reconstruct " + cloud_path;
  Scene scene;  // the primitives, for the legend and the labels
  for (size_t k = 0; k < job.primitives.size(); ++k) {
    ScenePrimitive p;
    p.name = job.primitives[k].name;
    p.model = job.primitives[k].model;
    p.rms_distance = job.primitives[k].rms;
    p.points = k < r.assigned.size() ? r.assigned[k] : -1;
    scene.primitives.push_back(std::move(p));
  }
  ViewLayer layer = PointsLayer(FileName(cloud_path), points);
  layer.labels = job.labels;
  if (layer.labels.size() != points.size()) {
    layer.labels = NearestPrimitiveLabels(scene, points);
    layer.note = "labels: nearest primitive within 3 x its RMS";
  }
  layer.legend = SceneLegend(scene);
  for (size_t k = 0; k < layer.legend.size() && k < r.sides.size(); ++k)
    layer.legend[k].kind += " (" + r.sides[k] + ")";
  layer.residuals = ModelResiduals(r.model, points);
  layer.residual_note = "f of the solid";
  layer.colour = "residual";
  page.layers.push_back(std::move(layer));
  page.layers.push_back(MeshOverPoints("solid", r.model, points));
  page.notes.push_back("solid " + r.expression);
  page.notes.push_back(std::string(r.bounded ? "bounded" : "NOT bounded") + "; RMS " +
                       Figure("%.4g", r.rms) + " over " + std::to_string(r.inliers) +
                       " inliers; normal agreement " + Figure("%.3f", r.normal_agreement));
  WritePage(page, page_path);
}

void WriteFitOutputs(const std::string& cloud_path, const Model& model,
                     const std::vector<int>* inliers, const std::string& page_path,
                     const std::string& ply_path) {
  if (page_path.empty() && ply_path.empty()) return;
  const PointCloud cloud = ReadCloudFile(cloud_path);
  const std::vector<double> residuals = ModelResiduals(model, cloud.points);
  std::vector<int> labels;
  if (inliers) {
    labels.assign(cloud.size(), -1);
    for (int i : *inliers)
      if (i >= 0 && static_cast<size_t>(i) < labels.size()) labels[i] = 0;
  }
  if (!ply_path.empty()) {
    PlyWriteOptions o;
    o.labels = labels;
    std::vector<double> finite = residuals;
    for (double& r : finite)
      if (!std::isfinite(r)) r = 0.0;
    WritePlyFile(cloud, ply_path, finite, o);
  }
  if (page_path.empty()) return;
  ViewPage page;
  page.title = "fit " + cloud_path;
  ViewLayer layer = PointsLayer(FileName(cloud_path), cloud.points);
  layer.residuals = residuals;
  layer.residual_note = "f of the fitted " + ModelKindText(model);
  layer.colour = "residual";
  if (inliers) {
    double ss = 0.0;
    for (int i : *inliers)
      if (i >= 0 && static_cast<size_t>(i) < residuals.size()) ss += residuals[i] * residuals[i];
    layer.labels = labels;
    layer.legend_title = "Inliers";
    layer.legend.push_back({"inliers", ModelKindText(model), ModelParameterText(model),
                            static_cast<int>(inliers->size()),
                            inliers->empty() ? 0.0 : std::sqrt(ss / inliers->size())});
  }
  page.layers.push_back(std::move(layer));
  page.layers.push_back(MeshOverPoints(ModelKindText(model), model, cloud.points));
  WritePage(page, page_path);
}

}  // namespace implicitfit
