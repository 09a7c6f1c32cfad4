#include "view/view_inputs.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "datasets/clouds/cloud_file.h"
#include "datasets/io/io_error.h"
#include "datasets/io/model_file.h"
#include "datasets/io/scene_file.h"
#include "datasets/io/text_file.h"
#include "datasets/meshing/mesh_file.h"
#include "view/view_layers.h"

namespace implicitfit {
namespace {

namespace fs = std::filesystem;

enum class InputKind { kCloud, kScene, kModel, kMesh };

std::string Extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

std::string FileName(const std::string& path) { return fs::path(path).filename().string(); }

InputKind Classify(const std::string& path) {
  const std::string ext = Extension(path);
  if (ext == ".json") {
    const std::string text = ReadTextFile(path);
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
      throw FileError(path, std::string("not valid JSON: ") + e.what());
    }
    const std::string format =
        j.is_object() && j.contains("format") && j["format"].is_string() ? j["format"].get<std::string>()
                                                                         : "";
    if (format == "implicitfit-scene") return InputKind::kScene;
    if (format == "implicitfit-model") return InputKind::kModel;
    throw FileError(path, "neither a model nor a scene file (\"format\" is not "
                          "\"implicitfit-model\" or \"implicitfit-scene\")");
  }
  if (ext == ".ply" && PlyHasFaces(path)) return InputKind::kMesh;
  return InputKind::kCloud;
}

// A cloud input: its layer and whether its labels came from a PLY/PCD "label" property (the
// labels of `detect --ply`, which a scene may take; .xyzl labels are ground-truth numbers).
struct CloudInput {
  ViewLayer layer;
  bool property_labels = false;
  bool has_scene = false;
};

CloudInput ReadCloudInput(const std::string& path) {
  CloudFileInfo info;
  const PointCloud cloud = ReadCloudFile(path, &info);
  CloudInput in;
  in.layer = PointsLayer(FileName(path), cloud.points);
  in.layer.labels = info.labels;
  in.layer.residuals = info.residuals;
  in.property_labels = !info.labels.empty() && Extension(path) != ".xyzl";
  if (!info.labels.empty()) in.layer.legend_title = "Labels of the file";
  if (!info.residuals.empty()) in.layer.residual_note = "the file's residual property";
  return in;
}

// The scene's cloud when no cloud input matches: its "cloud" path as given, else beside the
// scene file.
std::string SceneCloudPath(const Scene& scene, const std::string& scene_path) {
  if (scene.cloud.empty())
    throw FileError(scene_path, "names no cloud: give the cloud as an input too");
  if (fs::exists(scene.cloud)) return scene.cloud;
  const fs::path beside = fs::path(scene_path).parent_path() / fs::path(scene.cloud).filename();
  if (fs::exists(beside)) return beside.string();
  throw FileError(scene_path, "its cloud " + scene.cloud +
                                  " was not found (nor beside the scene file): give the cloud "
                                  "as an input too");
}

// Makes `cloud` the layer of `scene`: legend, labels, residuals.
void AttachScene(const Scene& scene, const std::string& scene_path, const ViewInputOptions& options,
                 bool first_scene, CloudInput* cloud) {
  ViewLayer& layer = cloud->layer;
  const size_t n = layer.points.size();
  const int primitives = static_cast<int>(scene.primitives.size());
  if (scene.points > 0 && static_cast<size_t>(scene.points) != n)
    throw FileError(scene_path, "is of a cloud of " + std::to_string(scene.points) + " points, " +
                                    layer.name + " has " + std::to_string(n));
  bool own = cloud->property_labels &&
             std::all_of(layer.labels.begin(), layer.labels.end(),
                         [&](int l) { return l >= -1 && l < primitives; });
  if (!options.labels.empty() && first_scene) {
    layer.labels = ReadLabelsFile(options.labels, primitives, static_cast<long>(n));
    layer.note = "labels of " + FileName(options.labels);
    own = true;
  } else if (!own) {
    if (!options.quiet)
      std::cerr << "view: " << scene_path << ": no labels given: each point goes to the nearest "
                << "primitive within 3 x its RMS\n";
    layer.labels = NearestPrimitiveLabels(scene, layer.points);
    layer.note = "labels: nearest primitive within 3 x its RMS (no labels given)";
  }
  if (layer.residuals.empty() || !cloud->property_labels) {
    layer.residuals = LabelledResiduals(scene, layer.labels, layer.points);
    layer.residual_note = "f of each point's primitive";
  }
  layer.name = FileName(scene_path) + " on " + layer.name;
  layer.legend = SceneLegend(scene);
  layer.legend_title = "Primitives";
  layer.colour = "primitive";
  cloud->has_scene = true;
}

}  // namespace

