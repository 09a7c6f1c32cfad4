#include "fit/reconstruct/fillet_primitives.h"

#include <cmath>

namespace implicitfit {

using Vec = Eigen::Vector3d;

std::vector<bool> FilletLikePrimitives(const std::vector<Vec>& points,
                                       const std::vector<Vec>& normals,
                                       const std::vector<Model>& primitives,
                                       const PointAssignment& assignment, double reach,
                                       double share) {
  const int K = static_cast<int>(primitives.size());
  std::vector<bool> fillet(K, false);
  std::vector<std::vector<size_t>> own(K);
  for (size_t i = 0; i < points.size(); ++i)
    if (assignment.label[i] >= 0) own[assignment.label[i]].push_back(i);
  for (int k = 0; k < K; ++k) {
    if (own[k].empty()) continue;
    std::vector<int> larger;
    for (int j = 0; j < K; ++j)
      if (j != k && assignment.assigned[j] > assignment.assigned[k]) larger.push_back(j);
    if (larger.size() < 2) continue;
    size_t between = 0;
    for (size_t i : own[k]) {
      // The larger faces within reach whose outward side n leans toward: their unit gradients,
      // turned to the material's outside.
      std::vector<Vec> leaning;
      for (int j : larger) {
        double f;
        const Vec g = primitives[j].Gradient(points[i], &f);
        const double gn = g.norm();
        if (!(gn > 0) || !std::isfinite(f) || std::abs(f) / gn >= reach) continue;
        const Vec outward = (assignment.side_vote[j] >= 0 ? 1.0 : -1.0) * g / gn;
        if (normals[i].dot(outward) > 0.05) leaning.push_back(outward);
      }
      bool found = false;
      for (size_t a = 0; a < leaning.size() && !found; ++a)
        for (size_t b = a + 1; b < leaning.size() && !found; ++b)
          found = std::abs(leaning[a].dot(leaning[b])) < 0.95;
      between += found;
    }
    fillet[k] = between >= share * own[k].size();
  }
  return fillet;
}

}  // namespace implicitfit
