// An independent minimum-zone reference for small CMM sets (tests/support/cmm_reference.h), by
// enumeration: at a Chebyshev optimum of a k-parameter primitive in general position, k + 1
// points touch the two faces of the zone with |d| = h (the levelled equations
// d_i(p) = sigma_i h). For every (k + 1)-subset and every sign pattern, Newton (long double,
// central-difference Jacobian, in the reference's own parameterisation) from the least-squares
// reference solves those equations; a solution is a candidate zone when no point lies outside
// it (|d_j| <= |h|). The narrowest candidate is the minimum zone (among the solutions Newton
// reaches from the least-squares fit: the problem is not convex). C(n, k + 1) 2^k systems:
// small n only.
#pragma once

#include <cmath>
#include <limits>
#include <vector>

#include "support/cmm_reference.h"

namespace testsupport {

struct MinimumZoneReferenceResult {
  long double width = std::numeric_limits<long double>::infinity();  // 2 |h| of the narrowest
  int candidates = 0;  // feasible levelled solutions found
};

inline MinimumZoneReferenceResult MinimumZoneByEnumeration(const CmmSet& set) {
  using LD = long double;
  using VecL = CmmReference::VecL;
  using MatL = CmmReference::MatL;
  const CmmReference ref(set);
  const VecL p0 = ref.Solve();
  const int k = static_cast<int>(p0.size()), m = k + 1, n = static_cast<int>(set.points.size());
  std::vector<Eigen::Matrix<LD, 3, 1>> y;
  for (const auto& x : set.points)
    y.push_back(set.rotation.cast<LD>().transpose() * (x.cast<LD>() - set.origin.cast<LD>()));
  MinimumZoneReferenceResult best;
  std::vector<int> S(m);
  for (int i = 0; i < m; ++i) S[i] = i;
  while (true) {
    for (int pattern = 0; pattern < (1 << k); ++pattern) {
      std::vector<int> sigma(m, 1);
      for (int i = 1; i < m; ++i) sigma[i] = (pattern >> (i - 1)) & 1 ? -1 : 1;
      VecL p = p0;
      LD h = 0, residual = 1;
      for (int it = 0; it < 25 && residual > 1e-19L; ++it) {
        VecL F(m);
        MatL J(m, m);
        for (int i = 0; i < m; ++i) {
          F[i] = ref.Distance(p, y[S[i]]) - sigma[i] * h;
          for (int j = 0; j < k; ++j) {
            const LD step = 1e-7L;
            VecL a = p, b = p;
            a[j] += step;
            b[j] -= step;
            J(i, j) = (ref.Distance(a, y[S[i]]) - ref.Distance(b, y[S[i]])) / (2 * step);
          }
          J(i, k) = -sigma[i];
        }
        const VecL delta = -J.fullPivLu().solve(F);
        if (!delta.allFinite()) break;
        p += delta.head(k);
        h += delta[k];
        residual = delta.cwiseAbs().maxCoeff();
      }
      if (!(residual <= 1e-17L)) continue;
      const LD t = std::abs(h);
      bool inside = true;
      for (int j = 0; j < n && inside; ++j)
        inside = std::abs(ref.Distance(p, y[j])) <= t * (1 + 1e-12L) + 1e-18L;
      if (!inside) continue;
      ++best.candidates;
      best.width = std::min(best.width, 2 * t);
    }
    // next subset in lexicographic order
    int i = m - 1;
    while (i >= 0 && S[i] == n - m + i) --i;
    if (i < 0) break;
    ++S[i];
    for (int j = i + 1; j < m; ++j) S[j] = S[j - 1] + 1;
  }
  return best;
}

}  // namespace testsupport
