// Soft partitions, docs/maths.md LP-1 tests 4 (for partition_sequence) and 7 (both kinds):
//  - C^(n-1) across a separator's band edge, not C^n: with the cubic step (n = 3) the first and
//    second derivatives of f agree from both sides, the third jumps by the closed-form amount
//    (Irwin-Hall: f_3''' steps from 0 to 1 at the support's end, so H_3''' = (3/2)^3 f_3'''
//    steps by 27/8 and mu_eps''' by 27 / (8 eps^3); f = f_0 + beta (f_1 - f_0) inherits it
//    times |f_1 - f_0|);
//  - Fig. 11: the zero set's maximum curvature across a cut falls as eps grows. Two planes
//    through the origin (a roof, slopes -+tan 30 deg) blended across x = 0: f is homogeneous of
//    degree 1 in (x, z, eps), so the zero curve for 2 eps is the curve for eps scaled by 2 and
//    its maximum curvature halves exactly. Sampled (bisection along z, second differences),
//    eps = 0.05, 0.1, 0.2 of the cell width 1: strictly decreasing, ratios 2 within 1%.
#include <gtest/gtest.h>

#include <cmath>

#include "model/model.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

// One separator x = 0.1 + 0.2 y (normal (1, -0.2, 0) unnormalised); cell 0 (x beyond it) holds
// the plane z = 0.3, cell 1 the tilted plane 0.2 x + z = -0.1 (unnormalised normal (0.2, 0, 1)).
Model OneSeparator(double eps, int order) {
  Model m;
  const int separator = m.AddPrimitive(NodeType::kPlane, {1, -0.2, 0, 0.1});
  const int a = m.AddPrimitive(NodeType::kPlane, {0, 0, 1, 0.3});
  const int b = m.AddPrimitive(NodeType::kPlane, {0.2, 0, 1, -0.1});
  m.AddPartitionSequence({separator}, eps, order, {a, b});
  return m;
}

TEST(PartitionSequenceSmoothness, CubicStepIsTwiceDifferentiableAcrossTheBandEdgeNotThrice) {
  const double eps = 0.2;
  const Model m = OneSeparator(eps, 3);
  const Vec n = Vec(1, -0.2, 0).normalized();
  // Points along the separator's unit normal from a point on it, so that s(x) = t: the band
  // edges are t = +-eps (beta = mu_eps(-t) leaves 0 at t = eps and reaches 1 at t = -eps).
  const Vec origin = Vec(0.1, 0.0, 0.05);  // s(origin) = 0: 1 * 0.1 - 0.2 * 0 - 0.1 = 0
  auto at = [&](double t) { return Vec(origin + t * n); };
  auto grad_n = [&](double t) { return m.Gradient(at(t)).dot(n); };  // df/dt, exact (Dual3)
  for (double edge : {eps, -eps}) {
    // First derivative: continuous (exact derivatives 1e-9 either side).
    EXPECT_NEAR(grad_n(edge - 1e-9), grad_n(edge + 1e-9), 1e-7) << "edge " << edge;
    // Second derivative from each side (one-sided differences of the exact first derivative):
    // they agree to the differencing error s |f'''| (< 2e-4 here), far below f'' ~ 1/eps; a C^1
    // step (order 2) would make them differ by 2 |f_1 - f_0| / eps^2 ~ 20.
    const double s = 1e-6;
    const double left2 = (grad_n(edge) - grad_n(edge - s)) / s;
    const double right2 = (grad_n(edge + s) - grad_n(edge)) / s;
    EXPECT_NEAR(left2, right2, 1e-3) << "edge " << edge;
    // Third derivative: one-sided second differences of f' jump by 27 / (8 eps^3) |f_1 - f_0|.
    const double h = 1e-3;
    const double left3 = (grad_n(edge) - 2 * grad_n(edge - h) + grad_n(edge - 2 * h)) / (h * h);
    const double right3 = (grad_n(edge + 2 * h) - 2 * grad_n(edge + h) + grad_n(edge)) / (h * h);
    const Vec x = at(edge);
    const double f0 = x.z() - 0.3, f1 = (0.2 * x.x() + x.z() + 0.1) / std::sqrt(1.04);
    const double jump = 27.0 / (8.0 * eps * eps * eps) * std::abs(f1 - f0);
    ASSERT_GT(jump, 1.0);
    EXPECT_NEAR(std::abs(left3 - right3), jump, 0.05 * jump) << "edge " << edge;
  }
}

