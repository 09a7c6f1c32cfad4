#include "datasets/generators/generated_solids.h"

#include <cmath>

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

Model One(NodeType type, const std::vector<double>& p) {
  Model m;
  m.SetRoot(m.AddPrimitive(type, p));
  return m;
}

// Faces of an axis-aligned box centred at the origin: -x, +x, -y, +y, -z, +z.
std::vector<std::vector<double>> BoxFaces(const Vec& half) {
  std::vector<std::vector<double>> faces;
  for (int a = 0; a < 3; ++a)
    for (int s : {-1, 1}) {
      Vec n = Vec::Zero();
      n[a] = s;
      faces.push_back({n.x(), n.y(), n.z(), half[a]});
    }
  return faces;
}

int AddBox(Model* m, const Vec& half, double delta, double epsilon, int order,
           GeneratedSolid* solid) {
  std::vector<int> faces;
  for (const auto& f : BoxFaces(half)) {
    faces.push_back(m->AddPrimitive(NodeType::kPlane, f));
    solid->primitives.push_back(One(NodeType::kPlane, f));
  }
  return m->AddOperator(NodeType::kIntersection, faces, delta, epsilon, order);
}

}  // namespace

GeneratedSolid RoundedBoxSolid() {
  GeneratedSolid s;
  s.name = "rounded box";
  const Vec half(1.0, 0.7, 0.5);
  s.fillet_delta = 0.2;
  s.truth.SetRoot(AddBox(&s.truth, half, 0.2, 0.12, 3, &s));
  s.box_min = -1.1 * half;
  s.box_max = 1.1 * half;
  return s;
}

GeneratedSolid PlateWithFilletedBoreSolid() {
  GeneratedSolid s;
  s.name = "plate with filleted bore";
  const Vec half(1.0, 1.0, 0.25);
  s.fillet_delta = 0.15;
  const int plate = AddBox(&s.truth, half, 0.1, 0.1, 0, &s);
  const std::vector<double> bore = {0.1, 0, 0, 0, 0, 1, 0.4};
  const int cyl = s.truth.AddPrimitive(NodeType::kCylinder, bore);
  s.primitives.push_back(One(NodeType::kCylinder, bore));
  s.truth.SetRoot(s.truth.AddOperator(NodeType::kDifference, {plate, cyl}, 0.15, 0.1, 3));
  s.box_min = -1.1 * half;
  s.box_max = 1.1 * half;
  return s;
}

GeneratedSolid BossOnSlabSolid() {
  GeneratedSolid s;
  s.name = "boss on slab";
  const Vec half(1.0, 1.0, 0.2);
  s.fillet_delta = 0.15;
  const int slab = AddBox(&s.truth, half, 0.1, 0.1, 0, &s);
  const std::vector<double> boss = {0, 0.1, 0, 0, 0, 1, 0.35}, top = {0, 0, 1, 0.8};
  const int cyl = s.truth.AddPrimitive(NodeType::kCylinder, boss);
  const int cap = s.truth.AddPrimitive(NodeType::kPlane, top);
  const int bottom = s.truth.AddPrimitive(NodeType::kPlane, {0, 0, -1, 0.2});
  const int boss_node =
      s.truth.AddOperator(NodeType::kIntersection, {cyl, cap, bottom}, 0.1, 0.1, 0);
  s.primitives.push_back(One(NodeType::kCylinder, boss));
  s.primitives.push_back(One(NodeType::kPlane, top));
  s.truth.SetRoot(s.truth.AddOperator(NodeType::kUnion, {slab, boss_node}, 0.15, 0.1, 3));
  s.box_min = Vec(-1.1, -1.1, -0.3);
  s.box_max = Vec(1.1, 1.1, 0.9);
  return s;
}

std::vector<GeneratedSolid> AllGeneratedSolids() {
  return {RoundedBoxSolid(), PlateWithFilletedBoreSolid(), BossOnSlabSolid()};
}

std::vector<int> GroundTruthLabels(const GeneratedSolid& solid, const PointCloud& cloud,
                                   double band) {
  std::vector<int> labels(cloud.size(), -1);
  for (size_t i = 0; i < cloud.size(); ++i) {
    double best = band;
    for (size_t k = 0; k < solid.primitives.size(); ++k) {
      double f;
      const Eigen::Vector3d g = solid.primitives[k].Gradient(cloud.points[i], &f);
      const double d = std::abs(f) / g.norm();
      if (d < best && cloud.has_normals() &&
          std::abs(g.normalized().dot(cloud.normals[i])) > 0.999) {
        best = d;
        labels[i] = static_cast<int>(k);
      }
    }
  }
  return labels;
}

}  // namespace implicitfit
