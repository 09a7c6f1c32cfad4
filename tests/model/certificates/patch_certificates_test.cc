// G-2 (label-invariant margin, Hessian bound), G-4 (tangent-restricted certificate,
// patch-localised verdict) and G-3 (edge sign changes) of docs/maths.md. Expected values:
// matrices built longhand (tests/oracle) and Eigen eigenvalues, Hessians from
// BernsteinPatch::Derivatives, the sampling tangent-plane test, dense sign scans, closed forms.
#include "model/certificates/patch_certificates.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "model/bernstein/bernstein_conversion.h"
#include "model/certificates/convexity_certificate.h"
#include "model/bernstein/patch_topology.h"
#include "model/certificates/tangent_plane_test.h"
#include "oracle/bernstein_oracle.h"
#include "support/random_patches.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;
using Corners = std::array<Vec, 4>;

Tetrahedron Tet(const Corners& c) { return Tetrahedron(c[0], c[1], c[2], c[3]); }

// Control points of a polynomial g of degree <= k on a tetrahedron, by interpolation at the
// domain points sum lambda_i x_i / k with the explicit multinomial basis (tests/oracle).
template <typename G>
std::vector<double> Interpolate(int k, const Corners& c, G g) {
  const std::vector<oracle::MultiIndex> l = oracle::DesignOrder(k);
  const int n = static_cast<int>(l.size());
  Eigen::MatrixXd m(n, n);
  Eigen::VectorXd rhs(n);
  for (int r = 0; r < n; ++r) {
    Eigen::Vector4d tau;
    Vec x = Vec::Zero();
    for (int i = 0; i < 4; ++i) tau[i] = double(l[r][i]) / k, x += tau[i] * c[i];
    for (int col = 0; col < n; ++col) m(r, col) = oracle::Bernstein(l[col], tau);
    rhs[r] = g(x);
  }
  const Eigen::VectorXd b = m.fullPivLu().solve(rhs);
  return std::vector<double>(b.data(), b.data() + n);
}

// Relabel: new vertex i is old vertex perm[i]; b'_lambda' = b_lambda with lambda'_i =
// lambda_perm[i].
std::vector<double> Relabel(int k, const std::vector<double>& b, const std::array<int, 4>& perm) {
  const std::vector<oracle::MultiIndex> l = oracle::DesignOrder(k);
  std::vector<double> out(b.size());
  for (size_t j = 0; j < l.size(); ++j) {
    oracle::MultiIndex old;
    for (int i = 0; i < 4; ++i) old[perm[i]] = l[j][i];
    out[j] = b[BernsteinIndex(old[1], old[2], old[3])];
  }
  return out;
}

TEST(CartesianMargin, MatchesLonghandMatricesAndIsInvariantUnderAll24Relabellings) {
  std::mt19937 rng(12);
  for (int k : {2, 3, 4}) {
    for (int trial = 0; trial < 20; ++trial) {
      const Corners c = testsupport::RandomCorners(rng);
      const std::vector<double> b = testsupport::RandomMixedPatch(rng, k);
      // Longhand: C^mu = E^-T A^mu E^-1, Eigen's eigenvalues.
      Eigen::Matrix3d e;
      for (int i = 0; i < 3; ++i) e.col(i) = c[i] - c[3];
      double expected = INFINITY;
      for (const Eigen::Matrix3d& a : oracle::GuoMatrices(k, b)) {
        const Eigen::Matrix3d cm = e.inverse().transpose() * a * e.inverse();
        expected =
            std::min(expected, Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cm).eigenvalues()[0]);
      }
      const CartesianMargin m0 = CartesianConvexityMargin(k, Tet(c), b.data());
      EXPECT_NEAR(m0.min_eigenvalue_cartesian, expected, 1e-10 * (1 + std::abs(expected)));
      EXPECT_DOUBLE_EQ(m0.hessian_lower_bound, k * (k - 1) * m0.min_eigenvalue_cartesian);
      std::array<int, 4> perm = {0, 1, 2, 3};
      std::set<long long> plain_values;
      int count = 0;
      do {
        const Corners pc = {c[perm[0]], c[perm[1]], c[perm[2]], c[perm[3]]};
        const std::vector<double> pb = Relabel(k, b, perm);
        // Same polynomial: f agrees at a random point.
        const Vec x = 0.25 * (c[0] + c[1] + c[2] + c[3]);
        ASSERT_NEAR(BernsteinPatch::Evaluate(k, Tet(pc), pb.data(), x.data()),
                    BernsteinPatch::Evaluate(k, Tet(c), b.data(), x.data()), 1e-12);
        const CartesianMargin m = CartesianConvexityMargin(k, Tet(pc), pb.data());
        EXPECT_NEAR(m.min_eigenvalue_cartesian, m0.min_eigenvalue_cartesian,
                    1e-12 * std::max(1.0, std::abs(m0.min_eigenvalue_cartesian)));
        plain_values.insert(std::llround(CertifyConvexity(k, pb.data()).min_eigenvalue * 1e9));
        ++count;
      } while (std::next_permutation(perm.begin(), perm.end()));
      EXPECT_EQ(count, 24);
      EXPECT_GT(plain_values.size(), 1u) << "min_eigenvalue (A^mu units) depends on the labelling";
    }
  }
}

