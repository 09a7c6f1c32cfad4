// Convex quadric-patch fits at their optimum (issue 28). The oriented saddle z = 0.4 (x^2 - y^2)
// over [-1, 1]^2, 5000 points, Gaussian noise 0.002 along the normal, normals up (+z outside):
// the solid below a saddle is not convex, so a convex fit must compromise; the least-squares
// plane is itself a convex solid, so the best convex quadric can do no worse. Over 12 random
// draws every --convex fit must be certified, with mean signed normal cosine >= 0.8, RMS <= 1.1x
// the best plane's, and the margin met on the WRITTEN patch (the JSON round trip):
// lambda_min(A) >= 1e-6 max |b|. Everything is recomputed here, independently of the fitter:
// the plane by PCA (total least squares), A from the control points longhand (Guo eq. 7) and
// its eigenvalues by Eigen, distances f / |grad f| and cosines from the written model.
// Before issue 28 the fit was started from the unconstrained fit's clamped matrix only, with a
// Cauchy scale from the unconstrained noise level: 11 of these 12 draws came out inside out.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "fit/bernstein/patch_fitter.h"
#include "model/file/model_json.h"
#include "support/sanitized_build.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

struct Saddle {
  std::vector<Vec> points, normals;
};

Saddle DrawSaddle(unsigned seed, int n) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.002);
  Saddle s;
  for (int i = 0; i < n; ++i) {
    const double x = u(rng), y = u(rng);
    const Vec normal = Vec(-0.8 * x, 0.8 * y, 1.0).normalized();
    s.points.push_back(Vec(x, y, 0.4 * (x * x - y * y)) + noise(rng) * normal);
    s.normals.push_back(normal);
  }
  return s;
}

// RMS orthogonal distance of the total-least-squares plane.
double BestPlaneRms(const std::vector<Vec>& points) {
  Vec c = Vec::Zero();
  for (const Vec& p : points) c += p;
  c /= static_cast<double>(points.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Vec& p : points) cov += (p - c) * (p - c).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  return std::sqrt(eig.eigenvalues()[0] / static_cast<double>(points.size()));
}

// lambda_min(A) / max |b| of a degree-2 patch, A_ij = b(e_i+e_j) + b(2e_4) - b(e_i+e_4) -
// b(e_j+e_4) in the design order 2000 1100 1010 1001 0200 0110 0101 0020 0011 0002.
double RelativeMargin(const std::vector<double>& b) {
  const int pair[4][4] = {{0, 1, 2, 3}, {1, 4, 5, 6}, {2, 5, 7, 8}, {3, 6, 8, 9}};
  Eigen::Matrix3d A;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) A(i, j) = b[pair[i][j]] + b[9] - b[pair[i][3]] - b[pair[j][3]];
  double scale = 0;
  for (double v : b) scale = std::max(scale, std::abs(v));
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(A).eigenvalues()[0] / scale;
}

TEST(ConvexPatchSaddle, TwelveDrawsCertifiedBetterThanThePlaneAndMarginMet) {
  // 12 draws; 3 in the sanitized build (about 0.7 s of CPU per draw in Release, several times
  // that under AddressSanitizer; the assertions are the same on every draw).
  const int draws = testsupport::kSanitizedBuild ? 3 : 12;
  // Seeds 1000..1011, or from IMPLICITFIT_TEST_SEED on for a held-out set of draws.
  const char* env = std::getenv("IMPLICITFIT_TEST_SEED");
  const unsigned base = env ? static_cast<unsigned>(std::strtoul(env, nullptr, 10)) : 1000;
  double cosine_sum = 0, worst_ratio = 0, worst_margin = INFINITY;
  for (int draw = 0; draw < draws; ++draw) {
    const Saddle s = DrawSaddle(base + draw, 5000);
    PatchFitOptions o;
    o.degree = 2;
    o.convex = true;
    const PatchFitResult r = FitBernsteinPatch(s.points, s.normals, o);
    ASSERT_TRUE(r.success) << "draw " << draw << ": " << r.message;
    EXPECT_TRUE(r.certified_convex) << "draw " << draw;
    // The written patch: the JSON round trip the command line does.
    const Model m = ModelFromJson(nlohmann::json::parse(ModelToJson(r.ToModel()).dump()));
    const ModelNode& node = m.nodes()[m.root()];
    const std::vector<double> b(m.parameters().begin() + node.first_parameter,
                                m.parameters().begin() + node.first_parameter + 10);
    const double margin = RelativeMargin(b);
    double ss = 0, cosines = 0;
    for (size_t i = 0; i < s.points.size(); ++i) {
      double f;
      const Vec g = m.Gradient(s.points[i], &f);
      ss += f * f / g.squaredNorm();
      cosines += g.normalized().dot(s.normals[i]);
    }
    const double rms = std::sqrt(ss / s.points.size()), cosine = cosines / s.points.size();
    const double plane = BestPlaneRms(s.points);
    std::printf("  draw %2d: cosine %.4f  rms %.4f  plane rms %.4f  ratio %.3f  margin %.3g\n",
                draw, cosine, rms, plane, rms / plane, margin);
    EXPECT_GE(margin, 1e-6) << "draw " << draw;
    EXPECT_LE(rms, 1.1 * plane) << "draw " << draw;
    EXPECT_GT(cosine, 0.0) << "draw " << draw << ": inside out";
    cosine_sum += cosine;
    worst_ratio = std::max(worst_ratio, rms / plane);
    worst_margin = std::min(worst_margin, margin);
  }
  std::printf("  mean cosine %.4f, worst rms / plane %.3f, smallest margin %.3g\n",
              cosine_sum / draws, worst_ratio, worst_margin);
  EXPECT_GE(cosine_sum / draws, 0.8);
}

}  // namespace
}  // namespace implicitfit
