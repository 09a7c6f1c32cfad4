#include "fit/reconstruct/term_bounds.h"

#include <Eigen/Geometry>
#include <cmath>

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

constexpr double kEps = 0.017452406437283512;  // sin(1 deg)

struct Cone {
  Vec u;
  double cos_alpha;
};

}  // namespace

bool TermIsBounded(const std::vector<Model>& literals, std::uint64_t positives) {
  std::vector<Vec> planes, lines;
  std::vector<Cone> cones;
  for (size_t k = 0; k < literals.size() && k < 64; ++k) {
    if (!(positives >> k & 1)) continue;
    const Model& m = literals[k];
    const ModelNode& node = m.nodes()[m.root()];
    const double* p = m.parameters().data() + node.first_parameter;
    switch (node.type) {
      case NodeType::kSphere:
      case NodeType::kTorus:
      case NodeType::kEllipsoid:
      case NodeType::kBox:
        return true;
      case NodeType::kPlane:
        planes.push_back(Vec(p[0], p[1], p[2]).normalized());
        break;
      case NodeType::kCylinder:
        lines.push_back(Vec(p[3], p[4], p[5]).normalized());
        break;
      case NodeType::kCone:
        cones.push_back({Vec(p[3], p[4], p[5]).normalized(), std::cos(p[6])});
        break;
      default:
        break;  // no known bound
    }
  }
  // v is an (almost) unbounded direction of every literal.
  auto recedes = [&](const Vec& v) {
    if (!(v.squaredNorm() > 0.5) || !v.allFinite()) return false;
    for (const Vec& n : planes)
      if (n.dot(v) > kEps) return false;
    for (const Vec& a : lines)
      if (std::abs(a.dot(v)) < 1 - 1e-9) return false;
    for (const Cone& c : cones)
      if (c.u.dot(v) < c.cos_alpha - kEps) return false;
    return true;
  };
  std::vector<Vec> candidates;
  if (!lines.empty()) {
    candidates = {lines[0], -lines[0]};
  } else {
    const size_t P = planes.size();
    if (P == 0) candidates.push_back(Vec::UnitX());  // no plane, no line: any direction
    for (size_t i = 0; i < P; ++i) {
      candidates.push_back(-planes[i]);
      for (size_t j = i + 1; j < P; ++j) {
        candidates.push_back(-(planes[i] + planes[j]).normalized());
        const Vec e = planes[i].cross(planes[j]);
        if (e.norm() > 1e-12) {
          candidates.push_back(e.normalized());
          candidates.push_back(-e.normalized());
        }
        for (size_t k = j + 1; k < P; ++k) {
          const Vec w = (planes[j] - planes[i]).cross(planes[k] - planes[i]);
          if (w.norm() < 1e-12) continue;
          candidates.push_back(w.normalized());
          candidates.push_back(-w.normalized());
        }
      }
    }
    // Rank-deficient normals (all parallel): directions along the planes.
    if (P > 0) {
      const Vec a = planes[0].unitOrthogonal(), b = planes[0].cross(a);
      candidates.push_back(a);
      candidates.push_back(-a);
      candidates.push_back(b);
      candidates.push_back(-b);
    }
    for (const Cone& c : cones) {
      candidates.push_back(c.u);
      const double s = std::sqrt(std::max(0.0, 1 - c.cos_alpha * c.cos_alpha));
      for (const Vec& n : planes) {
        // Rays v = cos(alpha) u + sin(alpha) (cos t e1 + sin t e2) with n . v = 0.
        const Vec e1 = c.u.unitOrthogonal(), e2 = c.u.cross(e1);
        const double A = s * n.dot(e1), B = s * n.dot(e2), C = c.cos_alpha * n.dot(c.u);
        const double R = std::hypot(A, B);
        if (!(R > 1e-12) || std::abs(C) > R) continue;
        const double phase = std::atan2(B, A), delta = std::acos(-C / R);
        for (const double t : {phase + delta, phase - delta})
          candidates.push_back(c.cos_alpha * c.u + s * (std::cos(t) * e1 + std::sin(t) * e2));
      }
    }
  }
  for (const Vec& v : candidates)
    if (recedes(v)) return false;
  return true;
}

}  // namespace implicitfit
