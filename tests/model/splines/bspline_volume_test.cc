// The bspline_volume node and its convexity certificate (docs/maths.md TB-3): polynomial
// reproduction (the expected values are the polynomials themselves), the Bezier extraction
// against direct evaluation, the certificate on convex and non-convex quadrics, and its
// soundness against finite-difference Hessians of random certified volumes.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <unsupported/Eigen/KroneckerProduct>
#include <cmath>
#include <random>

#include "model/file/model_json.h"
#include "model/model.h"
#include "model/splines/bspline_volume_certificate.h"

namespace implicitfit {
namespace {

const double kBox[6] = {-1, -0.5, 0, 2, 1.5, 1};

// Coefficients reproducing q exactly: interpolation at the Greville points per axis
// (Schoenberg-Whitney holds there), solved as one dense system of the tensor collocation.
std::vector<double> Interpolate(const SplineStructure& s,
                                const std::function<double(const Eigen::Vector3d&)>& q) {
  std::vector<double> g[3];
  Eigen::MatrixXd a[3];
  for (int d = 0; d < 3; ++d) {
    g[d] = GrevilleAbscissae(s.knots[d], s.degree[d], s.count[d]);
    a[d] = Eigen::MatrixXd::Zero(s.count[d], s.count[d]);
    for (int r = 0; r < s.count[d]; ++r) {
      const int span = FindSpan(s.degree[d], s.count[d], s.knots[d].data(), g[d][r]);
      double N[kMaxSplineDegree + 1];
      BasisFunctions(span, g[d][r], s.degree[d], s.knots[d].data(), N);
      for (int j = 0; j <= s.degree[d]; ++j) a[d](r, span - s.degree[d] + j) = N[j];
    }
  }
  const int nx = s.count[0], ny = s.count[1], nz = s.count[2];
  Eigen::VectorXd f(nx * ny * nz);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) f[i + nx * (j + ny * k)] = q({g[0][i], g[1][j], g[2][k]});
  const Eigen::MatrixXd kron =
      Eigen::kroneckerProduct(a[2], Eigen::kroneckerProduct(a[1], a[0])).eval();
  const Eigen::VectorXd c = kron.partialPivLu().solve(f);
  return std::vector<double>(c.data(), c.data() + c.size());
}

double Quadric(const Eigen::Vector3d& x) {
  return 0.7 * x[0] * x[0] + 1.3 * x[1] * x[1] + 2.0 * x[2] * x[2] + 0.4 * x[0] * x[1] -
         0.3 * x[1] * x[2] + 0.5 * x[0] - 0.2 * x[2] - 0.4;
}

TEST(BSplineVolume, ReproducesPolynomialsOfItsDegree) {
  const int cells[3] = {3, 2, 4};
  for (int k = 2; k <= 4; ++k) {
    Model m;
    const SplineStructure s = BSplineVolumeStructure(k, kBox, cells);
    m.AddBSplineVolume(k, kBox, cells, Interpolate(s, Quadric));
    std::mt19937 rng(k);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (int i = 0; i < 200; ++i) {
      Eigen::Vector3d x;
      for (int a = 0; a < 3; ++a) x[a] = kBox[a] + (kBox[3 + a] - kBox[a]) * u01(rng);
      EXPECT_NEAR(m.Value(x), Quadric(x), 1e-11) << "degree " << k;
    }
    // The box's far corner (the right ends) and beyond it: f(pi(x)) + |x - pi(x)|.
    const Eigen::Vector3d corner(kBox[3], kBox[4], kBox[5]);
    EXPECT_NEAR(m.Value(corner), Quadric(corner), 1e-11);
    const Eigen::Vector3d beyond = corner + Eigen::Vector3d(0.3, 0.0, 0.4);
    EXPECT_NEAR(m.Value(beyond), Quadric(corner) + 0.5, 1e-11);
  }
}

TEST(BSplineVolume, BezierExtractionReproducesTheSpline) {
  const int k = 3, n = 5;
  const std::vector<double> knots = ClampedUniformKnots(k, n + k, 0.0, 1.0);
  const std::vector<std::vector<double>> m = BezierExtraction(knots, k, n + k);
  ASSERT_EQ(static_cast<int>(m.size()), k * n + 1);
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> coefficient(-1.0, 1.0);
  std::vector<double> c(n + k);
  for (double& v : c) v = coefficient(rng);
  for (int cell = 0; cell < n; ++cell)
    for (double t : {0.0, 0.3, 0.77, 1.0}) {
      const double x = (cell + t) / n;
      const int span = FindSpan(k, n + k, knots.data(), x);
      double N[kMaxSplineDegree + 1];
      BasisFunctions(span, x, k, knots.data(), N);
      double spline = 0.0;
      for (int j = 0; j <= k; ++j) spline += N[j] * c[span - k + j];
      double bezier = 0.0;
      for (int i = 0; i <= k; ++i) {
        double b = 0.0;
        for (int j = 0; j < n + k; ++j) b += m[cell * k + i][j] * c[j];
        const double binomial = i == 0 || i == 3 ? 1.0 : 3.0;
        bezier += binomial * std::pow(t, i) * std::pow(1 - t, k - i) * b;
      }
      EXPECT_NEAR(bezier, spline, 1e-14);
    }
}

TEST(BSplineVolume, CertificateAcceptsConvexAndRefusesSaddles) {
  const int cells[3] = {2, 3, 2};
  const SplineStructure s = BSplineVolumeStructure(3, kBox, cells);
  const std::vector<double> convex = Interpolate(s, Quadric);
  const VolumeConvexityCertificate yes = CertifyVolumeConvexity(s, convex.data());
  EXPECT_TRUE(yes.convex);
  EXPECT_EQ(yes.certified_cells, 12);
  // The Hessian of the quadric is constant: its smallest eigenvalue is the certificate's.
  Eigen::Matrix3d H;
  H << 1.4, 0.4, 0, 0.4, 2.6, -0.3, 0, -0.3, 4.0;
  EXPECT_NEAR(yes.min_eigenvalue, Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(H).eigenvalues()[0],
              1e-9);
  const std::vector<double> saddle =
      Interpolate(s, [](const Eigen::Vector3d& x) { return x[0] * x[0] - 0.1 * x[1] * x[1] + x[2]; });
  const VolumeConvexityCertificate no = CertifyVolumeConvexity(s, saddle.data());
  EXPECT_FALSE(no.convex);
  EXPECT_LT(no.min_eigenvalue, 0.0);
  const int one_cell[3] = {1, 1, 1};
  const SplineStructure linear = BSplineVolumeStructure(1, kBox, one_cell);
  const std::vector<double> c(8, 1.0);
  EXPECT_FALSE(CertifyVolumeConvexity(linear, c.data()).convex);  // degree 1: never
  // The tree certificate reads it: a convex function on the node's box.
  Model m;
  m.AddBSplineVolume(3, kBox, cells, convex);
  const nlohmann::json j = ModelToJson(m);
  EXPECT_EQ(ModelFromJson(j).parameters(), m.parameters());
}

// Soundness: random perturbations of a convex quadric that the certificate accepts have
// positive semidefinite Hessians (central second differences) at random points; some that it
// refuses are seen, so the probe is not vacuous.
TEST(BSplineVolume, CertifiedVolumesHavePositiveSemidefiniteHessians) {
  const int cells[3] = {2, 2, 2};
  const SplineStructure s = BSplineVolumeStructure(3, kBox, cells);
  const std::vector<double> base = Interpolate(s, Quadric);
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  int certified = 0, refused = 0;
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<double> c = base;
    const double size = 0.004 * (1 + trial % 8);
    for (double& v : c) v += size * noise(rng);
    const VolumeConvexityCertificate cert = CertifyVolumeConvexity(s, c.data());
    if (!cert.convex) {
      ++refused;
      continue;
    }
    ++certified;
    Model m;
    m.AddBSplineVolume(3, kBox, cells, c);
    const double h = 1e-3;
    for (int i = 0; i < 40; ++i) {
      Eigen::Vector3d x;
      for (int a = 0; a < 3; ++a)
        x[a] = kBox[a] + h * 2 + (kBox[3 + a] - kBox[a] - 4 * h) * u01(rng);
      Eigen::Matrix3d hess;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
          const Eigen::Vector3d ea = h * Eigen::Vector3d::Unit(a), eb = h * Eigen::Vector3d::Unit(b);
          hess(a, b) = (m.Value(x + ea + eb) - m.Value(x + ea - eb) - m.Value(x - ea + eb) +
                        m.Value(x - ea - eb)) /
                       (4 * h * h);
        }
      const double smallest = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(hess).eigenvalues()[0];
      EXPECT_GE(smallest, cert.min_eigenvalue - 1e-4) << "trial " << trial;
    }
  }
  EXPECT_GT(certified, 5);
  EXPECT_GT(refused, 5);
}

TEST(BSplineVolume, JsonRefusals) {
  const int cells[3] = {1, 1, 1};
  Model m;
  m.AddBSplineVolume(2, kBox, cells, std::vector<double>(27, 0.5));
  const nlohmann::json j = ModelToJson(m);
  for (const auto& [field, value] :
       std::vector<std::pair<std::string, nlohmann::json>>{{"degree", 9},
                                                            {"cells", {1, 0, 1}},
                                                            {"cells", {1000, 1000, 1000}},
                                                            {"box", {0, 0, 0, 0, 1, 1}},
                                                            {"coefficients", {1, 2, 3}}}) {
    nlohmann::json bad = j;
    bad["root"][field] = value;
    EXPECT_THROW(ModelFromJson(bad), ModelFormatError) << field << " " << value.dump();
  }
}

}  // namespace
}  // namespace implicitfit
