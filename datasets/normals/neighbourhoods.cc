#include "datasets/normals/neighbourhoods.h"

#include <algorithm>
#include <flann/flann.hpp>
#include <stdexcept>

#include "model/median.h"

namespace implicitfit {

namespace {

// Exact duplicates collapsed: unique[u] is one point, rep[i] its index for point i, members[u]
// the points equal to it (increasing). A k-d tree cannot split equal points, so 80 000 copies
// of one point made each query scan them all (22 s); the search runs on the unique points.
struct UniquePoints {
  std::vector<size_t> first;                 // u -> its first point
  std::vector<size_t> rep;                   // point -> u
  std::vector<std::vector<size_t>> members;  // u -> its points, increasing
};

UniquePoints Deduplicate(const std::vector<Eigen::Vector3d>& points) {
  const size_t n = points.size();
  std::vector<size_t> order(n);
  for (size_t i = 0; i < n; ++i) order[i] = i;
  auto less = [&](size_t a, size_t b) {
    const Eigen::Vector3d &p = points[a], &q = points[b];
    if (p.x() != q.x()) return p.x() < q.x();
    if (p.y() != q.y()) return p.y() < q.y();
    if (p.z() != q.z()) return p.z() < q.z();
    return a < b;
  };
  std::sort(order.begin(), order.end(), less);
  UniquePoints u;
  u.rep.resize(n);
  for (size_t k = 0; k < n; ++k) {
    const size_t i = order[k];
    if (k == 0 || points[i] != points[order[k - 1]]) {
      u.first.push_back(i);
      u.members.emplace_back();
    }
    u.rep[i] = u.first.size() - 1;
    u.members.back().push_back(i);
  }
  // Unique points in the order of their first occurrence (the search order of the input).
  std::vector<size_t> by_first(u.first.size());
  for (size_t k = 0; k < by_first.size(); ++k) by_first[k] = k;
  std::sort(by_first.begin(), by_first.end(),
            [&](size_t a, size_t b) { return u.first[a] < u.first[b]; });
  std::vector<size_t> renumber(by_first.size());
  UniquePoints sorted;
  sorted.rep.resize(n);
  for (size_t k = 0; k < by_first.size(); ++k) {
    renumber[by_first[k]] = k;
    sorted.first.push_back(u.first[by_first[k]]);
    sorted.members.push_back(std::move(u.members[by_first[k]]));
  }
  for (size_t i = 0; i < n; ++i) sorted.rep[i] = renumber[u.rep[i]];
  return sorted;
}

}  // namespace

Neighbourhoods FindNeighbourhoods(const std::vector<Eigen::Vector3d>& points,
                                  const NeighbourhoodOptions& options) {
  const size_t n = points.size();
  if (n < 2) throw std::invalid_argument("neighbourhoods need at least 2 points");
  const UniquePoints unique = Deduplicate(points);
  const size_t m = unique.first.size();
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points) centroid += p;
  centroid /= static_cast<double>(n);
  std::vector<double> data(3 * m);
  for (size_t u = 0; u < m; ++u)
    for (int k = 0; k < 3; ++k) data[3 * u + k] = points[unique.first[u]][k] - centroid[k];

  const int max_k =
      std::max(1, std::min<int>(std::max(options.max_k, options.min_k), static_cast<int>(n) - 1));
  const int min_k = std::max(1, std::min(options.min_k, max_k));
  // The nearest max_k + 1 unique points of every unique point (itself first).
  std::vector<std::vector<size_t>> found(m);
  std::vector<std::vector<double>> squared(m);
  if (m == 1) {
    found[0] = {0};
    squared[0] = {0.0};
  } else {
    flann::Matrix<double> matrix(data.data(), m, 3);
    flann::Index<flann::L2_Simple<double>> index(matrix, flann::KDTreeSingleIndexParams(10));
    index.buildIndex();
    flann::SearchParams params(flann::FLANN_CHECKS_UNLIMITED);
    params.sorted = true;
    index.knnSearch(matrix, found, squared, std::min<size_t>(max_k + 1, m), params);
  }

  // Per point: itself, its duplicates (distance 0), then the points of the nearest unique
  // points in order of distance: the list a search over every point gives, up to the order of
  // ties; at most max_k + 1 entries.
  std::vector<std::pair<size_t, double>> sequence;  // (point, squared distance)
  auto build = [&](size_t i) {
    const size_t u = unique.rep[i];
    sequence.clear();
    sequence.emplace_back(i, 0.0);
    for (size_t j = 0; j < found[u].size() && sequence.size() <= static_cast<size_t>(max_k); ++j)
      for (size_t member : unique.members[found[u][j]]) {
        if (member == i) continue;
        sequence.emplace_back(member, found[u][j] == u ? 0.0 : squared[u][j]);
        if (sequence.size() > static_cast<size_t>(max_k)) break;
      }
  };
  // Spacing: median distance to the 6th neighbour (or the farthest found, for tiny clouds).
  const int spacing_rank = std::min(6, max_k);
  std::vector<double> d6;
  d6.reserve(n);
  for (size_t i = 0; i < n; ++i) {
    build(i);
    if (sequence.size() > static_cast<size_t>(spacing_rank))
      d6.push_back(sequence[spacing_rank].second);
  }
  Neighbourhoods out;
  out.duplicates = n - m;
  out.spacing = std::sqrt(Median(std::move(d6)));  // 0 when no point has 6 neighbours
  out.radius = options.radius_factor * out.spacing;
  const double r2 = out.radius * out.radius;
  out.indices.resize(n);
  for (size_t i = 0; i < n; ++i) {
    build(i);
    std::vector<int>& mine = out.indices[i];
    for (size_t k = 1; k < sequence.size(); ++k) {
      if (static_cast<int>(mine.size()) >= min_k && sequence[k].second > r2) break;
      mine.push_back(static_cast<int>(sequence[k].first));
      if (static_cast<int>(mine.size()) == max_k) break;
    }
  }
  return out;
}

}  // namespace implicitfit
