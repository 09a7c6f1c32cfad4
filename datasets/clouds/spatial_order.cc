#include "datasets/clouds/spatial_order.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace implicitfit {
namespace {

// Interleaves the low 21 bits of v with two zero bits between each (one axis of a Morton code).
std::uint64_t Spread3(std::uint64_t v) {
  v &= 0x1fffff;
  v = (v | v << 32) & 0x1f00000000ffffULL;
  v = (v | v << 16) & 0x1f0000ff0000ffULL;
  v = (v | v << 8) & 0x100f00f00f00f00fULL;
  v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
  v = (v | v << 2) & 0x1249249249249249ULL;
  return v;
}

template <typename T>
void Permute(const std::vector<size_t>& order, std::vector<T>* v) {
  std::vector<T> out;
  out.reserve(v->size());
  for (size_t i : order) out.push_back((*v)[i]);
  *v = std::move(out);
}

}  // namespace

std::vector<size_t> MortonOrder(const std::vector<Eigen::Vector3d>& points) {
  const size_t n = points.size();
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  for (const Eigen::Vector3d& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double extent = n ? std::max((hi - lo).maxCoeff(), 1e-300) : 1.0;
  const double scale = (static_cast<double>(1 << 21) - 1) / extent;
  std::vector<std::pair<std::uint64_t, size_t>> keys(n);
  for (size_t i = 0; i < n; ++i) {
    std::uint64_t code = 0;
    for (int k = 0; k < 3; ++k)
      code |= Spread3(static_cast<std::uint64_t>((points[i][k] - lo[k]) * scale)) << k;
    keys[i] = {code, i};
  }
  std::sort(keys.begin(), keys.end());
  std::vector<size_t> order(n);
  for (size_t i = 0; i < n; ++i) order[i] = keys[i].second;
  return order;
}

void ApplyOrder(const std::vector<size_t>& order, PointCloud* cloud, std::vector<int>* labels) {
  Permute(order, &cloud->points);
  if (cloud->has_normals()) Permute(order, &cloud->normals);
  if (labels && !labels->empty()) Permute(order, labels);
}

}  // namespace implicitfit
