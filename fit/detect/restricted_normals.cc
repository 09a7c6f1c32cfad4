#include "fit/detect/restricted_normals.h"

#include <Eigen/Eigenvalues>

namespace implicitfit {

namespace {
constexpr int kMinFreeNeighbours = 4;  // fewer: too few points for a plane's direction
constexpr double kMinSpread = 4.0;     // the second eigenvalue must exceed this x the first
}  // namespace

std::vector<Eigen::Vector3d> RestrictedNormals(const std::vector<Eigen::Vector3d>& points,
                                               const std::vector<Eigen::Vector3d>& normals,
                                               const NeighbourGraph& neighbours,
                                               const std::vector<char>& free) {
  std::vector<Eigen::Vector3d> out = normals;
  for (size_t i = 0; i < points.size(); ++i) {
    if (!free[i]) continue;
    std::vector<int> set = {static_cast<int>(i)};
    for (int j : neighbours[i])
      if (free[j]) set.push_back(j);
    if (static_cast<int>(set.size()) < kMinFreeNeighbours + 1) continue;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (int j : set) mean += points[j] - points[i];
    mean /= static_cast<double>(set.size());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (int j : set) {
      const Eigen::Vector3d d = points[j] - points[i] - mean;
      cov += d * d.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
    const Eigen::Vector3d l = eig.eigenvalues();  // ascending
    if (!(l[1] > 0) || l[1] < kMinSpread * l[0]) continue;
    Eigen::Vector3d n = eig.eigenvectors().col(0);
    if (n.dot(normals[i]) < 0) n = -n;
    out[i] = n;
  }
  return out;
}

}  // namespace implicitfit
