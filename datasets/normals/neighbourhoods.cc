#include "datasets/normals/neighbourhoods.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <flann/flann.hpp>
#include <numeric>
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

// Exact duplicates collapsed: unique point u is first[u] (increasing: the input's order), rep[i]
// the unique point of point i, and u's points (increasing) are members[offsets[u] ..
// offsets[u + 1]) (flat: no allocation per point).
struct UniquePoints {
  std::vector<size_t> first, rep, offsets, members;
  size_t size() const { return first.size(); }
};

UniquePoints Deduplicate(const std::vector<Eigen::Vector3d>& points) {
  const size_t n = points.size();
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), size_t{0});
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    const Eigen::Vector3d &p = points[a], &q = points[b];
    if (p.x() != q.x()) return p.x() < q.x();
    if (p.y() != q.y()) return p.y() < q.y();
    if (p.z() != q.z()) return p.z() < q.z();
    return a < b;
  });
  std::vector<size_t> group(n);  // point -> the first point equal to it
  for (size_t k = 0; k < n; ++k)
    group[order[k]] = k > 0 && points[order[k]] == points[order[k - 1]] ? group[order[k - 1]]
                                                                        : order[k];
  order = std::vector<size_t>();
  UniquePoints u;
  u.rep.resize(n);
  for (size_t i = 0; i < n; ++i)
    if (group[i] == i) {
      u.rep[i] = u.first.size();
      u.first.push_back(i);
    }
  for (size_t i = 0; i < n; ++i) u.rep[i] = u.rep[group[i]];
  u.offsets.assign(u.first.size() + 1, 0);
  for (size_t i = 0; i < n; ++i) ++u.offsets[u.rep[i] + 1];
  std::partial_sum(u.offsets.begin(), u.offsets.end(), u.offsets.begin());
  u.members.resize(n);
  std::vector<size_t> cursor(u.offsets.begin(), u.offsets.end() - 1);
  for (size_t i = 0; i < n; ++i) u.members[cursor[u.rep[i]]++] = i;
  return u;
}

}  // namespace

Neighbourhoods FindNeighbourhoods(const std::vector<Eigen::Vector3d>& points,
                                  const NeighbourhoodOptions& options) {
  const size_t n = points.size();
  if (n < 2) throw std::invalid_argument("neighbourhoods need at least 2 points");
  const UniquePoints unique = Deduplicate(points);
  const size_t m = unique.size();
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points) centroid += p;
  centroid /= static_cast<double>(n);
  std::vector<double> data(3 * m);  // the unique points, recentred
  for (size_t u = 0; u < m; ++u)
    for (int k = 0; k < 3; ++k) data[3 * u + k] = points[unique.first[u]][k] - centroid[k];

  const int max_k =
      std::max(1, std::min<int>(std::max(options.max_k, options.min_k), static_cast<int>(n) - 1));
  const int min_k = std::max(1, std::min(options.min_k, max_k));
  // The nearest max_k + 1 unique points of a unique point (itself among them).
  const size_t knn = std::min<size_t>(static_cast<size_t>(max_k) + 1, m);
  flann::Matrix<double> matrix(data.data(), m, 3);
  flann::Index<flann::L2_Simple<double>> index(matrix, flann::KDTreeSingleIndexParams(10));
  if (m > 1) index.buildIndex();
  flann::SearchParams params(flann::FLANN_CHECKS_UNLIMITED);
  params.sorted = true;
  params.cores = 1;  // the blocks below run on their own threads

  // Blocks of queries (one per unique point) on `threads` threads, each writing the rows of
  // the query's points in place: the point itself (rank 0), its copies (distance 0), then the
  // points of the nearest unique points by distance, the point itself excluded from its row,
  // at most max_k; the squared distance at rank 6 for the spacing. The radius rule cuts the
  // rows once the spacing is known.
  Neighbourhoods out;
  out.duplicates = n - m;
  out.indices = NeighbourGraph(n, static_cast<size_t>(max_k));
  // Queries in Morton order: consecutive ones are near each other, so the k-d tree's nodes and
  // points they visit stay in cache (the input order may be random: a generated or merged
  // cloud). Each query is answered the same in any order.
  std::vector<size_t> order;
  order.reserve(m);
  for (size_t i : MortonOrder(points))
    if (unique.first[unique.rep[i]] == i) order.push_back(unique.rep[i]);
  const int spacing_rank = std::min(6, max_k);
  std::vector<double> d6(n, -1.0);
  auto fill = [&](size_t u, const size_t* found, const double* squared, size_t count) {
    for (size_t c = unique.offsets[u]; c < unique.offsets[u + 1]; ++c) {
      const size_t i = unique.members[c];
      int* slots = out.indices.Slots(i);
      size_t filled = 0;
      int rank = 1;  // the point itself is rank 0
      auto add = [&](size_t q, double d2) {
        if (rank == spacing_rank) d6[i] = d2;
        ++rank;
        slots[filled++] = static_cast<int>(q);
      };
      for (size_t e = unique.offsets[u]; e < unique.offsets[u + 1] && filled < size_t(max_k); ++e)
        if (unique.members[e] != i) add(unique.members[e], 0.0);
      for (size_t j = 0; j < count && filled < static_cast<size_t>(max_k); ++j) {
        if (found[j] == u) continue;
        const size_t v = found[j];
        for (size_t e = unique.offsets[v]; e < unique.offsets[v + 1] && filled < size_t(max_k);
             ++e)
          add(unique.members[e], squared[j]);
      }
      out.indices.SetCount(i, filled);
    }
  };
  const size_t blocks = (m + kBlock - 1) / kBlock;
  int threads = options.num_threads > 0 ? options.num_threads
                                        : static_cast<int>(std::thread::hardware_concurrency());
  threads = std::max(1, std::min<int>(threads, static_cast<int>(blocks)));
  auto work = [&](int t) {
    std::vector<size_t> idx(kBlock * knn);
    std::vector<double> dist(kBlock * knn), query(3 * kBlock);
    for (size_t b = t; b < blocks; b += threads) {
      const size_t first = b * kBlock, rows = std::min(kBlock, m - first);
      if (m == 1) {  // every point is the same: its neighbours are its copies
        fill(0, nullptr, nullptr, 0);
        continue;
      }
      for (size_t r = 0; r < rows; ++r)
        for (int k = 0; k < 3; ++k) query[3 * r + k] = data[3 * order[first + r] + k];
      flann::Matrix<double> queries(query.data(), rows, 3);
      flann::Matrix<size_t> indices(idx.data(), rows, knn);
      flann::Matrix<double> dists(dist.data(), rows, knn);
      index.knnSearch(queries, indices, dists, knn, params);  // knn <= m: every row is full
      for (size_t r = 0; r < rows; ++r) fill(order[first + r], indices[r], dists[r], knn);
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
    const double* p = &data[3 * unique.rep[i]];
    size_t k = 0;
    while (k < row.size() &&
           (static_cast<int>(k) < min_k ||
            !(SquaredDistance(p, &data[3 * unique.rep[static_cast<size_t>(row[k])]]) > r2)))
      ++k;
    out.indices.SetCount(i, k);
  }
  return out;
}

}  // namespace implicitfit
