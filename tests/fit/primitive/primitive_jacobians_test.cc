// The closed-form derivatives of fit/primitive/primitive_jacobians.h against references that do not come
// from that file: central differences of the model evaluators (model/*.h) in double, and
// forward-mode ceres::Jet through the same evaluators; and the compressed residual block
// (fit/primitive/compressed_distance_cost.h) against the normal equations of the Jet path. One typed suite
// for every primitive; random parameters and points from a seeded RNG, including the cone's apex
// branch (points behind the apex) and points inside and outside every surface.
#include "fit/primitive/primitive_jacobians.h"

#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Dense>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include "fit/primitive/batched_distance_cost.h"
#include "fit/primitive/compressed_distance_cost.h"
#include "model/model.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

Vec RandomUnit(std::mt19937& rng) {
  std::normal_distribution<double> g;
  return Vec(g(rng), g(rng), g(rng)).normalized();
}

// Random valid parameters (axes and normals deliberately not of unit length) for each kind.
template <typename E>
std::vector<double> RandomParameters(std::mt19937& rng);

template <>
std::vector<double> RandomParameters<PlaneEvaluator>(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.5, 2.0), o(-1.0, 1.0);
  const Vec n = RandomUnit(rng) * u(rng);
  return {n.x(), n.y(), n.z(), o(rng)};
}
template <>
std::vector<double> RandomParameters<SphereEvaluator>(std::mt19937& rng) {
  std::uniform_real_distribution<double> o(-1.0, 1.0), r(0.3, 2.0);
  return {o(rng), o(rng), o(rng), r(rng)};
}
template <>
std::vector<double> RandomParameters<CylinderEvaluator>(std::mt19937& rng) {
  std::uniform_real_distribution<double> o(-1.0, 1.0), s(0.5, 2.0), r(0.3, 2.0);
  const Vec a = RandomUnit(rng) * s(rng);
  return {o(rng), o(rng), o(rng), a.x(), a.y(), a.z(), r(rng)};
}
template <>
std::vector<double> RandomParameters<ConeEvaluator>(std::mt19937& rng) {
  std::uniform_real_distribution<double> o(-1.0, 1.0), s(0.5, 2.0), al(0.15, 1.4);
  const Vec a = RandomUnit(rng) * s(rng);
  return {o(rng), o(rng), o(rng), a.x(), a.y(), a.z(), al(rng)};
}
template <>
std::vector<double> RandomParameters<TorusEvaluator>(std::mt19937& rng) {
  std::uniform_real_distribution<double> o(-1.0, 1.0), s(0.5, 2.0), R(1.0, 2.0), r(0.2, 0.9);
  const Vec a = RandomUnit(rng) * s(rng);
  return {o(rng), o(rng), o(rng), a.x(), a.y(), a.z(), R(rng), r(rng)};
}

// Points around the primitive's reference point (centre, apex, ...), out to a few units, so
// that both sides of every surface and both cone branches are hit.
std::vector<Vec> RandomPoints(const std::vector<double>& p, std::mt19937& rng, int count) {
  std::uniform_real_distribution<double> s(0.05, 3.0);
  const Vec origin(p[0], p[1], p[2]);
  std::vector<Vec> x;
  for (int i = 0; i < count; ++i) x.push_back(origin + RandomUnit(rng) * s(rng));
  return x;
}

template <typename E>
double F(const std::vector<double>& p, const Vec& x) {
  return E::Evaluate(p.data(), x.data());
}

// True when x is within `margin` of a place where f is not smooth (the cone's branch seam, any
// axis) or the finite differences would straddle one.
template <typename E>
bool NearKink(const std::vector<double>& p, const Vec& x, double margin) {
  if (E::kNumParameters == 4)
    return false;  // plane, sphere: the centre is never sampled closer than 0.05
  const Vec c(p[0], p[1], p[2]), u = Vec(p[3], p[4], p[5]).normalized(), d = x - c;
  const double h = u.dot(d), rho = u.cross(d).norm();
  if (rho < margin) return true;
  if (std::is_same<E, ConeEvaluator>::value &&
      std::abs(rho * std::sin(p[6]) + h * std::cos(p[6])) < margin)
    return true;
  if (std::is_same<E, TorusEvaluator>::value && std::hypot(rho - p[6], h) < margin) return true;
  return false;
}

