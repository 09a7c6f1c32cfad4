// The metrology estimators (fit/primitive/estimator.h) on coordinate-measuring-machine sets without
// normals (tests/support/cmm_reference.h):
// - least squares against an independent long double orthogonal-distance reference in another
//   parameterisation: every geometric parameter within 1e-9 of the part size, any point order;
// - minimum zone of planes against the exhaustive enumeration of the zones that 4 points
//   define (3 + 1: a facet and a vertex; 2 + 2: two edges), to 1e-12 mm;
// - minimum zone of spheres, cylinders and cones: zone width <= least-squares form error,
//   contacts on both faces, and no random small move of the parameters narrows the zone;
// - points-only hypotheses: a 10-point sphere with one stray point; degenerate sets refused.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <random>

#include "fit/metrology/point_hypotheses.h"
#include "fit/primitive/primitive_fitter.h"
#include "fit/metrology/primitive_tangent.h"
#include "support/cmm_reference.h"

namespace implicitfit {
namespace {

using testsupport::CmmKind;
using testsupport::CmmReference;
using testsupport::CmmSet;
using LD = long double;
using testsupport::ParameterDifferences;

NodeType KindOf(CmmKind k) {
  switch (k) {
    case CmmKind::kPlane:
      return NodeType::kPlane;
    case CmmKind::kSphere:
      return NodeType::kSphere;
    case CmmKind::kCylinder:
      return NodeType::kCylinder;
    case CmmKind::kTorus:
      return NodeType::kTorus;
    default:
      return NodeType::kCone;
  }
}

PrimitiveFitResult FitSet(const CmmSet& s, Estimator e,
                          const std::vector<Eigen::Vector3d>* points = nullptr) {
  PrimitiveFitOptions o;
  o.kind = KindOf(s.kind);
  o.estimator = e;
  o.num_threads = 1;
  return FitPrimitive(points ? *points : s.points, {}, o);
}

class LeastSquaresReference : public ::testing::TestWithParam<CmmKind> {};

TEST_P(LeastSquaresReference, AgreesWithLongDoubleOrthogonalDistanceReference) {
  const CmmKind kind = GetParam();
  const int k = FreeParameterCount(KindOf(kind));
  double worst = 0;
  int better_minima = 0;
  for (int n : {k + 1, 10, 20, 40}) {
    for (unsigned seed = 1; seed <= 5; ++seed) {
      const CmmSet s = testsupport::MakeCmmSet(kind, n, 100 * n + seed);
      LD last = 0;
      const CmmReference::VecL ref = CmmReference(s).Solve(&last);
      ASSERT_LT(static_cast<double>(last), 1e-13) << "reference not converged";
      const PrimitiveFitResult r = FitSet(s, Estimator::kLeastSquares);
      ASSERT_TRUE(r.success) << r.message << " n=" << n << " seed=" << seed;
      EXPECT_EQ(r.estimator, Estimator::kLeastSquares);
      EXPECT_EQ(r.inliers.size(), static_cast<size_t>(n));
      // With N = k + 1 points a cylinder's least-squares problem can have several minima; the
      // reference is the one nearest the truth. A different answer is accepted only when its sum
      // of squares is lower (a better minimum), never higher.
      LD ss_ref = 0, ss_fit = 0;
      for (const auto& x : s.points) {
        const Eigen::Matrix<LD, 3, 1> y = (s.rotation.transpose() * (x - s.origin)).cast<LD>();
        const LD a = CmmReference(s).Distance(ref, y);
        const LD b = PrimitiveSignedDistance(KindOf(kind), r.parameters.data(), x.data(), nullptr);
        ss_ref += a * a;
        ss_fit += b * b;
      }
      if (ss_fit < ss_ref * (1 - 1e-6L)) {
        ++better_minima;
        EXPECT_EQ(n, k + 1) << "a better minimum than the reference's with " << n << " points";
        continue;
      }
      for (const auto& [name, diff] : ParameterDifferences(s, r.parameters, ref)) {
        EXPECT_LE(diff, 1e-9 * CmmSet::kSize) << name << " n=" << n << " seed=" << seed;
        worst = std::max(worst, diff);
      }
      // The residual figures: every point, max - min of the signed distances.
      double lo = INFINITY, hi = -INFINITY, ss = 0;
      for (const auto& x : s.points) {
        const double d =
            PrimitiveSignedDistance(KindOf(kind), r.parameters.data(), x.data(), nullptr);
        lo = std::min(lo, d);
        hi = std::max(hi, d);
        ss += d * d;
      }
      EXPECT_NEAR(r.form.form_error, hi - lo, 1e-15 * CmmSet::kSize);
      EXPECT_NEAR(r.form.rms, std::sqrt(ss / n), 1e-15 * CmmSet::kSize);
    }
  }
  std::printf(
      "%s: largest difference to the reference %.3g mm (%.3g of the part size); %d of 20 sets "
      "found a lower sum of squares than the reference's minimum\n",
      NodeTypeName(KindOf(kind)), worst, worst / CmmSet::kSize, better_minima);
}

TEST_P(LeastSquaresReference, DoesNotDependOnThePointOrder) {
  const CmmKind kind = GetParam();
  for (unsigned seed = 1; seed <= 4; ++seed) {
    const CmmSet s = testsupport::MakeCmmSet(kind, 20, seed);
    const CmmReference::VecL ref = CmmReference(s).Solve();
    std::vector<Eigen::Vector3d> shuffled = s.points;
    std::mt19937 rng(seed);
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    std::reverse(shuffled.begin() + 3, shuffled.end());
    const PrimitiveFitResult a = FitSet(s, Estimator::kLeastSquares),
                             b = FitSet(s, Estimator::kLeastSquares, &shuffled);
    ASSERT_TRUE(a.success && b.success) << a.message << " / " << b.message;
    const auto da = ParameterDifferences(s, a.parameters, ref),
               db = ParameterDifferences(s, b.parameters, ref);
    for (size_t i = 0; i < da.size(); ++i) {
      EXPECT_LE(da[i].second, 1e-9 * CmmSet::kSize);
      EXPECT_LE(db[i].second, 1e-9 * CmmSet::kSize) << db[i].first;
    }
    EXPECT_NEAR(a.form.form_error, b.form.form_error, 1e-12 * CmmSet::kSize);
  }
}

INSTANTIATE_TEST_SUITE_P(CmmKinds, LeastSquaresReference,
                         ::testing::Values(CmmKind::kPlane, CmmKind::kSphere, CmmKind::kCylinder,
                                           CmmKind::kCone));

// k + 1 = 6 probed points of a cylinder, one of them moved 0.3 mm off the surface (the start's
// band is ~0.1 mm): the robust rounds that start the least-squares fit keep 5 of them, fewer
// than k + 1. Least squares uses every point, so it must still succeed, with all 6 points, at
// the long-double reference's minimum (Gauss-Newton from the truth, tests/support).
TEST(LeastSquaresEstimator, UsesEveryPointWhenTheRobustStartLeavesOneOut) {
  CmmSet s = testsupport::MakeCmmSet(CmmKind::kCylinder, 6, 604);
  const Eigen::Vector3d y = s.rotation.transpose() * (s.points[2] - s.origin);
  const Eigen::Vector3d radial = Eigen::Vector3d(y.x(), y.y(), 0).normalized();
  s.points[2] += s.rotation * (0.3 * radial);
  const PrimitiveFitResult r = FitSet(s, Estimator::kLeastSquares);
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_EQ(r.inliers.size(), 6u);
  LD last = 0;
  const CmmReference::VecL ref = CmmReference(s).Solve(&last);
  ASSERT_LT(static_cast<double>(last), 1e-13) << "reference not converged";
  for (const auto& [name, diff] : ParameterDifferences(s, r.parameters, ref))
    EXPECT_LE(diff, 1e-9 * CmmSet::kSize) << name;
}

// Minimum width of a point set by enumeration: every 4 points define the candidate directions
// of a 3 + 1 (facet-vertex) or 2 + 2 (edge-edge) contact; the width of all points across each.
double BruteForceMinimumWidth(const std::vector<Eigen::Vector3d>& x) {
  const int n = static_cast<int>(x.size());
  double best = INFINITY;
  auto width = [&](Eigen::Vector3d m) {
    if (!(m.norm() > 0)) return;
    m.normalize();
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& p : x) {
      lo = std::min(lo, m.dot(p - x[0]));
      hi = std::max(hi, m.dot(p - x[0]));
    }
    best = std::min(best, hi - lo);
  };
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b)
      for (int c = b + 1; c < n; ++c) {
        width((x[b] - x[a]).cross(x[c] - x[a]));  // facet a b c (3 + 1 with any fourth point)
        for (int d = c + 1; d < n; ++d) {
          width((x[b] - x[a]).cross(x[d] - x[c]));  // edges ab, cd
          width((x[c] - x[a]).cross(x[d] - x[b]));  // edges ac, bd
          width((x[d] - x[a]).cross(x[c] - x[b]));  // edges ad, bc
        }
      }
  return best;
}