ViewPage ReadViewInputs(const std::vector<std::string>& inputs, const ViewInputOptions& options) {
  // 1. Every input's kind (reading JSON and PLY headers: missing files are named here).
  std::vector<InputKind> kinds;
  for (const std::string& path : inputs) kinds.push_back(Classify(path));
  if (!options.labels.empty() &&
      std::find(kinds.begin(), kinds.end(), InputKind::kScene) == kinds.end())
    throw InputError("--labels " + options.labels + ": labels apply to a scene's cloud; no scene given");
  // 2. Clouds, then the scenes (each takes a cloud input of its size, or reads its own).
  std::vector<std::optional<CloudInput>> clouds(inputs.size());
  for (size_t i = 0; i < inputs.size(); ++i)
    if (kinds[i] == InputKind::kCloud) clouds[i] = ReadCloudInput(inputs[i]);
  bool first_scene = true;
  for (size_t i = 0; i < inputs.size(); ++i) {
    if (kinds[i] != InputKind::kScene) continue;
    const Scene scene = ReadSceneFile(inputs[i]);
    CloudInput* match = nullptr;
    for (std::optional<CloudInput>& c : clouds)
      if (c && !c->has_scene && scene.points > 0 &&
          c->layer.points.size() == static_cast<size_t>(scene.points) && !match)
        match = &*c;
    if (!match) {
      clouds[i] = ReadCloudInput(SceneCloudPath(scene, inputs[i]));
      match = &*clouds[i];
    }
    AttachScene(scene, inputs[i], options, first_scene, match);
    first_scene = false;
  }
  // 3. Models and meshes; models are meshed in the box of the page's clouds.
  std::vector<Eigen::Vector3d> all_points;
  for (const std::optional<CloudInput>& c : clouds)
    if (c) all_points.insert(all_points.end(), c->layer.points.begin(), c->layer.points.end());
  ModelMeshing meshing;
  meshing.resolution = options.resolution;
  meshing.has_box = options.has_box || PaddedBox(all_points, &meshing.lo, &meshing.hi);
  if (options.has_box) meshing.lo = options.box_min, meshing.hi = options.box_max;
  std::vector<std::optional<ViewLayer>> others(inputs.size());
  std::vector<std::pair<std::string, Model>> models;
  for (size_t i = 0; i < inputs.size(); ++i) {
    if (kinds[i] == InputKind::kModel) {
      models.emplace_back(FileName(inputs[i]), ReadModelFile(inputs[i]));
    } else if (kinds[i] == InputKind::kMesh) {
      ViewLayer layer;
      layer.name = FileName(inputs[i]);
      layer.is_mesh = true;
      layer.mesh = ReadMeshPlyFile(inputs[i]);
      others[i] = std::move(layer);
    }
  }
  for (size_t i = 0, m = 0; i < inputs.size(); ++i) {
    if (kinds[i] != InputKind::kModel) continue;
    const auto& [name, model] = models[m++];
    if (!options.quiet)
      std::cerr << "view: meshing " << inputs[i] << " (" << options.resolution
                << " cells along the box's longest side)\n";
    try {
      others[i] = ModelMeshLayer(name, model, meshing);
    } catch (const std::invalid_argument& e) {
      throw FileError(inputs[i], std::string("cannot be meshed: ") + e.what());
    }
  }
  // 4. With one model, clouds without residuals of their own get its f.
  if (models.size() == 1)
    for (std::optional<CloudInput>& c : clouds)
      if (c && c->layer.residuals.empty()) {
        c->layer.residuals = ModelResiduals(models[0].second, c->layer.points);
        c->layer.residual_note = "f of " + models[0].first;
      }
  ViewPage page;
  for (size_t i = 0; i < inputs.size(); ++i) {
    page.title += (i ? " " : "") + FileName(inputs[i]);
    if (clouds[i]) {
      if (options.residual_scale > 0) clouds[i]->layer.residual_scale = options.residual_scale;
      page.layers.push_back(std::move(clouds[i]->layer));
    }
    if (others[i]) page.layers.push_back(std::move(*others[i]));
  }
  return page;
}

}  // namespace implicitfit
