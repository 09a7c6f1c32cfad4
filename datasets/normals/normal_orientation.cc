#include "datasets/normals/normal_orientation.h"

#include <algorithm>
#include <numeric>
#include <queue>
#include <utility>

namespace implicitfit {

size_t OrientTowardViewpoint(const std::vector<Eigen::Vector3d>& points,
                             const Eigen::Vector3d& viewpoint,
                             std::vector<Eigen::Vector3d>* normals) {
  size_t flipped = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    if ((*normals)[i].dot(viewpoint - points[i]) < 0) {
      (*normals)[i] = -(*normals)[i];
      ++flipped;
    }
  }
  return flipped;
}

namespace {

constexpr size_t kMstNeighbours = 8;

}  // namespace

// Agreement of n_j with n_i mirrored across the plane halfway between p_i and p_j (König &
// Gumhold 2009): the mirror image of n_i is exactly n_j for two points of a sphere, and for
// the two sides of a symmetric crease or of a thin sheet, where the plain n_i . n_j misleads.
double MirroredAgreement(const std::vector<Eigen::Vector3d>& points,
                         const std::vector<Eigen::Vector3d>& normals, int i, int j) {
  const Eigen::Vector3d e = points[j] - points[i];
  const double length = e.norm();
  if (length == 0.0) return normals[i].dot(normals[j]);
  const Eigen::Vector3d u = e / length;
  const Eigen::Vector3d mirrored = normals[i] - 2.0 * normals[i].dot(u) * u;
  return mirrored.dot(normals[j]);
}

std::vector<std::vector<int>> SymmetricNeighbourGraph(
    const NeighbourGraph& neighbours) {
  std::vector<std::vector<int>> graph(neighbours.size());
  for (size_t i = 0; i < neighbours.size(); ++i)
    for (size_t k = 0; k < neighbours[i].size() && k < kMstNeighbours; ++k) {
      const int j = neighbours[i][k];
      graph[i].push_back(j);
      graph[j].push_back(static_cast<int>(i));
    }
  return graph;
}

// Prim's algorithm with a binary heap, written out (~20 lines) rather than pulling in
// Boost.Graph: the graph is the neighbour lists as they are, made symmetric.
size_t PropagateOrientation(const std::vector<Eigen::Vector3d>& points,
                            const std::vector<std::vector<int>>& graph,
                            const std::vector<int>& seeds, std::vector<char>* visited,
                            std::vector<Eigen::Vector3d>* normals) {
  std::vector<char>& done = *visited;
  std::vector<Eigen::Vector3d>& nrm = *normals;
  size_t flipped = 0;
  using Item = std::pair<double, std::pair<int, int>>;  // cost, (vertex, parent)
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
  auto reach_from = [&](int v) {
    for (int w : graph[v])
      if (!done[w]) heap.push({1.0 - std::abs(MirroredAgreement(points, nrm, v, w)), {w, v}});
  };
  for (int seed : seeds) done[seed] = 1;
  for (int seed : seeds) reach_from(seed);
  while (!heap.empty()) {
    const auto [v, parent] = heap.top().second;
    heap.pop();
    if (done[v]) continue;
    done[v] = 1;
    if (MirroredAgreement(points, nrm, parent, v) < 0) {
      nrm[v] = -nrm[v];
      ++flipped;
    }
    reach_from(v);
  }
  return flipped;
}

size_t OrientByMinimumSpanningTree(const std::vector<Eigen::Vector3d>& points,
                                   const NeighbourGraph& neighbours,
                                   std::vector<Eigen::Vector3d>* normals) {
  const size_t n = points.size();
  std::vector<Eigen::Vector3d>& nrm = *normals;
  const std::vector<std::vector<int>> graph = SymmetricNeighbourGraph(neighbours);
  // Seeds in decreasing x: the first unvisited one is the max-x point of its component.
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return points[a].x() > points[b].x(); });

  std::vector<char> done(n, 0);
  size_t flipped = 0;
  for (int seed : order) {
    if (done[seed]) continue;
    if (nrm[seed].x() < 0) {
      nrm[seed] = -nrm[seed];
      ++flipped;
    }
    flipped += PropagateOrientation(points, graph, {seed}, &done, normals);
  }
  return flipped;
}

double OpposedNeighbourFraction(const std::vector<Eigen::Vector3d>& normals,
                                const NeighbourGraph& neighbours) {
  size_t parallel = 0, opposed = 0;
  for (size_t i = 0; i < normals.size(); ++i)
    for (int j : neighbours[i]) {
      const double c = normals[i].dot(normals[j]);
      if (std::abs(c) <= 0.5) continue;
      ++parallel;
      opposed += c < 0;
    }
  return parallel ? static_cast<double>(opposed) / static_cast<double>(parallel) : 0.0;
}

}  // namespace implicitfit
