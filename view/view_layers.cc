#include "view/view_layers.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace implicitfit {
namespace {

std::string Number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g", v);
  return buffer;
}

bool IsLeaf(const ModelNode& node) {
  return node.children.empty() && node.type != NodeType::kBernsteinPatch &&
         node.type != NodeType::kBernsteinMesh && node.type != NodeType::kPartition;
}

}  // namespace

bool PaddedBox(const std::vector<Eigen::Vector3d>& points, Eigen::Vector3d* lo,
               Eigen::Vector3d* hi) {
  if (points.empty()) return false;
  *lo = *hi = points[0];
  for (const Eigen::Vector3d& p : points) {
    *lo = lo->cwiseMin(p);
    *hi = hi->cwiseMax(p);
  }
  const double pad = std::max(0.1 * (*hi - *lo).maxCoeff(), 1e-9 * (1.0 + lo->norm()));
  *lo -= Eigen::Vector3d::Constant(pad);
  *hi += Eigen::Vector3d::Constant(pad);
  return true;
}

ViewLayer PointsLayer(const std::string& name, const std::vector<Eigen::Vector3d>& points) {
  ViewLayer layer;
  layer.name = name;
  layer.points = points;
  return layer;
}

ViewLayer ModelMeshLayer(const std::string& name, const Model& model, const ModelMeshing& m) {
  MeshOptions options;
  Eigen::Vector3d lo = m.lo, hi = m.hi;
  if (!m.has_box) DefaultMeshBox(model, &lo, &hi);
  options.has_box = true;
  options.box_min = lo;
  options.box_max = hi;
  options.cell = (hi - lo).maxCoeff() / std::max(1, m.resolution);
  ViewLayer layer;
  layer.name = name;
  layer.is_mesh = true;
  MeshResult mesh = MeshModel(model, options);
  layer.mesh = std::move(mesh.mesh);
  layer.note = "meshed with cell " + Number(mesh.cell);
  if (layer.mesh.triangles.empty()) layer.note += ": the zero set does not meet the box";
  return layer;
}

std::vector<double> ModelResiduals(const Model& model, const std::vector<Eigen::Vector3d>& points) {
  std::vector<double> r(points.size());
  for (size_t i = 0; i < points.size(); ++i) r[i] = model.Value(points[i]);
  return r;
}

std::string ModelKindText(const Model& model) {
  if (model.root() < 0) return "empty";
  const ModelNode& root = model.nodes()[model.root()];
  std::string kind = NodeTypeName(root.type);
  if (model.nodes().size() > 1 && !root.children.empty())
    kind += " (" + std::to_string(model.nodes().size()) + " nodes)";
  return kind;
}

std::string ModelParameterText(const Model& model) {
  if (model.root() < 0) return "";
  const ModelNode& root = model.nodes()[model.root()];
  if (root.type == NodeType::kBernsteinPatch || root.type == NodeType::kBernsteinMesh)
    return "degree " + std::to_string(root.degree) + ", " + std::to_string(root.num_parameters) +
           " control points";
  if (!IsLeaf(root)) return "";
  std::string text;
  const double* p = model.parameters().data() + root.first_parameter;
  // Rounding noise of the fit (1e-9 of the node's largest parameter) shows as 0.
  double scale = 0.0;
  for (int i = 0; i < root.num_parameters; ++i) scale = std::max(scale, std::abs(p[i]));
  const auto shown = [&](double v) { return Number(std::abs(v) <= 1e-9 * scale ? 0.0 : v); };
  for (const ParameterField& field : ParameterFieldsOf(root)) {
    if (!text.empty()) text += ' ';
    text += field.name;
    text += ' ';
    if (field.size == 1) {
      text += shown(*p);
    } else {
      text += '(';
      for (int k = 0; k < field.size; ++k) text += (k ? ", " : "") + shown(p[k]);
      text += ')';
    }
    p += field.size;
  }
  return text;
}

std::vector<LegendEntry> SceneLegend(const Scene& scene) {
  std::vector<LegendEntry> legend;
  for (const ScenePrimitive& p : scene.primitives)
    legend.push_back({p.name, ModelKindText(p.model), ModelParameterText(p.model), p.points,
                      p.rms_distance});
  return legend;
}

std::vector<double> LabelledResiduals(const Scene& scene, const std::vector<int>& labels,
                                      const std::vector<Eigen::Vector3d>& points) {
  std::vector<double> r(points.size(), 0.0);
  for (size_t i = 0; i < points.size() && i < labels.size(); ++i)
    if (labels[i] >= 0 && labels[i] < static_cast<int>(scene.primitives.size()))
      r[i] = scene.primitives[labels[i]].model.Value(points[i]);
  return r;
}

std::vector<int> NearestPrimitiveLabels(const Scene& scene,
                                        const std::vector<Eigen::Vector3d>& points) {
  Eigen::Vector3d lo, hi;
  const double diagonal = PaddedBox(points, &lo, &hi) ? (hi - lo).norm() / 1.2 : 1.0;
  std::vector<int> labels(points.size(), -1);
  for (size_t i = 0; i < points.size(); ++i) {
    double best = HUGE_VAL;
    for (size_t k = 0; k < scene.primitives.size(); ++k) {
      const ScenePrimitive& p = scene.primitives[k];
      const double d = std::abs(p.model.Value(points[i]));
      if (d <= 3.0 * (p.rms_distance + 1e-9 * diagonal) && d < best) {
        best = d;
        labels[i] = static_cast<int>(k);
      }
    }
  }
  return labels;
}

}  // namespace implicitfit
