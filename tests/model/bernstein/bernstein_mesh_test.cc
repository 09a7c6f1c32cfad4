// The bernstein_mesh node (model/bernstein/bernstein_mesh.h) and its continuity rows and spline
// basis (model/bernstein/bernstein_mesh_continuity.h), against independent expectations: the naive
// oracle patch, exact polynomials, and the dimension table of docs/maths.md G-1.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <random>

#include "model/bernstein/bernstein_mesh_continuity.h"
#include "model/file/model_json.h"
#include "oracle/bernstein_oracle.h"
#include "support/grid_locate_check.h"

namespace implicitfit {
namespace {

using nlohmann::json;
using Vec = Eigen::Vector3d;

BernsteinGrid Grid(int nx, int ny, int nz, double h = 0.5, Vec origin = Vec(-0.3, 0.1, 0.2)) {
  BernsteinGrid g;
  g.origin = origin;
  g.cell = h;
  g.cells = {nx, ny, nz};
  return g;
}

std::array<Vec, 4> Corners(const BernsteinGrid& g, long long t) {
  const auto v = g.LatticeVertices(t);
  std::array<Vec, 4> c;
  for (int i = 0; i < 4; ++i) c[i] = g.origin + g.cell * Vec(v[i][0], v[i][1], v[i][2]);
  return c;
}

TEST(BernsteinMesh, KuhnSplitTilesEveryCubeAndLocatesPoints) {
  const BernsteinGrid g = Grid(2, 3, 1);
  // The 6 tetrahedra of a cube have volume h^3/6 each, share the main diagonal.
  for (long long t = 0; t < g.NumTetrahedra(); ++t) {
    const auto c = Corners(g, t);
    Eigen::Matrix3d e;
    for (int i = 0; i < 3; ++i) e.col(i) = c[i] - c[3];
    EXPECT_NEAR(std::abs(e.determinant()), std::pow(g.cell, 3), 1e-12);
  }
  testsupport::ExpectLocateMatchesOracle(
      g, [&](long long t) { return Corners(g, t); }, 2000, 3);
}

TEST(BernsteinMesh, EvaluatesEachTetrahedronsPolynomialAndExtrapolatesOutside) {
  const BernsteinGrid g = Grid(2, 1, 2);
  for (int k = 1; k <= 4; ++k) {
    const long long n = NumBernsteinControlPoints(k);
    std::mt19937 rng(10 + k);
    std::uniform_real_distribution<double> u(-1.0, 1.0), w(0.0, 1.0);
    std::vector<double> b(static_cast<size_t>(g.NumTetrahedra() * n));
    for (double& x : b) x = u(rng);
    Model m;
    m.AddBernsteinMesh(k, g, 0, b);
    for (int s = 0; s < 300; ++s) {
      // Inside: the oracle on the tetrahedron that contains x (found by brute force).
      const Vec x =
          g.BoxMin() + (g.BoxMax() - g.BoxMin()).cwiseProduct(Vec(w(rng), w(rng), w(rng)));
      long long owner = -1;
      for (long long t = 0; t < g.NumTetrahedra() && owner < 0; ++t)
        if ((oracle::Barycentric(Corners(g, t), x).array() >= -1e-12).all()) owner = t;
      ASSERT_GE(owner, 0);
      const std::vector<double> bt(b.begin() + owner * n, b.begin() + (owner + 1) * n);
      EXPECT_NEAR(m.Value(x), oracle::Patch(k, bt, Corners(g, owner), x), 1e-12);
    }
    // Outside: the polynomial of a tetrahedron holding the nearest box point, at x itself
    // (on edges and corners of the box several tetrahedra hold it: any of them is allowed).
    int outside = 0;
    for (int s = 0; s < 300; ++s) {
      const Vec x =
          g.BoxMin() - Vec::Constant(0.5) +
          (g.BoxMax() - g.BoxMin() + Vec::Constant(1.0)).cwiseProduct(Vec(w(rng), w(rng), w(rng)));
      const Vec nearest = x.cwiseMax(g.BoxMin()).cwiseMin(g.BoxMax());
      if (nearest == x) continue;
      ++outside;
      bool matched = false;
      double closest = 1e300;
      for (long long t = 0; t < g.NumTetrahedra(); ++t) {
        if ((oracle::Barycentric(Corners(g, t), nearest).array() < -1e-12).any()) continue;
        const std::vector<double> bt(b.begin() + t * n, b.begin() + (t + 1) * n);
        double magnitude;
        const double expected = oracle::Patch(k, bt, Corners(g, t), x, &magnitude);
        closest = std::min(closest, std::abs(m.Value(x) - expected));
        matched |= std::abs(m.Value(x) - expected) <= 1e-12 * (1 + magnitude);
      }
      EXPECT_TRUE(matched) << "closest candidate differs by " << closest;
    }
    EXPECT_GT(outside, 100);
  }
}

TEST(BernsteinMesh, JsonRoundTripAndRefusals) {
  const BernsteinGrid g = Grid(1, 2, 1, 0.25);
  std::vector<double> b(static_cast<size_t>(g.NumTetrahedra() * 10));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (double& x : b) x = u(rng);
  Model m;
  m.AddBernsteinMesh(2, g, 1, b, "mesh");
  const json doc = ModelToJson(m);
  EXPECT_EQ(doc["root"]["type"], "bernstein_mesh");
  EXPECT_EQ(doc["root"]["grid"]["cells"], json({1, 2, 1}));
  const Model again = ModelFromJson(json::parse(doc.dump()));
  EXPECT_EQ(again.parameters(), b);
  EXPECT_EQ(again.nodes()[0].continuity, 1);
  EXPECT_EQ(ModelToJson(again), doc);
  auto refused = [&](json root, const std::string& fragment) {
    json d = doc;
    d["root"] = root;
    try {
      ModelFromJson(d);
      ADD_FAILURE() << "accepted " << fragment;
    } catch (const ModelFormatError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  json r = doc["root"];
  r["continuity"] = 2;
  refused(r, "root.continuity");
  r = doc["root"];
  r["grid"]["cell"] = 0;
  refused(r, "root.grid.cell");
  r = doc["root"];
  r["grid"]["cells"] = {1, 0, 1};
  refused(r, "root.grid.cells[1]");
  r = doc["root"];
  r["control_points"].erase(0);
  refused(r, "root.control_points");
  r = doc["root"];
  r["grid"]["cells"] = {100000, 100000, 100000};
  refused(r, "root.grid.cells");
  r = doc["root"];
  r["vertices"] = json::array();
  refused(r, "root.vertices");
}

// Test 1 of G-1: b = N z is C0/C1 across every interior face, and not C2 in general.
TEST(BernsteinMeshContinuity, SplineBasisIsContinuousAcrossFacesButNotC2) {
  const BernsteinGrid g = Grid(2, 2, 2, 0.5);
  for (int continuity = 0; continuity <= 1; ++continuity) {
    const int k = 3;
    const long long n = NumBernsteinControlPoints(k);
    const Eigen::MatrixXd N = BernsteinSplineBasis(g, k, continuity);
    std::mt19937 rng(7 + continuity);
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> w(0.0, 1.0);
    Eigen::VectorXd z(N.cols());
    for (int i = 0; i < z.size(); ++i) z[i] = normal(rng);
    const Eigen::VectorXd b = N * z;
    const double scale = b.cwiseAbs().maxCoeff();
    double worst_f = 0, worst_g = 0, largest_hessian_jump = 0;
    int tested = 0;
    while (tested < 1000) {
      const long long t = std::uniform_int_distribution<long long>(0, g.NumTetrahedra() - 1)(rng);
      const int o = std::uniform_int_distribution<int>(0, 3)(rng);
      const auto c = Corners(g, t);
      double a[3] = {w(rng), w(rng), w(rng)};
      const double s = a[0] + a[1] + a[2];
      Vec x = Vec::Zero(), centroid = Vec::Zero();
      for (int i = 0, m = 0; i < 4; ++i)
        if (i != o) x += a[m++] / s * c[i];
      for (int i = 0; i < 4; ++i) centroid += c[i] / 4;
      const Vec outside = x + 1e-6 * (x - centroid);
      if (((outside - g.BoxMin()).array() <= 0).any() ||
          ((outside - g.BoxMax()).array() >= 0).any())
        continue;  // a boundary face
      double tau[4];
      const long long u = g.Locate(outside.data(), tau);
      if (u == t || (oracle::Barycentric(Corners(g, u), x).array() < -1e-9).any()) continue;
      ++tested;
      const Tetrahedron T = g.TetrahedronOf(t), U = g.TetrahedronOf(u);
      Eigen::Vector3d gt, gu;
      Eigen::Matrix3d ht, hu;
      const double ft = BernsteinPatch::Derivatives(k, T, b.data() + t * n, x.data(), &gt, &ht);
      const double fu = BernsteinPatch::Derivatives(k, U, b.data() + u * n, x.data(), &gu, &hu);
      worst_f = std::max(worst_f, std::abs(ft - fu));
      worst_g = std::max(worst_g, (gt - gu).norm());
      largest_hessian_jump = std::max(largest_hessian_jump, (ht - hu).cwiseAbs().maxCoeff());
    }
    const double h = g.cell;
    EXPECT_LE(worst_f, 1e-12 * scale);
    if (continuity == 1) {
      EXPECT_LE(worst_g, 1e-9 * scale / h);
    } else {
      EXPECT_GT(worst_g, 1e-3 * scale / h);  // C0 only: the gradient jumps somewhere
    }
    EXPECT_GT(largest_hessian_jump, 1e-3 * scale / (h * h));  // C2 is not implied
  }
}

// Rank of the C0 (+ C1) rows from the eigenvalues of C^T C (squared singular values), with the
// gap of docs/maths.md G-1 checked (kept singular values >= 7e-3, dropped ones at rounding level).
long long SplineDimension(const BernsteinGrid& g, int k, int continuity) {
  const ContinuityRows rows = BernsteinContinuityRows(g, k, 0, continuity);
  const Eigen::MatrixXd C(rows.C);
  const Eigen::MatrixXd CtC = C.transpose() * C;
  const Eigen::VectorXd e =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(CtC, Eigen::EigenvaluesOnly).eigenvalues();
  long long rank = 0;
  for (int i = 0; i < e.size(); ++i) {
    if (e[i] > 1e-7 * e.maxCoeff()) {
      ++rank;
      EXPECT_GT(e[i], 4.9e-5) << "no clear rank gap";
    } else {
      EXPECT_LT(std::abs(e[i]), 1e-9) << "no clear rank gap";
    }
  }
  return C.cols() - rank;
}

// Test 2 of G-1: the spline-space dimensions of the table.
TEST(BernsteinMeshContinuity, SplineSpaceDimensionsMatchTheTable) {
  struct Row {
    int n, k, c0, c1;
  };
  const Row table[] = {{1, 2, 27, 13},  {1, 3, 64, 34},  {1, 4, 125, 73},  {1, 5, 216, 136},
                       {2, 2, 125, 22}, {2, 3, 343, 88}, {2, 4, 729, 250}, {2, 5, 1331, 556}};
  for (const Row& r : table) {
    const BernsteinGrid g = Grid(r.n, r.n, r.n, 0.7);
    SCOPED_TRACE("grid " + std::to_string(r.n) + " degree " + std::to_string(r.k));
    if (g.NumTetrahedra() * NumBernsteinControlPoints(r.k) <= 1000) {  // dense check affordable
      EXPECT_EQ(SplineDimension(g, r.k, 0), r.c0);
      EXPECT_EQ(SplineDimension(g, r.k, 1), r.c1);
    }
    EXPECT_EQ(BernsteinSplineBasis(g, r.k, 0).cols(), r.c0);
    const Eigen::MatrixXd N = BernsteinSplineBasis(g, r.k, 1);
    EXPECT_EQ(N.cols(), r.c1);
    const ContinuityRows rows = BernsteinContinuityRows(g, r.k, 0, 1);
    EXPECT_LE((rows.C * N).cwiseAbs().maxCoeff(), 1e-12);
  }
  EXPECT_EQ(BernsteinSplineBasis(Grid(3, 3, 3), 2, 1).cols(), 31);
  EXPECT_EQ(BernsteinSplineBasis(Grid(3, 3, 3), 3, 1).cols(), 166);
}

// Test 3 of G-1: a global polynomial of degree <= k, converted per tetrahedron by
// interpolation at the domain points, satisfies every continuity row (C0, C1 and C2).
TEST(BernsteinMeshContinuity, GlobalPolynomialsSatisfyTheRows) {
  const BernsteinGrid g = Grid(2, 2, 1, 0.4, Vec(1.0, -2.0, 0.5));
  for (int k = 2; k <= 4; ++k) {
    std::mt19937 rng(20 + k);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    // p(x) = sum_{a+b+c <= k} coef x^a y^b z^c, random coefficients.
    std::vector<std::array<int, 3>> powers;
    std::vector<double> coef;
    for (int a = 0; a <= k; ++a)
      for (int bb = 0; a + bb <= k; ++bb)
        for (int c = 0; a + bb + c <= k; ++c) {
          powers.push_back({a, bb, c});
          coef.push_back(u(rng));
        }
    auto p = [&](const Vec& x) {
      double s = 0;
      for (size_t i = 0; i < coef.size(); ++i)
        s += coef[i] * std::pow(x[0], powers[i][0]) * std::pow(x[1], powers[i][1]) *
             std::pow(x[2], powers[i][2]);
      return s;
    };
    const auto multi = oracle::DesignOrder(k);
    const int n = static_cast<int>(multi.size());
    std::vector<double> b;
    for (long long t = 0; t < g.NumTetrahedra(); ++t) {
      const auto c = Corners(g, t);
      Eigen::MatrixXd M(n, n);
      Eigen::VectorXd rhs(n);
      for (int r = 0; r < n; ++r) {
        Vec xi = Vec::Zero();
        for (int i = 0; i < 4; ++i) xi += double(multi[r][i]) / k * c[i];
        const Eigen::Vector4d tau = oracle::Barycentric(c, xi);
        for (int col = 0; col < n; ++col) M(r, col) = oracle::Bernstein(multi[col], tau);
        rhs[r] = p(xi);
      }
      const Eigen::VectorXd bt = M.fullPivLu().solve(rhs);
      b.insert(b.end(), bt.data(), bt.data() + n);
    }
    const Eigen::Map<const Eigen::VectorXd> bv(b.data(), b.size());
    const double scale = bv.cwiseAbs().maxCoeff();
    const ContinuityRows rows = BernsteinContinuityRows(g, k, 0, 2);
    EXPECT_LE((rows.C * bv).cwiseAbs().maxCoeff(), 1e-12 * scale) << "degree " << k;
    EXPECT_LE(ContinuityDefect(g, k, 1, b.data()), 1e-12);
    Model m;
    m.AddBernsteinMesh(k, g, 1, b);
    for (int s = 0; s < 50; ++s) {
      const Vec x = g.BoxMin() + (g.BoxMax() - g.BoxMin())
                                     .cwiseProduct(Vec(0.5 + 0.5 * u(rng), 0.5 + 0.5 * u(rng),
                                                       0.5 + 0.5 * u(rng)));
      EXPECT_NEAR(m.Value(x), p(x), 1e-10 * scale);
    }
  }
}

}  // namespace
}  // namespace implicitfit
