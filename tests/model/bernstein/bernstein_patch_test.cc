// Bernstein patches (model/bernstein/bernstein_patch.h) against the naive oracle (tests/oracle) and
// against properties derived by hand: control-point order of docs/design.md, partition of unity,
// vertex interpolation, Guo's Lemma 1, derivatives vs central differences, Jets.
#include "model/bernstein/bernstein_patch.h"

#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <random>

#include "model/model.h"
#include "oracle/bernstein_oracle.h"
#include "support/random_patches.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;
using Corners = std::array<Vec, 4>;

using testsupport::RandomCorners;

Tetrahedron Tet(const Corners& c) { return Tetrahedron(c[0], c[1], c[2], c[3]); }

std::vector<double> RandomControlPoints(std::mt19937& rng, int k) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> b(static_cast<size_t>(NumBernsteinControlPoints(k)));
  for (double& x : b) x = u(rng);
  return b;
}

TEST(BernsteinPatch, ControlPointOrderIsDesignOrder) {
  // docs/design.md, k = 2: 2000, 1100, 1010, 1001, 0200, 0110, 0101, 0020, 0011, 0002.
  const std::vector<std::array<int, 4>> k2 = {
      {2, 0, 0, 0}, {1, 1, 0, 0}, {1, 0, 1, 0}, {1, 0, 0, 1}, {0, 2, 0, 0},
      {0, 1, 1, 0}, {0, 1, 0, 1}, {0, 0, 2, 0}, {0, 0, 1, 1}, {0, 0, 0, 2}};
  EXPECT_EQ(BernsteinMultiIndices(2), k2);
  for (int k = 0; k <= 7; ++k) {
    const auto order = oracle::DesignOrder(k);
    EXPECT_EQ(BernsteinMultiIndices(k), order);
    EXPECT_EQ(static_cast<long long>(order.size()), NumBernsteinControlPoints(k));
    for (size_t i = 0; i < order.size(); ++i)
      EXPECT_EQ(BernsteinIndex(order[i][1], order[i][2], order[i][3]), static_cast<int>(i));
  }
}

TEST(BernsteinPatch, PartitionOfUnity) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-4.0, 4.0);
  for (int k = 1; k <= 7; ++k) {
    const Tetrahedron tet = Tet(RandomCorners(rng));
    const std::vector<double> ones(static_cast<size_t>(NumBernsteinControlPoints(k)), 1.0);
    for (int i = 0; i < 50; ++i) {
      const Vec x(u(rng), u(rng), u(rng));  // inside and outside
      EXPECT_NEAR(BernsteinPatch::Evaluate(k, tet, ones.data(), x.data()), 1.0, 1e-9);
    }
  }
}

TEST(BernsteinPatch, InterpolatesTheVertexControlPoints) {
  std::mt19937 rng(2);
  for (int k = 1; k <= 6; ++k) {
    const Corners c = RandomCorners(rng);
    const std::vector<double> b = RandomControlPoints(rng, k);
    const auto at = oracle::ByIndex(k, b);
    for (int i = 0; i < 4; ++i) {
      oracle::MultiIndex vertex = {0, 0, 0, 0};
      vertex[i] = k;
      EXPECT_NEAR(BernsteinPatch::Evaluate(k, Tet(c), b.data(), c[i].data()), at.at(vertex), 1e-12);
    }
  }
}

TEST(BernsteinPatch, AgreesWithTheNaiveMultinomialSum) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int k = 1; k <= 6; ++k)
    for (int trial = 0; trial < 10; ++trial) {
      const Corners c = RandomCorners(rng);
      const std::vector<double> b = RandomControlPoints(rng, k);
      for (int i = 0; i < 30; ++i) {
        const Vec x(u(rng), u(rng), u(rng));
        const double expected = oracle::Patch(k, b, c, x);
        EXPECT_NEAR(BernsteinPatch::Evaluate(k, Tet(c), b.data(), x.data()), expected,
                    1e-11 * (1.0 + std::abs(expected)));
      }
    }
}

