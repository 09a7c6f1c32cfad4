#include "fit/tree/design_builder.h"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;
using Vec6 = Eigen::Matrix<double, 6, 1>;

}  // namespace

bool IsDesignPrimitive(const std::string& primitive) {
  return primitive == "plane" || primitive == "paraboloid";
}

bool IsDesignSmoothing(const std::string& smoothing) {
  return smoothing == "li-phillips" || smoothing == "convex";
}

std::vector<OrientedRepresentative> PickRepresentatives(const std::vector<Vec>& points,
                                                        const std::vector<Vec>& normals, int count,
                                                        bool with_curvature) {
  const int n = static_cast<int>(points.size());
  if (count < 1) throw std::invalid_argument("the representative count must be >= 1");
  if (n < count || static_cast<int>(normals.size()) != n)
    throw std::invalid_argument("fewer oriented points than representatives asked for");
  Vec lo = points[0], hi = points[0], mean = Vec::Zero();
  for (const Vec& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p), mean += p;
  mean /= n;
  const double scale = std::max((hi - lo).norm(), 1e-300);
  std::vector<Vec6> feature(n);
  for (int i = 0; i < n; ++i) {
    feature[i] << points[i] / scale, 2.0 * normals[i].normalized();
  }
  // Farthest-point seeds from the point nearest the centroid.
  std::vector<Vec6> centre;
  int first = 0;
  for (int i = 1; i < n; ++i)
    if ((points[i] - mean).squaredNorm() < (points[first] - mean).squaredNorm()) first = i;
  centre.push_back(feature[first]);
  std::vector<double> nearest(n, std::numeric_limits<double>::infinity());
  while (static_cast<int>(centre.size()) < count) {
    int far = 0;
    for (int i = 0; i < n; ++i) {
      nearest[i] = std::min(nearest[i], (feature[i] - centre.back()).squaredNorm());
      if (nearest[i] > nearest[far]) far = i;
    }
    centre.push_back(feature[far]);
  }
  std::vector<int> label(n, 0);
  for (int round = 0; round < 50; ++round) {
    bool changed = false;
    for (int i = 0; i < n; ++i) {
      int best = 0;
      for (int c = 1; c < count; ++c)
        if ((feature[i] - centre[c]).squaredNorm() < (feature[i] - centre[best]).squaredNorm())
          best = c;
      changed |= best != label[i];
      label[i] = best;
    }
    std::vector<Vec6> sum(count, Vec6::Zero());
    std::vector<int> size(count, 0);
    for (int i = 0; i < n; ++i) sum[label[i]] += feature[i], ++size[label[i]];
    for (int c = 0; c < count; ++c)
      if (size[c] > 0) centre[c] = sum[c] / size[c];
    if (!changed && round > 0) break;
  }
  std::vector<OrientedRepresentative> out;
  for (int c = 0; c < count; ++c) {
    Vec position = Vec::Zero(), normal = Vec::Zero();
    int size = 0;
    for (int i = 0; i < n; ++i)
      if (label[i] == c) position += points[i], normal += normals[i].normalized(), ++size;
    if (size == 0 || !(normal.norm() > 0)) continue;
    position /= size;
    int medoid = -1;
    for (int i = 0; i < n; ++i)
      if (label[i] == c && (medoid < 0 || (points[i] - position).squaredNorm() <
                                              (points[medoid] - position).squaredNorm()))
        medoid = i;
    OrientedRepresentative r{points[medoid], normal.normalized(), 0.0};
    if (with_curvature) {
      double num = 0, den = 0;
      for (int i = 0; i < n; ++i) {
        if (label[i] != c) continue;
        const Vec u = points[i] - r.point;
        const double h = r.normal.dot(u), w2 = (u - h * r.normal).squaredNorm();
        num += h * w2;
        den += w2 * w2;
      }
      r.curvature = den > 0 ? -2.0 * num / den : 0.0;
    }
    out.push_back(r);
  }
  return out;
}

