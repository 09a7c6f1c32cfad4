// Each stage of the primitive fitter (fit/primitive/primitive_fit_stages.h) on its own, against values
// computed here by closed forms (sphere distances |x - c| - r, medians by sorting, the plane
// offset's variance s^2 / N), and max_rounds as a hard bound on FitPrimitive's rounds.
#include "fit/primitive/primitive_fit_stages.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <iterator>
#include <numeric>
#include <random>

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

const Vec kCentre(0.2, -0.1, 0.3);
constexpr double kRadius = 1.5;

// Points on the sphere (kCentre, kRadius) at signed distances d[i] from it, outward normals.
std::vector<Vec> SphereShell(const std::vector<double>& d, unsigned seed, std::vector<Vec>* n) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g;
  std::vector<Vec> x;
  n->clear();
  for (double di : d) {
    const Vec u = Vec(g(rng), g(rng), g(rng)).normalized();
    x.push_back(kCentre + (kRadius + di) * u);
    n->push_back(u);
  }
  return x;
}

double SphereDistance(const std::vector<double>& p, const Vec& x) {
  return (x - Vec(p[0], p[1], p[2])).norm() - p[3];
}

TEST(PrimitiveFitStages, RecentreMovesTheCloudToItsCentroid) {
  const Vec offset(5e5, -3e6, 1e3);  // UTM-sized coordinates
  const std::vector<Vec> x = {offset + Vec(0, 0, 0), offset + Vec(2, 0, 0), offset + Vec(0, 4, 0),
                              offset + Vec(2, 4, 8)};
  const RecentredCloud c = Recentre(x);
  EXPECT_LT((c.centroid - (offset + Vec(1, 2, 2))).norm(), 1e-9);
  EXPECT_NEAR(c.diagonal, std::sqrt(4.0 + 16.0 + 64.0), 1e-9);
  Vec sum = Vec::Zero();
  for (size_t i = 0; i < x.size(); ++i) {
    EXPECT_LT((c.points[i] - (x[i] - c.centroid)).norm(), 1e-9);
    sum += c.points[i];
  }
  EXPECT_LT(sum.norm(), 1e-9);
}

TEST(PrimitiveFitStages, FixedValuesMoveIntoTheRecentredFrame) {
  const Vec centroid(10, 20, 30);
  const std::vector<double> sphere =
      FixedInRecentred(NodeType::kSphere, {{"center", {1, 2, 3}}}, centroid);
  ASSERT_EQ(sphere.size(), 4u);
  EXPECT_DOUBLE_EQ(sphere[0], -9);
  EXPECT_DOUBLE_EQ(sphere[2], -27);
  EXPECT_TRUE(std::isnan(sphere[3]));  // the radius is free
  // The plane n . x = d with n = (0, 0, 2), d = 70 (z = 35) is z' = 5 around the centroid.
  const std::vector<double> plane =
      FixedInRecentred(NodeType::kPlane, {{"normal", {0, 0, 2}}, {"offset", {70}}}, centroid);
  EXPECT_NEAR(plane[3] / 2.0, 5.0, 1e-12);
  std::vector<double> p = {1, 1, 1, 1};
  ApplyFixed(sphere, &p);
  EXPECT_EQ(p, (std::vector<double>{-9, -18, -27, 1}));
}

TEST(PrimitiveFitStages, HypothesesFindTheSphereAmongOutliers) {
  std::vector<double> d(700, 0.0);
  std::vector<Vec> n;
  std::vector<Vec> x = SphereShell(d, 3, &n);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-3, 3);
  for (int i = 0; i < 300; ++i) {  // 30% outliers
    x.push_back(Vec(u(rng), u(rng), u(rng)));
    n.push_back(Vec(u(rng), u(rng), u(rng)).normalized());
  }
  const RecentredCloud cloud = Recentre(x);
  PrimitiveFitOptions options;
  options.kind = NodeType::kSphere;
  std::mt19937 draw(1);
  const std::vector<double> none(4, NAN);
  const HypothesisSearchResult h = FindHypothesis(cloud, n, 0.02, options, none, draw);
  ASSERT_EQ(h.parameters.size(), 4u);
  EXPECT_LT(
      (Vec(h.parameters[0], h.parameters[1], h.parameters[2]) + cloud.centroid - kCentre).norm(),
      1e-9);
  EXPECT_NEAR(h.parameters[3], kRadius, 1e-9);
  // A fixed radius is imposed on every hypothesis.
  std::vector<double> fixed = none;
  fixed[3] = 1.2;
  std::mt19937 draw2(1);
  EXPECT_DOUBLE_EQ(FindHypothesis(cloud, n, 0.02, options, fixed, draw2).parameters[3], 1.2);
  // Given initial parameters are only moved into the frame.
  options.initial = {1, 2, 3, 4};
  std::mt19937 draw3(1);
  const HypothesisSearchResult given = FindHypothesis(cloud, n, 0.02, options, none, draw3);
  EXPECT_NEAR(given.parameters[0], 1 - cloud.centroid[0], 1e-12);
  EXPECT_DOUBLE_EQ(given.parameters[3], 4);
}

