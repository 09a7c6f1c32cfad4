#include "datasets/generators/cad_solids.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

// Adds primitives in the solid's own frame, turned by CadSolidRotation() into the model's.
class RotatedBuilder {
 public:
  explicit RotatedBuilder(Model* m, const Eigen::Matrix3d& r = CadSolidRotation())
      : m_(m), r_(r) {}
  // The half-space n . x <= d (n unit, own frame).
  int Plane(const Vec& n, double d) {
    const Vec rn = r_ * n.normalized();
    return m_->AddPrimitive(NodeType::kPlane, {rn.x(), rn.y(), rn.z(), d});
  }
  int Cylinder(const Vec& q, const Vec& a, double radius) {
    const Vec rq = r_ * q, ra = r_ * a;
    return m_->AddPrimitive(NodeType::kCylinder,
                            {rq.x(), rq.y(), rq.z(), ra.x(), ra.y(), ra.z(), radius});
  }
  int Paraboloid(const Vec& vertex, const Vec& axis, double curvature) {
    const Vec rv = r_ * vertex, ra = r_ * axis;
    return m_->AddPrimitive(NodeType::kParaboloid,
                            {rv.x(), rv.y(), rv.z(), ra.x(), ra.y(), ra.z(), curvature});
  }
  // q(x) = x^T A x + 2 b . x + c <= 0 (own frame).
  int Quadric(const Eigen::Matrix3d& a, const Vec& b, double c) {
    const Eigen::Matrix3d ra = r_ * a * r_.transpose();
    const Vec rb = r_ * b;
    return m_->AddPrimitive(NodeType::kQuadric, {ra(0, 0), ra(1, 1), ra(2, 2), ra(0, 1), ra(0, 2),
                                                 ra(1, 2), rb.x(), rb.y(), rb.z(), c});
  }
  // The sharp box lo <= x <= hi, less the faces listed in `skip` (0..5: -x, +x, -y, +y, -z, +z).
  std::vector<int> BoxFaces(const Vec& lo, const Vec& hi, std::vector<int> skip = {}) {
    std::vector<int> faces;
    for (int a = 0; a < 3; ++a)
      for (int s = 0; s < 2; ++s) {
        if (std::find(skip.begin(), skip.end(), 2 * a + s) != skip.end()) continue;
        Vec n = Vec::Zero();
        n[a] = s ? 1.0 : -1.0;
        faces.push_back(Plane(n, s ? hi[a] : -lo[a]));
      }
    return faces;
  }
  int Sharp(NodeType op, std::vector<int> children) {
    return m_->AddOperator(op, std::move(children), 0.1, 0.1, 0);
  }
  int Filleted(NodeType op, std::vector<int> children, double delta) {
    return m_->AddOperator(op, std::move(children), delta, 0.8 * delta, 3);
  }

 private:
  Model* m_;
  Eigen::Matrix3d r_;
};

// The box around the own-frame box [lo, hi] turned by r (its 8 corners turned).
void RotatedBox(const Vec& lo, const Vec& hi, CadSolid* s,
                const Eigen::Matrix3d& r = CadSolidRotation()) {
  s->box_min = Vec::Constant(1e300);
  s->box_max = -s->box_min;
  for (int c = 0; c < 8; ++c) {
    const Vec p(c & 1 ? hi.x() : lo.x(), c & 2 ? hi.y() : lo.y(), c & 4 ? hi.z() : lo.z());
    s->box_min = s->box_min.cwiseMin(r * p);
    s->box_max = s->box_max.cwiseMax(r * p);
  }
  const Vec margin = 0.05 * (s->box_max - s->box_min);
  s->box_min -= margin;
  s->box_max += margin;
}

}  // namespace

Eigen::Matrix3d CadSolidRotation() {
  return Eigen::AngleAxisd(0.5, Vec(1, 2, 3).normalized()).toRotationMatrix();
}

CadSolid BracketSolid() {
  CadSolid s;
  s.name = "bracket";
  RotatedBuilder b(&s.truth);
  const int base = b.Sharp(NodeType::kIntersection, b.BoxFaces(Vec(-1, -0.6, -0.5), Vec(1, 0.6, -0.2)));
  const int upright =
      b.Sharp(NodeType::kIntersection, b.BoxFaces(Vec(-0.85, -0.45, -0.4), Vec(-0.45, 0.45, 0.7)));
  const int body = b.Filleted(NodeType::kUnion, {base, upright}, 0.1);
  const int bore = b.Cylinder(Vec(0, 0, 0.25), Vec(1, 0, 0), 0.2);
  s.truth.SetRoot(b.Sharp(NodeType::kDifference, {body, bore}));
  RotatedBox(Vec(-1, -0.6, -0.5), Vec(1, 0.6, 0.7), &s);
  return s;
}

