// The free parameters of a model tree as Ceres parameter blocks, and the map back to the tree's
// flat parameter vector (model/model.h). One block per free field of every node:
// By the field's role (model/model.h FieldRole, model/primitives/primitive_kinds.h):
//   directions (axis, normal)           SphereManifold<3> (unit vectors by construction)
//   positive lengths (radius, radii,
//   major/minor_radius, half_sizes,
//   blobs widths)                       lower bound 0
//   angles (half_angle)                 bounds (0, pi/2)
//   rotations (box axes, a quaternion
//   w, x, y, z)                         ceres::QuaternionManifold
// By the node type:
//   morph t                             t = 1 / (1 + exp(-b)), so 0 < t < 1 for every b
//   blobs threshold                     never fitted (it fixes the scale of f)
//   partition epsilon                   eps = (w_min / 2) / (1 + exp(-b)), w_min the narrowest
//                                       finite cell, so every iterate keeps cells >= 2 eps
//                                       (no finite cell: eps = exp(b))
//   partition_sequence epsilon          the same with w_min the narrowest cell (twice its
//                                       inscribed radius); its separator planes are structure
//                                       (held fixed, as the grid's cuts)
//   delta, epsilon of a blend           reparameterised so that 0 < epsilon <= delta holds for
//                                       every value of the free variables:
//                                         delta = exp(a),  epsilon = delta / (1 + exp(-b))
//                                       (with delta fixed: epsilon = delta / (1 + exp(-b));
//                                        with epsilon fixed: delta = epsilon + exp(a))
//   everything else (centres, offsets,
//   control points, coefficients)       free
//   delta of a "smoothing": "convex" blend  delta = exp(a) (its epsilon slot is unused, no block)
//   Coleman feature points (coleman_features "features", skeleton_offset "features")
//                                       f moves only orthogonally to u_f, the unit direction
//                                       from its closest core point c(f) to f at the start (a
//                                       linear subspace manifold on the features block): f
//                                       enters the field only through c(f) and u_f, which do
//                                       not change when f slides along u_f (exactly for a
//                                       planar, spherical or skeleton core), so that direction
//                                       is free and a solver can drift along it (a fitted point
//                                       went from 0.7 to 14.6, out of its falloff region)
// Fields named in a node's "fixed" list get no block: they keep their value.
#pragma once

#include <ceres/ceres.h>

#include <Eigen/Core>

#include <cmath>
#include <vector>

#include "model/model.h"

namespace implicitfit {

class TreeParameters {
 public:
  explicit TreeParameters(const Model& model);

  // The blocks (free variables), initialised from the model's parameters.
  std::vector<std::vector<double>>& blocks() { return blocks_; }
  const std::vector<int>& block_sizes() const { return block_sizes_; }
  // Adds manifolds and bounds for every block to the problem (after the blocks were used).
  void Configure(ceres::Problem* problem);

  // The flat parameter vector of the tree from block values (any scalar type).
  template <typename T>
  void ToFlat(T const* const* blocks, T* flat) const;
  std::vector<double> ToFlat() const;
  // Blends whose free epsilon fell below min_ratio * delta restart at epsilon = delta / 2 (the
  // logit b = 0): epsilon -> 0 is a plateau of the parameterisation (d epsilon / d b =
  // epsilon (1 - epsilon / delta) -> 0) where a pass far from the solution can strand it.
  // Returns how many restarted.
  int RestartCollapsedEpsilons(double min_ratio);
  // One flag per node of the model: 1 when no parameter of its subtree is free (the subtree's
  // f is a constant of the fit; fit/tree/pruned_tree_evaluation.h evaluates it once in double).
  std::vector<char> ConstantSubtrees(const Model& model) const;

  // How a block is parameterised (from its field's role, or the node type's own rules).
  enum class Kind {
    kPlain,
    kDirection,
    kPositive,
    kAngle,
    kDeltaLog,
    kEpsilonLogit,
    kQuaternion,
    kUnitLogit,
    kLog,
    kFeatureTangent
  };

 private:
  struct Entry {                 // one flat parameter
    int block = -1, offset = 0;  // -1: fixed
    double fixed_value = 0.0;
    Kind kind = Kind::kPlain;
    int delta_flat = -1;  // kEpsilonLogit / kDeltaLog with fixed epsilon: the partner
    double scale = 1.0;   // kUnitLogit: the value = scale / (1 + exp(-b))
  };
  std::vector<Entry> entries_;
  std::vector<std::vector<double>> blocks_;
  std::vector<int> block_sizes_;
  std::vector<Kind> block_kinds_;
  std::vector<Eigen::MatrixXd> block_bases_;  // kFeatureTangent: the subspace basis
};

template <typename T>
void TreeParameters::ToFlat(T const* const* blocks, T* flat) const {
  using std::exp;
  // Plain values first, then the blend pairs (epsilon depends on delta).
  for (size_t i = 0; i < entries_.size(); ++i) {
    const Entry& e = entries_[i];
    if (e.block < 0) {
      flat[i] = T(e.fixed_value);
    } else if (e.kind == Kind::kDeltaLog) {
      flat[i] = exp(blocks[e.block][e.offset]);
      if (e.delta_flat >= 0) flat[i] += T(entries_[e.delta_flat].fixed_value);  // epsilon fixed
    } else if (e.kind == Kind::kUnitLogit) {
      flat[i] = e.scale / (1.0 + exp(-blocks[e.block][e.offset]));
    } else if (e.kind == Kind::kLog) {
      flat[i] = exp(blocks[e.block][e.offset]);
    } else if (e.kind != Kind::kEpsilonLogit) {
      flat[i] = blocks[e.block][e.offset];
    }
  }
  for (size_t i = 0; i < entries_.size(); ++i) {
    const Entry& e = entries_[i];
    if (e.block >= 0 && e.kind == Kind::kEpsilonLogit)
      flat[i] = flat[e.delta_flat] / (1.0 + exp(-blocks[e.block][e.offset]));
  }
}

}  // namespace implicitfit