// Zero-set height z(x) at y = 0 by bisection in [-1, 1] (f < 0 below).
double Height(const Model& m, double x) {
  double lo = -1, hi = 1;
  for (int it = 0; it < 100; ++it) {
    const double mid = 0.5 * (lo + hi);
    (m.Value(Vec(x, 0, mid)) < 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// The largest curvature |z''| / (1 + z'^2)^(3/2) of the zero curve sampled on [-0.5, 0.5].
double MaxCurvature(const Model& m) {
  const double h = 0.001;
  double largest = 0;
  double prev = Height(m, -0.5 - h), here = Height(m, -0.5);
  for (double x = -0.5; x <= 0.5; x += h) {
    const double next = Height(m, x + h);
    const double d1 = (next - prev) / (2 * h), d2 = (next - 2 * here + prev) / (h * h);
    largest = std::max(largest, std::abs(d2) / std::pow(1 + d1 * d1, 1.5));
    prev = here;
    here = next;
  }
  return largest;
}

TEST(PartitionSmoothness, CurvatureAcrossACutFallsAsEpsilonGrows) {
  const double slope = std::tan(30.0 * M_PI / 180.0);
  // Cuts at -1, 0, 1 (cells 1 wide); the two left cells hold plane L, the right ones plane R
  // (a roof: z = -slope |x| away from the cut; f < 0 below).
  auto grid = [&](double eps) {
    Model m;
    const int l = m.AddPrimitive(NodeType::kPlane, {-slope, 0, 1, 0});
    const int r = m.AddPrimitive(NodeType::kPlane, {slope, 0, 1, 0});
    m.AddPartition({{-1, 0, 1}, {}, {}}, eps, 3, {l, l, r, r});
    return m;
  };
  auto sequence = [&](double eps) {  // cell 0 beyond the separator x = 0: the right plane
    Model m;
    const int separator = m.AddPrimitive(NodeType::kPlane, {1, 0, 0, 0});
    const int r = m.AddPrimitive(NodeType::kPlane, {slope, 0, 1, 0});
    const int l = m.AddPrimitive(NodeType::kPlane, {-slope, 0, 1, 0});
    m.AddPartitionSequence({separator}, eps, 3, {r, l});
    return m;
  };
  for (int kind = 0; kind < 2; ++kind) {
    std::vector<double> kappa;
    for (double eps : {0.05, 0.1, 0.2})
      kappa.push_back(MaxCurvature(kind == 0 ? grid(eps) : sequence(eps)));
    EXPECT_GT(kappa[0], kappa[1]) << "kind " << kind;
    EXPECT_GT(kappa[1], kappa[2]) << "kind " << kind;
    EXPECT_NEAR(kappa[0] / kappa[1], 2.0, 0.02) << "kind " << kind;
    EXPECT_NEAR(kappa[1] / kappa[2], 2.0, 0.02) << "kind " << kind;
    // Sharp roof (eps -> 0) has unbounded curvature; a visible blend has a finite one: the
    // turning angle 60 degrees spread over about 2 eps gives kappa of order 1 / (2 eps).
    EXPECT_GT(kappa[0], 0.5 / (2 * 0.05)) << "kind " << kind;
    EXPECT_LT(kappa[0], 20.0 / (2 * 0.05)) << "kind " << kind;
  }
}

}  // namespace
}  // namespace implicitfit
