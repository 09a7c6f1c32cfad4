#include "fit/tree/shape_starts.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "fit/primitive/primitive_fitter.h"
#include "model/median.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

PrimitiveFitResult RobustFit(NodeType kind, const std::vector<Vec>& points,
                             const std::vector<Vec>& normals, unsigned seed) {
  PrimitiveFitOptions options;
  options.kind = kind;
  options.seed = seed;
  options.compute_covariance = false;
  return FitPrimitive(points, normals, options);
}

ShapeStart Failed(const std::string& why) {
  ShapeStart s;
  s.message = why;
  return s;
}

ShapeStart ParaboloidStart(const std::vector<Vec>& points, const std::vector<Vec>& normals,
                           unsigned seed) {
  const PrimitiveFitResult sphere = RobustFit(NodeType::kSphere, points, normals, seed);
  if (!sphere.success) return Failed("no osculating sphere for the start: " + sphere.message);
  const Vec c(sphere.parameters[0], sphere.parameters[1], sphere.parameters[2]);
  const double radius = sphere.parameters[3];
  Vec centroid = Vec::Zero();
  double outward = 0.0;
  for (int i : sphere.inliers) {
    centroid += points[i];
    if (!normals.empty()) outward += normals[i].dot((points[i] - c).normalized());
  }
  centroid /= static_cast<double>(sphere.inliers.size());
  Vec dir = (centroid - c).normalized();
  if (!dir.allFinite()) return Failed("the sphere's inliers surround its centre: no cap");
  const Vec vertex = c + radius * dir;
  double kappa = 1.0 / radius;
  if (outward < 0) dir = -dir, kappa = -kappa;  // normals point to the centre: concave
  ShapeStart s;
  s.model.AddPrimitive(NodeType::kParaboloid,
                       {vertex.x(), vertex.y(), vertex.z(), dir.x(), dir.y(), dir.z(), kappa});
  s.success = true;
  return s;
}

ShapeStart CapsuleStart(const std::vector<Vec>& points, const std::vector<Vec>& normals,
                        unsigned seed) {
  const PrimitiveFitResult cylinder = RobustFit(NodeType::kCylinder, points, normals, seed);
  if (!cylinder.success) return Failed("no cylinder for the start: " + cylinder.message);
  const std::vector<double>& p = cylinder.parameters;
  const Vec origin(p[0], p[1], p[2]), axis = Vec(p[3], p[4], p[5]).normalized();
  double lo = 1e300, hi = -1e300;
  for (int i : cylinder.inliers) {
    const double t = (points[i] - origin).dot(axis);
    lo = std::min(lo, t);
    hi = std::max(hi, t);
  }
  const Vec a = origin + lo * axis, b = origin + hi * axis;
  ShapeStart s;
  s.model.AddSkeletonOffset(SkeletonKind::kSegments, {a.x(), a.y(), a.z(), b.x(), b.y(), b.z()},
                            p[6]);
  s.success = true;
  return s;
}

ShapeStart BoxStart(const std::vector<Vec>& points, const std::vector<Vec>& normals,
                    unsigned seed) {
  if (normals.size() != points.size()) return Failed("the box start needs normals");
  const PrimitiveFitResult first = RobustFit(NodeType::kPlane, points, normals, seed);
  if (!first.success) return Failed("no first face: " + first.message);
  const Vec e1 = Vec(first.parameters[0], first.parameters[1], first.parameters[2]).normalized();
  std::vector<Vec> side_points, side_normals;
  for (size_t i = 0; i < points.size(); ++i)
    if (std::abs(normals[i].dot(e1)) < 0.3)
      side_points.push_back(points[i]), side_normals.push_back(normals[i]);
  if (side_points.size() < 10) return Failed("no points on faces perpendicular to the first");
  const PrimitiveFitResult second = RobustFit(NodeType::kPlane, side_points, side_normals, seed);
  if (!second.success) return Failed("no second face: " + second.message);
  Vec e2(second.parameters[0], second.parameters[1], second.parameters[2]);
  e2 = (e2 - e2.dot(e1) * e1).normalized();
  const Vec e3 = e1.cross(e2);
  const Vec axes[3] = {e1, e2, e3};
  Vec centre, half;
  for (int k = 0; k < 3; ++k) {
    std::vector<double> plus, minus, all;
    for (size_t i = 0; i < points.size(); ++i) {
      const double along = normals[i].dot(axes[k]), s = points[i].dot(axes[k]);
      if (along > 0.9)
        plus.push_back(s);
      else if (along < -0.9)
        minus.push_back(s);
      else
        all.push_back(s);
    }
    if (all.empty() && (plus.empty() || minus.empty()))
      return Failed("too few faces seen to bound the box");
    std::sort(all.begin(), all.end());
    // A face not seen: the extent of the other faces' points (5% trimmed against outliers).
    const double hi = plus.empty() ? all[all.size() * 95 / 100] : Median(plus);
    const double lo = minus.empty() ? all[all.size() * 5 / 100] : Median(minus);
    if (!(hi > lo)) return Failed("degenerate box extent along an axis");
    centre[k] = (hi + lo) / 2;
    half[k] = (hi - lo) / 2;
  }
  Eigen::Matrix3d r;
  r << e1, e2, e3;
  const Vec c = r * centre;  // centre was in the (e1, e2, e3) coordinates
  const Eigen::Quaterniond q(r);
  ShapeStart s;
  s.model.AddPrimitive(NodeType::kBox, {c.x(), c.y(), c.z(), q.w(), q.x(), q.y(), q.z(), half.x(),
                                        half.y(), half.z()});
  s.success = true;
  return s;
}

}  // namespace

bool IsShapeStartKind(const std::string& kind) {
  return kind == "paraboloid" || kind == "capsule" || kind == "box";
}

ShapeStart RobustShapeStart(const std::string& kind, const std::vector<Vec>& points,
                            const std::vector<Vec>& normals, unsigned seed) {
  if (kind == "paraboloid") return ParaboloidStart(points, normals, seed);
  if (kind == "capsule") return CapsuleStart(points, normals, seed);
  if (kind == "box") return BoxStart(points, normals, seed);
  return Failed("no robust start for kind '" + kind + "'");
}

}  // namespace implicitfit
