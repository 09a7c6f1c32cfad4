#include "fit/metrology/least_squares_fit.h"

#include <ceres/ceres.h>
#include <ceres/sphere_manifold.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "fit/primitive/batched_distance_cost.h"
#include "fit/metrology/primitive_tangent.h"

namespace implicitfit {
namespace {

constexpr int kChunk = 256;  // points per residual block

template <typename E>
void AddCosts(const std::vector<Eigen::Vector3d>& x, const std::vector<int>& sizes,
              const std::vector<double*>& blocks, ceres::Problem* problem) {
  const int n = static_cast<int>(x.size());
  for (int s = 0; s < n; s += kChunk) {
    std::vector<int> idx;
    for (int i = s; i < std::min(n, s + kChunk); ++i) idx.push_back(i);
    problem->AddResidualBlock(new BatchedDistanceCost<E, true>(x[0].data(), std::move(idx), sizes),
                              nullptr, blocks);
  }
}

}  // namespace

FormFigures ComputeFormFigures(NodeType kind, const std::vector<double>& params,
                               const std::vector<Eigen::Vector3d>& points) {
  FormFigures f;
  if (points.empty()) return f;
  f.min_distance = INFINITY;
  f.max_distance = -INFINITY;
  double ss = 0;
  for (const auto& x : points) {
    const double d = PrimitiveSignedDistance(kind, params.data(), x.data(), nullptr);
    ss += d * d;
    f.min_distance = std::min(f.min_distance, d);
    f.max_distance = std::max(f.max_distance, d);
  }
  f.rms = std::sqrt(ss / static_cast<double>(points.size()));
  f.form_error = f.max_distance - f.min_distance;
  return f;
}

LeastSquaresResult LeastSquaresFit(NodeType kind, const std::vector<Eigen::Vector3d>& points,
                                   const std::vector<double>& start,
                                   const std::map<std::string, std::vector<double>>& fixed) {
  LeastSquaresResult result;
  const int k = FreeParameterCount(kind);
  if (static_cast<int>(points.size()) <= k ||
      static_cast<int>(start.size()) != NumParametersOf(kind)) {
    result.message = "least squares needs more points than free parameters and a start";
    return result;
  }
  // Centred frame.
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto& p : points) centroid += p;
  centroid /= static_cast<double>(points.size());
  std::vector<Eigen::Vector3d> x(points.size());
  double size = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    x[i] = points[i] - centroid;
    size = std::max(size, x[i].norm());
  }
  std::vector<double> params = start;
  TranslatePrimitive(kind, -centroid, &params);

  // 1. Ceres Levenberg-Marquardt, one block per named field.
  const std::vector<ParameterField>& fields = ParameterFieldsOf(kind);
  std::vector<std::vector<double>> blocks;
  std::vector<double*> ptrs;
  std::vector<int> sizes;
  int offset = 0;
  for (const ParameterField& f : fields) {
    blocks.emplace_back(params.begin() + offset, params.begin() + offset + f.size);
    offset += f.size;
    sizes.push_back(f.size);
  }
  for (auto& b : blocks) ptrs.push_back(b.data());
  ceres::Problem problem;
  switch (kind) {
    case NodeType::kPlane:
      AddCosts<PlaneEvaluator>(x, sizes, ptrs, &problem);
      break;
    case NodeType::kSphere:
      AddCosts<SphereEvaluator>(x, sizes, ptrs, &problem);
      break;
    case NodeType::kCylinder:
      AddCosts<CylinderEvaluator>(x, sizes, ptrs, &problem);
      break;
    case NodeType::kCone:
      AddCosts<ConeEvaluator>(x, sizes, ptrs, &problem);
      break;
    case NodeType::kTorus:
      AddCosts<TorusEvaluator>(x, sizes, ptrs, &problem);
      break;
    default:
      result.message = "least squares: unsupported kind";
      return result;
  }
  bool any_fixed = false;
  for (size_t b = 0; b < fields.size(); ++b) {
    const std::string name = fields[b].name;
    if (fixed.count(name)) {
      problem.SetParameterBlockConstant(ptrs[b]);
      any_fixed = true;
      continue;
    }
    if (name == "axis" || name == "normal")
      problem.SetManifold(ptrs[b], new ceres::SphereManifold<3>());
    if (name == "half_angle") {
      problem.SetParameterLowerBound(ptrs[b], 0, 1e-9);
      problem.SetParameterUpperBound(ptrs[b], 0, M_PI / 2 - 1e-9);
    }
  }
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = 200;
  options.function_tolerance = 1e-16;
  options.gradient_tolerance = 1e-30;
  options.parameter_tolerance = 1e-16;
  options.num_threads = 1;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  result.iterations = static_cast<int>(summary.iterations.size());
  offset = 0;
  for (auto& b : blocks) {
    std::copy(b.begin(), b.end(), params.begin() + offset);
    offset += static_cast<int>(b.size());
  }
  // Ceres may stop on "invalid steps" at the rounding floor; its last accepted iterate stands
  // unless it is not finite (the polishing below decides the rest).
  for (double v : params)
    if (!std::isfinite(v)) {
      result.message = "least squares: " + summary.message;
      return result;
    }

  // 2. Gauss-Newton polishing in local coordinates (not with fixed fields: the local basis
  //    moves every field). Near the minimum the cost is flat to rounding, so steps are judged
  //    by their length: taken while they shrink (quadratic convergence), until below 1e-14 of
  //    the part size.
  result.final_step = 0.0;
  if (!any_fixed) {
    const int P = static_cast<int>(params.size()), n = static_cast<int>(x.size());
    std::vector<double> dp(P);
    double previous = INFINITY;
    for (int it = 0; it < 10; ++it) {
      const Eigen::MatrixXd B = TangentBasis(kind, params);
      Eigen::MatrixXd J(n, k);
      Eigen::VectorXd r(n);
      for (int i = 0; i < n; ++i) {
        r[i] = PrimitiveSignedDistance(kind, params.data(), x[i].data(), dp.data());
        J.row(i) = Eigen::Map<const Eigen::RowVectorXd>(dp.data(), P) * B;
      }
      Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(J);
      const Eigen::VectorXd delta = -qr.solve(r);
      const double step = (B * delta).norm();
      result.final_step = step;
      if (!(step < previous)) break;  // no longer shrinking: rounding level
      Retract(kind, B, delta, &params);
      ++result.iterations;
      previous = step;
      if (step <= 1e-14 * std::max(size, 1e-300)) break;
    }
  }
  if (kind == NodeType::kCylinder) {  // axis point closest to the centroid (the origin here)
    Eigen::Map<Eigen::Vector3d> q(params.data()), a(params.data() + 3);
    a.normalize();
    q -= a * a.dot(q);
  }
  TranslatePrimitive(kind, centroid, &params);
  result.parameters = params;
  result.figures = ComputeFormFigures(kind, params, points);
  result.success = true;
  char text[96];
  std::snprintf(text, sizeof text, "least squares converged (last Gauss-Newton step %.3g)",
                result.final_step);
  result.message = text;
  return result;
}

}  // namespace implicitfit
