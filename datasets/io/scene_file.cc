#include "datasets/io/scene_file.h"

#include <cmath>
#include <set>
#include <sstream>

#include "datasets/io/atomic_file.h"
#include "datasets/io/input_file.h"
#include "datasets/io/io_error.h"
#include "datasets/io/json_file.h"
#include "datasets/io/read_limits.h"
#include "datasets/io/text_file.h"
#include "model/file/model_json.h"

namespace implicitfit {
namespace {

using nlohmann::json;

// A model-file NODE read with the model reader's rules; its paths ("root.radius") are renamed
// to the scene's ("primitives[2].model.radius").
Model NodeToModel(const json& node, const std::string& where) {
  const json document = {{"format", "implicitfit-model"}, {"version", 1}, {"root", node}};
  try {
    return ModelFromJson(document);
  } catch (const ModelFormatError& e) {
    std::string what = e.what();
    if (what.rfind("root", 0) == 0) what = where + what.substr(4);
    throw ModelFormatError(what);
  }
}

const json& Field(const json& object, const std::string& key, const std::string& where) {
  if (!object.contains(key)) throw ModelFormatError(where + "." + key + ": missing");
  return object.at(key);
}

long Count(const json& object, const std::string& key, const std::string& where) {
  const json& v = Field(object, key, where);
  if (!v.is_number_integer() || v.get<long>() < 0)
    throw ModelFormatError(where + "." + key + ": must be an integer >= 0");
  return v.get<long>();
}

double Finite(const json& v, const std::string& where) {
  if (!v.is_number() || !std::isfinite(v.get<double>()))
    throw ModelFormatError(where + ": must be a finite number");
  return v.get<double>();
}

void OnlyKnownKeys(const json& object, const std::set<std::string>& known,
                   const std::string& where) {
  for (auto it = object.begin(); it != object.end(); ++it)
    if (!known.count(it.key())) throw ModelFormatError(where + "." + it.key() + ": unknown field");
}

Scene SceneFromJson(const json& d) {
  if (!d.is_object()) throw ModelFormatError("document: must be a JSON object");
  OnlyKnownKeys(d, {"format", "version", "cloud", "points", "primitives", "unassigned"}, "scene");
  if (Field(d, "format", "scene") != "implicitfit-scene")
    throw ModelFormatError("scene.format: must be \"implicitfit-scene\"");
  if (Field(d, "version", "scene") != 1) throw ModelFormatError("scene.version: must be 1");
  Scene scene;
  const json& cloud = Field(d, "cloud", "scene");
  if (!cloud.is_string()) throw ModelFormatError("scene.cloud: must be a string");
  scene.cloud = cloud.get<std::string>();
  scene.points = static_cast<int>(Count(d, "points", "scene"));
  scene.unassigned = static_cast<int>(Count(d, "unassigned", "scene"));
  const json& list = Field(d, "primitives", "scene");
  if (!list.is_array()) throw ModelFormatError("scene.primitives: must be an array");
  for (size_t i = 0; i < list.size(); ++i) {
    const std::string where = "primitives[" + std::to_string(i) + "]";
    const json& p = list[i];
    if (!p.is_object()) throw ModelFormatError(where + ": must be an object");
    OnlyKnownKeys(p,
                  {"name", "model", "points", "rms_distance", "standard_deviations", "normal_side"},
                  where);
    ScenePrimitive prim;
    const json& name = Field(p, "name", where);
    if (!name.is_string()) throw ModelFormatError(where + ".name: must be a string");
    prim.name = name.get<std::string>();
    prim.model = NodeToModel(Field(p, "model", where), where + ".model");
    prim.points = static_cast<int>(Count(p, "points", where));
    prim.rms_distance = Finite(Field(p, "rms_distance", where), where + ".rms_distance");
    if (p.contains("standard_deviations")) {
      const json& sd = p.at("standard_deviations");
      if (!sd.is_object())
        throw ModelFormatError(where + ".standard_deviations: must be an object");
      for (auto it = sd.begin(); it != sd.end(); ++it)
        prim.standard_deviations[it.key()] =
            Finite(it.value(), where + ".standard_deviations." + it.key());
    }
    const json& side = Field(p, "normal_side", where);
    if (side != "outward" && side != "inward" && side != "unknown")
      throw ModelFormatError(where +
                             ".normal_side: must be \"outward\", \"inward\" or \"unknown\"");
    prim.normal_side = side.get<std::string>();
    scene.primitives.push_back(std::move(prim));
  }
  return scene;
}

}  // namespace

Scene ReadSceneFile(const std::string& path) {
  const std::string text = ReadTextFile(path);
  const json document = ParseJsonDocument(text, path);
  try {
    return SceneFromJson(document);
  } catch (const ModelFormatError& e) {
    throw FileError(path, std::string("invalid scene: ") + e.what());
  }
}

void WriteSceneFile(const Scene& scene, const std::string& path) {
  json list = json::array();
  for (const ScenePrimitive& p : scene.primitives) {
    json sd = json::object();
    for (const auto& [name, value] : p.standard_deviations) sd[name] = value;
    list.push_back({{"name", p.name},
                    {"model", ModelToJson(p.model).at("root")},
                    {"points", p.points},
                    {"rms_distance", p.rms_distance},
                    {"standard_deviations", sd},
                    {"normal_side", p.normal_side}});
  }
  const json document = {
      {"format", "implicitfit-scene"}, {"version", 1},       {"cloud", scene.cloud},
      {"points", scene.points},        {"primitives", list}, {"unassigned", scene.unassigned}};
  WriteFileAtomically(path, document.dump(2) + "\n");
}

std::vector<int> ReadLabelsFile(const std::string& path, int num_primitives, long expected_count) {
  InputFile file(path);  // streamed: a labels file has one line per point
  std::vector<int> labels;
  std::string line;
  while (file.ReadLine(&line, CurrentReadLimits().max_line_bytes)) {
    const long number = file.line_number();
    std::istringstream fields(line);
    long value = 0;
    std::string rest;
    if (!(fields >> value) || (fields >> rest))
      throw LineError(path, number,
                      "expected one integer label, found '" + line.substr(0, 60) + "'");
    if (value < -1 || value >= num_primitives)
      throw LineError(path, number,
                      "label " + std::to_string(value) + " is outside -1.." +
                          std::to_string(num_primitives - 1));
    if (labels.size() >= CurrentReadLimits().max_points)
      throw LineError(path, number, "more labels than the limit of " +
                                        std::to_string(CurrentReadLimits().max_points) +
                                        " points (raise it with --max-points)");
    labels.push_back(static_cast<int>(value));
  }
  if (expected_count >= 0 && static_cast<long>(labels.size()) != expected_count)
    throw FileError(path, std::to_string(labels.size()) + " labels for " +
                              std::to_string(expected_count) + " points");
  return labels;
}

void WriteLabelsFile(const std::vector<int>& labels, const std::string& path) {
  std::string text;
  text.reserve(labels.size() * 3);
  for (int l : labels) text += std::to_string(l) + "\n";
  WriteFileAtomically(path, text);
}

}  // namespace implicitfit
