#include "fit/bernstein/cloud_scales.h"

#include <cmath>
#include <stdexcept>

#include "fit/bernstein/point_hash_grid.h"
#include "fit/detect/surface_noise.h"
#include "model/median.h"

namespace implicitfit {

CloudScales EstimateCloudScales(const std::vector<Eigen::Vector3d>& points,
                                const std::vector<Eigen::Vector3d>& normals, size_t stride) {
  if (points.size() < 2 || normals.size() != points.size())
    throw std::invalid_argument("EstimateCloudScales: at least 2 points with normals are needed");
  Eigen::Vector3d lo = points[0], hi = points[0];
  for (const Eigen::Vector3d& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double diagonal = (hi - lo).norm();
  if (!(diagonal > 0) || !std::isfinite(diagonal))
    throw std::invalid_argument("EstimateCloudScales: the points must span a finite box");
  CloudScales out;
  out.size = (hi - lo).maxCoeff();
  const PointHashGrid grid(
      points, std::max(diagonal / std::sqrt(static_cast<double>(points.size())), 1e-6 * diagonal));
  constexpr int kNeighbours = 8;  // what EstimateSurfaceNoise reads
  stride = std::max<size_t>(1, stride);
  std::vector<std::vector<int>> neighbours(points.size());
  std::vector<double> nearest;
  for (size_t i = 0; i < points.size(); i += stride) {
    const auto near =
        grid.Nearest(points[i], kNeighbours, [&](int j) { return static_cast<size_t>(j) != i; });
    for (const auto& [d2, j] : near) neighbours[i].push_back(j);
    if (!near.empty()) nearest.push_back(std::sqrt(near[0].first));
  }
  out.spacing = Median(nearest);
  out.noise = EstimateSurfaceNoise(points, normals, neighbours, stride) / std::sqrt(2.0);
  return out;
}

}  // namespace implicitfit
