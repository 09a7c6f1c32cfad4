#include "fit/detect/surface_noise.h"

#include <algorithm>
#include <cmath>

#include "model/median.h"

namespace implicitfit {

namespace {

constexpr size_t kNeighbours = 8;

// Median of |(n_i + n_j) / 2 . (p_j - p_i)| over i's first kNeighbours neighbours; false when
// i has none.
bool MidNormalFigure(const std::vector<Eigen::Vector3d>& points,
                     const std::vector<Eigen::Vector3d>& normals, const NeighbourGraph& neighbours,
                     size_t i, std::vector<double>* e, double* figure) {
  e->clear();
  for (size_t k = 0; k < std::min(kNeighbours, neighbours[i].size()); ++k) {
    const int j = neighbours[i][k];
    const Eigen::Vector3d nj = normals[j].dot(normals[i]) < 0 ? -normals[j] : normals[j];
    e->push_back(std::abs(0.5 * (normals[i] + nj).dot(points[j] - points[i])));
  }
  if (e->empty()) return false;
  *figure = Median(*e);
  return true;
}

}  // namespace

double EstimateSurfaceNoise(const std::vector<Eigen::Vector3d>& points,
                            const std::vector<Eigen::Vector3d>& normals,
                            const NeighbourGraph& neighbours, size_t stride) {
  std::vector<double> figures, e;
  stride = std::max<size_t>(1, stride);
  double figure = 0;
  for (size_t i = 0; i < points.size(); i += stride)
    if (MidNormalFigure(points, normals, neighbours, i, &e, &figure)) figures.push_back(figure);
  return 1.4826 * Median(figures);
}

}  // namespace implicitfit
