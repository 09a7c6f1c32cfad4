// A held-out set of spline models (random degrees 1-5, uneven knots with multiplicities, random
// control points and rational weights, seeds not used elsewhere) checks the evaluators
// (model/splines/bspline_evaluation.h, bspline_volume.h) against de Boor's algorithm written here
// from its definition (repeated affine combinations of control points, in homogeneous
// coordinates for NURBS: no basis function is formed), and their derivatives against central
// differences of that algorithm (Richardson-extrapolated central differences at h and 2h, error
// O(h^4), at parameters farther than 2h from every knot).
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "model/splines/bspline_evaluation.h"
#include "model/splines/bspline_volume.h"

namespace implicitfit {
namespace {

using Vec4 = Eigen::Vector4d;  // (w x, w y, w z, w)

// de Boor on one parameter: the point of degree p, knots t, control points d (homogeneous) at u.
// The span k with t_k <= u < t_{k+1} (the last non-empty span at the right end); then
// d_i^r = (1 - a) d_{i-1}^{r-1} + a d_i^{r-1}, a = (u - t_i) / (t_{i+p+1-r} - t_i).
Vec4 DeBoor(int p, const std::vector<double>& t, const std::vector<Vec4>& d, double u) {
  const int n = static_cast<int>(d.size());
  int k = p;
  while (k < n - 1 && u >= t[k + 1]) ++k;
  std::vector<Vec4> c(d.begin() + (k - p), d.begin() + (k + 1));
  for (int r = 1; r <= p; ++r)
    for (int j = p; j >= r; --j) {
      const int i = k - p + j;
      const double a = (u - t[i]) / (t[i + p + 1 - r] - t[i]);
      c[j] = (1.0 - a) * c[j - 1] + a * c[j];
    }
  return c[p];
}

Eigen::Vector3d Project(const Vec4& h) { return h.head<3>() / h[3]; }

// Uneven clamped knots on [a, b] for n control points of degree p, some interior knots repeated
// (multiplicity <= p - 1, so the curve stays continuous).
std::vector<double> RandomKnots(int p, int n, double a, double b, std::mt19937& rng) {
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::vector<double> inner;
  while (static_cast<int>(inner.size()) < n - p - 1) {
    const double x = a + (b - a) * (0.05 + 0.9 * u01(rng));
    const int times = std::min<int>(n - p - 1 - static_cast<int>(inner.size()),
                                    1 + (p > 1 && u01(rng) < 0.3 ? 1 : 0));
    for (int m = 0; m < times; ++m) inner.push_back(x);
  }
  std::sort(inner.begin(), inner.end());
  std::vector<double> t(p + 1, a);
  t.insert(t.end(), inner.begin(), inner.end());
  t.insert(t.end(), p + 1, b);
  return t;
}

// A point away from every knot by at least 1e-3 of the range (for the differences).
double AwayFromKnots(const std::vector<double>& t, double a, double b, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(a, b);
  for (;;) {
    const double x = u(rng);
    bool near = false;
    for (double k : t) near |= std::abs(x - k) < 1e-3 * (b - a);
    if (!near) return x;
  }
}

TEST(DeBoorHeldOut, CurvesAndTheirDerivatives) {
  std::mt19937 rng(90210);
  std::uniform_real_distribution<double> coord(-2.0, 2.0), weight(0.3, 3.0);
  for (int model = 0; model < 40; ++model) {
    const int p = 1 + model % 5, n = p + 1 + static_cast<int>(rng() % 6);
    const bool rational = model % 2 == 1;
    SplineStructure s;
    s.degree[0] = p;
    s.count[0] = n;
    s.knots[0] = RandomKnots(p, n, -0.5, 1.5, rng);
    std::vector<double> P;
    std::vector<Vec4> H;
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector3d x(coord(rng), coord(rng), coord(rng));
      const double w = rational ? weight(rng) : 1.0;
      P.insert(P.end(), {x[0], x[1], x[2]});
      if (rational) s.weights.push_back(w);
      H.push_back(Vec4(w * x[0], w * x[1], w * x[2], w));
    }
    ASSERT_EQ(CurveStructureProblem(s), "") << model;
    const auto at = [&](double u) { return Project(DeBoor(p, s.knots[0], H, u)); };
    // Values at random parameters and at both ends.
    std::uniform_real_distribution<double> u(-0.5, 1.5);
    for (int k = 0; k < 30; ++k) {
      const double t = k == 0 ? -0.5 : k == 1 ? 1.5 : u(rng);
      double out[3][3];
      CurveDerivatives(s, P.data(), t, 0, out);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(out[0][c], at(t)[c], 1e-12) << model << " " << t;
    }
    // First and second derivatives against central differences (away from the knots, where
    // the curve is a polynomial / rational function).
    for (int k = 0; k < 10; ++k) {
      const double t = AwayFromKnots(s.knots[0], -0.5, 1.5, rng), h = 1e-4;
      double out[3][3];
      CurveDerivatives(s, P.data(), t, 2, out);
      const auto D1 = [&](double e) { return Eigen::Vector3d((at(t + e) - at(t - e)) / (2 * e)); };
      const auto D2 = [&](double e) {
        return Eigen::Vector3d((at(t + e) - 2 * at(t) + at(t - e)) / (e * e));
      };
      const Eigen::Vector3d d1 = (4 * D1(h) - D1(2 * h)) / 3, d2 = (4 * D2(h) - D2(2 * h)) / 3;
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(out[1][c], d1[c], 1e-5 * (1 + std::abs(d1[c]))) << model;
        if (p >= 2) EXPECT_NEAR(out[2][c], d2[c], 2e-3 * (1 + std::abs(d2[c]))) << model;
      }
    }
  }
}

