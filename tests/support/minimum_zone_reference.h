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

#include <algorithm>
#include <cmath>
#include <utility>
#include <limits>
#include <vector>

#include "support/cmm_reference.h"

namespace testsupport {

struct MinimumZoneReferenceResult {
  long double width = std::numeric_limits<long double>::infinity();  // 2 |h| of the narrowest
  int candidates = 0;  // feasible levelled solutions found
};

// The enumeration over the (k + 1)-subsets of `candidates` (indices into set.points), a
// solution kept when it holds every candidate; `holds_all` says whether the narrowest one also
// holds every point of the set.
inline MinimumZoneReferenceResult MinimumZoneOverCandidates(const CmmSet& set,
                                                            const std::vector<int>& candidates,
                                                            int* outside = nullptr) {
  using LD = long double;
  using VecL = CmmReference::VecL;
  using MatL = CmmReference::MatL;
  const CmmReference ref(set);
  const VecL p0 = ref.Solve();
  const int k = static_cast<int>(p0.size()), m = k + 1, n = static_cast<int>(candidates.size());
  std::vector<Eigen::Matrix<LD, 3, 1>> all, y;
  for (const auto& x : set.points)
    all.push_back(set.rotation.cast<LD>().transpose() * (x.cast<LD>() - set.origin.cast<LD>()));
  for (int c : candidates) y.push_back(all[c]);
  MinimumZoneReferenceResult best;
  VecL best_p;
  if (n < m) return best;
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
      if (2 * t < best.width) {
        best.width = 2 * t;
        best_p = p;
      }
    }
    // next subset in lexicographic order
    int i = m - 1;
    while (i >= 0 && S[i] == n - m + i) --i;
    if (i < 0) break;
    ++S[i];
    for (int j = i + 1; j < m; ++j) S[j] = S[j - 1] + 1;
  }
  if (outside && best.candidates > 0) {
    *outside = -1;
    LD worst = best.width / 2 * (1 + 1e-12L) + 1e-18L;
    for (size_t j = 0; j < all.size(); ++j) {
      const LD d = std::abs(ref.Distance(best_p, all[j]));
      if (d > worst) {
        worst = d;
        *outside = static_cast<int>(j);
      }
    }
  }
  return best;
}

inline MinimumZoneReferenceResult MinimumZoneByEnumeration(const CmmSet& set) {
  std::vector<int> every(set.points.size());
  for (size_t i = 0; i < every.size(); ++i) every[i] = static_cast<int>(i);
  return MinimumZoneOverCandidates(set, every);
}

// A GLOBAL reference for larger sets, by exchange over enumerations (independent of
// fit/metrology): the minimum zone of a subset is a lower bound of the whole set's, so when the
// narrowest levelled zone of a subset holds every point it is the whole set's minimum zone
// (among the levelled zones: the Haar case, k + 1 contacts). The subset starts as the k + 4
// points farthest from the least-squares reference; while the subset's narrowest zone leaves
// some point out, the point farthest outside it joins (at most `max_candidates` points).
// `decided` is false when the subset grew too large or has no levelled solution.
struct GlobalMinimumZoneReference {
  long double width = std::numeric_limits<long double>::infinity();
  bool decided = false;
  int subset_size = 0;
};

inline GlobalMinimumZoneReference MinimumZoneBySubsetExchange(const CmmSet& set,
                                                              int max_candidates = 13) {
  using LD = long double;
  const CmmReference ref(set);
  const CmmReference::VecL p0 = ref.Solve();
  const int k = static_cast<int>(p0.size()), n = static_cast<int>(set.points.size());
  std::vector<std::pair<LD, int>> far;
  for (int i = 0; i < n; ++i) {
    const Eigen::Matrix<LD, 3, 1> y =
        set.rotation.cast<LD>().transpose() * (set.points[i].cast<LD>() - set.origin.cast<LD>());
    far.emplace_back(-std::abs(ref.Distance(p0, y)), i);
  }
  std::sort(far.begin(), far.end());
  std::vector<int> subset;
  for (int i = 0; i < std::min(n, k + 4); ++i) subset.push_back(far[i].second);
  GlobalMinimumZoneReference out;
  while (static_cast<int>(subset.size()) <= max_candidates) {
    int outside = -1;
    const MinimumZoneReferenceResult r = MinimumZoneOverCandidates(set, subset, &outside);
    out.subset_size = static_cast<int>(subset.size());
    if (r.candidates == 0) return out;
    out.width = r.width;
    if (outside < 0) {
      out.decided = true;
      return out;
    }
    subset.push_back(outside);  // the point farthest outside the subset's zone joins
  }
  return out;
}

}  // namespace testsupport
