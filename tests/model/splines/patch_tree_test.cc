// docs/maths.md JE-1 checks 1-4 on Jensen's example (tests/support/dome_on_plane.h): the blend
// weights sum to 1 and are exactly 1 / 0 where the paper says; G is f_1 exactly outside the
// band and the placed child exactly where theta = 1 (the placement recomputed here with Eigen's
// rotations); tau by the paper's Cramer formula agrees with a ray-polygon intersection; sigma
// agrees with numerical integration; G is C^1 across the band.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "model/dual3.h"
#include "support/dome_on_plane.h"

namespace implicitfit {
namespace {

using testsupport::DomeOnPlane;

Eigen::Vector3d G(const PatchTree& tree, double s, double t) {
  double out[3];
  tree.Evaluate(tree.placements.data(), s, t, out);
  return Eigen::Vector3d(out[0], out[1], out[2]);
}

// Check 1: phi + theta o gamma = 1; phi = 1 where the filter square misses gamma^-1(D_2)
// (farther than eps sqrt 2 from the domain); theta = 1 on the closed set sigma >= band.
TEST(PatchTree, BlendWeightsSumToOneWithTheirPlateaus) {
  const PatchTree tree = DomeOnPlane();
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> box(-2.0, 2.0);
  int inner = 0, outer = 0, band = 0;
  for (int i = 0; i < 20000; ++i) {
    const double s = box(rng), t = box(rng);
    double u, v;
    tree.Gamma(0, tree.placements.data(), s, t, &u, &v);
    const double theta = tree.Theta(0, u, v), phi = tree.Phi(0, tree.placements.data(), s, t);
    EXPECT_NEAR(phi + theta, 1.0, 1e-15);
    const double outside = std::max(std::abs(u), std::abs(v)) - 0.7;  // square domain
    if (outside > 0.1 + 1e-12) {  // the filter square lies outside D_2
      EXPECT_EQ(phi, 1.0);
      ++outer;
    }
    if (std::max(std::abs(u), std::abs(v)) < 0.15) {  // sigma = tau-average >= 0.5 there
      EXPECT_EQ(theta, 1.0);
      ++inner;
    }
    band += theta > 0.0 && theta < 1.0;
  }
  EXPECT_GT(inner, 100);
  EXPECT_GT(outer, 10000);
  EXPECT_GT(band, 500);
}

// Check 2: G = f_1 exactly where theta o gamma = 0; G = Gamma(f_2 o gamma) where theta = 1,
// the placement recomputed with an Eigen rotation of the child's frame (independent code).
TEST(PatchTree, OutsideTheBandGIsExactlyThePatches) {
  const double a = 0.3, b = -0.2, theta = 20.0 * M_PI / 180.0;
  const PatchTree tree = DomeOnPlane(a, b, theta);
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> box(-2.0, 2.0);
  int plateau = 0;
  for (int i = 0; i < 5000; ++i) {
    const double s = box(rng), t = box(rng);
    double u, v;
    tree.Gamma(0, tree.placements.data(), s, t, &u, &v);
    const double w = tree.Theta(0, u, v);
    const Eigen::Vector3d g = G(tree, s, t);
    if (w == 0.0) EXPECT_EQ(g, Eigen::Vector3d(s, t, 0.0));
    if (w == 1.0) {
      ++plateau;
      // The dome in its own frame, rotated by theta about the plane's normal z, moved to (a, b).
      const Eigen::Vector2d local =
          Eigen::Rotation2Dd(-theta) * (Eigen::Vector2d(s, t) - Eigen::Vector2d(a, b));
      const double rho = local.norm();
      const double S = rho > 0 ? std::sin(M_PI * rho / 2) / rho : M_PI / 2;
      const Eigen::Vector3d child(S * local[0], S * local[1], std::cos(M_PI * rho / 2));
      const Eigen::Vector3d placed =
          Eigen::Vector3d(a, b, 0) + Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ()) * child;
      EXPECT_LE((g - placed).norm(), 1e-15) << s << " " << t;
    }
  }
  EXPECT_GT(plateau, 20);
}

// Check 3: tau by the Cramer formula against the ray-polygon intersection (Eigen's 2x2 solve of
// c + lambda (p - c) = A + alpha (B - A)), tau = 1 - 1 / lambda, on random star polygons.
TEST(PatchTree, StarRatioAgreesWithRayPolygonIntersection) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  double worst = 0.0;
  for (int poly = 0; poly < 50; ++poly) {
    const int m = 3 + poly % 8;
    std::vector<Eigen::Vector2d> v;
    for (int i = 0; i < m; ++i) {
      const double angle = 2 * M_PI * (i + 0.3 * u01(rng)) / m, r = 0.5 + u01(rng);
      v.emplace_back(0.2 + r * std::cos(angle), -0.1 + r * std::sin(angle));
    }
    if (!StarDomainProblem(v).empty()) continue;
    const StarDomain d = MakeStarDomain(v);
    for (int k = 0; k < 200; ++k) {
      const double angle = 2 * M_PI * u01(rng), r = 1.6 * u01(rng);
      const Eigen::Vector2d p = d.centroid + r * Eigen::Vector2d(std::cos(angle), std::sin(angle));
      double lambda = INFINITY;
      for (int i = 0; i < m; ++i) {
        const Eigen::Vector2d A = v[i], B = v[(i + 1) % m];
        Eigen::Matrix2d M;
        M << p - d.centroid, A - B;
        const Eigen::Vector2d sol = M.fullPivLu().solve(A - d.centroid);
        if (sol[0] > 0 && sol[1] >= -1e-12 && sol[1] <= 1 + 1e-12) lambda = std::min(lambda, sol[0]);
      }
      const double expected = 1.0 - 1.0 / lambda;
      worst = std::max(worst, std::abs(StarRatio(d, p[0], p[1], false) - expected));
    }
  }
  EXPECT_LE(worst, 1e-14);
}