TEST(DeBoorHeldOut, TensorSurfacesAndTheirDerivatives) {
  std::mt19937 rng(4711);
  std::uniform_real_distribution<double> coord(-2.0, 2.0), weight(0.3, 3.0);
  for (int model = 0; model < 24; ++model) {
    const int p = 1 + model % 5, q = 1 + (model / 5) % 4;
    const int nu = p + 1 + static_cast<int>(rng() % 4), nv = q + 1 + static_cast<int>(rng() % 4);
    const bool rational = model % 3 == 2;
    SplineStructure s;
    s.degree[0] = p;
    s.degree[1] = q;
    s.count[0] = nu;
    s.count[1] = nv;
    s.knots[0] = RandomKnots(p, nu, 0.0, 1.0, rng);
    s.knots[1] = RandomKnots(q, nv, -1.0, 2.0, rng);
    std::vector<double> P;
    std::vector<std::vector<Vec4>> rows(nu);
    for (int i = 0; i < nu; ++i)
      for (int j = 0; j < nv; ++j) {
        const Eigen::Vector3d x(coord(rng), coord(rng), coord(rng));
        const double w = rational ? weight(rng) : 1.0;
        P.insert(P.end(), {x[0], x[1], x[2]});
        if (rational) s.weights.push_back(w);
        rows[i].push_back(Vec4(w * x[0], w * x[1], w * x[2], w));
      }
    ASSERT_EQ(SurfaceStructureProblem(s), "") << model;
    // S(u, v): de Boor along v in every row, then along u through the results.
    const auto at = [&](double u, double v) {
      std::vector<Vec4> column;
      for (int i = 0; i < nu; ++i) column.push_back(DeBoor(q, s.knots[1], rows[i], v));
      return Project(DeBoor(p, s.knots[0], column, u));
    };
    std::uniform_real_distribution<double> uu(0.0, 1.0), vv(-1.0, 2.0);
    for (int k = 0; k < 20; ++k) {
      const double u = k == 0 ? 1.0 : uu(rng), v = k == 0 ? 2.0 : vv(rng);
      double out[3][3][3];
      SurfaceDerivatives(s, P.data(), u, v, 0, out);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(out[0][0][c], at(u, v)[c], 1e-12) << model;
    }
    for (int k = 0; k < 6; ++k) {
      const double u = AwayFromKnots(s.knots[0], 0.0, 1.0, rng);
      const double v = AwayFromKnots(s.knots[1], -1.0, 2.0, rng), h = 1e-4;
      double out[3][3][3];
      SurfaceDerivatives(s, P.data(), u, v, 2, out);
      const auto Su = [&](double e) { return Eigen::Vector3d((at(u + e, v) - at(u - e, v)) / (2 * e)); };
      const auto Sv = [&](double e) { return Eigen::Vector3d((at(u, v + e) - at(u, v - e)) / (2 * e)); };
      const auto Suv = [&](double e) {
        return Eigen::Vector3d(
            (at(u + e, v + e) - at(u + e, v - e) - at(u - e, v + e) + at(u - e, v - e)) / (4 * e * e));
      };
      const Eigen::Vector3d su = (4 * Su(h) - Su(2 * h)) / 3, sv = (4 * Sv(h) - Sv(2 * h)) / 3;
      const Eigen::Vector3d suv = (4 * Suv(h) - Suv(2 * h)) / 3;
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(out[1][0][c], su[c], 1e-5 * (1 + std::abs(su[c]))) << model;
        EXPECT_NEAR(out[0][1][c], sv[c], 1e-5 * (1 + std::abs(sv[c]))) << model;
        EXPECT_NEAR(out[1][1][c], suv[c], 2e-3 * (1 + std::abs(suv[c]))) << model;
      }
    }
  }
}

