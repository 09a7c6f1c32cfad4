// Sequential (BSP-like) soft space partition (Li & Phillips eq. 7-8, 11; docs/maths.md LP-1), project
// sign. Separator planes s_1..s_m (signed distances, negative on their "inside" side) and the
// steps beta_i = mu_eps(-s_i) = H_n(-s_i / eps) give the telescoping bases
//   w_0 = 1 - beta_1,  w_j = beta_1 ... beta_j (1 - beta_(j+1)),  w_m = beta_1 ... beta_m,
//   f(x) = sum_j w_j(x) f_j(x),
// which sum to 1 identically (any planes, any eps) and lie in [0, 1]. Cell j is the polyhedron
//   C_0 = {s_1 > 0},  C_j = {s_1 < 0, ..., s_j < 0, s_(j+1) > 0},  C_m = {s_1 < 0, ..., s_m < 0};
// its core, where w_j = 1 and f = f_j exactly, is C_j shrunk by eps (every plane moved eps
// inwards). The core is non-empty exactly when C_j holds a ball of radius eps, i.e. when the
// cell is at least 2 eps wide (width = twice its inscribed radius): the reader refuses
// narrower cells, since their child would never be reproduced anywhere (the grid's rule,
// model/blends/partition.h). JSON: {"type": "partition_sequence", "separators": [plane x m],
// "epsilon", "order", "children": [node x (m + 1)]}. Node children: the m separators, then the
// m + 1 cell children. Parameters: [eps]; the separators' own parameters are structure for the
// fitter (as the grid's cuts).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "model/scalar.h"
#include "model/blends/unit_step.h"

namespace implicitfit {

// A separator as the half-space n . x <= d (n unit): s(x) = n . x - d.
struct SeparatorPlane {
  Eigen::Vector3d normal;
  double offset = 0.0;
};

struct PartitionSequence {
  // sum_j w_j f_j with separator(j) = s_(j+1)(x) (j = 0..m-1) and child(j) = f_j(x)
  // (j = 0..m); children whose weight is exactly 0 are not evaluated.
  template <typename T, typename Separator, typename Child>
  static T Evaluate(const UnitStep& mu, const T& eps, int m, const Separator& separator,
                    const Child& child) {
    T acc = T(0.0), prefix = T(1.0);
    for (int j = 0; j < m; ++j) {
      const T beta = mu.WithRisingRange(T(-separator(j)), eps);
      const T w = prefix * (1.0 - beta);
      if (ValueOf(w) != 0.0) acc += w * child(j);
      prefix = prefix * beta;
      if (ValueOf(prefix) == 0.0) return acc;
    }
    return acc + prefix * child(m);
  }
};

// Width of cell j (0..m) of the separators: twice the radius of the largest ball inside it
// (inscribed radius by bisection on the feasibility of the shrunk cell, relative accuracy
// 1e-9); returns +infinity for a cell that holds arbitrarily large balls (and for empty
// intersections of parallel planes the width is 0).
double PartitionSequenceCellWidth(const std::vector<SeparatorPlane>& separators, int cell);

// True when cell j shrunk by r (every plane moved r inwards) is non-empty.
bool PartitionSequenceCoreIsNonEmpty(const std::vector<SeparatorPlane>& separators, int cell,
                                     double r);

// The first cell narrower than 2 eps, or -1 when every cell is wide enough; *width its width.
int NarrowPartitionSequenceCell(const std::vector<SeparatorPlane>& separators, double eps,
                                double* width);

// Smallest cell width over all m + 1 cells (+infinity when every cell is unbounded enough).
double SmallestPartitionSequenceCell(const std::vector<SeparatorPlane>& separators);

}  // namespace implicitfit
