// One Ceres residual block for a batch of points: r_i = f(x_i; theta), the primitive's signed
// distance (model/*.h evaluators), for every point i of the batch.
//
// Why batched: one AutoDiffCostFunction per point costs a heap allocation and a virtual call per
// point and dominated the profile of the plain per-point fit; a batch of a few hundred points
// per block keeps Ceres' multithreaded evaluation and amortises the rest.
// Derivatives: closed form for the five primitives (fit/primitive/primitive_jacobians.h; the
// parameter-only quantities are computed once per batch, then a few dozen flops per point);
// for any other evaluator, or with kAnalytic = false, each point is evaluated once with
// ceres::Jet<double, P> (P = all parameters of the primitive). Either way the point's
// derivative vector is scattered into the Jacobians of the parameter blocks. The parameter
// blocks are the primitive's named fields in flat order (e.g. cylinder: point 3, axis 3,
// radius 1), so manifolds and bounds can be set per field.
// The primitive fitter hands Ceres the compressed form of such a chunk instead
// (fit/primitive/compressed_distance_cost.h: P + 1 residuals, same normal equations); this per-point form
// is its reference in the tests only (hence here, in tests/fit/).
#pragma once

#include <ceres/ceres.h>

#include <vector>

#include "fit/primitive/point_chunk_cost.h"
#include "fit/primitive/primitive_jacobians.h"

namespace implicitfit {

template <typename Evaluator, bool kAnalytic = PrimitiveDistance<Evaluator>::kAvailable>
class BatchedDistanceCost final : public PointChunkCost {
 public:
  static constexpr int kP = Evaluator::kNumParameters;

  // One residual per point of `indices` (see PointChunkCost).
  BatchedDistanceCost(const double* xyz, std::vector<int> indices,
                      const std::vector<int>& block_sizes)
      : PointChunkCost(xyz, std::move(indices), block_sizes, -1) {}

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    if constexpr (kAnalytic)
      return EvaluateAnalytic(parameters, residuals, jacobians);
    else
      return EvaluateJets(parameters, residuals, jacobians);
  }

 private:
  bool EvaluateAnalytic(double const* const* parameters, double* residuals,
                        double** jacobians) const {
    const std::vector<int32_t>& sizes = parameter_block_sizes();
    double p[kP];
    Gather(parameters, p);
    const PrimitiveDistance<Evaluator> f(p);
    const int n = static_cast<int>(indices_.size());
    if (!jacobians) {
      for (int i = 0; i < n; ++i) residuals[i] = f(xyz_ + 3 * indices_[i], nullptr, nullptr);
      return true;
    }
    double dp[kP];
    for (int i = 0; i < n; ++i) {
      residuals[i] = f(xyz_ + 3 * indices_[i], dp, nullptr);
      for (size_t b = 0; b < sizes.size(); ++b) {
        if (!jacobians[b]) continue;
        for (int j = 0; j < sizes[b]; ++j) jacobians[b][i * sizes[b] + j] = dp[offsets_[b] + j];
      }
    }
    return true;
  }

  bool EvaluateJets(double const* const* parameters, double* residuals, double** jacobians) const {
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
};

}  // namespace implicitfit
