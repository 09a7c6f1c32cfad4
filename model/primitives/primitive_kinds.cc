#include "model/primitives/primitive_kinds.h"

#include <algorithm>
#include <cmath>

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;
using R = FieldRole;

// The cube of half side `half` around c.
void Around(const Vec& c, double half, Vec* lo, Vec* hi) {
  *lo = c - Vec::Constant(half);
  *hi = c + Vec::Constant(half);
}

}  // namespace

const std::vector<PrimitiveKind>& PrimitiveKinds() {
  static const std::vector<PrimitiveKind> kinds = {
      {NodeType::kPlane,
       "plane",
       {{"normal", 3, R::kDirection}, {"offset", 1, R::kPlaneOffset}},
       // a unit cube around the foot of the origin on the plane
       [](const double* p, Vec* lo, Vec* hi) {
         const Vec n(p[0], p[1], p[2]);
         Around(n * p[3] / n.squaredNorm(), 1.0, lo, hi);
       }},
      {NodeType::kSphere,
       "sphere",
       {{"center", 3, R::kPosition}, {"radius", 1, R::kPositiveLength}},
       [](const double* p, Vec* lo, Vec* hi) {
         Around(Vec(p[0], p[1], p[2]), p[3] * 1.05, lo, hi);
       }},
      {NodeType::kCylinder,
       "cylinder",
       {{"point", 3, R::kAxisPoint}, {"axis", 3, R::kDirection}, {"radius", 1, R::kPositiveLength}},
       [](const double* p, Vec* lo, Vec* hi) {
         Around(Vec(p[0], p[1], p[2]), 2.0 * p[6], lo, hi);
       }},
      {NodeType::kCone,
       "cone",
       {{"apex", 3, R::kPosition}, {"axis", 3, R::kDirection}, {"half_angle", 1, R::kAngle}},
       // a unit length of the opening
       [](const double* p, Vec* lo, Vec* hi) {
         const Vec a = Vec(p[3], p[4], p[5]).normalized();
         Around(Vec(p[0], p[1], p[2]) + a, 1.0 + std::tan(p[6]), lo, hi);
       }},
      {NodeType::kTorus,
       "torus",
       {{"center", 3, R::kPosition},
        {"axis", 3, R::kDirection},
        {"major_radius", 1, R::kPositiveLength},
        {"minor_radius", 1, R::kPositiveLength}},
       [](const double* p, Vec* lo, Vec* hi) {
         Around(Vec(p[0], p[1], p[2]), (p[6] + p[7]) * 1.05, lo, hi);
       }},
      {NodeType::kEllipsoid,
       "ellipsoid",
       {{"center", 3, R::kPosition}, {"radii", 3, R::kPositiveLength}, {"axes", 6}},
       [](const double* p, Vec* lo, Vec* hi) {
         Around(Vec(p[0], p[1], p[2]), 1.05 * std::max({p[3], p[4], p[5]}), lo, hi);
       }},
      {NodeType::kQuadric,
       "quadric",
       {{"coefficients", 10}},
       [](const double*, Vec* lo, Vec* hi) { Around(Vec::Zero(), 2.0, lo, hi); }},
      {NodeType::kBox,
       "box",
       {{"center", 3, R::kPosition},
        {"axes", 4, R::kRotation},
        {"half_sizes", 3, R::kPositiveLength}},
       [](const double* p, Vec* lo, Vec* hi) {
         Around(Vec(p[0], p[1], p[2]), 1.05 * Vec(p[7], p[8], p[9]).norm(), lo, hi);
       }},
      {NodeType::kParaboloid,
       "paraboloid",
       {{"vertex", 3, R::kPosition}, {"axis", 3, R::kDirection}, {"curvature", 1}},
       // the cap |w| <= 1
       [](const double* p, Vec* lo, Vec* hi) { Around(Vec(p[0], p[1], p[2]), 1.0, lo, hi); }},
  };
  return kinds;
}

const PrimitiveKind* FindPrimitiveKind(NodeType type) {
  for (const PrimitiveKind& kind : PrimitiveKinds())
    if (kind.type == type) return &kind;
  return nullptr;
}

int DegreesOfFreedom(const ParameterField& field) {
  switch (field.role) {
    case FieldRole::kDirection:
    case FieldRole::kAxisPoint:
      return 2;
    case FieldRole::kRotation:
      return 3;
    case FieldRole::kPlain:
    case FieldRole::kPosition:
    case FieldRole::kPlaneOffset:
    case FieldRole::kPositiveLength:
    case FieldRole::kAngle:
      return field.size;
  }
  return field.size;
}

bool FindFieldWithRole(const std::vector<ParameterField>& fields, FieldRole role, int* offset) {
  int k = 0;
  for (const ParameterField& f : fields) {
    if (f.role == role) {
      if (offset) *offset = k;
      return true;
    }
    k += f.size;
  }
  return false;
}

}  // namespace implicitfit
