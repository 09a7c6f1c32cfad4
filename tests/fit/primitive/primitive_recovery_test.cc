// Recovery of every fittable primitive from partial views with 0.5% noise and 20% uniform
// outliers, judged on many seeds against the Cramer-Rao reference: for each identifiable
// quantity q(theta) (centre, radius, unit axis, ...), the ideal spread is
//   sd(q) = sigma sqrt(grad q^T (J^T J)^+ grad q),  J_ij = d f(x_i; theta) / d theta_j
// over the true inliers at the true parameters (J and grad q by central differences here, not
// by the fitter's code). The RMS error over the seeds must stay within kMultiple of sd(q).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <functional>

#include "datasets/generators/model_sampler.h"
#include "fit/primitive/primitive_fitter.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;
constexpr double kMultiple = 2.0;
constexpr int kSeeds = 16;

struct Quantity {
  std::string name;
  std::function<double(const std::vector<double>&)> q;
};

Vec Unit(const std::vector<double>& p, int at) {
  return Vec(p[at], p[at + 1], p[at + 2]).normalized();
}

// Unit axis components, with the sign aligned to the truth's axis.
std::vector<Quantity> AxisQuantities(int at, const std::vector<double>& truth) {
  std::vector<Quantity> out;
  const Vec t = Unit(truth, at);
  for (int k = 0; k < 3; ++k)
    out.push_back({"axis[" + std::to_string(k) + "]", [at, k, t](const std::vector<double>& p) {
                     Vec a = Unit(p, at);
                     if (a.dot(t) < 0) a = -a;
                     return a[k];
                   }});
  return out;
}

std::vector<Quantity> Coordinates(const std::string& name, int at) {
  std::vector<Quantity> out;
  for (int k = 0; k < 3; ++k)
    out.push_back({name + "[" + std::to_string(k) + "]",
                   [at, k](const std::vector<double>& p) { return p[at + k]; }});
  return out;
}

struct Case {
  NodeType kind;
  std::vector<double> truth;
  double size;  // characteristic size; noise = 0.5% of it
  Vec view;
  double view_angle;
  std::vector<Quantity> quantities;
};

std::vector<Case> Cases() {
  std::vector<Case> cases;
  {
    std::vector<double> t = {0.2, -0.3, 0.9327379053088815, 0.4};  // unit normal
    Case c{NodeType::kPlane, t, 1.0, Vec::Zero(), 180, AxisQuantities(0, t)};
    c.quantities.push_back({"offset", [](const std::vector<double>& p) {
                              return p[3] / Vec(p[0], p[1], p[2]).norm();
                            }});
    cases.push_back(c);
  }
  {
    std::vector<double> t = {1.0, -2.0, 0.5, 1.5};
    Case c{NodeType::kSphere, t, 1.5, Vec(1, 1, 1), 70, Coordinates("center", 0)};
    c.quantities.push_back({"radius", [](const std::vector<double>& p) { return p[3]; }});
    cases.push_back(c);
  }
  {
    std::vector<double> t = {0.5, 0.2, -1.0, 0.0, 0.6, 0.8, 0.8};
    Case c{NodeType::kCylinder, t, 0.8, Vec(1, 0, 0), 80, AxisQuantities(3, t)};
    c.quantities.push_back({"radius", [](const std::vector<double>& p) { return p[6]; }});
    const Vec p0(t[0], t[1], t[2]);
    for (int k = 0; k < 3; ++k)
      c.quantities.push_back(
          {"axis point[" + std::to_string(k) + "]", [p0, k](const std::vector<double>& p) {
             const Vec q(p[0], p[1], p[2]), a = Unit(p, 3);
             return (q + a * a.dot(p0 - q))[k];
           }});
    cases.push_back(c);
  }
  {
    std::vector<double> t = {0.1, 0.2, 0.3, -0.3, 0.4, 1.0, 0.5};
    Case c{NodeType::kCone, t, 1.0, Vec(1, 0, 0), 85, Coordinates("apex", 0)};
    for (auto& q : AxisQuantities(3, t)) c.quantities.push_back(q);
    c.quantities.push_back({"half_angle", [](const std::vector<double>& p) { return p[6]; }});
    cases.push_back(c);
  }
  {
    std::vector<double> t = {-1.0, 0.0, 2.0, 0.0, 0.6, 0.8, 2.0, 0.6};
    Case c{NodeType::kTorus, t, 0.6, Vec(0, 0.6, 0.8), 100, Coordinates("center", 0)};
    for (auto& q : AxisQuantities(3, t)) c.quantities.push_back(q);
    c.quantities.push_back({"major_radius", [](const std::vector<double>& p) { return p[6]; }});
    c.quantities.push_back({"minor_radius", [](const std::vector<double>& p) { return p[7]; }});
    cases.push_back(c);
  }
  return cases;
}

