#include "model/certificates/tangent_plane_test.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace implicitfit {

TangentPlaneTestResult TangentPlaneTestCore(
    const std::function<Eigen::Vector3d()>& random_point,
    const std::function<double(const Eigen::Vector3d&)>& f,
    const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& gradient, double longest,
    double min_gradient, const TangentPlaneTestOptions& options) {
  TangentPlaneTestResult result;
  std::vector<Eigen::Vector3d> points, normals;
  for (int s = 0; s < options.segments; ++s) {
    const Eigen::Vector3d a = random_point(), c = random_point();
    Eigen::Vector3d x0 = a;
    double f0 = f(x0);
    for (int step = 1; step <= options.steps; ++step) {
      const Eigen::Vector3d x1 = a + (c - a) * (double(step) / options.steps);
      const double f1 = f(x1);
      if ((f0 < 0.0) != (f1 < 0.0)) {
        Eigen::Vector3d lo = x0, hi = x1;  // f(lo) has f0's sign
        for (int it = 0; it < 60; ++it) {
          const Eigen::Vector3d mid = 0.5 * (lo + hi);
          if ((f(mid) < 0.0) == (f0 < 0.0))
            lo = mid;
          else
            hi = mid;
        }
        const Eigen::Vector3d p = 0.5 * (lo + hi);
        const Eigen::Vector3d g = gradient(p);
        if (g.norm() > min_gradient) {
          points.push_back(p);
          normals.push_back(g.normalized());
        }
      }
      x0 = x1;
      f0 = f1;
    }
  }
  result.zero_points = static_cast<int>(points.size());
  const double allowed = options.tolerance * longest;
  for (size_t i = 0; i < points.size(); ++i) {
    double worst = 0.0;
    for (size_t j = 0; j < points.size(); ++j)
      worst = std::max(worst, (points[j] - points[i]).dot(normals[i]));
    result.worst_excursion = std::max(result.worst_excursion, worst / longest);
    if (worst > allowed) ++result.violations;
  }
  return result;
}

TangentPlaneTestResult TangentPlaneTest(int k, const Tetrahedron& tet, const double* b,
                                        const TangentPlaneTestOptions& options) {
  double longest = 0.0, largest = 0.0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      longest = std::max(longest, (tet.vertex(i) - tet.vertex(j)).norm());
  for (long long i = 0; i < NumBernsteinControlPoints(k); ++i)
    largest = std::max(largest, std::abs(b[i]));
  if (largest == 0.0) return TangentPlaneTestResult{};

  std::mt19937_64 rng(options.seed);
  std::exponential_distribution<double> exponential(1.0);
  auto random_point = [&]() {
    double w[4], sum = 0.0;
    for (double& x : w) sum += (x = exponential(rng));
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (int i = 0; i < 4; ++i) p += (w[i] / sum) * tet.vertex(i);
    return p;
  };
  auto f = [&](const Eigen::Vector3d& x) { return BernsteinPatch::Evaluate(k, tet, b, x.data()); };
  auto gradient = [&](const Eigen::Vector3d& x) {
    Eigen::Matrix<double, 3, 1> g;
    BernsteinPatch::Derivatives(k, tet, b, x.data(), &g);
    return Eigen::Vector3d(g);
  };
  return TangentPlaneTestCore(random_point, f, gradient, longest, 1e-6 * largest / longest,
                              options);
}

TangentPlaneTestResult TangentPlaneTest(const Model& model, const Eigen::Vector3d& box_min,
                                        const Eigen::Vector3d& box_max,
                                        const TangentPlaneTestOptions& options) {
  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto random_point = [&]() {
    Eigen::Vector3d p;
    for (int i = 0; i < 3; ++i) p[i] = box_min[i] + (box_max[i] - box_min[i]) * u(rng);
    return p;
  };
  auto f = [&](const Eigen::Vector3d& x) { return model.Value(x); };
  auto gradient = [&](const Eigen::Vector3d& x) { return model.Gradient(x); };
  const double diagonal = (box_max - box_min).norm();
  return TangentPlaneTestCore(random_point, f, gradient, diagonal, 1e-9 / diagonal, options);
}

}  // namespace implicitfit
