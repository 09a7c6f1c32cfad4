// The minimum zone over working sets (fit/metrology/minimum_zone.cc, the exchange used above
// direct_limit points) against the one LP over every point on the same noisy clouds: the same
// zone, every point inside it (distances recomputed here in closed form), certified.
#include <gtest/gtest.h>

#include <random>

#include "fit/metrology/least_squares_fit.h"
#include "fit/metrology/minimum_zone.h"

namespace implicitfit {
namespace {

std::vector<Eigen::Vector3d> NoisySphere(int n, double noise, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d u = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
    points.push_back(Eigen::Vector3d(0.3, -0.2, 0.1) + (2.0 + noise * g(rng)) * u);
  }
  return points;
}

std::vector<Eigen::Vector3d> NoisyCylinder(int n, double noise, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> angle(0, 2 * M_PI), height(-1, 1);
  std::normal_distribution<double> g(0.0, noise);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < n; ++i) {
    const double a = angle(rng), r = 0.5 + g(rng);
    points.emplace_back(r * std::cos(a), r * std::sin(a), height(rng));
  }
  return points;
}

TEST(MinimumZoneExchange, SameZoneAsOneLpOverEveryPoint) {
  struct Set {
    NodeType kind;
    std::vector<Eigen::Vector3d> points;
    std::vector<double> guess;
  };
  const std::vector<Set> sets = {
      // 2 100 points: the first working set (at most 1 000) is under half the cloud, so the
      // exchange runs rounds instead of falling back to the one LP.
      {NodeType::kSphere, NoisySphere(2100, 0.01, 3), {0, 0, 0, 2}},
      {NodeType::kCylinder, NoisyCylinder(2100, 0.005, 5), {0, 0, 0, 0, 0, 1, 0.5}},
  };
  for (const Set& s : sets) {
    const LeastSquaresResult ls = LeastSquaresFit(s.kind, s.points, s.guess);
    ASSERT_TRUE(ls.success) << ls.message;
    const MinimumZoneResult direct =
        MinimumZoneFit(s.kind, s.points, ls.parameters, 1 << 30);  // one LP, every point
    const MinimumZoneResult exchange = MinimumZoneFit(s.kind, s.points, ls.parameters, 300);
    ASSERT_TRUE(direct.success) << direct.message;
    ASSERT_TRUE(exchange.success) << exchange.message;
    EXPECT_NEAR(exchange.zone_width, direct.zone_width, 1e-10 * direct.zone_width)
        << NodeTypeName(s.kind);
    // Every point inside the exchange's zone, by the closed-form distance.
    const std::vector<double>& p = exchange.parameters;
    double lo = 1e300, hi = -1e300;
    for (const Eigen::Vector3d& x : s.points) {
      double d;
      if (s.kind == NodeType::kSphere) {
        d = (x - Eigen::Vector3d(p[0], p[1], p[2])).norm() - p[3];
      } else {
        const Eigen::Vector3d q(p[0], p[1], p[2]), u = Eigen::Vector3d(p[3], p[4], p[5]).normalized();
        d = ((x - q) - (x - q).dot(u) * u).norm() - p[6];
      }
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
    EXPECT_LE(hi - lo, exchange.zone_width * (1 + 1e-9)) << NodeTypeName(s.kind);
    EXPECT_GE(exchange.outer_contacts, 1);
    EXPECT_GE(exchange.inner_contacts, 1);
    for (int c : exchange.contacts) {  // contacts index the whole cloud
      ASSERT_GE(c, 0);
      ASSERT_LT(c, static_cast<int>(s.points.size()));
    }
  }
}

}  // namespace
}  // namespace implicitfit