// Guo's Lemma 1 with the factor the derivation gives (the printed statement drops 1/k; §3 of
// the paper has it): directional derivative from x_i towards x_j is k (b_{(k-1)e_i+e_j} - b_{k
// e_i}).
TEST(BernsteinPatch, Lemma1GradientAtAVertexFromItsNeighbours) {
  std::mt19937 rng(4);
  for (int k = 1; k <= 5; ++k) {
    const Corners c = RandomCorners(rng);
    const std::vector<double> b = RandomControlPoints(rng, k);
    const auto at = oracle::ByIndex(k, b);
    for (int i = 0; i < 4; ++i) {
      // Gradient at x_i by central differences of the oracle (a polynomial: O(h^2) error).
      const double h = 1e-5;
      Vec g;
      for (int a = 0; a < 3; ++a) {
        Vec xp = c[i], xm = c[i];
        xp[a] += h;
        xm[a] -= h;
        g[a] = (oracle::Patch(k, b, c, xp) - oracle::Patch(k, b, c, xm)) / (2 * h);
      }
      Eigen::Matrix<double, 3, 1> analytic;
      BernsteinPatch::Derivatives(k, Tet(c), b.data(), c[i].data(), &analytic);
      for (int j = 0; j < 4; ++j) {
        if (j == i) continue;
        oracle::MultiIndex vertex = {0, 0, 0, 0}, neighbour;
        vertex[i] = k;
        neighbour = vertex;
        --neighbour[i];
        ++neighbour[j];
        const double lemma = k * (at.at(neighbour) - at.at(vertex));
        EXPECT_NEAR(g.dot(c[j] - c[i]), lemma, 1e-6 * (1.0 + std::abs(lemma)));
        EXPECT_NEAR(analytic.dot(c[j] - c[i]), lemma, 1e-10 * (1.0 + std::abs(lemma)));
      }
    }
  }
}

// A well-shaped tetrahedron (a regular one, randomly scaled, perturbed and moved), so finite
// differences of the polynomial are accurate.
Corners WellShapedCorners(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), scale(0.7, 1.5);
  const double s = scale(rng);
  const Vec shift(u(rng), u(rng), u(rng));
  Corners c = {Vec(1, 1, 1), Vec(1, -1, -1), Vec(-1, 1, -1), Vec(-1, -1, 1)};
  for (Vec& v : c) v = s * v + 0.2 * Vec(u(rng), u(rng), u(rng)) + shift;
  return c;
}

// Central differences with one Richardson step: (4 D(h/2) - D(h)) / 3, error O(h^4).
template <typename F>
double Richardson(F central, double h) {
  return (4.0 * central(h / 2) - central(h)) / 3.0;
}

TEST(BernsteinPatch, GradientAndHessianAgreeWithCentralDifferences) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  for (int k = 1; k <= 5; ++k)
    for (int trial = 0; trial < 5; ++trial) {
      const Corners c = WellShapedCorners(rng);
      const std::vector<double> b = RandomControlPoints(rng, k);
      for (int i = 0; i < 10; ++i) {
        const Vec x = c[3] + Vec(u(rng), u(rng), u(rng));
        Eigen::Matrix<double, 3, 1> g;
        Eigen::Matrix<double, 3, 3> hess;
        const double f = BernsteinPatch::Derivatives(k, Tet(c), b.data(), x.data(), &g, &hess);
        EXPECT_NEAR(f, oracle::Patch(k, b, c, x), 1e-11 * (1.0 + std::abs(f)));
        auto at = [&](int a, double sa, int d, double sd) {
          Vec y = x;
          y[a] += sa;
          y[d] += sd;
          return oracle::Patch(k, b, c, y);
        };
        const double h = 1e-3;
        const double scale = 1.0 + hess.cwiseAbs().maxCoeff() + g.cwiseAbs().maxCoeff();
        for (int a = 0; a < 3; ++a) {
          const double ga =
              Richardson([&](double s) { return (at(a, s, a, 0) - at(a, -s, a, 0)) / (2 * s); }, h);
          EXPECT_NEAR(g[a], ga, 1e-7 * scale) << "k " << k;
          for (int d = 0; d < 3; ++d) {
            const double hd = Richardson(
                [&](double s) {
                  return (at(a, s, d, s) - at(a, s, d, -s) - at(a, -s, d, s) + at(a, -s, d, -s)) /
                         (4 * s * s);
                },
                h);
            EXPECT_NEAR(hess(a, d), hd, 1e-6 * scale) << "k " << k;
          }
        }
      }
    }
}

