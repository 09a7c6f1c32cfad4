#include "fit/detect/surface_noise.h"

#include <algorithm>
#include <cmath>

#include "model/median.h"

namespace implicitfit {

double EstimateSurfaceNoise(const std::vector<Eigen::Vector3d>& points,
                            const std::vector<Eigen::Vector3d>& normals,
                            const NeighbourGraph& neighbours, size_t stride) {
  constexpr size_t kNeighbours = 8;
  std::vector<double> figures, e;
  stride = std::max<size_t>(1, stride);
  for (size_t i = 0; i < points.size(); i += stride) {
    e.clear();
    for (size_t k = 0; k < std::min(kNeighbours, neighbours[i].size()); ++k) {
      const int j = neighbours[i][k];
      const Eigen::Vector3d nj = normals[j].dot(normals[i]) < 0 ? -normals[j] : normals[j];
      e.push_back(std::abs(0.5 * (normals[i] + nj).dot(points[j] - points[i])));
    }
    if (!e.empty()) figures.push_back(Median(e));
  }
  return 1.4826 * Median(figures);
}

}  // namespace implicitfit
