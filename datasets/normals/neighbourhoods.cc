#include "datasets/normals/neighbourhoods.h"

#include <algorithm>
#include <flann/flann.hpp>
#include <stdexcept>

#include "model/median.h"

namespace implicitfit {

Neighbourhoods FindNeighbourhoods(const std::vector<Eigen::Vector3d>& points,
                                  const NeighbourhoodOptions& options) {
  const size_t n = points.size();
  if (n < 2) throw std::invalid_argument("neighbourhoods need at least 2 points");
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points) centroid += p;
  centroid /= static_cast<double>(n);
  std::vector<double> data(3 * n);
  for (size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) data[3 * i + k] = points[i][k] - centroid[k];

  const int max_k =
      std::max(1, std::min<int>(std::max(options.max_k, options.min_k), static_cast<int>(n) - 1));
  const int min_k = std::max(1, std::min(options.min_k, max_k));
  flann::Matrix<double> matrix(data.data(), n, 3);
  flann::Index<flann::L2_Simple<double>> index(matrix, flann::KDTreeSingleIndexParams(10));
  index.buildIndex();
  std::vector<std::vector<size_t>> found;
  std::vector<std::vector<double>> squared;
  flann::SearchParams params(flann::FLANN_CHECKS_UNLIMITED);
  params.sorted = true;
  index.knnSearch(matrix, found, squared, max_k + 1, params);

  // Spacing: median distance to the 6th neighbour (or the farthest found, for tiny clouds).
  const int spacing_rank = std::min(6, max_k);
  std::vector<double> d6;
  d6.reserve(n);
  for (size_t i = 0; i < n; ++i)
    if (squared[i].size() > static_cast<size_t>(spacing_rank))
      d6.push_back(squared[i][spacing_rank]);
  Neighbourhoods out;
  out.spacing = std::sqrt(Median(std::move(d6)));  // 0 when no point has 6 neighbours
  out.radius = options.radius_factor * out.spacing;
  const double r2 = out.radius * out.radius;
  out.indices.resize(n);
  for (size_t i = 0; i < n; ++i) {
    std::vector<int>& mine = out.indices[i];
    for (size_t j = 0; j < found[i].size(); ++j) {
      if (found[i][j] == i) continue;  // the point itself (duplicates stay: they are neighbours)
      if (static_cast<int>(mine.size()) >= min_k && squared[i][j] > r2) break;
      mine.push_back(static_cast<int>(found[i][j]));
      if (static_cast<int>(mine.size()) == max_k) break;
    }
  }
  return out;
}

}  // namespace implicitfit
