// Patch fits respect the orientation of the normals (issue #12): on the oriented saddle
// z = 0.4 (x^2 - y^2) with normals pointing up (+z side outside), grad f of the fitted patch,
// with or without --convex, must point along the normals: mean signed cosine > 0 (it was -0.83
// for the convex fit when the normal residual ignored the sign). Cosines are recomputed here
// from BernsteinPatch::Derivatives.
#include <gtest/gtest.h>

#include <random>

#include "fit/bernstein/patch_fitter.h"
#include "model/certificates/convexity_certificate.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

TEST(PatchOrientation, FitsOfAnUpwardOrientedSaddleFollowTheNormals) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  std::normal_distribution<double> noise(0.0, 0.002);
  std::vector<Vec> points, normals;
  for (int i = 0; i < 1500; ++i) {
    const double x = u(rng), y = u(rng);
    points.emplace_back(x, y, 0.4 * (x * x - y * y) + noise(rng));
    normals.push_back(Vec(-0.8 * x, 0.8 * y, 1.0).normalized());  // up: +z is outside
  }
  for (bool convex : {false, true})
    for (int degree : {2, 3}) {
      PatchFitOptions o;
      o.degree = degree;
      o.convex = convex;
      const PatchFitResult r = FitBernsteinPatch(points, normals, o);
      ASSERT_TRUE(r.success) << r.message;
      double cosines = 0.0;
      for (size_t i = 0; i < points.size(); ++i) {
        Eigen::Matrix<double, 3, 1> g;
        BernsteinPatch::Derivatives(degree, r.tetrahedron, r.control_points.data(),
                                    points[i].data(), &g);
        cosines += g.normalized().dot(normals[i]);
      }
      const double mean = cosines / points.size();
      EXPECT_NEAR(r.mean_normal_cosine, mean, 1e-12);
      EXPECT_GT(mean, 0.5) << "degree " << degree << (convex ? " convex" : "");
      EXPECT_LT(r.mean_normal_angle_deg, 90.0);
      if (convex) {
        EXPECT_TRUE(CertifyConvexity(degree, r.control_points.data()).convex);
      } else {
        EXPECT_GT(mean, 0.99);
      }
      std::printf("  saddle k=%d%s: mean signed normal cosine %.4f, angle %.1f deg, rms %.4f\n",
                  degree, convex ? " --convex" : "", mean, r.mean_normal_angle_deg, r.rms);
    }
}

}  // namespace
}  // namespace implicitfit