TEST(MinimumZone, PlaneMatchesExhaustiveEnumeration) {
  double worst = 0;
  for (int n : {6, 10, 20, 30}) {
    for (unsigned seed = 1; seed <= 6; ++seed) {
      const CmmSet s = testsupport::MakeCmmSet(CmmKind::kPlane, n, 7 * n + seed);
      const PrimitiveFitResult r = FitSet(s, Estimator::kMinimumZone);
      ASSERT_TRUE(r.success) << r.message;
      // Recentre before enumerating (the parts sit ~100 mm from the origin).
      std::vector<Eigen::Vector3d> local;
      for (const auto& p : s.points) local.push_back(p - s.points[0]);
      const double brute = BruteForceMinimumWidth(local);
      EXPECT_NEAR(r.zone.zone_width, brute, 1e-12) << "n=" << n << " seed=" << seed;
      EXPECT_NEAR(r.form.form_error, brute, 1e-12);
      EXPECT_TRUE(r.zone.optimality_verified);
      EXPECT_EQ(r.zone.contacts.size(), 4u);
      worst = std::max(worst, std::abs(r.zone.zone_width - brute));
    }
  }
  std::printf("plane minimum zone vs enumeration: largest difference %.3g mm\n", worst);
}

class MinimumZoneCurved : public ::testing::TestWithParam<CmmKind> {};

