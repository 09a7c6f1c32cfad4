// Linear start of `fit --model partition --grid AxBxC [--child plane|quadric|quadric-patch]`
// (docs/maths.md LP-1):
//   1. A x B x C cells at equal spacing over the cloud's bounding box enlarged 5% on every side
//      (or a given box): cuts t_i = lo + i (hi - lo) / A, i = 1..A-1 per axis;
//      eps = 0.25 * the smallest cell width (so the >= 2 eps rule holds with margin);
//   2. every child is linear in its coefficients before normalisation: a plane
//      f_c = a . x - d, a quadric q_c = x^T A x + 2 b^T x + c. At fixed eps the partition
//      f = sum_c w_c(x) f_c(x) (w_c = b_i(x) b_j(y) b_k(z), at most 8 non-zero) is therefore
//      linear in all children's coefficients together, and the conditions
//        f(p_i) = 0,   f(p_i + h n_i) = h,   f(p_i - h n_i) = -h     (h = 1% of the box diagonal)
//      are ONE sparse linear least-squares problem (normal equations, sparse LDL^T, in
//      coordinates centred on the box and scaled by its half diagonal). A small Tikhonov term
//      (1e-6 of the mean diagonal) pulls every child towards one global child fitted the same
//      way, so cells without points get that child instead of a singular system.
//   3. The children become plane / quadric nodes (their evaluators normalise: plane
//      (a . x - d) / |a|, quadric q / |grad q|) or degree-2 Bernstein patches of the same
//      quadric (quadric-patch: control points on a tetrahedron holding the cell grown by eps,
//      values not normalised, so every child keeps the common scale f ~ distance / s), under
//      one `partition` node (order 3 by
//      default). The tree fitter (fit/tree/tree_fitter.h) then refines children and eps, eps
//      reparameterised as (w_min / 2) sigmoid(b) so every iterate keeps cells >= 2 eps.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "model/model.h"

namespace implicitfit {

struct PartitionStartOptions {
  int cells[3] = {1, 1, 1};     // A, B, C >= 1
  std::string child = "plane";  // plane | quadric | quadric-patch
  int order = 3;                // n of H_n
  bool has_box = false;         // use box_min / box_max instead of the cloud's box + 5%
  Eigen::Vector3d box_min = Eigen::Vector3d::Zero(), box_max = Eigen::Vector3d::Zero();
  double epsilon_fraction = 0.25;  // eps = fraction * smallest cell width (<= 0.5)
};

struct PartitionStart {
  bool success = false;
  std::string message;
  Model model;              // partition of A B C children
  double linear_rms = 0.0;  // RMS residual of the linear system (units of distance)
};

bool IsPartitionChildKind(const std::string& child);

// Throws std::invalid_argument for invalid options (cells < 1, unknown child, bad box).
PartitionStart LinearPartitionStart(const std::vector<Eigen::Vector3d>& points,
                                    const std::vector<Eigen::Vector3d>& normals,
                                    const PartitionStartOptions& options);

}  // namespace implicitfit
