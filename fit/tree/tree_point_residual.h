// Residual of one oriented point against a whole model tree (fit --init).
//   r_0       = f(x) / sqrt(|grad f(x)|^2 + eta^2)         first-order geometric distance
//   r_1..r_3  = w (g - s n),  g = grad f / |grad f|         normal agreement (when n is given)
// with s = sign(g . n) taken at the current value (not differentiated), so normals of either
// orientation are accepted. grad f is the central difference of f over x with step h (O(h^2)
// error), evaluated on Jets: the derivatives of r w.r.t. every tree parameter (primitive
// parameters, delta and epsilon through the unit-step polynomials, control points) stay
// automatic, with no second-derivative code. eta = 1e-6 keeps r finite where grad f vanishes.
#pragma once

#include <ceres/ceres.h>

#include <cmath>
#include <vector>

#include "fit/tree/pruned_tree_evaluation.h"
#include "fit/tree/tree_parameters.h"
#include "model/model.h"

namespace implicitfit {

struct TreePointResidual {
  const Model* model;
  const TreeParameters* parameters;
  double x[3];
  double n[3];
  bool has_normal;
  double normal_weight;
  double h;
  const std::vector<char>* constant = nullptr;  // TreeParameters::ConstantSubtrees, or none

  template <typename T>
  bool operator()(T const* const* blocks, T* residuals) const {
    using std::sqrt;
    // Reused per thread (Ceres evaluates blocks concurrently): no allocation per point.
    thread_local std::vector<T> flat;
    thread_local std::vector<double> values;
    const size_t size = model->parameters().size();
    flat.resize(size);
    values.resize(size);
    parameters->ToFlat(blocks, flat.data());
    for (size_t i = 0; i < size; ++i) values[i] = ValueOf(flat[i]);
    // Children a blend ignores at the point are evaluated in double only
    // (fit/tree/pruned_tree_evaluation.h): the same f and derivatives, to rounding.
    auto evaluate = [&](const double* xd) {
      const T xt[3] = {T(xd[0]), T(xd[1]), T(xd[2])};
      return PrunedEvaluate(*model, flat.data(), values.data(), xt, xd,
                            constant ? constant->data() : nullptr);
    };
    const T f = evaluate(x);
    T g[3];
    for (int k = 0; k < 3; ++k) {
      double xp[3] = {x[0], x[1], x[2]}, xm[3] = {x[0], x[1], x[2]};
      xp[k] += h;
      xm[k] -= h;
      g[k] = (evaluate(xp) - evaluate(xm)) / (2.0 * h);
    }
    const T gn = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2] + 1e-12);
    residuals[0] = f / gn;
    if (has_normal) {
      const double dot = ValueOf(g[0]) * n[0] + ValueOf(g[1]) * n[1] + ValueOf(g[2]) * n[2];
      const double s = dot < 0 ? -1.0 : 1.0;
      for (int k = 0; k < 3; ++k) residuals[1 + k] = normal_weight * (g[k] / gn - s * n[k]);
    }
    return true;
  }
};

}  // namespace implicitfit
