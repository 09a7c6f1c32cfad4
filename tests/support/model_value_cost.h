// f of a model as a Ceres cost of two blocks, all its parameters and the point, for
// ceres::DynamicAutoDiffCostFunction: its Jet derivatives are checked against central
// differences (support/derivative_check.h).
#pragma once

#include "model/model.h"

namespace testsupport {

struct ModelValueCost {
  const implicitfit::Model* model;
  template <typename T>
  bool operator()(T const* const* blocks, T* residual) const {
    residual[0] = model->Evaluate(blocks[0], blocks[1]);
    return true;
  }
};

}  // namespace testsupport