TEST(PrimitiveFitStages, ClassifyKeepsCloseAndAgreeingPoints) {
  std::vector<double> d;
  for (int i = -20; i <= 20; ++i) d.push_back(0.01 * i);
  std::vector<Vec> n;
  const std::vector<Vec> x = SphereShell(d, 5, &n);
  std::vector<Vec> tilted = n;
  const Eigen::AngleAxisd turn(M_PI / 3, Vec::UnitZ().cross(n[20]).normalized());
  tilted[20] = turn * n[20];  // 60 degrees off: |cos| = 0.5 < 0.8
  std::vector<int> pool(x.size());
  std::iota(pool.begin(), pool.end(), 0);
  const std::vector<double> p = {kCentre[0], kCentre[1], kCentre[2], kRadius};
  std::vector<int> expected;
  for (size_t i = 0; i < d.size(); ++i)
    if (std::abs(d[i]) < 0.055 && i != 20) expected.push_back(static_cast<int>(i));
  EXPECT_EQ(Classify(NodeType::kSphere, p, x, tilted, pool, 0.055, 0.8), expected);
  // Without normals only the distance counts.
  std::vector<int> by_distance;
  for (size_t i = 0; i < d.size(); ++i)
    if (std::abs(d[i]) < 0.055) by_distance.push_back(static_cast<int>(i));
  EXPECT_EQ(Classify(NodeType::kSphere, p, x, {}, pool, 0.055, 0.8), by_distance);
}

TEST(PrimitiveFitStages, ARoundSolvesTheLeastSquaresOfTheInliers) {
  std::vector<Vec> n;
  const std::vector<Vec> x = SphereShell(std::vector<double>(500, 0.0), 6, &n);
  std::vector<int> all(x.size());
  std::iota(all.begin(), all.end(), 0);
  std::vector<double> p = {kCentre[0] + 0.05, kCentre[1] - 0.04, kCentre[2], kRadius * 1.03};
  RefinementRound round;
  SolveRound(NodeType::kSphere, x, all, {}, 1, nullptr, &p, &round);
  EXPECT_LT((Vec(p[0], p[1], p[2]) - kCentre).norm(), 1e-8);
  EXPECT_NEAR(p[3], kRadius, 1e-8);
  EXPECT_GT(round.summary.iterations.size(), 1u);
  // A fixed field stays where it was.
  std::vector<double> q = {kCentre[0] + 0.05, kCentre[1], kCentre[2], 1.4};
  SolveRound(NodeType::kSphere, x, all, {{"radius", {1.4}}}, 1, nullptr, &q, &round);
  EXPECT_DOUBLE_EQ(q[3], 1.4);
}

TEST(PrimitiveFitStages, ReclassifyTakesTheScaleFromTheMedian) {
  std::vector<double> d;
  std::mt19937 rng(8);
  std::normal_distribution<double> g(0.0, 0.01);
  for (int i = 0; i < 400; ++i) d.push_back(g(rng));
  for (int i = 0; i < 10; ++i) d.push_back(0.5);  // far points: outside the new band
  std::vector<Vec> n;
  const std::vector<Vec> x = SphereShell(d, 9, &n);
  std::vector<int> all(x.size());
  std::iota(all.begin(), all.end(), 0);
  const std::vector<double> p = {kCentre[0], kCentre[1], kCentre[2], kRadius};
  PrimitiveFitOptions options;
  options.kind = NodeType::kSphere;
  const Reclassification r = Reclassify(NodeType::kSphere, p, x, n, all, all, options);
  std::vector<double> a;
  for (double v : d) a.push_back(std::abs(v));
  std::sort(a.begin(), a.end());
  const double median = a[a.size() / 2];  // model/median.h: the element of rank n/2
  EXPECT_NEAR(r.sigma, 1.4826 * median, 1e-12);
  EXPECT_NEAR(r.band, 3.0 * r.sigma, 1e-12);
  std::vector<int> expected;
  for (size_t i = 0; i < d.size(); ++i)
    if (std::abs(SphereDistance(p, x[i])) < r.band) expected.push_back(static_cast<int>(i));
  EXPECT_EQ(r.inliers, expected);
  EXPECT_GE(d.size() - expected.size(), 10u);
  EXPECT_FALSE(r.stable);  // >= 10 of 410 changed: more than 0.2%
  // From the new inliers: the band shrinks (no far points in the median); stable exactly when
  // at most 0.2% of them changed.
  const Reclassification again = Reclassify(NodeType::kSphere, p, x, n, all, r.inliers, options);
  std::vector<int> changed;
  std::set_symmetric_difference(again.inliers.begin(), again.inliers.end(), r.inliers.begin(),
                                r.inliers.end(), std::back_inserter(changed));
  EXPECT_LT(again.sigma, r.sigma);
  EXPECT_EQ(again.stable, changed.size() <= 0.002 * r.inliers.size());
}

