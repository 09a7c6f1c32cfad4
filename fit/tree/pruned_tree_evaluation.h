// f(x) of a model tree on Jets, skipping the children a smooth CSG operator ignores at x.
//
// A union / intersection / difference folds its children left to right with a smooth max
// (model/blends/smooth_ops.h, model/blends/convex_smooth_ops.h). With x, y its two arguments
// (intersection: a, b; union: -a, -b, result negated; difference: a, -b) and t = x - y:
//   S_max(x, y) = max(x, y) exactly when |t| > delta + eps (Li & Phillips: every g is 0 or 1)
//                 or |t| >= w (convex smoothing), and always for order 0 (sharp).
// There the result is the winning argument, and its derivatives are the winner's: the loser's
// are multiplied by exact zeros. So each fold step first evaluates the next child in double
// (cheap), and only the children that win, or sit inside a blend band, are evaluated on the
// Jet type: away from the edges of a 7-child intersection that is one child of seven. Values
// agree with Model::Evaluate to rounding (max(x, y) instead of (x + y + |x - y|) / 2), and so
// do the derivatives. Every other node type (leaves, partitions, morph, ...) is evaluated by
// Model::EvaluateNode as it is; operators below operators are pruned recursively.
//
// params: the flat parameters on T; values: the same as doubles (ValueOf of each); x on T and
// as doubles. With T = double this is the same evaluation without the Jet bookkeeping.
//
// constant (optional, one flag per node): nodes whose subtree has no free parameter (every field
// fixed, e.g. the primitives while only the blends are refitted, fit/reconstruct/blend_refit.h).
// Their value is a constant of the fit, so its Jet is T(value) with zero derivatives (x carries
// no derivative here: the gradient in x is by differences, fit/tree/tree_point_residual.h); it is
// evaluated in double once, and not again on T. On the Kinect milk carton's refit (215
// parameters, 8 free) this removed most of the Jet work of the tree fit.
#pragma once

#include <cmath>

#include "model/model.h"

namespace implicitfit {

template <typename T>
T PrunedEvaluateNode(const Model& model, int index, const T* params, const double* values,
                     const T* x, const double* xd, const char* constant = nullptr) {
  if (constant && constant[index]) return T(model.EvaluateNode(index, values, xd));
  const ModelNode& node = model.nodes()[index];
  if (!IsOperator(node.type) || node.children.size() < 2)
    return model.EvaluateNode(index, params, x);
  const double* pv = values + node.first_parameter;
  const bool convex = node.smoothing == BlendSmoothing::kConvex;
  // A gap beyond which the smooth max is exactly the max (order 0: every gap).
  const double band = node.order == 0 ? -1.0 : convex ? pv[0] : pv[0] + pv[1];
  const double out_sign = node.type == NodeType::kUnion ? -1.0 : 1.0;       // result = sign S_max
  const double a_sign = node.type == NodeType::kUnion ? -1.0 : 1.0;         // x = a_sign acc
  const double b_sign = node.type == NodeType::kIntersection ? 1.0 : -1.0;  // y = b_sign b

  // The accumulated result: its double value and either its Jet or the child it equals
  // (times sign), whose Jet is computed only when needed.
  double acc_value = model.EvaluateNode(node.children[0], values, xd);
  int acc_child = node.children[0];
  double acc_child_sign = 1.0;
  T acc = T(0.0);
  auto resolve = [&]() {
    if (acc_child >= 0) {
      acc = constant && constant[acc_child]
                ? T(acc_value)  // acc_child_sign times the child's value, computed already
                : acc_child_sign *
                      PrunedEvaluateNode(model, acc_child, params, values, x, xd, constant);
      acc_child = -1;
    }
  };
  for (size_t c = 1; c < node.children.size(); ++c) {
    const int child = node.children[c];
    const double b_value = model.EvaluateNode(child, values, xd);
    const double xv = a_sign * acc_value, yv = b_sign * b_value, t = xv - yv;
    const bool sharp = node.order == 0 || (convex ? std::abs(t) >= band : std::abs(t) > band);
    if (sharp) {
      const bool x_wins = node.order == 0 ? xv >= yv : t > 0.0;
      if (x_wins) continue;  // the result stays the accumulated one
      // The result is out_sign * y = out_sign * b_sign * b.
      acc_value = out_sign * yv;
      acc_child = child;
      acc_child_sign = out_sign * b_sign;
      continue;
    }
    resolve();
    const T b = constant && constant[child]
                    ? T(b_value)
                    : PrunedEvaluateNode(model, child, params, values, x, xd, constant);
    acc = BlendPair(node, acc, b, params + node.first_parameter);
    acc_value = ValueOf(acc);
  }
  resolve();
  return acc;
}

template <typename T>
T PrunedEvaluate(const Model& model, const T* params, const double* values, const T* x,
                 const double* xd, const char* constant = nullptr) {
  return PrunedEvaluateNode(model, model.root(), params, values, x, xd, constant);
}

}  // namespace implicitfit