double F(NodeType kind, const std::vector<double>& p, const Vec& x) {
  Model m;
  m.AddPrimitive(kind, p);
  return m.Value(x);
}

class PrimitiveRecovery : public ::testing::TestWithParam<int> {};

TEST_P(PrimitiveRecovery, ErrorsStayWithinTwiceTheCramerRaoSpread) {
  const Case c = Cases()[GetParam()];
  const double sigma = 0.005 * c.size;
  std::vector<std::vector<double>> errors(c.quantities.size());
  std::vector<double> ideal(c.quantities.size(), 0.0);
  int failures = 0;
  for (int seed = 1; seed <= kSeeds; ++seed) {
    Model truth;
    truth.AddPrimitive(c.kind, c.truth);
    SampleOptions so;
    so.count = 2500;
    so.noise = sigma;
    so.outlier_fraction = 0.2;
    so.seed = seed;
    so.view_dir = c.view;
    so.view_angle_deg = c.view_angle;
    const SampledCloud s = SampleModel(truth, so);
    PrimitiveFitOptions fo;
    fo.kind = c.kind;
    fo.seed = seed;
    fo.compute_covariance = false;
    const PrimitiveFitResult r = FitPrimitive(s.cloud.points, s.cloud.normals, fo);
    if (!r.success) {
      ++failures;
      ADD_FAILURE() << NodeTypeName(c.kind) << " seed " << seed << ": " << r.message;
      continue;
    }
    for (size_t q = 0; q < c.quantities.size(); ++q)
      errors[q].push_back(c.quantities[q].q(r.parameters) - c.quantities[q].q(c.truth));

    if (seed == 1) {  // Cramer-Rao reference from the first cloud's true inliers
      std::vector<Vec> in;
      for (size_t i = 0; i < s.cloud.size(); ++i)
        if (!s.is_outlier[i]) in.push_back(s.cloud.points[i]);
      const int P = static_cast<int>(c.truth.size());
      Eigen::MatrixXd J(in.size(), P);
      for (int j = 0; j < P; ++j) {
        std::vector<double> plus = c.truth, minus = c.truth;
        const double h = 1e-6;
        plus[j] += h;
        minus[j] -= h;
        for (size_t i = 0; i < in.size(); ++i)
          J(i, j) = (F(c.kind, plus, in[i]) - F(c.kind, minus, in[i])) / (2 * h);
      }
      const Eigen::MatrixXd info = J.transpose() * J;
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(info);
      Eigen::VectorXd inv = eig.eigenvalues();
      for (int k = 0; k < P; ++k)
        inv[k] = inv[k] > 1e-9 * eig.eigenvalues().maxCoeff() ? 1.0 / inv[k] : 0.0;
      const Eigen::MatrixXd pinv =
          eig.eigenvectors() * inv.asDiagonal() * eig.eigenvectors().transpose();
      for (size_t q = 0; q < c.quantities.size(); ++q) {
        Eigen::VectorXd g(P);
        for (int j = 0; j < P; ++j) {
          std::vector<double> plus = c.truth, minus = c.truth;
          plus[j] += 1e-6;
          minus[j] -= 1e-6;
          g[j] = (c.quantities[q].q(plus) - c.quantities[q].q(minus)) / 2e-6;
        }
        ideal[q] = sigma * std::sqrt(std::max(0.0, g.dot(pinv * g)));
      }
    }
  }
  ASSERT_EQ(failures, 0);
  for (size_t q = 0; q < c.quantities.size(); ++q) {
    double ss = 0, mean = 0;
    for (double e : errors[q]) ss += e * e, mean += e / errors[q].size();
    const double rms = std::sqrt(ss / errors[q].size());
    if (ideal[q] < 1e-12) continue;  // a component fixed by the geometry (e.g. axis along itself)
    EXPECT_LE(rms, kMultiple * ideal[q])
        << NodeTypeName(c.kind) << " " << c.quantities[q].name << ": rms error " << rms
        << " vs ideal " << ideal[q] << " (ratio " << rms / ideal[q] << ")";
    std::printf("  %-9s %-16s rms %.3g  mean %.3g  ideal %.3g  ratio %.2f\n", NodeTypeName(c.kind),
                c.quantities[q].name.c_str(), rms, mean, ideal[q], rms / ideal[q]);
  }
}

