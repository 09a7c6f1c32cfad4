// Guo §3 shape control in the patch fitter (docs/maths.md G-3): the constraints hold exactly after a fit
// (f(x_i) = 0, grad f(x_i) / |grad f| = n, f = 0 along a constrained edge), by evaluating the
// fitted patch; the fit stays close to data that satisfy them.
#include <gtest/gtest.h>

#include <random>

#include "fit/bernstein/patch_fitter.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

double MaxAbs(const std::vector<double>& b) {
  double m = 0;
  for (double v : b) m = std::max(m, std::abs(v));
  return m;
}

TEST(PatchShapeConstraints, BasisHasExactZeroRowsAndTiesTheNormalPoints) {
  const Tetrahedron tet(Vec(0, 0, 1), Vec(1.5, -1, -0.5), Vec(-1.5, -1, -0.5), Vec(0, 1.5, -0.5));
  PatchShapeConstraints c;
  c.vertex_normals.push_back({0, Vec(0, 0, 1)});
  c.through_edges.push_back({1, 2});
  Eigen::MatrixXd n;
  std::string error;
  ASSERT_TRUE(ShapeConstraintBasis(3, tet, c, &n, &error)) << error;
  EXPECT_NEAR((n.transpose() * n - Eigen::MatrixXd::Identity(n.cols(), n.cols())).norm(), 0, 1e-15);
  // 20 control points - 1 (vertex) - 3 tied + 1 scale - 4 (edge 2-3) = 13 free.
  EXPECT_EQ(n.cols(), 13);
  EXPECT_EQ(n.row(BernsteinIndex(0, 0, 0)).norm(), 0.0);
  EXPECT_EQ(n.row(BernsteinIndex(3, 0, 0)).norm(), 0.0);
  EXPECT_EQ(n.row(BernsteinIndex(1, 2, 0)).norm(), 0.0);
  PatchShapeConstraints bad;
  bad.vertex_normals.push_back({0, Vec(0, 0, 1)});
  bad.vertex_normals.push_back({1, Vec(0, 0, 1)});
  EXPECT_FALSE(ShapeConstraintBasis(2, tet, bad, &n, &error));  // share b_{e1+e2} at degree 2
  EXPECT_TRUE(ShapeConstraintBasis(3, tet, bad, &n, &error)) << error;
}

TEST(PatchShapeConstraints, VertexNormalHoldsExactlyAfterTheFit) {
  // Sphere |x| = 1, cap z > 0.5; vertex x1 = (0, 0, 1) on it with outward normal (0, 0, 1).
  std::mt19937 rng(31);
  std::normal_distribution<double> g(0.0, 1.0), noise(0.0, 0.002);
  std::vector<Vec> points, normals;
  while (points.size() < 1500) {
    const Vec d = Vec(g(rng), g(rng), g(rng)).normalized();
    if (d.z() < 0.5) continue;
    points.push_back(d * (1 + noise(rng)));
    normals.push_back(d);
  }
  const Tetrahedron tet(Vec(0, 0, 1), Vec(1.5, -1, -0.5), Vec(-1.5, -1, -0.5), Vec(0, 1.5, -0.5));
  for (int k : {2, 3}) {
    PatchFitOptions o;
    o.degree = k;
    o.has_tetrahedron = true;
    o.tetrahedron = tet;
    o.constraints.vertex_normals.push_back({0, Vec(0, 0, 1)});
    const PatchFitResult r = FitBernsteinPatch(points, normals, o);
    ASSERT_TRUE(r.success) << r.message;
    const double scale = MaxAbs(r.control_points);
    const Vec x1 = tet.vertex(0);
    Eigen::Matrix<double, 3, 1> grad;
    const double f = BernsteinPatch::Derivatives(k, tet, r.control_points.data(), x1.data(), &grad);
    EXPECT_LE(std::abs(f), 1e-14 * scale);
    EXPECT_LT((grad.normalized() - Vec(0, 0, 1)).norm(), 1e-12) << grad.transpose();
    EXPECT_LT(r.rms, 0.01);
    std::printf("  vertex normal k=%d: f(x1) %.2g, grad %.3g %.3g %.3g, rms %.5f\n", k, f, grad.x(),
                grad.y(), grad.z(), r.rms);
  }
}

TEST(PatchShapeConstraints, ThroughVertexAndEdgeHoldExactly) {
  // Plane z = 0.1 x (cloud in the tetrahedron); edge x1 x2 and vertex x3 lie on it.
  const Vec x1(-1, -1, -0.1), x2(1, -1, 0.1), x3(0, 1.2, 0.0), x4(0, 0, 1.5);
  const Tetrahedron tet(x1, x2, x3, x4);
  std::mt19937 rng(32);
  std::uniform_real_distribution<double> u(-0.6, 0.6);
  std::normal_distribution<double> noise(0.0, 0.001);
  std::vector<Vec> points, normals;
  const Vec n = Vec(-0.1, 0, 1).normalized();
  for (int i = 0; i < 1000; ++i) {
    const double x = u(rng), y = u(rng);
    points.emplace_back(x, y, 0.1 * x + noise(rng));
    normals.push_back(n);
  }
  PatchFitOptions o;
  o.degree = 3;
  o.has_tetrahedron = true;
  o.tetrahedron = tet;
  o.constraints.through_edges.push_back({0, 1});
  o.constraints.through_vertices.push_back(2);
  const PatchFitResult r = FitBernsteinPatch(points, normals, o);
  ASSERT_TRUE(r.success) << r.message;
  const double scale = MaxAbs(r.control_points);
  for (int s = 0; s <= 10; ++s) {
    const Vec x = x1 + (x2 - x1) * (s / 10.0);
    EXPECT_LE(std::abs(BernsteinPatch::Evaluate(3, tet, r.control_points.data(), x.data())),
              1e-14 * scale);
  }
  EXPECT_LE(std::abs(BernsteinPatch::Evaluate(3, tet, r.control_points.data(), x3.data())),
            1e-14 * scale);
  EXPECT_LT(r.rms, 0.003);
  PatchFitOptions bad = o;
  bad.convex = true;
  std::string error;
  EXPECT_FALSE(bad.IsValid(&error));
}

}  // namespace
}  // namespace implicitfit