CadSolid DomedBlockSolid() {
  CadSolid s;
  s.name = "domed block";
  RotatedBuilder b(&s.truth);
  std::vector<int> faces = b.BoxFaces(Vec(-1, -0.7, -0.4), Vec(1, 0.7, 1), {5});
  faces.push_back(b.Paraboloid(Vec(0, 0, 0.4), Vec(0, 0, 1), 0.6));
  s.truth.SetRoot(b.Sharp(NodeType::kIntersection, faces));
  RotatedBox(Vec(-1, -0.7, -0.4), Vec(1, 0.7, 0.4), &s);
  return s;
}

CadSolid FlangeSolid() {
  CadSolid s;
  s.name = "flange";
  RotatedBuilder b(&s.truth);
  const Vec z(0, 0, 1);
  const int disc = b.Sharp(NodeType::kIntersection,
                           {b.Cylinder(Vec::Zero(), z, 1.0), b.Plane(z, 0.15), b.Plane(-z, 0.15)});
  const int boss = b.Sharp(NodeType::kIntersection,
                           {b.Cylinder(Vec::Zero(), z, 0.4), b.Plane(z, 0.8), b.Plane(-z, 0.0)});
  const int body = b.Filleted(NodeType::kUnion, {disc, boss}, 0.12);
  s.truth.SetRoot(b.Sharp(NodeType::kDifference, {body, b.Cylinder(Vec::Zero(), z, 0.2)}));
  RotatedBox(Vec(-1, -1, -0.15), Vec(1, 1, 0.8), &s);
  return s;
}

CadSolid ChamferedBlockSolid() {
  CadSolid s;
  s.name = "chamfered block";
  RotatedBuilder b(&s.truth);
  std::vector<int> faces = b.BoxFaces(Vec(-1, -0.6, -0.4), Vec(1, 0.6, 0.4));
  faces.push_back(b.Plane(Vec(1, 0, 1), (1.0 + 0.4 - 0.3) / std::sqrt(2.0)));
  faces.push_back(b.Plane(Vec(0, -1, 1), (0.6 + 0.4 - 0.25) / std::sqrt(2.0)));
  s.truth.SetRoot(b.Sharp(NodeType::kIntersection, faces));
  RotatedBox(Vec(-1, -0.6, -0.4), Vec(1, 0.6, 0.4), &s);
  return s;
}

CadSolid SaddleBlockSolid() {
  CadSolid s;
  s.name = "saddle block";
  RotatedBuilder b(&s.truth);
  std::vector<int> faces = b.BoxFaces(Vec(-1, -0.7, -0.4), Vec(1, 0.7, 1), {5});
  // z - 0.35 - 0.125 (x^2 - y^2) <= 0: A = diag(-0.125, 0.125, 0), 2 b = (0, 0, 1), c = -0.35.
  faces.push_back(b.Quadric(Eigen::Vector3d(-0.125, 0.125, 0).asDiagonal(), Vec(0, 0, 0.5), -0.35));
  s.truth.SetRoot(b.Sharp(NodeType::kIntersection, faces));
  RotatedBox(Vec(-1, -0.7, -0.4), Vec(1, 0.7, 0.5), &s);
  return s;
}

CadSolid HeldOutPartSolid() {
  CadSolid s;
  s.name = "held-out stepped part";
  const Eigen::Matrix3d r = Eigen::AngleAxisd(0.7, Vec(2, -1, 1).normalized()).toRotationMatrix();
  RotatedBuilder b(&s.truth, r);
  const int lower =
      b.Sharp(NodeType::kIntersection, b.BoxFaces(Vec(-1, -0.6, -0.4), Vec(1, 0.6, 0.0)));
  std::vector<int> upper_faces = b.BoxFaces(Vec(-1, -0.6, -0.4), Vec(0.2, 0.6, 1), {5});
  // z - 0.45 - 0.12 x y + 0.08 y^2 <= 0: A = [[0, -0.06, 0], [-0.06, 0.08, 0], [0, 0, 0]],
  // 2 b = (0, 0, 1), c = -0.45.
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  a(0, 1) = a(1, 0) = -0.06;
  a(1, 1) = 0.08;
  upper_faces.push_back(b.Quadric(a, Vec(0, 0, 0.5), -0.45));
  const int upper = b.Sharp(NodeType::kIntersection, upper_faces);
  const int body = b.Sharp(NodeType::kUnion, {lower, upper});
  // A sharp bevel across the lower step's far end: the plane through (0.8, 0, 0) whose normal
  // leans 30 degrees up from +x (120 degrees to the top face, 150 to the end face).
  const Vec bevel_normal(std::sqrt(3.0) / 2, 0, 0.5);
  const int bevel = b.Plane(bevel_normal, bevel_normal.dot(Vec(0.8, 0, 0)));
  s.truth.SetRoot(b.Sharp(NodeType::kIntersection, {body, bevel}));
  RotatedBox(Vec(-1, -0.6, -0.4), Vec(1, 0.6, 0.6), &s, r);
  return s;
}

std::vector<CadSolid> AllCadSolids() {
  return {BracketSolid(), DomedBlockSolid(), FlangeSolid(), ChamferedBlockSolid(),
          SaddleBlockSolid()};
}

}  // namespace implicitfit