TEST(DeBoorHeldOut, VolumesAreTripleDeBoor) {
  std::mt19937 rng(1234567);
  std::uniform_real_distribution<double> coef(-1.0, 1.0);
  for (int model = 0; model < 10; ++model) {
    const int k = 1 + model % 5;
    const double box[6] = {-1.0, 0.0, 0.5, 0.5, 2.0, 1.0};
    const int cells[3] = {1 + model % 3, 2, 1 + model % 2};
    const SplineStructure s = BSplineVolumeStructure(k, box, cells);
    const int nx = s.count[0], ny = s.count[1], nz = s.count[2];
    std::vector<double> c(static_cast<size_t>(nx) * ny * nz);
    for (double& x : c) x = coef(rng);
    // The knots are the clamped uniform ones of each axis, built here from the box and cells.
    std::vector<double> t[3];
    for (int a = 0; a < 3; ++a) {
      t[a].assign(k, box[a]);
      for (int m = 0; m <= cells[a]; ++m)
        t[a].push_back(box[a] + (box[3 + a] - box[a]) * m / cells[a]);
      t[a].insert(t[a].end(), k, box[3 + a]);
    }
    const auto at = [&](const double x[3]) {  // de Boor along x, then y, then z (scalars)
      std::vector<Vec4> planes;
      for (int kk = 0; kk < nz; ++kk) {
        std::vector<Vec4> lines;
        for (int jj = 0; jj < ny; ++jj) {
          std::vector<Vec4> d;
          for (int ii = 0; ii < nx; ++ii) d.push_back(Vec4(c[ii + nx * (jj + ny * kk)], 0, 0, 1));
          lines.push_back(DeBoor(k, t[0], d, x[0]));
        }
        planes.push_back(DeBoor(k, t[1], lines, x[1]));
      }
      return DeBoor(k, t[2], planes, x[2])[0];
    };
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (int r = 0; r < 30; ++r) {
      double x[3];
      for (int a = 0; a < 3; ++a) x[a] = box[a] + (box[3 + a] - box[a]) * u01(rng);
      EXPECT_NEAR(BSplineVolumeEvaluator::Evaluate(s, c.data(), x), at(x), 1e-13) << model;
    }
  }
}

}  // namespace
}  // namespace implicitfit
