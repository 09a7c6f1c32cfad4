#include "datasets/normals/neighbourhoods.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <flann/flann.hpp>
#include <stdexcept>
#include <thread>

#include "datasets/clouds/spatial_order.h"
#include "model/median.h"

namespace implicitfit {
namespace {

// Queries answered per block: a block's result matrices are all the search holds besides the
// graph (the former per-point result vectors of the whole cloud took about 550 bytes a point
// at 10^6 points and 31 neighbours).
constexpr size_t kBlock = 4096;

// Squared distance as FLANN's L2_Simple computes it (same order of operations, so the radius
// test below decides exactly as on the search's own distances).
double SquaredDistance(const double* a, const double* b) {
  double result = 0;
  for (int k = 0; k < 3; ++k) {
    const double diff = a[k] - b[k];
    result += diff * diff;
  }
  return result;
}

}  // namespace

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
  const size_t knn = static_cast<size_t>(max_k) + 1;  // the point itself comes back too
  flann::Matrix<double> matrix(data.data(), n, 3);
  flann::Index<flann::L2_Simple<double>> index(matrix, flann::KDTreeSingleIndexParams(10));
  index.buildIndex();
  flann::SearchParams params(flann::FLANN_CHECKS_UNLIMITED);
  params.sorted = true;
  params.cores = 1;  // the blocks below run on their own threads

  // Blocks of queries on `threads` threads, each writing its points' rows of the graph in
  // place: the max_k nearest (the point itself excluded; duplicates stay: they are neighbours)
  // and the squared distance to the 6th for the spacing. The radius rule cuts the rows once the
  // spacing is known.
  Neighbourhoods out;
  out.indices = NeighbourGraph(n, static_cast<size_t>(max_k));
  // Queries in Morton order: consecutive ones are near each other, so the k-d tree's nodes and
  // points they visit stay in cache (the input order may be random: a generated or merged
  // cloud). Each query is answered the same in any order.
  const std::vector<size_t> order = MortonOrder(points);
  const int spacing_rank = std::min(6, max_k);
  std::vector<double> d6(n, -1.0);
  const size_t blocks = (n + kBlock - 1) / kBlock;
  int threads = options.num_threads > 0 ? options.num_threads
                                        : static_cast<int>(std::thread::hardware_concurrency());
  threads = std::max(1, std::min<int>(threads, static_cast<int>(blocks)));
  auto work = [&](int t) {
    std::vector<size_t> idx(kBlock * knn);
    std::vector<double> dist(kBlock * knn), query(3 * kBlock);
    for (size_t b = t; b < blocks; b += threads) {
      const size_t first = b * kBlock, rows = std::min(kBlock, n - first);
      for (size_t r = 0; r < rows; ++r)
        for (int k = 0; k < 3; ++k) query[3 * r + k] = data[3 * order[first + r] + k];
      flann::Matrix<double> queries(query.data(), rows, 3);
      flann::Matrix<size_t> indices(idx.data(), rows, knn);
      flann::Matrix<double> dists(dist.data(), rows, knn);
      const int found = index.knnSearch(queries, indices, dists, knn, params);
      (void)found;  // every row holds knn entries: knn <= n
      for (size_t r = 0; r < rows; ++r) {
        const size_t i = order[first + r];
        int* slots = out.indices.Slots(i);
        size_t m = 0;
        for (size_t j = 0; j < knn; ++j) {
          if (static_cast<int>(j) == spacing_rank) d6[i] = dists[r][j];
          const size_t q = indices[r][j];
          if (q == i || m == static_cast<size_t>(max_k)) continue;  // the point itself
          slots[m++] = static_cast<int>(q);
        }
        out.indices.SetCount(i, m);
      }
    }
  };
  if (threads == 1) {
    work(0);
  } else {
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t) pool.emplace_back(work, t);
    for (auto& th : pool) th.join();
  }

  // Spacing: median distance to the 6th neighbour (or the farthest found, for tiny clouds).
  d6.erase(std::remove(d6.begin(), d6.end(), -1.0), d6.end());
  out.spacing = std::sqrt(Median(std::move(d6)));  // 0 when no point has 6 neighbours
  out.radius = options.radius_factor * out.spacing;
  const double r2 = out.radius * out.radius;
  // Every neighbour within the radius, at least min_k, at most max_k (nearest first).
  for (size_t i = 0; i < n; ++i) {
    const NeighbourGraph::Row row = out.indices[i];
    size_t m = 0;
    while (m < row.size() &&
           (static_cast<int>(m) < min_k ||
            !(SquaredDistance(&data[3 * i], &data[3 * static_cast<size_t>(row[m])]) > r2)))
      ++m;
    out.indices.SetCount(i, m);
  }
  return out;
}

}  // namespace implicitfit
