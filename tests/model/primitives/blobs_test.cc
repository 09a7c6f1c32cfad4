// Blobs (docs/maths.md TB-2): the closed forms of docs/maths.md TB-2, derived from the kernels by
// hand.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "model/file/model_json.h"
#include "model/model.h"
#include "support/model_document.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

using testsupport::ModelFromRoot;

TEST(Blobs, OneGaussianBlobIsTheSphereOfRadiusSqrtLnAOverTOverB) {
  // a = e, b = 1, T = 1: the unit sphere.
  const Model unit =
      ModelFromRoot(R"({"type": "blobs", "centers": [[1, 2, 3]], "weights": [2.718281828459045],
      "widths": [1], "threshold": 1, "kernel": "gaussian"})");
  std::mt19937 rng(2);
  std::normal_distribution<double> g;
  for (int i = 0; i < 200; ++i) {
    const Vec d = Vec(g(rng), g(rng), g(rng)).normalized();
    EXPECT_NEAR(unit.Value(Vec(1, 2, 3) + d), 0.0, 1e-12);
  }
  // General a, b, T: R = sqrt(ln(a / T) / b).
  const double a = 5.0, b = 2.5, t = 0.7, radius = std::sqrt(std::log(a / t) / b);
  Model m;
  m.AddBlobs(BlobKernel::kGaussian, 0, {0, 0, 0}, {a}, {b}, t);
  for (int i = 0; i < 100; ++i) {
    const Vec d = Vec(g(rng), g(rng), g(rng)).normalized();
    EXPECT_NEAR(m.Value(radius * d), 0.0, 1e-12);
    EXPECT_LT(m.Value(0.99 * radius * d), 0.0);
    EXPECT_GT(m.Value(1.01 * radius * d), 0.0);
  }
}

TEST(Blobs, MidpointOfTwoEqualBlobsIsInsideExactlyWhenTwoAExpMinusBDSquaredReachesT) {
  // Blobs at +-d on x: f(0) = T - 2 a exp(-b d^2). Both sides of the threshold.
  const double a = 1.0, b = 1.0, t = 1.0;
  const double d_star = std::sqrt(std::log(2 * a / t) / b);  // 2 a exp(-b d^2) = T
  for (double d : {0.9 * d_star, 1.1 * d_star}) {
    Model m;
    m.AddBlobs(BlobKernel::kGaussian, 0, {-d, 0, 0, d, 0, 0}, {a, a}, {b, b}, t);
    const bool inside = 2 * a * std::exp(-b * d * d) >= t;
    EXPECT_EQ(m.Value(Vec::Zero()) <= 0.0, inside) << d;
    EXPECT_NEAR(m.Value(Vec::Zero()), t - 2 * a * std::exp(-b * d * d), 1e-15);
  }
}

TEST(Blobs, NegativeWeightCarvesADent) {
  Model plain, dented;
  plain.AddBlobs(BlobKernel::kGaussian, 0, {0, 0, 0}, {3.0}, {1.0}, 1.0);
  dented.AddBlobs(BlobKernel::kGaussian, 0, {0, 0, 0, 1.0, 0, 0}, {3.0, -1.0}, {1.0, 4.0}, 1.0);
  const double radius = std::sqrt(std::log(3.0));
  const Vec on_x(radius - 0.05, 0, 0), on_y(0, radius - 0.05, 0);
  EXPECT_LT(plain.Value(on_x), 0.0);
  EXPECT_GT(dented.Value(on_x), 0.0);  // carved away next to the negative blob
  EXPECT_GT(dented.Value(on_x), plain.Value(on_x));
  EXPECT_LT(dented.Value(on_y), 0.0);  // far from it the solid stays
}

TEST(Blobs, CompactKernelsHaveHalfWidthSpheresAndExactSupport) {
  // 1 - H_n(2R/w - 1) = 1/2 at R = w/2 (H_n(0) = 1/2), so a = 2 T gives the sphere R = w / 2.
  for (int order : {1, 2, 3, 5}) {
    Model m;
    m.AddBlobs(BlobKernel::kUnitStep, order, {0.5, 0, 0}, {2.0}, {1.6}, 1.0);
    EXPECT_NEAR(m.Value(Vec(0.5 + 0.8, 0, 0)), 0.0, 1e-14) << order;
    EXPECT_NEAR(m.Value(Vec(0.5, -0.8, 0)), 0.0, 1e-14) << order;
    EXPECT_EQ(m.Value(Vec(0.5, 0, 1.6)), 1.0);               // beyond the support: f = T exactly
    EXPECT_NEAR(m.Value(Vec(0.5, 0, 0)), 1.0 - 2.0, 1e-15);  // centre: k = 1
  }
  // Wyvill: k(w/2) = 1 - 4/9/64 + 17/9/16 - 22/9/4 = 0.4398..; k(w) = 0 with zero slope.
  Model w;
  w.AddBlobs(BlobKernel::kWyvill, 0, {0, 0, 0}, {1.0}, {2.0}, 0.0);
  const double s2 = 0.25, k = 1 - 4.0 / 9 * s2 * s2 * s2 + 17.0 / 9 * s2 * s2 - 22.0 / 9 * s2;
  EXPECT_NEAR(w.Value(Vec(1.0, 0, 0)), -k, 1e-15);
  EXPECT_NEAR(w.Value(Vec(0, 1.999999, 0)), 0.0, 1e-10);
  EXPECT_EQ(w.Value(Vec(0, 0, 2.5)), 0.0);
}

TEST(Blobs, JsonFormOfTheNotesRoundTripsAndRefusesMismatchedLengths) {
  const Model m =
      ModelFromRoot(R"({"type": "blobs", "centers": [[0, 0, 0], [1, 0, 0]], "weights": [2, -0.5],
      "widths": [1.5, 2], "threshold": 1, "kernel": "h_n", "order": 4})");
  const Model back = ModelFromJson(ModelToJson(m));
  EXPECT_EQ(ModelToJson(back), ModelToJson(m));
  EXPECT_EQ(ModelToJson(m)["root"]["order"], 4);
  for (const Vec& x : {Vec(0.3, 0.2, 0.1), Vec(0.9, -0.4, 0.2)})
    EXPECT_EQ(back.Value(x), m.Value(x));
  EXPECT_THROW(
      ModelFromRoot(R"({"type": "blobs", "centers": [[0, 0, 0]], "weights": [2, 1], "widths": [1],
      "threshold": 1, "kernel": "gaussian"})"),
      ModelFormatError);
  EXPECT_THROW(
      ModelFromRoot(R"({"type": "blobs", "centers": [[0, 0, 0]], "weights": [2], "widths": [0],
      "threshold": 1, "kernel": "gaussian"})"),
      ModelFormatError);
  EXPECT_THROW(
      ModelFromRoot(R"({"type": "blobs", "centers": [[0, 0, 0]], "weights": [2], "widths": [1],
      "threshold": 1, "kernel": "metaball"})"),
      ModelFormatError);
}

}  // namespace
}  // namespace implicitfit