TEST(CartesianMargin, BoundsTheHessiansSmallestEigenvalueEverywhereInTheTetrahedron) {
  std::mt19937 rng(13);
  std::exponential_distribution<double> ex(1.0);
  int points = 0;
  for (int k : {2, 3, 4}) {
    for (int trial = 0; trial < 50; ++trial) {
      const Corners c = testsupport::RandomCorners(rng);
      const std::vector<double> b = testsupport::RandomMixedPatch(rng, k);
      const Tetrahedron t = Tet(c);
      const double bound = CartesianConvexityMargin(k, t, b.data()).hessian_lower_bound;
      for (int i = 0; i < 70; ++i, ++points) {
        double w[4], s = 0;
        for (double& v : w) s += (v = ex(rng));
        Vec x = Vec::Zero();
        for (int j = 0; j < 4; ++j) x += w[j] / s * c[j];
        Eigen::Matrix<double, 3, 1> g;
        Eigen::Matrix3d h;
        BernsteinPatch::Derivatives(k, t, b.data(), x.data(), &g, &h);
        const double lmin = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(h).eigenvalues()[0];
        EXPECT_LE(bound, lmin + 1e-9 * (1 + h.norm()));
      }
    }
  }
  EXPECT_GE(points, 10000);
}

Corners RegularTetrahedron(double circumradius, const Vec& centre) {
  const double s = circumradius / std::sqrt(3.0);
  return {centre + s * Vec(1, 1, 1), centre + s * Vec(1, -1, -1), centre + s * Vec(-1, 1, -1),
          centre + s * Vec(-1, -1, 1)};
}

// A regular tetrahedron with its first vertex straight below the centre.
Corners RegularTetrahedronVertexDown(double circumradius, const Vec& centre) {
  const double r = circumradius, h = r * 2 * std::sqrt(2.0) / 3, q = h * std::sqrt(3.0) / 2;
  return {centre + Vec(0, 0, -r), centre + Vec(h, 0, r / 3), centre + Vec(-h / 2, q, r / 3),
          centre + Vec(-h / 2, -q, r / 3)};
}

TEST(FinslerCertificate, CertifiesOneSheetOfATwoSheetHyperboloid) {
  // f = x^2 + y^2 - z^2 + 1 (solid z >= sqrt(1 + x^2 + y^2) inside), docs/maths.md G-4 a.
  // Vertex down, so the tetrahedron (z in [0.9, 1.43]) meets the sheet z = sqrt(1 + x^2 + y^2).
  const Corners c = RegularTetrahedronVertexDown(0.4, Vec(0, 0, 1.3));
  CartesianQuadric q;
  q.A = Eigen::Vector3d(1, 1, -1).asDiagonal();
  q.c = 1.0;
  const std::vector<double> b = QuadricToBernstein(q, Tet(c), 2);
  EXPECT_FALSE(CertifyConvexity(2, b.data()).convex);
  const FinslerCertificate f = CertifyFinsler(2, b.data());
  EXPECT_TRUE(f.convex) << "margin " << f.margin << " c " << f.c;
  EXPECT_GT(f.c, 0.0);
  TangentPlaneTestOptions o;
  o.segments = 10000;
  const TangentPlaneTestResult s = TangentPlaneTest(2, Tet(c), b.data(), o);
  EXPECT_GT(s.zero_points, 100);
  EXPECT_EQ(s.violations, 0);
}

TEST(FinslerCertificate, NeverContradictsSamplingAndKeepsEveryPlainCertificate) {
  std::mt19937 rng(14);
  const Corners c = RegularTetrahedron(std::sqrt(3.0), Vec::Zero());  // docs/convexity.md's
  int plain = 0, finsler = 0, checked = 0;
  for (int i = 0; i < 10000; ++i) {
    const int k = 2 + i % 2;
    const std::vector<double> b = testsupport::RandomMixedPatch(rng, k);
    const bool p = CertifyConvexity(k, b.data()).convex;
    const FinslerCertificate f = CertifyFinsler(k, b.data());
    plain += p;
    finsler += f.convex;
    if (p) EXPECT_TRUE(f.convex) << "patch " << i;
    if (f.convex) {
      TangentPlaneTestOptions o;
      o.segments = 200;
      o.seed = i;
      const TangentPlaneTestResult s = TangentPlaneTest(k, Tet(c), b.data(), o);
      EXPECT_EQ(s.violations, 0) << "patch " << i << " c " << f.c;
      ++checked;
    }
  }
  std::printf("  10^4 random patches: plain %d, finsler %d certified\n", plain, finsler);
  EXPECT_GT(finsler, plain);
  EXPECT_EQ(checked, finsler);
}

