#include "datasets/normals/visibility_orientation.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>
#include <utility>

#include "datasets/normals/normal_orientation.h"

namespace implicitfit {
namespace {

constexpr size_t kGraphNeighbours = 8;

// Union-find with path halving.
int Find(std::vector<int>* parent, int i) {
  std::vector<int>& p = *parent;
  while (p[i] != i) i = p[i] = p[p[i]];
  return i;
}

// Directions spread evenly over the unit sphere (Fibonacci lattice).
std::vector<Eigen::Vector3d> SphereDirections(int count) {
  std::vector<Eigen::Vector3d> d;
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < count; ++k) {
    const double z = 1.0 - (2.0 * k + 1.0) / count;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    d.emplace_back(r * std::cos(golden * k), r * std::sin(golden * k), z);
  }
  return d;
}

}  // namespace

VisibilityOrientationResult OrientPatchesByVisibility(
    const std::vector<Eigen::Vector3d>& points, const NeighbourGraph& neighbours,
    double spacing, const std::vector<double>& variation, std::vector<Eigen::Vector3d>* normals,
    const VisibilityOrientationOptions& options) {
  VisibilityOrientationResult result;
  const size_t n = points.size();
  std::vector<Eigen::Vector3d>& nrm = *normals;
  if (n < 2 || !(spacing > 0)) return result;

  // Smooth patches: union-find over smooth points joined by agreeing edges.
  std::vector<char> smooth(n);
  for (size_t i = 0; i < n; ++i) smooth[i] = variation[i] <= options.max_variation;
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (size_t i = 0; i < n; ++i) {
    if (!smooth[i]) continue;
    for (size_t k = 0; k < neighbours[i].size() && k < kGraphNeighbours; ++k) {
      const int j = neighbours[i][k];
      if (!smooth[j] ||
          MirroredAgreement(points, nrm, static_cast<int>(i), j) < options.smooth_agreement)
        continue;
      parent[Find(&parent, static_cast<int>(i))] = Find(&parent, j);
    }
  }
  std::vector<int> patch(n, -1);
  std::unordered_map<int, int> patch_of_root;
  for (size_t i = 0; i < n; ++i) {
    if (!smooth[i]) continue;
    const int root = Find(&parent, static_cast<int>(i));
    auto [it, added] = patch_of_root.emplace(root, static_cast<int>(patch_of_root.size()));
    patch[i] = it->second;
  }
  result.patches = patch_of_root.size();

  // Votes: the front-most point of each z-buffer cell, per direction.
  std::vector<long> votes_for(result.patches, 0), votes_against(result.patches, 0);
  const double cell = options.cell_factor * spacing;
  const Eigen::Vector3d centre =
      std::accumulate(points.begin(), points.end(), Eigen::Vector3d(Eigen::Vector3d::Zero())) /
      static_cast<double>(n);
  std::unordered_map<uint64_t, int> front;
  front.reserve(n);
  for (const Eigen::Vector3d& d : SphereDirections(options.directions)) {
    const Eigen::Vector3d u = d.unitOrthogonal(), v = d.cross(u);
    front.clear();
    for (size_t i = 0; i < n; ++i) {
      const Eigen::Vector3d q = points[i] - centre;
      const int64_t a = static_cast<int64_t>(std::floor(q.dot(u) / cell));
      const int64_t b = static_cast<int64_t>(std::floor(q.dot(v) / cell));
      // unsigned: shifting a negative cell index is undefined (UBSan)
      const uint64_t key =
          (static_cast<uint64_t>(a) << 32) ^ (static_cast<uint64_t>(b) & 0xffffffffu);
      auto [it, added] = front.emplace(key, static_cast<int>(i));
      if (!added && (points[i] - centre).dot(d) < (points[it->second] - centre).dot(d))
        it->second = static_cast<int>(i);
    }
    for (const auto& [key, i] : front) {
      if (patch[i] < 0) continue;
      const double c = nrm[i].dot(d);
      if (std::abs(c) < options.min_cosine) continue;
      (c < 0 ? votes_for : votes_against)[patch[i]]++;
    }
  }

  std::vector<size_t> patch_size(result.patches, 0);
  for (size_t i = 0; i < n; ++i)
    if (patch[i] >= 0) ++patch_size[patch[i]];
  std::vector<char> flip(result.patches, 0);
  for (size_t p = 0; p < result.patches; ++p) {
    flip[p] = patch_size[p] >= static_cast<size_t>(options.min_patch_points) &&
              votes_against[p] >= options.min_votes &&
              static_cast<double>(votes_against[p]) >
                  options.flip_ratio * static_cast<double>(votes_for[p]);
    result.flipped_patches += flip[p];
  }
  if (result.flipped_patches == 0) return result;
  for (size_t i = 0; i < n; ++i)
    if (patch[i] >= 0 && flip[patch[i]]) {
      nrm[i] = -nrm[i];
      ++result.flipped;
    }

  // Crease points: the propagation again, seeded from every patch point at once.
  std::vector<char> visited(n, 0);
  std::vector<int> seeds;
  for (size_t i = 0; i < n; ++i)
    if (patch[i] >= 0) seeds.push_back(static_cast<int>(i));
  result.flipped +=
      PropagateOrientation(points, SymmetricNeighbourGraph(neighbours), seeds, &visited, normals);
  return result;
}

}  // namespace implicitfit