TEST_P(MinimumZoneCurved, NarrowerThanLeastSquaresAndLocallyOptimal) {
  const CmmKind kind = GetParam();
  const NodeType nk = KindOf(kind);
  const int k = FreeParameterCount(nk);
  int sets = 0, certified = 0;
  for (int n : {k + 2, 12, 25, 40}) {
    for (unsigned seed = 1; seed <= 4; ++seed) {
      const CmmSet s = testsupport::MakeCmmSet(kind, n, 31 * n + seed);
      const PrimitiveFitResult ls = FitSet(s, Estimator::kLeastSquares);
      const PrimitiveFitResult mz = FitSet(s, Estimator::kMinimumZone);
      ASSERT_TRUE(ls.success) << ls.message;
      ++sets;
      // Every set is certified (the sequential LP cannot cycle).
      ASSERT_TRUE(mz.success) << mz.message;
      ++certified;
      EXPECT_LE(mz.zone.zone_width, ls.form.form_error + 1e-15);
      EXPECT_TRUE(mz.zone.optimality_verified);
      EXPECT_GE(mz.zone.outer_contacts, 1);
      EXPECT_GE(mz.zone.inner_contacts, 1);
      // k + 1 contacts in the Haar case; fewer when curvature holds the optimum.
      EXPECT_LE(mz.zone.contacts.size(), static_cast<size_t>(k + 1));
      EXPECT_LE(mz.zone.kkt_residual, 1e-6);
      // Independent check: the zone's half width t = max |d_i|, and no random move of the
      // parameters (radius, centre, axis, angle) by up to 1e-4 mm lowers it.
      auto half_width = [&](const std::vector<double>& p) {
        double t = 0;
        for (const auto& x : s.points)
          t = std::max(t, std::abs(PrimitiveSignedDistance(nk, p.data(), x.data(), nullptr)));
        return t;
      };
      const double t = half_width(mz.parameters);
      EXPECT_NEAR(2 * t, mz.zone.zone_width, 1e-12);
      std::mt19937 rng(seed);
      std::normal_distribution<double> g;
      for (int trial = 0; trial < 500; ++trial) {
        std::vector<double> q = mz.parameters;
        const double scale = std::pow(10.0, -4 - 3 * (trial % 3));
        for (double& v : q) v += scale * g(rng) / CmmSet::kSize;
        EXPECT_GE(half_width(q), t * (1 - 1e-9)) << "trial " << trial;
      }
    }
  }
  std::printf("%s minimum zone: %d of %d sets certified optimal\n", NodeTypeName(nk), certified,
              sets);
}

INSTANTIATE_TEST_SUITE_P(CmmKinds, MinimumZoneCurved,
                         ::testing::Values(CmmKind::kSphere, CmmKind::kCylinder, CmmKind::kCone));

