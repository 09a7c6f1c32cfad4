// Points hashed into cubes of edge `cell` (a bucket grid: fit/ has no k-d tree); queries visit
// the Chebyshev rings of cubes around a point. Nearest(x, k, keep): the k nearest points j with
// keep(j), nearest first, as (squared distance, index): rings grow until k are found and the next
// ring is farther than the k-th (fewer than k when fewer are kept). Used by the patch-mesh fit
// (winding-number areas, cloud scales, nearest data points of far-field samples).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace implicitfit {

class PointHashGrid {
 public:
  // points must outlive the grid.
  PointHashGrid(const std::vector<Eigen::Vector3d>& points, double cell)
      : points_(points), cell_(cell) {
    lo_ = points.empty() ? Eigen::Vector3d::Zero() : points[0];
    for (const Eigen::Vector3d& p : points) lo_ = lo_.cwiseMin(p);
    for (size_t i = 0; i < points.size(); ++i)
      cells_[Key(CellOf(points[i]))].push_back(static_cast<int>(i));
  }
  // fn(j, squared distance) for every point j within the cubes of Chebyshev ring first..last.
  template <class Fn>
  void ForRings(const Eigen::Vector3d& x, int first_ring, int last_ring, Fn&& fn) const {
    const Eigen::Vector3i c = CellOf(x);
    for (int dx = -last_ring; dx <= last_ring; ++dx)
      for (int dy = -last_ring; dy <= last_ring; ++dy)
        for (int dz = -last_ring; dz <= last_ring; ++dz) {
          if (std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) < first_ring) continue;
          const Eigen::Vector3i n = c + Eigen::Vector3i(dx, dy, dz);
          if (n.minCoeff() < 0) continue;
          const auto it = cells_.find(Key(n));
          if (it == cells_.end()) continue;
          for (int j : it->second) fn(j, (points_[j] - x).squaredNorm());
        }
  }
  template <class Keep>
  std::vector<std::pair<double, int>> Nearest(const Eigen::Vector3d& x, int k, Keep&& keep) const {
    std::vector<std::pair<double, int>> found;
    size_t seen = 0;
    // The query may lie outside the points' box: rings start from its (clamped) distance.
    for (int ring = 0; seen < points_.size() && ring <= kMaxRings; ++ring) {
      ForRings(x, ring, ring, [&](int j, double q) {
        ++seen;
        if (keep(j)) found.emplace_back(q, j);
      });
      if (static_cast<int>(found.size()) >= k) {
        std::nth_element(found.begin(), found.begin() + (k - 1), found.end());
        const double reach = ring * cell_;  // every point of later rings is farther
        if (found[k - 1].first <= reach * reach) break;
      }
    }
    std::sort(found.begin(), found.end());
    if (static_cast<int>(found.size()) > k) found.resize(k);
    return found;
  }
  double cell() const { return cell_; }

 private:
  static constexpr int kMaxRings = 1 << 20;
  Eigen::Vector3i CellOf(const Eigen::Vector3d& p) const {
    return ((p - lo_) / cell_).array().floor().cast<int>();
  }
  // Cells are non-negative and below 2^21 per axis (cell >= diagonal / 10^6).
  static std::uint64_t Key(const Eigen::Vector3i& c) {
    return (static_cast<std::uint64_t>(c.x()) << 42) | (static_cast<std::uint64_t>(c.y()) << 21) |
           static_cast<std::uint64_t>(c.z());
  }
  const std::vector<Eigen::Vector3d>& points_;
  double cell_;
  Eigen::Vector3d lo_;
  std::unordered_map<std::uint64_t, std::vector<int>> cells_;
};

}  // namespace implicitfit