TEST(LocalConvexity, ConvexNearTheZeroSetButIndefiniteFarFromIt) {
  // f = |x - c|^2 - 0.12^2 - x1^3 / 2 on the reference tetrahedron: Hess = 2 I - 3 x1 e1 e1^T
  // is indefinite for x1 > 2/3, positive definite near the sphere at c = (0.2, 0.2, 0.2).
  const Corners ref = {Vec(1, 0, 0), Vec(0, 1, 0), Vec(0, 0, 1), Vec(0, 0, 0)};
  const Vec centre(0.2, 0.2, 0.2);
  const std::vector<double> b = Interpolate(3, ref, [&](const Vec& x) {
    return (x - centre).squaredNorm() - 0.0144 - 0.5 * x.x() * x.x() * x.x();
  });
  EXPECT_FALSE(CertifyConvexity(3, b.data()).convex);
  const LocalConvexity l = CertifyLocalConvexity(3, b.data());
  EXPECT_TRUE(l.locally_convex) << l.max_depth_reached;
  EXPECT_GT(l.pieces_certified, 0);
  EXPECT_GT(l.pieces_dropped, 0);
}

TEST(LocalConvexity, TwoSmallSpheresAreLocallyButNotGloballyConvex) {
  const Corners ref = {Vec(1, 0, 0), Vec(0, 1, 0), Vec(0, 0, 1), Vec(0, 0, 0)};
  // Radius 0.05, centres 0.42 apart: near each sphere Hess f ~ 2 g_other I + (a b^T + b a^T)
  // stays positive definite (distance > 4 radii), between them f > 0.
  const Vec c1(0.2, 0.2, 0.2), c2(0.6, 0.15, 0.1);
  auto g = [&](const Vec& x) {
    return ((x - c1).squaredNorm() - 0.0025) * ((x - c2).squaredNorm() - 0.0025);
  };
  const std::vector<double> b = Interpolate(4, ref, g);
  EXPECT_NEAR(BernsteinPatch::Evaluate(4, Tet(ref), b.data(), c1.data()), g(c1), 1e-12);
  EXPECT_FALSE(CertifyConvexity(4, b.data()).convex);
  EXPECT_FALSE(CertifyFinsler(4, b.data()).convex);
  const LocalConvexity l = CertifyLocalConvexity(4, b.data());
  EXPECT_TRUE(l.locally_convex) << l.max_depth_reached;
  TangentPlaneTestOptions o;
  o.segments = 20000;
  const TangentPlaneTestResult s = TangentPlaneTest(4, Tet(ref), b.data(), o);
  EXPECT_GT(s.violations, 0) << s.zero_points;
}

TEST(LocalConvexity, SubTetrahedronControlPointsReproduceThePolynomial) {
  std::mt19937 rng(15);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Tetrahedron ref;
  for (int k : {2, 3, 5}) {
    const std::vector<double> b = testsupport::RandomMixedPatch(rng, k);
    double tau[4][4];
    Corners sub;
    for (int v = 0; v < 4; ++v) {
      double s = 0;
      for (int a = 0; a < 4; ++a) s += (tau[v][a] = u(rng) + 0.1);
      for (int a = 0; a < 4; ++a) tau[v][a] /= s;
      sub[v] = Vec(tau[v][0], tau[v][1], tau[v][2]);  // reference tetrahedron: x = tau_1..3
    }
    const std::vector<double> sb = SubTetrahedronControlPoints(k, b.data(), tau);
    // Points inside the sub-tetrahedron (random barycentric weights of its corners): two
    // polynomials equal on an open set are equal everywhere, and inside, unlike far outside
    // the small sub-tetrahedron, evaluation does not amplify rounding by its inverse size^k.
    for (int i = 0; i < 20; ++i) {
      double w[4], s = 0;
      for (double& wv : w) s += (wv = u(rng));
      Vec x = Vec::Zero();
      for (int v = 0; v < 4; ++v) x += (w[v] / s) * sub[v];
      EXPECT_NEAR(BernsteinPatch::Evaluate(k, Tet(sub), sb.data(), x.data()),
                  BernsteinPatch::Evaluate(k, ref, b.data(), x.data()), 1e-10);
    }
  }
}

