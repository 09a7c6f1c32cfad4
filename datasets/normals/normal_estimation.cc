#include "datasets/normals/normal_estimation.h"

#include <Eigen/Eigenvalues>
#include <stdexcept>

#include "datasets/normals/normal_orientation.h"
#include "datasets/normals/visibility_orientation.h"

namespace implicitfit {
namespace {

// Covariance of p_i and its neighbours, centred on p_i first (cancels large coordinates), then
// about the mean.
Eigen::Matrix3d LocalCovariance(const std::vector<Eigen::Vector3d>& points, size_t i,
                                const NeighbourGraph::Row& nb) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (int j : nb) mean += points[j] - points[i];
  mean /= static_cast<double>(nb.size() + 1);
  Eigen::Matrix3d cov = (-mean) * (-mean).transpose();
  for (int j : nb) {
    const Eigen::Vector3d d = points[j] - points[i] - mean;
    cov += d * d.transpose();
  }
  return cov;
}

Eigen::Vector3d PcaNormal(const std::vector<Eigen::Vector3d>& points, size_t i,
                          const NeighbourGraph::Row& nb) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(LocalCovariance(points, i, nb));
  return solver.eigenvectors().col(0).normalized();  // eigenvalues ascend
}

double MeanSize(const Neighbourhoods& nb) {
  double total = 0;
  for (size_t i = 0; i < nb.indices.size(); ++i) total += static_cast<double>(nb.indices[i].size());
  return nb.indices.empty() ? 0.0 : total / static_cast<double>(nb.indices.size());
}

}  // namespace

std::vector<Eigen::Vector3d> EstimatePcaNormals(const std::vector<Eigen::Vector3d>& points,
                                                const Neighbourhoods& neighbourhoods) {
  std::vector<Eigen::Vector3d> normals(points.size());
  for (size_t i = 0; i < points.size(); ++i)
    normals[i] = PcaNormal(points, i, neighbourhoods.indices[i]);
  return normals;
}

std::vector<double> SurfaceVariation(const std::vector<Eigen::Vector3d>& points,
                                     const Neighbourhoods& neighbourhoods) {
  std::vector<double> variation(points.size(), 0.0);
  for (size_t i = 0; i < points.size(); ++i) {
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(
        LocalCovariance(points, i, neighbourhoods.indices[i]), Eigen::EigenvaluesOnly);
    const Eigen::Vector3d l = solver.eigenvalues().cwiseMax(0.0);
    const double sum = l.sum();
    variation[i] = sum > 0 ? l(0) / sum : 0.0;
  }
  return variation;
}

NormalResult EnsureOrientedNormals(PointCloud* cloud, const NormalOptions& options,
                                   Neighbourhoods* neighbourhoods) {
  Neighbourhoods local;
  Neighbourhoods& nb = neighbourhoods ? *neighbourhoods : local;
  NormalResult result;
  const bool estimate = !cloud->has_normals() || options.reestimate;
  if (estimate && cloud->size() < 3)
    throw std::invalid_argument("estimating normals needs at least 3 points, the cloud has " +
                                std::to_string(cloud->size()));
  if (cloud->size() < 2) {
    result.action = "read from file";
    return result;
  }
  nb = FindNeighbourhoods(cloud->points, options.neighbourhood);
  result.mean_neighbours = MeanSize(nb);
  result.duplicates = nb.duplicates;
  // Reports say how many points repeat an earlier one (searched once: neighbourhoods.h).
  const std::string duplicates =
      nb.duplicates ? " (" + std::to_string(nb.duplicates) + " duplicate points)" : "";
  if (estimate) {
    cloud->normals = EstimatePcaNormals(cloud->points, nb);
    result.estimated = cloud->size();
  } else {
    result.opposed_fraction = OpposedNeighbourFraction(cloud->normals, nb.indices);
    if (result.opposed_fraction <= options.max_opposed_fraction) {
      result.action = "read from file" + duplicates;
      return result;
    }
  }
  const std::string prefix = estimate ? "estimated, " : "read from file, ";
  if (options.viewpoint) {
    result.flipped = OrientTowardViewpoint(cloud->points, *options.viewpoint, &cloud->normals);
    result.action =
        prefix + (estimate ? "oriented toward viewpoint" : "re-oriented toward viewpoint");
  } else {
    result.flipped = OrientByMinimumSpanningTree(cloud->points, nb.indices, &cloud->normals);
    if (options.visibility_vote) {
      const VisibilityOrientationResult vote =
          OrientPatchesByVisibility(cloud->points, nb.indices, nb.spacing,
                                    SurfaceVariation(cloud->points, nb), &cloud->normals);
      result.visibility_flipped_patches = vote.flipped_patches;
      result.flipped += vote.flipped;  // may count a point twice (MST and vote): an upper bound
    }
    result.action = prefix + (estimate ? "MST-oriented" : "MST-re-oriented");
  }
  result.action += duplicates;
  return result;
}

void ReestimateNormalsAt(PointCloud* cloud, const std::vector<size_t>& indices,
                         const NeighbourhoodOptions& options) {
  if (indices.empty()) return;
  if (cloud->size() < 3)
    throw std::invalid_argument("re-estimating normals needs at least 3 points");
  const Neighbourhoods nb = FindNeighbourhoods(cloud->points, options);
  std::vector<char> invalid(cloud->size(), 0);
  for (size_t i : indices) invalid[i] = 1;
  for (size_t i : indices) {
    Eigen::Vector3d n = PcaNormal(cloud->points, i, nb.indices[i]);
    Eigen::Vector3d vote = Eigen::Vector3d::Zero();
    for (int j : nb.indices[i])
      if (!invalid[j]) vote += cloud->normals[j];
    if (n.dot(vote) < 0) n = -n;
    cloud->normals[i] = n;
  }
}

}  // namespace implicitfit
