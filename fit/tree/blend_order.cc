#include "fit/tree/blend_order.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

constexpr size_t kMinCornerPoints = 10;

// The cost with operator o's epsilon the best of its own and three shares of its delta.
double BestEpsilonCost(Model* m, int o, const std::vector<Vec>& points, double clip,
                       double* best_epsilon = nullptr) {
  const int first = m->nodes()[o].first_parameter;
  std::vector<double>& p = m->mutable_parameters();
  const double delta = p[first], own = p[first + 1];
  double best = TruncatedCost(*m, points, clip), epsilon = own;
  for (double share : {0.3, 0.6, 0.9}) {
    p[first + 1] = share * delta;
    const double c = TruncatedCost(*m, points, clip);
    if (c < best) {
      best = c;
      epsilon = p[first + 1];
    }
  }
  p[first + 1] = own;
  if (best_epsilon) *best_epsilon = epsilon;
  return best;
}

}  // namespace

double TruncatedCost(const Model& m, const std::vector<Vec>& points, double clip) {
  double cost = 0;
  for (const Vec& x : points) {
    double f;
    const Vec g = m.Gradient(x, &f);
    const double d = std::abs(f) / std::sqrt(g.squaredNorm() + 1e-300);
    cost += std::min(d * d, clip * clip);
  }
  return cost;
}

bool ChooseChildOrders(Model* m, const std::vector<Vec>& points, double clip) {
  bool changed = false;
  for (int o = 0; o < static_cast<int>(m->nodes().size()); ++o) {
    const ModelNode& node = m->nodes()[o];
    if (node.order == 0 || node.children.size() < 3 ||
        (node.type != NodeType::kUnion && node.type != NodeType::kIntersection))
      continue;
    const int k = static_cast<int>(node.children.size());
    // Only where three or more children are within delta of the extreme does the order count.
    const double delta = m->parameters()[node.first_parameter];
    const double sign = node.type == NodeType::kIntersection ? 1.0 : -1.0;
    std::vector<Vec> corner;
    std::vector<double> w(k);
    for (const Vec& x : points) {
      for (int c = 0; c < k; ++c)
        w[c] = sign * m->EvaluateNode(node.children[c], m->parameters().data(), x.data());
      const double top = *std::max_element(w.begin(), w.end());
      if (std::count_if(w.begin(), w.end(), [&](double v) { return v >= top - delta; }) >= 3)
        corner.push_back(x);
    }
    if (corner.size() < kMinCornerPoints) continue;
    double best = BestEpsilonCost(m, o, corner, clip);
    // A swap must gain more than rounding: 1e-6 clip^2 per point.
    const double gain = 1e-6 * clip * clip * static_cast<double>(corner.size());
    for (int pass = 0; pass < 4 * k; ++pass) {
      int bi = -1, bj = -1;
      double pass_best = best;
      for (int i = 0; i < k; ++i)
        for (int j = i + 1; j < k; ++j) {
          std::vector<int>& children = m->mutable_nodes()[o].children;
          std::swap(children[i], children[j]);
          const double c = BestEpsilonCost(m, o, corner, clip);
          std::swap(m->mutable_nodes()[o].children[i], m->mutable_nodes()[o].children[j]);
          if (c < pass_best - gain) {
            pass_best = c;
            bi = i;
            bj = j;
          }
        }
      if (bi < 0) break;
      std::swap(m->mutable_nodes()[o].children[bi], m->mutable_nodes()[o].children[bj]);
      best = pass_best;
      changed = true;
      double epsilon;  // the refit starts from the epsilon that suits the new order
      BestEpsilonCost(m, o, corner, clip, &epsilon);
      m->mutable_parameters()[m->nodes()[o].first_parameter + 1] = epsilon;
    }
  }
  return changed;
}

}  // namespace implicitfit