std::string KindName(const ::testing::TestParamInfo<int>& info) {
  return NodeTypeName(Cases()[info.param].kind);
}
INSTANTIATE_TEST_SUITE_P(EveryKind, PrimitiveRecovery, ::testing::Range(0, 5), KindName);

TEST(PrimitiveFitter, DegenerateInputFailsWithAReason) {
  std::vector<Vec> pts, nrm;
  for (int i = 0; i < 100; ++i) {  // collinear points
    pts.push_back(Vec(i * 0.01, 0, 0));
    nrm.push_back(Vec(0, 0, 1));
  }
  PrimitiveFitOptions o;
  o.kind = NodeType::kSphere;
  const PrimitiveFitResult r = FitPrimitive(pts, nrm, o);
  EXPECT_FALSE(r.success);
  EXPECT_FALSE(r.message.empty());
}

TEST(PrimitiveFitter, FixedParametersStayFixed) {
  Model truth;
  truth.AddPrimitive(NodeType::kSphere, {0, 0, 0, 2});
  SampleOptions so;
  so.count = 1000;
  so.noise = 0.01;
  const SampledCloud s = SampleModel(truth, so);
  PrimitiveFitOptions o;
  o.kind = NodeType::kSphere;
  o.fixed["radius"] = {2.5};
  const PrimitiveFitResult r = FitPrimitive(s.cloud.points, s.cloud.normals, o);
  ASSERT_FALSE(r.parameters.empty());
  EXPECT_EQ(r.parameters[3], 2.5);
}

TEST(PrimitiveFitter, HugeCoordinatesLoseNoPrecision) {
  // The same sphere far away (UTM-like offsets): the recovered centre error stays small.
  const Vec offset(512345.0, 5234567.0, 250.0);
  Model truth;
  truth.AddPrimitive(NodeType::kSphere, {offset.x(), offset.y(), offset.z(), 1.0});
  SampleOptions so;
  so.count = 2000;
  so.noise = 0.001;
  so.has_box = true;
  so.box_min = offset - Vec::Constant(1.1);
  so.box_max = offset + Vec::Constant(1.1);
  const SampledCloud s = SampleModel(truth, so);
  PrimitiveFitOptions o;
  o.kind = NodeType::kSphere;
  const PrimitiveFitResult r = FitPrimitive(s.cloud.points, s.cloud.normals, o);
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_LT((Vec(r.parameters[0], r.parameters[1], r.parameters[2]) - offset).norm(), 2e-4);
  EXPECT_NEAR(r.parameters[3], 1.0, 2e-4);
}

}  // namespace
}  // namespace implicitfit
