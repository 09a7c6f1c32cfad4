#include "model/file/clip_to_tetrahedron.h"

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "model/file/model_json.h"

namespace implicitfit {
namespace {

using nlohmann::json;

// The four face planes of the tetrahedron x1..x4 (face i opposite vertex i), outward.
json FacePlanes(const json& vertices) {
  Eigen::Vector3d x[4];
  for (int i = 0; i < 4; ++i)
    x[i] = Eigen::Vector3d(vertices[i][0].get<double>(), vertices[i][1].get<double>(),
                           vertices[i][2].get<double>());
  json planes = json::array();
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d& a = x[(i + 1) % 4];
    const Eigen::Vector3d& b = x[(i + 2) % 4];
    const Eigen::Vector3d& c = x[(i + 3) % 4];
    Eigen::Vector3d n = (b - a).cross(c - a).normalized();
    if (n.dot(x[i] - a) > 0) n = -n;  // away from the opposite vertex
    planes.push_back({{"type", "plane"}, {"normal", {n.x(), n.y(), n.z()}}, {"offset", n.dot(a)}});
  }
  return planes;
}

json Clip(const json& node, int* clipped) {
  if (node.is_object() && node.value("type", "") == "bernstein_patch") {
    ++*clipped;
    json children = FacePlanes(node.at("vertices"));
    children.insert(children.begin(), node);
    return {{"type", "intersection"},
            {"delta", 1.0},
            {"epsilon", 1.0},
            {"order", 0},
            {"name", node.value("name", std::string("patch")) + " clipped to its tetrahedron"},
            {"children", children}};
  }
  json out = node;
  if (node.is_object())
    for (auto it = out.begin(); it != out.end(); ++it)
      if (it.value().is_object() || it.value().is_array()) it.value() = Clip(it.value(), clipped);
  if (node.is_array())
    for (auto& child : out) child = Clip(child, clipped);
  return out;
}

}  // namespace

Model ClipPatchesToTetrahedra(const Model& model, int* clipped) {
  *clipped = 0;
  json document = ModelToJson(model);
  document["root"] = Clip(document["root"], clipped);
  if (*clipped == 0) return model;
  return ModelFromJson(document);
}

}  // namespace implicitfit
