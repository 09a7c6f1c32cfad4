#include "fit/reconstruct/solid_bounding.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

// The direction a one-node primitive defines (plane normal, axis), or zero.
Vec DirectionOf(const Model& m) {
  const ModelNode& node = m.nodes()[m.root()];
  if (m.nodes().size() != 1) return Vec::Zero();
  const double* p = m.parameters().data() + node.first_parameter;
  switch (node.type) {
    case NodeType::kPlane:
      return Vec(p[0], p[1], p[2]);
    case NodeType::kCylinder:
    case NodeType::kCone:
    case NodeType::kTorus:
      return Vec(p[3], p[4], p[5]);
    default:
      return Vec::Zero();
  }
}

}  // namespace

Model PlaneLiteral::ToModel(const std::string& name) const {
  Model m;
  m.SetRoot(m.AddPrimitive(NodeType::kPlane, {normal.x(), normal.y(), normal.z(), offset}, name));
  m.mutable_nodes()[m.root()].fixed = {"normal", "offset"};
  return m;
}

std::vector<Vec> SeparatorDirections(const std::vector<Model>& primitives) {
  std::vector<Vec> candidates;
  for (const Model& m : primitives) candidates.push_back(DirectionOf(m));
  candidates.push_back(Vec::UnitX());
  candidates.push_back(Vec::UnitY());
  candidates.push_back(Vec::UnitZ());
  std::vector<Vec> directions;
  const double same = std::cos(M_PI / 180.0);
  for (const Vec& c : candidates) {
    if (!(c.norm() > 0)) continue;
    const Vec d = c.normalized();
    bool known = false;
    for (const Vec& e : directions) known = known || std::abs(d.dot(e)) > same;
    if (!known) directions.push_back(d);
  }
  return directions;
}

StumpSplit BestStump(const std::vector<Vec>& x, const std::vector<bool>& inside,
                     const std::vector<Vec>& directions) {
  StumpSplit best;
  const int n = static_cast<int>(x.size());
  if (n < 2) return best;
  const int total_in = static_cast<int>(std::count(inside.begin(), inside.end(), true));
  const int total_out = n - total_in;
  double best_gap = 0;
  best.errors = std::min(total_in, total_out);  // no split: the minority is wrong
  std::vector<std::pair<double, bool>> s(n);
  for (const Vec& d : directions) {
    for (int i = 0; i < n; ++i) s[i] = {d.dot(x[i]), inside[i]};
    std::sort(s.begin(), s.end());
    int in_left = 0;
    for (int i = 1; i < n; ++i) {  // split between s[i - 1] and s[i]
      in_left += s[i - 1].second;
      const int out_left = i - in_left;
      const double gap = s[i].first - s[i - 1].first;
      if (!(gap > 0)) continue;
      // left inside: wrong are the outside samples on the left and inside ones on the right.
      const int left_in_errors = out_left + (total_in - in_left);
      const int right_in_errors = in_left + (total_out - out_left);
      const int errors = std::min(left_in_errors, right_in_errors);
      if (errors < best.errors || (errors == best.errors && best.found && gap > best_gap)) {
        best.found = true;
        best.errors = errors;
        best_gap = gap;
        const double c = 0.5 * (s[i].first + s[i - 1].first);
        if (left_in_errors <= right_in_errors)
          best.plane = {d, c};  // f = d . x - c < 0 on the left
        else
          best.plane = {-d, -c};
      }
    }
  }
  return best;
}

Eigen::Matrix3d ClosureFrame(const std::vector<Model>& primitives,
                             const std::vector<int>& assigned_points,
                             const std::vector<Vec>& points) {
  std::vector<int> planes;
  for (int k = 0; k < static_cast<int>(primitives.size()); ++k)
    if (primitives[k].nodes().size() == 1 && primitives[k].nodes()[0].type == NodeType::kPlane &&
        assigned_points[k] > 0)
      planes.push_back(k);
  std::stable_sort(planes.begin(), planes.end(),
                   [&](int a, int b) { return assigned_points[a] > assigned_points[b]; });
  Eigen::Matrix3d frame;
  if (!planes.empty()) {
    const Vec a0 = DirectionOf(primitives[planes[0]]).normalized();
    // the plane most orthogonal to the first (ties: the one with more points)
    int second = -1;
    double least = 0.2;  // |cos| below this: at least 78 degrees apart
    for (size_t j = 1; j < planes.size(); ++j) {
      const double c = std::abs(a0.dot(DirectionOf(primitives[planes[j]]).normalized()));
      if (c < least - 1e-9) {
        least = c;
        second = planes[j];
      }
    }
    if (second >= 0) {
      Vec a1 = DirectionOf(primitives[second]).normalized();
      a1 = (a1 - a1.dot(a0) * a0).normalized();
      frame.row(0) = a0;
      frame.row(1) = a1;
      frame.row(2) = a0.cross(a1);
      return frame;
    }
  }
  Vec mean = Vec::Zero();
  for (const Vec& p : points) mean += p;
  mean /= std::max<size_t>(1, points.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Vec& p : points) cov += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  frame = eig.eigenvectors().transpose();
  return frame;
}

std::vector<PlaneLiteral> ClosureBox(const Eigen::Matrix3d& frame, const std::vector<Vec>& points,
                                     double margin) {
  Vec lo = Vec::Constant(1e300), hi = Vec::Constant(-1e300);
  for (const Vec& p : points) {
    const Vec q = frame * p;
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  std::vector<PlaneLiteral> faces;
  for (int a = 0; a < 3; ++a) {
    const Vec axis = frame.row(a).transpose();
    faces.push_back({-axis, -(lo[a] - margin)});  // -axis . x - (-(lo - m)) < 0: above lo - m
    faces.push_back({axis, hi[a] + margin});
  }
  return faces;
}

}  // namespace implicitfit