TEST(PointsOnly, TenPointSphereWithAStrayPoint) {
  // 9 points on a sphere (centre (1, -2, 0.5), radius 2) spread over the sphere, one stray.
  const Eigen::Vector3d c(1, -2, 0.5);
  std::vector<Eigen::Vector3d> pts;
  const double golden = M_PI * (3 - std::sqrt(5.0));
  for (int i = 0; i < 9; ++i) {
    const double z = 1 - 2 * (i + 0.5) / 9, r = std::sqrt(1 - z * z);
    pts.push_back(c + 2 * Eigen::Vector3d(r * std::cos(golden * i), r * std::sin(golden * i), z));
  }
  pts.insert(pts.begin() + 4, c + Eigen::Vector3d(0.7, 0.4, -0.3));  // stray, inside
  PrimitiveFitOptions o;
  o.kind = NodeType::kSphere;
  const PrimitiveFitResult r = FitPrimitive(pts, {}, o);
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_TRUE(r.points_only);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(r.parameters[k], c[k], 1e-3);
  EXPECT_NEAR(r.parameters[3], 2.0, 1e-3);
  EXPECT_EQ(r.inliers.size(), 9u);
}

TEST(PointsOnly, EveryKindFromAFewProbedPoints) {
  for (CmmKind kind : {CmmKind::kPlane, CmmKind::kSphere, CmmKind::kCylinder, CmmKind::kCone}) {
    const int k = FreeParameterCount(KindOf(kind));
    for (int n : {k + 1, 15, 40}) {
      const CmmSet s = testsupport::MakeCmmSet(kind, n, 5 * n + 3);
      const PrimitiveFitResult r = FitSet(s, Estimator::kRobust);
      ASSERT_TRUE(r.success) << NodeTypeName(KindOf(kind)) << " n=" << n << ": " << r.message;
      EXPECT_TRUE(r.points_only);
      const auto ref = CmmReference(s).Solve();
      for (const auto& [name, diff] : ParameterDifferences(s, r.parameters, ref))
        EXPECT_LE(diff, 0.01) << name;
    }
  }
}

TEST(PointsOnly, RefusesTooFewAndDegeneratePoints) {
  PrimitiveFitOptions o;
  std::vector<Eigen::Vector3d> line, disc;
  for (int i = 0; i < 8; ++i) line.push_back(Eigen::Vector3d(1 + i, 2 + 2 * i, -i));
  for (int i = 0; i < 12; ++i)
    disc.push_back(Eigen::Vector3d(std::cos(i), std::sin(i), 0) * (1 + 0.1 * i));
  o.kind = NodeType::kPlane;
  PrimitiveFitResult r = FitPrimitive(line, {}, o);
  EXPECT_FALSE(r.success);
  EXPECT_NE(r.message.find("collinear"), std::string::npos) << r.message;
  o.kind = NodeType::kSphere;
  r = FitPrimitive(disc, {}, o);
  EXPECT_FALSE(r.success);
  EXPECT_NE(r.message.find("coplanar"), std::string::npos) << r.message;
  r = FitPrimitive(std::vector<Eigen::Vector3d>(disc.begin(), disc.begin() + 4), {}, o);
  EXPECT_FALSE(r.success);
  EXPECT_NE(r.message.find("at least 5 points"), std::string::npos) << r.message;
  o.kind = NodeType::kCone;
  const CmmSet s = testsupport::MakeCmmSet(CmmKind::kCone, 6, 1);
  r = FitPrimitive(s.points, {}, o);
  EXPECT_FALSE(r.success);
  EXPECT_NE(r.message.find("at least 7 points"), std::string::npos) << r.message;
}

TEST(PointsOnly, HypothesesFromExactlyKPointsPassThroughThem) {
  std::mt19937 rng(3);
  for (CmmKind kind : {CmmKind::kPlane, CmmKind::kSphere, CmmKind::kCylinder, CmmKind::kCone}) {
    const NodeType nk = KindOf(kind);
    const int k = FreeParameterCount(nk);
    const CmmSet s = testsupport::MakeCmmSet(kind, k, 11, 0.0, 0.0);
    std::vector<Eigen::Vector3d> local;
    for (const auto& p : s.points) local.push_back(p - s.origin);
    std::vector<double> h;
    bool ok = false;
    switch (nk) {
      case NodeType::kPlane:
        ok = PlaneFromPoints(local.data(), &h);
        break;
      case NodeType::kSphere:
        ok = SphereFromPoints(local.data(), &h);
        break;
      case NodeType::kCylinder:
        ok = CylinderFromPoints(local.data(), &h);
        break;
      default:
        ok = ConeFromPoints(local.data(), &h);
        break;
    }
    ASSERT_TRUE(ok) << NodeTypeName(nk);
    for (const auto& x : local)
      EXPECT_NEAR(PrimitiveSignedDistance(nk, h.data(), x.data(), nullptr), 0.0, 1e-6)
          << NodeTypeName(nk);
  }
}

}  // namespace
}  // namespace implicitfit
