// Soft space partition on a grid (Li & Phillips eq. 9-11; docs/maths.md LP-1), project sign:
//   f(x) = sum_{ijk} b_i(x_1) b_j(x_2) b_k(x_3) f_ijk(x),
//   b_i(t) = mu_eps(t - t_i) mu_eps(t_{i+1} - t),   mu_eps(s) = H_n(s / eps),
// with the cuts t_1 < ... < t_a of each axis, t_0 = -inf, t_{a+1} = +inf (the outer factors are
// 1). The b are a partition of unity (sum = 1, 0 <= b <= 1) exactly when every finite cell is at
// least 2 eps wide (unstated in the paper; the reader refuses narrower cells), since then at most
// two cells overlap at any t and mu(s) + mu(-s) = 1. Farther than eps from every cut of its cell
// a point gets f = f_ijk exactly (the factors are exactly 1 and 0). f is C^(n-1) across a cut
// when the children are smooth. Children are listed x fastest: cell (i, j, k) at position
// i + (a+1) (j + (b+1) k). Not convex even when every f_ijk is (grad b grad f^T terms).
// Parameters: [eps] (1); the cuts are structure.
#pragma once

#include <algorithm>
#include <vector>

#include "model/scalar.h"
#include "model/blends/unit_step.h"

namespace implicitfit {

struct PartitionAxis {
  // The cells of one axis whose factor b_i(t) is not zero, and those factors: at most
  // kMaxCells (two suffice when every finite cell is >= 2 eps wide). Returns their number.
  static constexpr int kMaxCells = 3;
  template <typename T>
  static int Factors(const std::vector<double>& cuts, const T& t, const T& eps, const UnitStep& mu,
                     int* cells, T* factors) {
    const int a = static_cast<int>(cuts.size());
    int count = 0;
    for (int i = 0; i <= a && count < kMaxCells; ++i) {
      T b = T(1.0);
      if (i > 0) {
        const T lower = mu.WithRisingRange(t - cuts[i - 1], eps);
        if (ValueOf(lower) == 0.0) continue;
        b = lower;
      }
      if (i < a) {
        const T upper = mu.WithRisingRange(cuts[i] - t, eps);
        if (ValueOf(upper) == 0.0) continue;
        b = i > 0 ? b * upper : upper;
      }
      cells[count] = i;
      factors[count] = b;
      ++count;
    }
    return count;
  }
};

// Smallest finite cell width over the axes (infinity when no axis has two cuts).
inline double SmallestPartitionCell(const std::vector<std::vector<double>>& cuts) {
  double w = 1e308;
  for (const std::vector<double>& c : cuts)
    for (size_t i = 1; i < c.size(); ++i) w = std::min(w, c[i] - c[i - 1]);
  return w;
}

}  // namespace implicitfit
