// One Ceres residual block for a batch of points: r_i = f(x_i; theta), the primitive's signed
// distance (model/*.h evaluators), for every point i of the batch.
//
// Why batched: one AutoDiffCostFunction per point costs a heap allocation and a virtual call per
// point and dominated the profile of the plain per-point fit; a batch of a few hundred points
// per block keeps Ceres' multithreaded evaluation and amortises the rest. Derivatives are still
// automatic: each point is evaluated once with ceres::Jet<double, P> (P = all parameters of the
// primitive), and the Jet's derivative vector is scattered into the Jacobians of the parameter
// blocks. The parameter blocks are the primitive's named fields in flat order (e.g. cylinder:
// point 3, axis 3, radius 1), so manifolds and bounds can be set per field.
#pragma once

#include <ceres/ceres.h>

#include <vector>

namespace implicitfit {

template <typename Evaluator>
class BatchedDistanceCost final : public ceres::CostFunction {
 public:
  static constexpr int kP = Evaluator::kNumParameters;

  // xyz: 3 doubles per point, owned by the caller and alive while the cost is used.
  BatchedDistanceCost(const double* xyz, std::vector<int> indices, const std::vector<int>& block_sizes)
      : xyz_(xyz), indices_(std::move(indices)) {
    int offset = 0;
    for (int size : block_sizes) {
      mutable_parameter_block_sizes()->push_back(size);
      offsets_.push_back(offset);
      offset += size;
    }
    set_num_residuals(static_cast<int>(indices_.size()));
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    using Jet = ceres::Jet<double, kP>;
    const std::vector<int32_t>& sizes = parameter_block_sizes();
    double p[kP];
    Jet pj[kP];
    for (size_t b = 0; b < sizes.size(); ++b)
      for (int j = 0; j < sizes[b]; ++j) {
        p[offsets_[b] + j] = parameters[b][j];
        pj[offsets_[b] + j] = Jet(parameters[b][j], offsets_[b] + j);
      }
    const int n = static_cast<int>(indices_.size());
    for (int i = 0; i < n; ++i) {
      const double* x = xyz_ + 3 * indices_[i];
      if (!jacobians) {
        residuals[i] = Evaluator::Evaluate(p, x);
        continue;
      }
      const Jet xj[3] = {Jet(x[0]), Jet(x[1]), Jet(x[2])};
      const Jet r = Evaluator::Evaluate(pj, xj);
      residuals[i] = r.a;
      for (size_t b = 0; b < sizes.size(); ++b) {
        if (!jacobians[b]) continue;
        for (int j = 0; j < sizes[b]; ++j) jacobians[b][i * sizes[b] + j] = r.v[offsets_[b] + j];
      }
    }
    return true;
  }

 private:
  const double* xyz_;
  std::vector<int> indices_;
  std::vector<int> offsets_;
};

}  // namespace implicitfit