std::vector<double> EnclosingEllipsoid(const std::vector<Vec>& points) {
  Vec mean = Vec::Zero();
  for (const Vec& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Vec& p : points) cov += (p - mean) * (p - mean).transpose();
  cov /= static_cast<double>(points.size());
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  const Vec sd =
      eig.eigenvalues().cwiseMax(1e-12 * eig.eigenvalues().maxCoeff() + 1e-300).cwiseSqrt();
  double reach = 0;
  for (const Vec& p : points)
    reach = std::max(reach, (eig.eigenvectors().transpose() * (p - mean)).cwiseQuotient(sd).norm());
  const Vec r = 1.25 * reach * sd;
  const Vec e1 = eig.eigenvectors().col(0), e2 = eig.eigenvectors().col(1);
  return {mean.x(), mean.y(), mean.z(), r.x(),  r.y(),  r.z(),
          e1.x(),   e1.y(),   e1.z(),   e2.x(), e2.y(), e2.z()};
}

std::vector<double> EnclosingBox(const std::vector<Vec>& points) {
  Vec mean = Vec::Zero();
  for (const Vec& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Vec& p : points) cov += (p - mean) * (p - mean).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  Eigen::Matrix3d axes = eig.eigenvectors();
  if (axes.determinant() < 0) axes.col(2) = -axes.col(2);  // a rotation
  Vec reach = Vec::Zero();
  for (const Vec& p : points) reach = reach.cwiseMax((axes.transpose() * (p - mean)).cwiseAbs());
  const double floor = 1e-6 * std::max(reach.maxCoeff(), 1e-300);
  const Vec h = 1.25 * reach.cwiseMax(floor);
  const Eigen::Quaterniond q(axes);
  return {mean.x(), mean.y(), mean.z(), q.w(), q.x(), q.y(), q.z(), h.x(), h.y(), h.z()};
}

Model DesignModel(const std::vector<OrientedRepresentative>& representatives,
                  const std::vector<double>& base, const DesignOptions& options) {
  if (!IsDesignPrimitive(options.primitive))
    throw std::invalid_argument("the design primitive must be plane or paraboloid, not '" +
                                options.primitive + "'");
  if (!IsDesignSmoothing(options.smoothing))
    throw std::invalid_argument("the design smoothing must be li-phillips or convex, not '" +
                                options.smoothing + "'");
  const bool convex = options.smoothing == "convex";
  if (!(options.delta > 0) || (!convex && (!(options.epsilon > 0) || options.epsilon > options.delta)))
    throw std::invalid_argument("need 0 < epsilon <= delta");
  Model m;
  std::vector<int> children = {
      m.AddPrimitive(convex ? NodeType::kBox : NodeType::kEllipsoid, base, "base")};
  for (const OrientedRepresentative& r : representatives) {
    const Vec n = r.normal.normalized();
    if (options.primitive == "plane")
      children.push_back(m.AddPrimitive(NodeType::kPlane, {n.x(), n.y(), n.z(), n.dot(r.point)}));
    else
      children.push_back(m.AddPrimitive(
          NodeType::kParaboloid, {r.point.x(), r.point.y(), r.point.z(), n.x(), n.y(), n.z(),
                                  convex ? std::max(r.curvature, 0.0) : r.curvature}));
  }
  // A convex blend's epsilon slot is unused (kept equal to delta, model/model.h).
  const int op = m.AddOperator(NodeType::kIntersection, children, options.delta,
                               convex ? options.delta : options.epsilon, options.order);
  if (convex) m.mutable_nodes()[op].smoothing = BlendSmoothing::kConvex;
  return m;
}

Model DesignFromOrientedPoints(const std::vector<Vec>& points, const std::vector<Vec>& normals,
                               DesignOptions options) {
  if (!IsDesignPrimitive(options.primitive))
    throw std::invalid_argument("the design primitive must be plane or paraboloid, not '" +
                                options.primitive + "'");
  if (options.order < 0 || options.order > UnitStep::kMaxOrder)
    throw std::invalid_argument("the blend order must be in 0.." +
                                std::to_string(UnitStep::kMaxOrder));
  Vec lo = points.empty() ? Vec::Zero() : points[0], hi = lo;
  for (const Vec& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  if (options.delta <= 0) options.delta = 0.02 * (hi - lo).norm();
  if (options.epsilon <= 0) options.epsilon = 0.5 * options.delta;
  const std::vector<OrientedRepresentative> reps =
      PickRepresentatives(points, normals, options.count, options.primitive == "paraboloid");
  return DesignModel(
      reps, options.smoothing == "convex" ? EnclosingBox(points) : EnclosingEllipsoid(points),
      options);
}

}  // namespace implicitfit
