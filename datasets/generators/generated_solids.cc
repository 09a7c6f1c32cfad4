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

// A primitive of the truth that is also one of the solid's distinct surfaces.
int AddSurface(NodeType type, const std::vector<double>& p, GeneratedSolid* s) {
  s->primitives.push_back(One(type, p));
  return s->truth.AddPrimitive(type, p);
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

GeneratedSolid FlangedShaftSolid() {
  GeneratedSolid s;
  s.name = "flanged shaft with blind bore";
  s.fillet_delta = 0.1;
  Model& m = s.truth;
  const int bottom = AddSurface(NodeType::kPlane, {0, 0, -1, 0}, &s);
  const int flange_top = AddSurface(NodeType::kPlane, {0, 0, 1, 0.3}, &s);
  const int flange_side = AddSurface(NodeType::kCylinder, {0, 0, 0, 0, 0, 1, 1.0}, &s);
  const int flange =
      m.AddOperator(NodeType::kIntersection, {flange_side, bottom, flange_top}, 0.1, 0.1, 0);
  const int shaft_side = AddSurface(NodeType::kCylinder, {0, 0, 0, 0, 0, 1, 0.45}, &s);
  const int shaft_top = AddSurface(NodeType::kPlane, {0, 0, 1, 1.5}, &s);
  const int shaft_foot = m.AddPrimitive(NodeType::kPlane, {0, 0, -1, -0.25});  // inside the flange
  const int shaft =
      m.AddOperator(NodeType::kIntersection, {shaft_side, shaft_foot, shaft_top}, 0.1, 0.1, 0);
  const int body = m.AddOperator(NodeType::kUnion, {flange, shaft}, 0.1, 0.06, 3);
  const int bore_side = AddSurface(NodeType::kCylinder, {0, 0, 0, 0, 0, 1, 0.2}, &s);
  const int bore_floor = AddSurface(NodeType::kPlane, {0, 0, -1, -0.8}, &s);
  const int bore = m.AddOperator(NodeType::kIntersection, {bore_side, bore_floor}, 0.1, 0.1, 0);
  m.SetRoot(m.AddOperator(NodeType::kDifference, {body, bore}, 0.1, 0.1, 0));
  s.box_min = Vec(-1.1, -1.1, -0.1);
  s.box_max = Vec(1.1, 1.1, 1.6);
  return s;
}

GeneratedSolid LBracketSolid() {
  GeneratedSolid s;
  s.name = "L-bracket with fillet and holes";
  s.fillet_delta = 0.12;
  Model& m = s.truth;
  std::vector<int> faces;
  const Vec lo(-1, -0.6, 0), hi(1, 0.6, 1.2);
  for (int a = 0; a < 3; ++a) {
    Vec n = Vec::Zero();
    n[a] = -1;
    faces.push_back(AddSurface(NodeType::kPlane, {n.x(), n.y(), n.z(), -lo[a]}, &s));
    n[a] = 1;
    faces.push_back(AddSurface(NodeType::kPlane, {n.x(), n.y(), n.z(), hi[a]}, &s));
  }
  const int box = m.AddOperator(NodeType::kIntersection, faces, 0.1, 0.1, 0);
  // The notch {x > -0.7} & {z > 0.3}; its surfaces are the bracket's inner faces.
  const int inner_x = AddSurface(NodeType::kPlane, {-1, 0, 0, 0.7}, &s);
  const int inner_z = AddSurface(NodeType::kPlane, {0, 0, -1, -0.3}, &s);
  const int notch = m.AddOperator(NodeType::kIntersection, {inner_x, inner_z}, 0.12, 0.08, 3);
  const int hole_z = AddSurface(NodeType::kCylinder, {0.35, 0, 0, 0, 0, 1, 0.2}, &s);
  const int hole_x = AddSurface(NodeType::kCylinder, {0, 0, 0.8, 1, 0, 0, 0.18}, &s);
  m.SetRoot(m.AddOperator(NodeType::kDifference, {box, notch, hole_z, hole_x}, 0.1, 0.1, 0));
  s.box_min = Vec(-1.1, -0.7, -0.1);
  s.box_max = Vec(1.1, 0.7, 1.3);
  return s;
}

GeneratedSolid DomeOnPlateSolid() {
  GeneratedSolid s;
  s.name = "dome on plate with holes";
  s.fillet_delta = 0.1;
  Model& m = s.truth;
  const Vec half(1.0, 1.0, 0.15);
  std::vector<int> faces;
  for (const auto& f : BoxFaces(half)) {
    std::vector<double> g = f;
    g[3] += g[2] * 0.15;  // the plate from z = 0 to 0.3
    faces.push_back(AddSurface(NodeType::kPlane, g, &s));
  }
  const int plate = m.AddOperator(NodeType::kIntersection, faces, 0.1, 0.1, 0);
  const int sphere = AddSurface(NodeType::kSphere, {0, 0, 0.2, 0.6}, &s);
  const int cut = m.AddPrimitive(NodeType::kPlane, {0, 0, -1, -0.2});  // inside the plate
  const int dome = m.AddOperator(NodeType::kIntersection, {sphere, cut}, 0.1, 0.1, 0);
  const int body = m.AddOperator(NodeType::kUnion, {plate, dome}, 0.1, 0.06, 3);
  const int hole_a = AddSurface(NodeType::kCylinder, {0.7, 0.7, 0, 0, 0, 1, 0.12}, &s);
  const int hole_b = AddSurface(NodeType::kCylinder, {-0.7, -0.7, 0, 0, 0, 1, 0.12}, &s);
  m.SetRoot(m.AddOperator(NodeType::kDifference, {body, hole_a, hole_b}, 0.1, 0.1, 0));
  s.box_min = Vec(-1.1, -1.1, -0.1);
  s.box_max = Vec(1.1, 1.1, 0.9);
  return s;
}

std::vector<GeneratedSolid> GeneratedParts() {
  return {FlangedShaftSolid(), LBracketSolid(), DomeOnPlateSolid()};
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