// Jets flow through the model tree: df/db_lambda = B_lambda(tau) (f is linear in the control
// points), and Model::Gradient (Dual3) equals the analytic gradient.
TEST(BernsteinPatch, JetsThroughTheModelGiveBernsteinBasisAndGradient) {
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int k = 3;
  using Jet = ceres::Jet<double, 20>;
  const Corners c = RandomCorners(rng);
  const std::vector<double> b = RandomControlPoints(rng, k);
  Model m;
  m.AddBernsteinPatch(k, Tet(c), b);
  ASSERT_EQ(m.parameters().size(), 20u);
  std::vector<Jet> p(20);
  for (int i = 0; i < 20; ++i) p[i] = Jet(b[i], i);
  const auto order = oracle::DesignOrder(k);
  for (int trial = 0; trial < 20; ++trial) {
    const Vec x(u(rng), u(rng), u(rng));
    const Jet xj[3] = {Jet(x[0]), Jet(x[1]), Jet(x[2])};
    const Jet f = m.Evaluate(p.data(), xj);
    const Eigen::Vector4d tau = oracle::Barycentric(c, x);
    for (int i = 0; i < 20; ++i) EXPECT_NEAR(f.v[i], oracle::Bernstein(order[i], tau), 1e-12);
    Eigen::Matrix<double, 3, 1> g;
    BernsteinPatch::Derivatives(k, Tet(c), b.data(), x.data(), &g);
    EXPECT_LT((m.Gradient(x) - g).norm(), 1e-12 * (1.0 + g.norm()));
  }
}

TEST(BernsteinPatch, RefusesFlatTetrahedra) {
  const Vec a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  for (const Vec& d : {Vec(1, 1, 0), Vec(0.3, 0.3, 1e-12), Vec(0, 0, 0)}) {
    try {
      Tetrahedron(a, b, c, d);
      ADD_FAILURE() << "accepted a flat tetrahedron, d = " << d.transpose();
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("degenerate"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(Tetrahedron(a, b, c, Vec(0, 0, NAN)), std::invalid_argument);
  // Thin is fine; the test is relative, so scale does not matter.
  EXPECT_NO_THROW(Tetrahedron(a, b, c, Vec(0.2, 0.2, 1e-6)));
  EXPECT_NO_THROW(Tetrahedron(1e-6 * a, 1e-6 * b, 1e-6 * c, Vec(0, 0, 1e-6)));
  EXPECT_NEAR(
      Tetrahedron(Vec(1, 1, 1), Vec(1, -1, -1), Vec(-1, 1, -1), Vec(-1, -1, 1)).relative_volume(),
      1.0 / std::sqrt(2.0), 1e-12);
}

TEST(BernsteinPatch, ModelRefusesAWrongControlPointCountAndNamesParameters) {
  Model m;
  EXPECT_THROW(m.AddBernsteinPatch(2, Tetrahedron(), std::vector<double>(9)),
               std::invalid_argument);
  EXPECT_THROW(m.AddBernsteinPatch(0, Tetrahedron(), std::vector<double>(1)),
               std::invalid_argument);
  EXPECT_THROW(m.AddPrimitive(NodeType::kBernsteinPatch, std::vector<double>(10)),
               std::invalid_argument);
  m.AddBernsteinPatch(2, Tetrahedron(), std::vector<double>(10, 0.5), "cap");
  const std::vector<std::string> names = m.ParameterNames();
  ASSERT_EQ(names.size(), 10u);
  EXPECT_EQ(names[0], "cap.control_points[0]");
  EXPECT_EQ(names[9], "cap.control_points[9]");
}

}  // namespace
}  // namespace implicitfit
