// Compares a Ceres cost function's analytic (Jet) Jacobians with central finite differences
// computed here (step h = 1e-6 * max(1, |x|), truncation error O(h^2)), and reports the worst
// relative disagreement. Used instead of ceres::GradientChecker, whose default numeric
// differentiation was too coarse (1e-4 relative) to judge smooth evaluators.
#pragma once

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace testsupport {

struct DerivativeReport {
  double worst_error = 0.0;  // max |analytic - numeric| / max(1, |numeric|)
  std::string detail;
  double largest_entry = 0.0;  // max |analytic| seen, to check the probe was not trivial
};

inline DerivativeReport CompareWithCentralDifferences(const ceres::CostFunction& cost,
                                                      std::vector<std::vector<double>> blocks) {
  const std::vector<int32_t>& sizes = cost.parameter_block_sizes();
  const int m = cost.num_residuals();
  std::vector<const double*> ptrs;
  for (auto& b : blocks) ptrs.push_back(b.data());
  std::vector<std::vector<double>> jac(blocks.size());
  std::vector<double*> jac_ptrs;
  for (size_t i = 0; i < blocks.size(); ++i) {
    jac[i].resize(m * sizes[i]);
    jac_ptrs.push_back(jac[i].data());
  }
  std::vector<double> r(m), rp(m), rm(m);
  DerivativeReport report;
  if (!cost.Evaluate(ptrs.data(), r.data(), jac_ptrs.data())) {
    report.worst_error = INFINITY;
    report.detail = "evaluation failed";
    return report;
  }
  for (size_t i = 0; i < blocks.size(); ++i)
    for (int k = 0; k < sizes[i]; ++k) {
      const double x0 = blocks[i][k];
      const double h = 1e-6 * std::max(1.0, std::abs(x0));
      blocks[i][k] = x0 + h;
      cost.Evaluate(ptrs.data(), rp.data(), nullptr);
      blocks[i][k] = x0 - h;
      cost.Evaluate(ptrs.data(), rm.data(), nullptr);
      blocks[i][k] = x0;
      for (int row = 0; row < m; ++row) {
        const double numeric = (rp[row] - rm[row]) / (2 * h);
        const double analytic = jac[i][row * sizes[i] + k];
        const double err = std::abs(analytic - numeric) / std::max(1.0, std::abs(numeric));
        report.largest_entry = std::max(report.largest_entry, std::abs(analytic));
        if (err > report.worst_error) {
          report.worst_error = err;
          std::ostringstream s;
          s << "block " << i << " entry " << k << " row " << row << ": analytic " << analytic
            << " numeric " << numeric;
          report.detail = s.str();
        }
      }
    }
  return report;
}

}  // namespace testsupport