// sigma (exact, by clipping) against the midpoint rule on a 400 x 400 grid of tau.
TEST(PatchTree, SmoothedRatioIsTheBoxFilteredRatio) {
  const StarDomain d = MakeStarDomain({{0, 0}, {1, -0.2}, {1.3, 0.8}, {0.4, 1.1}, {-0.3, 0.6}});
  const double eps = 0.15;
  for (const Eigen::Vector2d p : {Eigen::Vector2d(0.5, 0.4), Eigen::Vector2d(1.2, 0.7),
                                  Eigen::Vector2d(-0.35, 0.55), Eigen::Vector2d(0.05, 0.0)}) {
    const int n = 400;
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        sum += StarRatio(d, p[0] - eps + 2 * eps * (i + 0.5) / n, p[1] - eps + 2 * eps * (j + 0.5) / n);
    EXPECT_NEAR(SmoothedStarRatio(d, p[0], p[1], eps), sum / (n * n), 2e-5) << p.transpose();
  }
}

// Check 4: G is C^1 across the band: along lines through the dome, the Jacobian (Dual3 in s, t)
// agrees with central differences and changes by O(step) between neighbouring samples (a
// C^0-only blend jumps by O(1) at sigma = 0 and sigma = band).
TEST(PatchTree, BlendedSurfaceIsC1AcrossTheBand) {
  const PatchTree tree = DomeOnPlane();
  std::vector<Dual3> placement(tree.placements.begin(), tree.placements.end());
  for (double angle : {0.0, 0.4, 0.8, 1.7, 2.9}) {
    const Eigen::Vector2d dir(std::cos(angle), std::sin(angle));
    Eigen::Matrix<double, 3, 2> previous;
    double worst_jump = 0.0, worst_fd = 0.0;
    const double step = 2e-4;
    for (int i = 0; i <= 7500; ++i) {
      const Eigen::Vector2d st = Eigen::Vector2d(0.3, -0.2) + (i * step) * dir;
      const Dual3 s(st[0], Eigen::Vector3d::UnitX()), t(st[1], Eigen::Vector3d::UnitY());
      Dual3 out[3];
      tree.Evaluate(placement.data(), s, t, out);
      Eigen::Matrix<double, 3, 2> J;
      for (int k = 0; k < 3; ++k) J.row(k) << out[k].v[0], out[k].v[1];
      if (i > 0) worst_jump = std::max(worst_jump, (J - previous).cwiseAbs().maxCoeff());
      previous = J;
      if (i % 50 == 0) {
        const double h = 1e-6;
        const Eigen::Vector3d ds = (G(tree, st[0] + h, st[1]) - G(tree, st[0] - h, st[1])) / (2 * h);
        const Eigen::Vector3d dt = (G(tree, st[0], st[1] + h) - G(tree, st[0], st[1] - h)) / (2 * h);
        worst_fd = std::max({worst_fd, (ds - J.col(0)).cwiseAbs().maxCoeff(),
                             (dt - J.col(1)).cwiseAbs().maxCoeff()});
      }
    }
    EXPECT_LE(worst_jump, 0.05) << "angle " << angle;  // |G''| * step with |G''| < 250
    EXPECT_LE(worst_fd, 1e-6) << "angle " << angle;
  }
}

TEST(PatchTree, ProblemsAreNamed) {
  PatchTree tree = DomeOnPlane();
  EXPECT_EQ(tree.Problem(), "");
  PatchTree bad = tree;
  bad.links[0].child = 0;
  EXPECT_NE(bad.Problem(), "");
  bad = tree;
  bad.patches[1].domain = MakeStarDomain({{0, 0}, {0, 1}, {1, 0}});  // clockwise
  EXPECT_NE(bad.Problem(), "");
  bad = tree;
  bad.placements.pop_back();
  EXPECT_NE(bad.Problem(), "");
}

}  // namespace
}  // namespace implicitfit