TEST(EdgeSignChanges, PlaneElevatedHasOneChangeExactlyWhereTheEndValuesDifferInSign) {
  std::mt19937 rng(16);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k : {1, 2, 3, 5}) {
    for (int trial = 0; trial < 50; ++trial) {
      double v[4];
      for (double& x : v) x = u(rng);
      std::vector<double> b;  // an affine function: b_lambda = sum lambda_i v_i / k
      for (const auto& l : oracle::DesignOrder(k))
        b.push_back((l[0] * v[0] + l[1] * v[1] + l[2] * v[2] + l[3] * v[3]) / k);
      for (const EdgeSignChanges& e : EdgeSignChangeCounts(k, b.data()))
        EXPECT_EQ(e.sign_changes, (v[e.vertices[0]] < 0) != (v[e.vertices[1]] < 0) ? 1 : 0);
    }
  }
}

TEST(EdgeSignChanges, SphereCrossingOneEdgeTwice) {
  // Sphere centre (0.5, 0, 0), radius 0.3 on the reference tetrahedron: edge x1 x4 (the x axis
  // from 1 to 0) meets it at x = 0.2 and 0.8.
  const Tetrahedron ref;
  CartesianQuadric q;
  q.A = Eigen::Matrix3d::Identity();
  q.b = Vec(-0.5, 0, 0);
  q.c = 0.25 - 0.09;
  for (int k : {2, 3}) {
    const std::vector<double> b = QuadricToBernstein(q, ref, k);
    int v = -1;
    for (const EdgeSignChanges& e : EdgeSignChangeCounts(k, b.data()))
      if (e.vertices[0] == 0 && e.vertices[1] == 3) v = e.sign_changes;
    EXPECT_EQ(v, 2);
    // Bisection of f(t e1) on the two sign-change brackets [0, 0.5] and [0.5, 1].
    auto f = [&](double t) {
      const Vec x(t, 0, 0);
      return BernsteinPatch::Evaluate(k, ref, b.data(), x.data());
    };
    for (auto [lo, hi, root] : {std::array<double, 3>{0.0, 0.5, 0.2}, {0.5, 1.0, 0.8}}) {
      const bool lo_positive = f(lo) > 0;
      ASSERT_NE(lo_positive, f(hi) > 0);
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        ((f(mid) > 0) == lo_positive ? lo : hi) = mid;
      }
      EXPECT_NEAR(lo, root, 1e-12);
    }
  }
}

TEST(EdgeSignChanges, RootCountsNeverExceedVAndShareItsParity) {
  std::mt19937 rng(17);
  const Tetrahedron ref;
  for (int trial = 0; trial < 300; ++trial) {
    const int k = 2 + trial % 4;
    const std::vector<double> b = testsupport::RandomMixedPatch(rng, k);
    for (const EdgeSignChanges& e : EdgeSignChangeCounts(k, b.data())) {
      const Vec a = ref.vertex(e.vertices[0]), c = ref.vertex(e.vertices[1]);
      int changes = 0;
      double prev = BernsteinPatch::Evaluate(k, ref, b.data(), a.data());
      for (int s = 1; s <= 10000; ++s) {
        const Vec x = a + (c - a) * (s / 10000.0);
        const double v = BernsteinPatch::Evaluate(k, ref, b.data(), x.data());
        if ((v < 0) != (prev < 0)) ++changes;
        prev = v;
      }
      EXPECT_LE(changes, e.sign_changes);
      EXPECT_EQ(changes % 2, e.sign_changes % 2);
    }
  }
}

TEST(FacesWithoutCrossing, OneSignedFacesHoldNoZero) {
  const Tetrahedron ref;
  CartesianQuadric q;  // sphere centre (0.5, 0, 0) radius 0.3 touches only faces containing x1, x4
  q.A = Eigen::Matrix3d::Identity();
  q.b = Vec(-0.5, 0, 0);
  q.c = 0.25 - 0.09;
  const std::vector<double> b = QuadricToBernstein(q, ref, 2);
  const auto faces = FacesWithoutCrossing(2, b.data());
  // Face x2 x3 x4 (x = 0 plane) is outside the sphere; its control points are positive.
  EXPECT_NE(std::find(faces.begin(), faces.end(), std::array<int, 3>{1, 2, 3}), faces.end());
  for (const auto& f : faces) EXPECT_FALSE(f[0] == 0 && f[2] == 3);  // faces with edge x1 x4 cross
}

}  // namespace
}  // namespace implicitfit