TEST(PrimitiveFitStages, FiguresOfKnownDistancesAndNormalAngles) {
  const std::vector<double> d = {0.01, -0.02, 0.03, -0.04, 0.0};
  std::vector<Vec> n;
  const std::vector<Vec> x = SphereShell(d, 10, &n);
  // Every normal turned by 10 degrees about an axis orthogonal to it.
  for (Vec& v : n) v = Eigen::AngleAxisd(10.0 * M_PI / 180, v.unitOrthogonal()) * v;
  const std::vector<double> p = {kCentre[0], kCentre[1], kCentre[2], kRadius};
  const InlierFigures f = Figures(NodeType::kSphere, p, x, n, {0, 1, 2, 3, 4});
  EXPECT_NEAR(f.rss, 0.0001 + 0.0004 + 0.0009 + 0.0016, 1e-14);
  EXPECT_NEAR(f.rms, std::sqrt(0.003 / 5), 1e-12);
  EXPECT_NEAR(f.max_abs, 0.04, 1e-12);
  // Off the sphere the gradient is still radial, so the angle is the 10 degree turn.
  EXPECT_NEAR(f.mean_normal_angle_deg, 10.0, 1e-4);
  EXPECT_EQ(Figures(NodeType::kSphere, p, x, {}, {0, 1}).mean_normal_angle_deg, -1.0);
}

// A plane through points centred on the origin: the offset's standard deviation is s / sqrt(N),
// s^2 = RSS / (N - 3), independent of the normal's (the regressors are centred).
TEST(PrimitiveFitStages, StandardDeviationOfAPlaneOffset) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(-1, 1);
  std::normal_distribution<double> noise(0.0, 0.01);
  std::vector<Vec> x;
  for (int i = 0; i < 2000; ++i) x.push_back(Vec(u(rng), u(rng), noise(rng)));
  const RecentredCloud cloud = Recentre(x);
  std::vector<int> all(x.size());
  std::iota(all.begin(), all.end(), 0);
  std::vector<double> p = {0.01, 0.0, 1.0, 0.001};
  RefinementRound round;
  SolveRound(NodeType::kPlane, cloud.points, all, {}, 1, nullptr, &p, &round);
  const InlierFigures f = Figures(NodeType::kPlane, p, cloud.points, {}, all);
  const std::vector<double> sd =
      StandardDeviations(NodeType::kPlane, &round, {}, f.rss, all.size(), 1);
  ASSERT_EQ(sd.size(), 4u);
  const double n = static_cast<double>(x.size());
  double rss = 0.0;  // recomputed here from the fitted plane
  const Vec normal = Vec(p[0], p[1], p[2]).normalized();
  for (const Vec& y : cloud.points)
    rss += std::pow(normal.dot(y) - p[3] / Vec(p[0], p[1], p[2]).norm(), 2);
  EXPECT_NEAR(sd[3], std::sqrt(rss / (n - 3)) / std::sqrt(n), 0.02 * sd[3]);
  // A fixed offset has no uncertainty.
  SolveRound(NodeType::kPlane, cloud.points, all, {{"offset", {p[3]}}}, 1, nullptr, &p, &round);
  EXPECT_EQ(
      StandardDeviations(NodeType::kPlane, &round, {{"offset", {p[3]}}}, f.rss, all.size(), 1)[3],
      0.0);
}

// max_rounds bounds the rounds of the working subset and of every point together. With
// stable_fraction < 0 the inlier set is never "stable", so every allowed round runs.
TEST(PrimitiveFitStages, MaxRoundsIsAHardMaximum) {
  std::mt19937 rng(13);
  std::normal_distribution<double> g(0.0, 0.002);
  std::vector<double> d(8000);
  for (double& v : d) v = g(rng);
  std::vector<Vec> n;
  const std::vector<Vec> x = SphereShell(d, 14, &n);  // 8000 > working_subsample 5000
  for (int max_rounds : {1, 2, 3, 5}) {
    SCOPED_TRACE(max_rounds);
    PrimitiveFitOptions options;
    options.kind = NodeType::kSphere;
    options.max_rounds = max_rounds;
    options.stable_fraction = -1.0;
    options.compute_covariance = false;
    const PrimitiveFitResult r = FitPrimitive(x, n, options);
    EXPECT_TRUE(r.success) << r.message;
    EXPECT_EQ(r.rounds, max_rounds);
    EXPECT_NEAR(r.parameters[3], kRadius, 1e-3);
  }
  PrimitiveFitOptions bad;
  bad.max_rounds = 0;
  std::string error;
  EXPECT_FALSE(bad.IsValid(&error));
  EXPECT_NE(error.find("max_rounds"), std::string::npos);
}

}  // namespace
}  // namespace implicitfit
