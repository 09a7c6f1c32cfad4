#include "fit/splines/parameter_frame.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace implicitfit {
namespace {

using Vec2 = Eigen::Vector2d;

double Cross(const Vec2& o, const Vec2& a, const Vec2& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

// Andrew's monotone chain, counter-clockwise, without collinear points.
std::vector<Vec2> ConvexHull(std::vector<Vec2> p) {
  std::sort(p.begin(), p.end(),
            [](const Vec2& a, const Vec2& b) { return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]); });
  if (p.size() < 3) return p;
  std::vector<Vec2> hull(2 * p.size());
  size_t k = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && Cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
    hull[k++] = p[i];
  }
  for (size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && Cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
    hull[k++] = p[i];
  }
  hull.resize(k - 1);
  return hull;
}

}  // namespace

Eigen::Vector2d ParameterFrame::Parameters(const Eigen::Vector3d& x) const {
  const Eigen::Vector3d d = x - origin;
  return Eigen::Vector2d(d.dot(e_u) / length_u, d.dot(e_v) / length_v);
}

ParameterFrame FitParameterFrame(const std::vector<Eigen::Vector3d>& points,
                                 const std::vector<Eigen::Vector3d>& normals) {
  if (points.size() < 3) throw std::invalid_argument("a surface needs at least 3 points");
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points) centroid += p;
  centroid /= static_cast<double>(points.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& p : points) cov += (p - centroid) * (p - centroid).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  Eigen::Vector3d w = eig.eigenvectors().col(0);
  if (!normals.empty()) {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& n : normals) mean += n;
    if (mean.dot(w) < 0) w = -w;
  }
  Eigen::Vector3d a = eig.eigenvectors().col(2);
  Eigen::Vector3d b = w.cross(a);
  std::vector<Vec2> flat;
  flat.reserve(points.size());
  for (const Eigen::Vector3d& p : points) flat.emplace_back((p - centroid).dot(a), (p - centroid).dot(b));
  const std::vector<Vec2> hull = ConvexHull(flat);
  if (hull.size() < 3) throw std::invalid_argument("the points are collinear: no surface");
  double best_area = INFINITY;
  ParameterFrame frame;
  frame.normal = w;
  for (size_t i = 0; i < hull.size(); ++i) {
    Vec2 edge = hull[(i + 1) % hull.size()] - hull[i];
    if (!(edge.norm() > 0)) continue;
    edge.normalize();
    const Vec2 across(-edge[1], edge[0]);
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (const Vec2& q : hull) {
      const double s[2] = {q.dot(edge), q.dot(across)};
      for (int k = 0; k < 2; ++k) {
        lo[k] = std::min(lo[k], s[k]);
        hi[k] = std::max(hi[k], s[k]);
      }
    }
    const double area = (hi[0] - lo[0]) * (hi[1] - lo[1]);
    if (area < best_area) {
      best_area = area;
      // e_u along the longer side; e_u x e_v = w keeps S_u x S_v on the normals' side.
      Vec2 du = edge, dv = across;
      double lu = hi[0] - lo[0], lv = hi[1] - lo[1], ou = lo[0], ov = lo[1];
      if (lv > lu) {  // swap the sides, keeping the orientation: (du, dv) -> (dv, -du)
        std::swap(lu, lv);
        const Vec2 t = du;
        du = dv;
        dv = -t;
        const double o = ou;
        ou = ov;
        ov = -(o + lv);  // the new v coordinate is -old u: its minimum is -(old max)
      }
      frame.e_u = du[0] * a + du[1] * b;
      frame.e_v = dv[0] * a + dv[1] * b;
      frame.length_u = lu;
      frame.length_v = lv;
      frame.origin = centroid + ou * frame.e_u + ov * frame.e_v;
    }
  }
  if (!(frame.length_v > 0)) throw std::invalid_argument("the points are collinear: no surface");
  return frame;
}

}  // namespace implicitfit
