#include "fit/splines/patch_tree_fit.h"

#include <ceres/ceres.h>

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "fit/common/thread_count.h"
#include "model/dual3.h"

namespace implicitfit {
namespace {

struct PointResidual {
  const PatchTree* tree;
  Eigen::Vector3d x;
  template <typename T>
  bool operator()(T const* const* blocks, T* r) const {
    T g[3];
    tree->Evaluate(blocks[1], blocks[0][0], blocks[0][1], g);
    for (int k = 0; k < 3; ++k) r[k] = g[k] - x[k];
    return true;
  }
};

// The root domain's bounding box.
void DomainBox(const PatchTree& tree, Eigen::Vector2d* lo, Eigen::Vector2d* hi) {
  const std::vector<Eigen::Vector2d>& v = tree.patches[tree.root].domain.vertices;
  *lo = *hi = v[0];
  for (const Eigen::Vector2d& p : v) {
    *lo = lo->cwiseMin(p);
    *hi = hi->cwiseMax(p);
  }
}

// Start parameters (header).
std::vector<Eigen::Vector2d> StartParameters(const PatchTree& tree,
                                             const std::vector<Eigen::Vector3d>& points) {
  Eigen::Vector2d lo, hi;
  DomainBox(tree, &lo, &hi);
  const int n = 96;
  std::vector<Eigen::Vector3d> samples;
  std::vector<Eigen::Vector2d> where;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const Eigen::Vector2d st = lo + Eigen::Vector2d(i, j).cwiseProduct(hi - lo) / n;
      double g[3];
      tree.Evaluate(tree.placements.data(), st[0], st[1], g);
      samples.emplace_back(g[0], g[1], g[2]);
      where.push_back(st);
    }
  std::vector<Dual3> placement(tree.placements.begin(), tree.placements.end());
  std::vector<Eigen::Vector2d> out(points.size());
  for (size_t k = 0; k < points.size(); ++k) {
    size_t best = 0;
    double best_d2 = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < samples.size(); ++i) {
      const double d2 = (samples[i] - points[k]).squaredNorm();
      if (d2 < best_d2) best_d2 = d2, best = i;
    }
    Eigen::Vector2d st = where[best];
    for (int it = 0; it < 8; ++it) {  // Gauss-Newton on |G - x|^2
      Dual3 g[3];
      tree.Evaluate(placement.data(), Dual3(st[0], Eigen::Vector3d::UnitX()),
                    Dual3(st[1], Eigen::Vector3d::UnitY()), g);
      Eigen::Matrix<double, 3, 2> J;
      Eigen::Vector3d r;
      for (int c = 0; c < 3; ++c) {
        J.row(c) << g[c].v[0], g[c].v[1];
        r[c] = g[c].a - points[k][c];
      }
      const Eigen::Vector2d step = (J.transpose() * J + 1e-12 * Eigen::Matrix2d::Identity())
                                       .ldlt()
                                       .solve(-J.transpose() * r);
      if (!step.allFinite()) break;
      st = (st + step).cwiseMax(lo).cwiseMin(hi);
      if (step.norm() < 1e-12) break;
    }
    out[k] = st;
  }
  return out;
}

double Rms(const PatchTree& tree, const std::vector<double>& placement,
           const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector2d>& st) {
  double sum = 0.0;
  for (size_t k = 0; k < points.size(); ++k) {
    double g[3];
    tree.Evaluate(placement.data(), st[k][0], st[k][1], g);
    sum += (Eigen::Vector3d(g[0], g[1], g[2]) - points[k]).squaredNorm();
  }
  return std::sqrt(sum / std::max<size_t>(1, points.size()));
}

}  // namespace

PatchTreeFitResult FitPatchTreePlacements(const PatchTree& start,
                                          const std::vector<Eigen::Vector3d>& points,
                                          const PatchTreeFitOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  PatchTreeFitResult r;
  r.points = points.size();
  const std::string problem_text = start.Problem();
  if (!problem_text.empty() || points.empty() || start.links.empty()) {
    r.message = problem_text.empty() ? "no points or no link to fit" : problem_text;
    return r;
  }
  r.placements = start.placements;
  r.parameters = StartParameters(start, points);
  r.initial_rms = Rms(start, r.placements, points, r.parameters);
  const int np = static_cast<int>(r.placements.size());
  ceres::Problem problem;
  auto* ordering = new ceres::ParameterBlockOrdering;
  Eigen::Vector2d lo, hi;
  DomainBox(start, &lo, &hi);
  for (size_t k = 0; k < points.size(); ++k) {
    auto* cost = new ceres::DynamicAutoDiffCostFunction<PointResidual, 8>(
        new PointResidual{&start, points[k]});
    cost->AddParameterBlock(2);
    cost->AddParameterBlock(np);
    cost->SetNumResiduals(3);
    problem.AddResidualBlock(cost, nullptr, r.parameters[k].data(), r.placements.data());
    for (int c = 0; c < 2; ++c) {
      problem.SetParameterLowerBound(r.parameters[k].data(), c, lo[c]);
      problem.SetParameterUpperBound(r.parameters[k].data(), c, hi[c]);
    }
    ordering->AddElementToGroup(r.parameters[k].data(), 0);
  }
  ordering->AddElementToGroup(r.placements.data(), 1);
  std::vector<int> fixed;
  for (size_t l = 0; l < start.links.size(); ++l)
    for (int j = 0; j < PatchTree::kPerLink; ++j) {
      const bool is_free = l < options.free.size() && j < static_cast<int>(options.free[l].size())
                               ? options.free[l][j]
                               : (j == 0 || j == 1 || j == 4);
      if (!is_free) fixed.push_back(static_cast<int>(l) * PatchTree::kPerLink + j);
    }
  if (static_cast<int>(fixed.size()) == np) {
    problem.SetParameterBlockConstant(r.placements.data());
  } else if (!fixed.empty()) {
    problem.SetManifold(r.placements.data(), new ceres::SubsetManifold(np, fixed));
  }
  ceres::Solver::Options o;
  o.linear_solver_type = ceres::DENSE_SCHUR;
  o.linear_solver_ordering.reset(ordering);
  o.max_num_iterations = options.max_iterations;
  o.num_threads = ThreadCountOrDefault(options.num_threads);
  o.function_tolerance = 1e-12;
  o.parameter_tolerance = 1e-12;
  o.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(o, &problem, &summary);
  r.iterations = static_cast<int>(summary.iterations.size());
  r.rms = Rms(start, r.placements, points, r.parameters);
  r.success = summary.IsSolutionUsable() && std::isfinite(r.rms);
  r.termination = summary.termination_type == ceres::CONVERGENCE ? FitTermination::kConverged
                  : r.success                                     ? FitTermination::kNoConvergence
                                                                  : FitTermination::kFailure;
  r.message = r.success ? (summary.termination_type == ceres::CONVERGENCE ? "converged"
                                                                          : "no convergence")
                        : summary.message;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace implicitfit
