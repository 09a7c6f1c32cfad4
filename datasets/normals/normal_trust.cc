#include "datasets/normals/normal_trust.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cstdio>

#include "datasets/normals/neighbourhoods.h"
#include "datasets/normals/oriented_cloud.h"
#include "model/median.h"

namespace implicitfit {
namespace {

constexpr double kMaxShare = 0.1;
constexpr double kMaxVariation = 0.15;
constexpr size_t kCheckedUpTo = 20000;

}  // namespace

NormalTrust AssessEstimatedNormals(const std::vector<Eigen::Vector3d>& points) {
  NormalTrust t;
  const size_t n = points.size();
  if (n > kCheckedUpTo) return t;
  if (n < 3) {
    t.trusted = false;
    t.reason = "fewer than 3 points";
    return t;
  }
  const Neighbourhoods nb = FindNeighbourhoods(points);
  std::vector<double> share(n), variation(n);
  for (size_t i = 0; i < n; ++i) {
    const NeighbourGraph::Row list = nb.indices[i];
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (int j : list) mean += points[j] - points[i];
    mean /= static_cast<double>(list.size() + 1);
    Eigen::Matrix3d cov = mean * mean.transpose();
    for (int j : list) {
      const Eigen::Vector3d d = points[j] - points[i] - mean;
      cov += d * d.transpose();
    }
    const Eigen::Vector3d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvalues();
    const double sum = ev.sum();
    share[i] = static_cast<double>(list.size() + 1) / static_cast<double>(n);
    variation[i] = sum > 0 ? std::max(0.0, ev[0]) / sum : 1.0;
  }
  t.median_share = Median(share);
  t.median_variation = Median(variation);
  char text[160];
  if (t.median_share > kMaxShare) {
    std::snprintf(text, sizeof text, "a neighbourhood holds %.0f%% of the cloud: not local",
                  100 * t.median_share);
    t.trusted = false;
    t.reason = text;
  } else if (t.median_variation > kMaxVariation) {
    std::snprintf(text, sizeof text,
                  "surface variation %.2g > %.2g: neighbourhoods without a tangent plane",
                  t.median_variation, kMaxVariation);
    t.trusted = false;
    t.reason = text;
  }
  return t;
}

PointCloud ReadCloudForPrimitiveFit(const std::string& path, std::string* normals_action,
                                    Neighbourhoods* neighbourhoods,
                                    std::vector<Eigen::Vector3d>* untrusted_normals) {
  std::string action;
  PointCloud cloud = ReadOrientedCloud(path, &action, true, nullptr, neighbourhoods);
  if (untrusted_normals) untrusted_normals->clear();
  if (action.rfind("estimated", 0) == 0) {
    const NormalTrust trust = AssessEstimatedNormals(cloud.points);
    if (!trust.trusted) {
      if (untrusted_normals) untrusted_normals->swap(cloud.normals);
      cloud.normals.clear();
      action = "estimated, not trusted (" + trust.reason + "): fit from points only";
    }
  } else if (!cloud.has_normals()) {
    action += ": fit from points only";
  }
  if (normals_action) *normals_action = action;
  return cloud;
}

}  // namespace implicitfit
