#include "fit/reconstruct/point_assignment.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace implicitfit {

using Vec = Eigen::Vector3d;

namespace {

// First-order distance |f| / |grad f| of x to one primitive; infinity where undefined.
double Distance(const Model& m, const Vec& x) {
  double f;
  const Vec g = m.Gradient(x, &f);
  const double gn = g.norm();
  if (!(gn > 0) || !std::isfinite(f)) return INFINITY;
  return std::abs(f) / gn;
}

}  // namespace

PointAssignment AssignPoints(const std::vector<Vec>& points, const std::vector<Vec>& normals,
                             const std::vector<Model>& primitives, const std::vector<double>& tau,
                             const std::vector<bool>& active) {
  const int K = static_cast<int>(primitives.size());
  const size_t N = points.size();
  PointAssignment a;
  a.label.assign(N, -1);
  a.assigned.assign(K, 0);
  a.side_vote.assign(K, 0.0);
  for (size_t i = 0; i < N; ++i) {
    double best = 1.0;
    int best_k = -1;
    double best_dot = 0.0;
    for (int k = 0; k < K; ++k) {
      if (!active[k]) continue;
      double f;
      const Vec g = primitives[k].Gradient(points[i], &f);
      const double gn = g.norm();
      if (!(gn > 0) || !std::isfinite(f)) continue;
      const double d = std::abs(f) / gn / tau[k];
      const double dot = g.dot(normals[i]);
      if (d < best && std::abs(dot) >= 0.8 * gn) {
        best = d;
        best_k = k;
        best_dot = dot;
      }
    }
    a.label[i] = best_k;
    if (best_k >= 0) {
      ++a.assigned[best_k];
      a.side_vote[best_k] += best_dot > 0 ? 1 : -1;
    } else {
      ++a.unassigned;
    }
  }
  return a;
}

int DropRedundantPrimitives(const std::vector<Vec>& points, const std::vector<Model>& primitives,
                            const std::vector<double>& band, const PointAssignment& assignment,
                            double share, std::vector<bool>* active) {
  const int K = static_cast<int>(primitives.size());
  std::vector<std::vector<size_t>> own(K);
  for (size_t i = 0; i < points.size(); ++i)
    if (assignment.label[i] >= 0) own[assignment.label[i]].push_back(i);
  std::vector<int> order(K);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return assignment.assigned[a] < assignment.assigned[b];
  });
  int dropped = 0;
  for (int k : order) {
    if (!(*active)[k] || own[k].empty()) continue;
    std::vector<int> larger;
    for (int j = 0; j < K; ++j)
      if (j != k && (*active)[j] && assignment.assigned[j] > assignment.assigned[k])
        larger.push_back(j);
    if (larger.empty()) continue;
    size_t near = 0;
    for (size_t i : own[k]) {
      bool on_other = false;
      for (int j : larger) {
        if (Distance(primitives[j], points[i]) < band[j]) {
          on_other = true;
          break;
        }
      }
      near += on_other;
    }
    if (near >= share * own[k].size()) {
      (*active)[k] = false;
      ++dropped;
    }
  }
  return dropped;
}

}  // namespace implicitfit