// The sizes of the kind's parameter fields: the fitter's parameter blocks.
template <typename E>
std::vector<int> FieldSizes() {
  NodeType kind = NodeType::kPlane;
  if (std::is_same<E, SphereEvaluator>::value) kind = NodeType::kSphere;
  if (std::is_same<E, CylinderEvaluator>::value) kind = NodeType::kCylinder;
  if (std::is_same<E, ConeEvaluator>::value) kind = NodeType::kCone;
  if (std::is_same<E, TorusEvaluator>::value) kind = NodeType::kTorus;
  std::vector<int> sizes;
  for (const ParameterField& field : ParameterFieldsOf(kind)) sizes.push_back(field.size);
  return sizes;
}

template <typename E>
class PrimitiveJacobians : public ::testing::Test {};
using Evaluators = ::testing::Types<PlaneEvaluator, SphereEvaluator, CylinderEvaluator,
                                    ConeEvaluator, TorusEvaluator>;
TYPED_TEST_SUITE(PrimitiveJacobians, Evaluators);

TYPED_TEST(PrimitiveJacobians, MatchTheEvaluatorAndItsCentralDifferences) {
  using E = TypeParam;
  constexpr int P = E::kNumParameters;
  std::mt19937 rng(7);
  int checked = 0, apex_branch = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const std::vector<double> p = RandomParameters<E>(rng);
    const PrimitiveDistance<E> f(p.data());
    for (const Vec& x : RandomPoints(p, rng, 50)) {
      if (NearKink<E>(p, x, 1e-3)) continue;
      double dp[P], dx[3];
      const double v = f(x.data(), dp, dx);
      const double ref = F<E>(p, x);
      ASSERT_NEAR(v, ref, 1e-12 * (1.0 + std::abs(ref)));
      EXPECT_EQ(f(x.data(), nullptr, nullptr), v);
      if (std::is_same<E, ConeEvaluator>::value) {
        const Vec d = x - Vec(p[0], p[1], p[2]), u = Vec(p[3], p[4], p[5]).normalized();
        if (u.cross(d).norm() * std::sin(p[6]) + u.dot(d) * std::cos(p[6]) < 0) ++apex_branch;
      }
      const double step = 1e-6;
      for (int j = 0; j < P; ++j) {
        std::vector<double> plus = p, minus = p;
        plus[j] += step;
        minus[j] -= step;
        const double numeric = (F<E>(plus, x) - F<E>(minus, x)) / (2 * step);
        EXPECT_NEAR(dp[j], numeric, 1e-6) << "parameter " << j << " trial " << trial;
      }
      for (int k = 0; k < 3; ++k) {
        Vec plus = x, minus = x;
        plus[k] += step;
        minus[k] -= step;
        const double numeric = (F<E>(p, plus) - F<E>(p, minus)) / (2 * step);
        EXPECT_NEAR(dx[k], numeric, 1e-6) << "coordinate " << k << " trial " << trial;
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 800);
  if (std::is_same<E, ConeEvaluator>::value) {
    EXPECT_GT(apex_branch, 50);
  }
}

TYPED_TEST(PrimitiveJacobians, MatchForwardModeJets) {
  using E = TypeParam;
  constexpr int P = E::kNumParameters;
  using Jet = ceres::Jet<double, P>;
  std::mt19937 rng(11);
  for (int trial = 0; trial < 20; ++trial) {
    const std::vector<double> p = RandomParameters<E>(rng);
    const PrimitiveDistance<E> f(p.data());
    Jet pj[P];
    for (int j = 0; j < P; ++j) pj[j] = Jet(p[j], j);
    for (const Vec& x : RandomPoints(p, rng, 50)) {
      if (NearKink<E>(p, x, 1e-9)) continue;
      const Jet xj[3] = {Jet(x[0]), Jet(x[1]), Jet(x[2])};
      const Jet r = E::Evaluate(pj, xj);
      double dp[P];
      f(x.data(), dp, nullptr);
      for (int j = 0; j < P; ++j)
        EXPECT_NEAR(dp[j], r.v[j], 1e-11 * (1.0 + std::abs(r.v[j]))) << "parameter " << j;
    }
  }
}

// The batched residual block gives the same residuals and block Jacobians with closed-form
// derivatives as with Jets, field blocks split as the fitter splits them.
TYPED_TEST(PrimitiveJacobians, BatchedCostAgreesWithItsJetPath) {
  using E = TypeParam;
  constexpr int P = E::kNumParameters;
  std::mt19937 rng(5);
  const std::vector<double> p = RandomParameters<E>(rng);
  const std::vector<Vec> pts = RandomPoints(p, rng, 300);
  std::vector<double> xyz;
  std::vector<int> indices;
  for (size_t i = 0; i < pts.size(); ++i) {
    if (NearKink<E>(p, pts[i], 1e-9)) continue;
    xyz.insert(xyz.end(), pts[i].data(), pts[i].data() + 3);
    indices.push_back(static_cast<int>(i));
  }
  // xyz is compacted: index i of the batch is the i-th kept point.
  for (size_t i = 0; i < indices.size(); ++i) indices[i] = static_cast<int>(i);
  const std::vector<int> sizes = FieldSizes<E>();
  ASSERT_EQ(std::accumulate(sizes.begin(), sizes.end(), 0), P);

  const BatchedDistanceCost<E, true> analytic(xyz.data(), indices, sizes);
  const BatchedDistanceCost<E, false> jets(xyz.data(), indices, sizes);
  std::vector<const double*> blocks;
  for (int b = 0, at = 0; b < static_cast<int>(sizes.size()); at += sizes[b], ++b)
    blocks.push_back(p.data() + at);
  const size_t n = indices.size();
  std::vector<double> ra(n), rj(n), r0(n);
  std::vector<std::vector<double>> ja, jj;
  std::vector<double*> pa, pj;
  for (int s : sizes) {
    ja.emplace_back(n * s, NAN);
    jj.emplace_back(n * s, NAN);
  }
  for (size_t b = 0; b < sizes.size(); ++b) {
    pa.push_back(ja[b].data());
    pj.push_back(jj[b].data());
  }
  pa[1] = nullptr;  // a block the solver holds constant gets no Jacobian
  pj[1] = nullptr;
  ASSERT_TRUE(analytic.Evaluate(blocks.data(), ra.data(), pa.data()));
  ASSERT_TRUE(jets.Evaluate(blocks.data(), rj.data(), pj.data()));
  ASSERT_TRUE(analytic.Evaluate(blocks.data(), r0.data(), nullptr));
  for (size_t i = 0; i < n; ++i) {
    EXPECT_NEAR(ra[i], rj[i], 1e-12 * (1.0 + std::abs(rj[i])));
    EXPECT_EQ(r0[i], ra[i]);
  }
  for (size_t b = 0; b < sizes.size(); ++b) {
    if (b == 1) {
      for (double v : ja[b])
        EXPECT_TRUE(std::isnan(v)) << "the constant block's Jacobian was written";
      continue;
    }
    for (size_t k = 0; k < ja[b].size(); ++k)
      EXPECT_NEAR(ja[b][k], jj[b][k], 1e-11 * (1.0 + std::abs(jj[b][k])));
  }
}

// The compressed block (P + 1 residuals) reproduces J^T J, J^T r and r^T r of the per-point
// residuals (Jet path), also with a constant block and for the cylinder's gauge freedom.
TYPED_TEST(PrimitiveJacobians, CompressedCostKeepsTheNormalEquations) {
  using E = TypeParam;
  constexpr int P = E::kNumParameters;
  std::mt19937 rng(3);
  for (int trial = 0; trial < 5; ++trial) {
    const std::vector<double> p = RandomParameters<E>(rng);
    std::vector<double> xyz;
    for (const Vec& x : RandomPoints(p, rng, 400))
      if (!NearKink<E>(p, x, 1e-9)) xyz.insert(xyz.end(), x.data(), x.data() + 3);
    std::vector<int> indices(xyz.size() / 3);
    std::iota(indices.begin(), indices.end(), 0);
    const int n = static_cast<int>(indices.size());
    const std::vector<int> sizes = FieldSizes<E>();
    std::vector<const double*> blocks;
    for (int b = 0, at = 0; b < static_cast<int>(sizes.size()); at += sizes[b], ++b)
      blocks.push_back(p.data() + at);

    // Reference: the full n x P Jacobian and residuals from the Jet path.
    const BatchedDistanceCost<E, false> full(xyz.data(), indices, sizes);
    Eigen::VectorXd r(n);
    Eigen::MatrixXd J(n, P);
    {
      std::vector<std::vector<double>> jb;
      std::vector<double*> ptrs;
      for (int s : sizes) jb.emplace_back(n * s);
      for (auto& v : jb) ptrs.push_back(v.data());
      ASSERT_TRUE(full.Evaluate(blocks.data(), r.data(), ptrs.data()));
      for (size_t b = 0, at = 0; b < sizes.size(); at += sizes[b], ++b)
        for (int i = 0; i < n; ++i)
          for (int j = 0; j < sizes[b]; ++j) J(i, at + j) = jb[b][i * sizes[b] + j];
    }
    const Eigen::MatrixXd A = J.transpose() * J;
    const Eigen::VectorXd g = J.transpose() * r;
    const double c = r.squaredNorm();

    const CompressedDistanceCost<E> compressed(xyz.data(), indices, sizes);
    ASSERT_EQ(compressed.num_residuals(), P + 1);
    for (int constant = -1; constant < static_cast<int>(sizes.size()); ++constant) {
      Eigen::VectorXd rc(P + 1);
      std::vector<std::vector<double>> jb;
      std::vector<double*> ptrs;
      for (int s : sizes) jb.emplace_back((P + 1) * s, NAN);
      for (auto& v : jb) ptrs.push_back(v.data());
      if (constant >= 0) ptrs[constant] = nullptr;
      ASSERT_TRUE(compressed.Evaluate(blocks.data(), rc.data(), ptrs.data()));
      EXPECT_NEAR(rc.squaredNorm(), c, 1e-10 * c);
      std::vector<int> free;  // columns of the free blocks
      for (size_t b = 0, at = 0; b < sizes.size(); at += sizes[b], ++b)
        if (static_cast<int>(b) != constant)
          for (int j = 0; j < sizes[b]; ++j) free.push_back(static_cast<int>(at) + j);
      Eigen::MatrixXd Jc(P + 1, free.size());
      for (size_t b = 0, col = 0; b < sizes.size(); ++b) {
        if (static_cast<int>(b) == constant) {
          for (double v : jb[b])
            EXPECT_TRUE(std::isnan(v)) << "the constant block's Jacobian was written";
          continue;
        }
        for (int j = 0; j < sizes[b]; ++j, ++col)
          for (int k = 0; k <= P; ++k) Jc(k, col) = jb[b][k * sizes[b] + j];
      }
      const Eigen::MatrixXd Ac = Jc.transpose() * Jc;
      const Eigen::VectorXd gc = Jc.transpose() * rc;
      const double scale_a = A.cwiseAbs().maxCoeff(), scale_g = g.cwiseAbs().maxCoeff() + 1e-300;
      for (size_t u = 0; u < free.size(); ++u) {
        EXPECT_NEAR(gc[u], g[free[u]], 1e-9 * scale_g)
            << "trial " << trial << " column " << free[u];
        for (size_t v = 0; v < free.size(); ++v)
          EXPECT_NEAR(Ac(u, v), A(free[u], free[v]), 1e-10 * scale_a) << "trial " << trial;
      }
    }
    Eigen::VectorXd only(P + 1);
    ASSERT_TRUE(compressed.Evaluate(blocks.data(), only.data(), nullptr));
    EXPECT_NEAR(only.squaredNorm(), c, 1e-12 * c);
  }
}

}  // namespace
}  // namespace implicitfit
