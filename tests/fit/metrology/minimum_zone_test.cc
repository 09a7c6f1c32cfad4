// Minimum zone of curved primitives (fit/metrology/minimum_zone.h) on generated CMM sets
// (tests/support/cmm_reference.h), started from the least-squares fit:
// - cylinders and cones with k + 2 .. k + 4 points against the enumeration of every levelled
//   (k + 1)-point zone in long double (tests/support/minimum_zone_reference.h): equal to the
//   narrowest within 1e-12 mm when k + 1 points touch the zone, never wider except on at most
//   one set per kind (another local minimum, within 1e-5 of the width);
// - spheres, cylinders and cones on many seeds and sizes (6-40 points): every fit certified, the
//   width no more than the least-squares form error, equal to 2 max |d_i| recomputed here,
//   contacts on both faces, and no random small move of the parameters narrows the zone.
#include "fit/metrology/minimum_zone.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "fit/metrology/least_squares_fit.h"
#include "fit/metrology/primitive_tangent.h"
#include "support/minimum_zone_reference.h"

namespace implicitfit {
namespace {

using testsupport::CmmKind;
using testsupport::CmmSet;

NodeType KindOf(CmmKind k) {
  return k == CmmKind::kPlane      ? NodeType::kPlane
         : k == CmmKind::kSphere   ? NodeType::kSphere
         : k == CmmKind::kCylinder ? NodeType::kCylinder
         : k == CmmKind::kTorus    ? NodeType::kTorus
                                   : NodeType::kCone;
}

// The generating part in implicitfit's layout (world frame): the least-squares start.
std::vector<double> TrueParameters(const CmmSet& s) {
  const Eigen::Vector3d o = s.origin, u = s.rotation.col(2);
  switch (s.kind) {
    case CmmKind::kSphere:
      return {o.x(), o.y(), o.z(), 5.0};
    case CmmKind::kCylinder:
      return {o.x(), o.y(), o.z(), u.x(), u.y(), u.z(), 5.0};
    case CmmKind::kTorus:
      return {o.x(), o.y(), o.z(), u.x(), u.y(), u.z(), 5.0, 2.0};
    default:
      return {o.x(), o.y(), o.z(), u.x(), u.y(), u.z(), CmmSet::kConeHalfAngle};
  }
}

struct Fits {
  LeastSquaresResult ls;
  MinimumZoneResult mz;
};

Fits FitBoth(const CmmSet& s) {
  Fits f;
  f.ls = LeastSquaresFit(KindOf(s.kind), s.points, TrueParameters(s));
  if (f.ls.success) f.mz = MinimumZoneFit(KindOf(s.kind), s.points, f.ls.parameters);
  return f;
}

class MinimumZoneEnumeration : public ::testing::TestWithParam<CmmKind> {};

TEST_P(MinimumZoneEnumeration, MatchesTheNarrowestLevelledZone) {
  const CmmKind kind = GetParam();
  const int k = FreeParameterCount(KindOf(kind));
  double worst = 0;
  int sets = 0, fewer_contacts = 0, other_minima = 0;
  for (int n : {k + 2, k + 3, k + 4}) {
    for (unsigned seed = 1; seed <= 3; ++seed) {
      const CmmSet s = testsupport::MakeCmmSet(kind, n, 53 * n + seed);
      const Fits f = FitBoth(s);
      ASSERT_TRUE(f.ls.success) << f.ls.message;
      ASSERT_TRUE(f.mz.success) << f.mz.message << " n=" << n << " seed=" << seed;
      const testsupport::MinimumZoneReferenceResult ref = testsupport::MinimumZoneByEnumeration(s);
      ASSERT_GT(ref.candidates, 0) << "n=" << n << " seed=" << seed;
      const double diff = f.mz.zone_width - static_cast<double>(ref.width);
      // The problem is not convex: the SLP from the least-squares fit can end in another
      // (certified, local) minimum than the narrowest levelled zone. Allowed on at most one set
      // per kind and by at most 1e-5 of the width; every other set equals the enumeration's
      // narrowest zone within 1e-12 mm (with fewer than k + 1 contacts the optimum is not a
      // levelled (k + 1)-point zone and the enumeration only bounds it from above).
      if (diff > 1e-12) {
        ++other_minima;
        EXPECT_LE(diff, 1e-5 * f.mz.zone_width) << "n=" << n << " seed=" << seed;
        std::printf("n=%d seed=%u: another local minimum, %.3g mm wider than the enumeration's\n",
                    n, seed, diff);
      } else if (f.mz.contacts.size() == static_cast<size_t>(k + 1)) {
        EXPECT_GE(diff, -1e-12) << "n=" << n << " seed=" << seed;
        worst = std::max(worst, std::abs(diff));
      } else {
        ++fewer_contacts;
      }
      ++sets;
    }
  }
  EXPECT_LE(other_minima, 1);
  std::printf(
      "%s minimum zone vs enumeration (%d sets, %d with fewer than k + 1 contacts, %d in another "
      "local minimum): largest difference otherwise %.3g mm\n",
      NodeTypeName(KindOf(kind)), sets, fewer_contacts, other_minima, worst);
}

INSTANTIATE_TEST_SUITE_P(CurvedKinds, MinimumZoneEnumeration,
                         ::testing::Values(CmmKind::kCylinder, CmmKind::kCone));

class MinimumZoneManySeeds : public ::testing::TestWithParam<CmmKind> {};

TEST_P(MinimumZoneManySeeds, EverySetCertifiedAndLocallyOptimal) {
  const CmmKind kind = GetParam();
  const NodeType nk = KindOf(kind);
  const int k = FreeParameterCount(nk);
  int sets = 0, certified = 0, iterations = 0;
  double narrowing = 0;
  for (int n : {k + 2, 8, 12, 16, 25, 40}) {
    for (unsigned seed = 1; seed <= 15; ++seed) {
      const CmmSet s = testsupport::MakeCmmSet(kind, n, 1000 + 97 * n + seed);
      const Fits f = FitBoth(s);
      ASSERT_TRUE(f.ls.success) << f.ls.message;
      ++sets;
      EXPECT_TRUE(f.mz.success) << f.mz.message << " n=" << n << " seed=" << seed;
      if (!f.mz.success) continue;
      ++certified;
      iterations += f.mz.iterations;
      EXPECT_LE(f.mz.zone_width, f.ls.figures.form_error + 1e-15);
      narrowing = std::max(narrowing, 1 - f.mz.zone_width / f.ls.figures.form_error);
      EXPECT_GE(f.mz.outer_contacts, 1);
      EXPECT_GE(f.mz.inner_contacts, 1);
      EXPECT_LE(f.mz.kkt_residual, 1e-6);
      EXPECT_LE(f.mz.contacts.size(), static_cast<size_t>(k + 1));
      auto half_width = [&](const std::vector<double>& p) {
        double t = 0;
        for (const auto& x : s.points)
          t = std::max(t, std::abs(PrimitiveSignedDistance(nk, p.data(), x.data(), nullptr)));
        return t;
      };
      const double t = half_width(f.mz.parameters);
      EXPECT_NEAR(2 * t, f.mz.zone_width, 1e-13);
      std::mt19937 rng(seed);
      std::normal_distribution<double> g;
      for (int trial = 0; trial < 60; ++trial) {
        std::vector<double> q = f.mz.parameters;
        const double scale = std::pow(10.0, -4 - 3 * (trial % 3));
        for (double& v : q) v += scale * g(rng) / CmmSet::kSize;
        EXPECT_GE(half_width(q), t * (1 - 1e-9)) << "trial " << trial << " n=" << n;
      }
    }
  }
  std::printf(
      "%s minimum zone: %d of %d sets certified, %.1f LP steps per fit, narrower than least "
      "squares by up to %.1f%%\n",
      NodeTypeName(nk), certified, sets, static_cast<double>(iterations) / std::max(1, certified),
      100 * narrowing);
}

INSTANTIATE_TEST_SUITE_P(CurvedKinds, MinimumZoneManySeeds,
                         ::testing::Values(CmmKind::kSphere, CmmKind::kCylinder, CmmKind::kCone));

}  // namespace
}  // namespace implicitfit
