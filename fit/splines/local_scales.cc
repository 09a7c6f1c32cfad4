#include "fit/splines/local_scales.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "fit/detect/detection_scales.h"
#include "model/median.h"

namespace implicitfit {
namespace {

constexpr double kMaxBandDeg = 45.0;  // the detector's cap on theta

double Radians(double deg) { return deg * M_PI / 180.0; }

// 3 a clamped to [theta, max(theta, 45 deg)] (a given theta over 45 degrees is kept).
double Band(double a, double normal_angle_deg) {
  const double lo = Radians(normal_angle_deg);
  return std::clamp(3.0 * a, lo, std::max(lo, Radians(kMaxBandDeg)));
}

// q_i of the header: r_i^2 (k + 1) / (k - 2) over the first k <= 12 neighbours; -1 under 3.
double PlaneFigure(const std::vector<Eigen::Vector3d>& points, const NeighbourGraph::Row& nb,
                   size_t i) {
  const size_t k = std::min<size_t>(12, nb.size());
  if (k < 3) return -1.0;
  Eigen::Vector3d c = points[i];
  for (size_t a = 0; a < k; ++a) c += points[nb[a]];
  c /= static_cast<double>(k + 1);
  Eigen::Matrix3d cov = (points[i] - c) * (points[i] - c).transpose();
  for (size_t a = 0; a < k; ++a) cov += (points[nb[a]] - c) * (points[nb[a]] - c).transpose();
  const Eigen::Vector3d n =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvectors().col(0);
  const double r = (points[i] - c).dot(n);
  return r * r * (k + 1.0) / (k - 2.0);
}

}  // namespace

LocalScaleFigures ComputeLocalScaleFigures(const std::vector<Eigen::Vector3d>& points,
                                           const std::vector<Eigen::Vector3d>& normals,
                                           const NeighbourGraph& neighbours,
                                           double normal_angle_deg) {
  LocalScaleFigures f;
  f.noise.resize(points.size());
  for (size_t i = 0; i < points.size(); ++i) f.noise[i] = PlaneFigure(points, neighbours[i], i);
  f.angle.assign(points.size(), 0.0);
  f.spacing.assign(points.size(), -1.0);
  f.tangent.assign(points.size(), 0.0);
  f.cos_band.assign(points.size(), std::cos(Radians(normal_angle_deg)));
  std::vector<double> a, t;
  for (size_t i = 0; i < points.size(); ++i) {
    a.clear();
    t.clear();
    for (size_t k = 0; k < std::min<size_t>(8, neighbours[i].size()); ++k) {
      const int j = neighbours[i][k];
      a.push_back(std::acos(std::min(1.0, std::abs(normals[i].dot(normals[j])))));
      t.push_back(std::abs(normals[i].dot(points[j] - points[i])));
    }
    if (a.empty()) continue;
    if (neighbours[i].size() >= 6) f.spacing[i] = (points[neighbours[i][5]] - points[i]).norm();
    f.angle[i] = Median(a);
    f.tangent[i] = Median(t);
    f.cos_band[i] = std::cos(Band(f.angle[i], normal_angle_deg));
  }
  return f;
}

PartScales ScalesOfPart(const LocalScaleFigures& figures, const std::vector<int>& part,
                        const DetectionBands& d) {
  std::vector<double> q, a, spacing, t;
  q.reserve(part.size());
  a.reserve(part.size());
  for (int i : part) {
    if (figures.noise[i] >= 0) {
      q.push_back(figures.noise[i]);
      a.push_back(figures.angle[i]);
      t.push_back(figures.tangent[i]);
    }
    if (figures.spacing[i] >= 0) spacing.push_back(figures.spacing[i]);
  }
  PartScales s;
  s.noise = std::sqrt(Median(q) / 0.4549);
  s.volume = 1.4826 * Median(t) > kVolumeNoiseToSpacing * Median(spacing) &&
             Median(a) > Radians(kVolumeNormalAngleDeg);
  if (d.spacing > 0) {
    s.threshold = std::max(3.0 * s.noise, 0.1 * d.spacing);
  } else {
    s.noise = std::max(s.noise, d.noise);
    s.threshold = std::max(d.threshold, 3.0 * s.noise);
  }
  s.cos_normal_angle = std::cos(Band(Median(a), d.normal_angle_deg));
  s.likelihood_sigma = std::clamp(s.noise, s.threshold / 10.0, s.threshold / 3.0);
  return s;
}

}  // namespace implicitfit
