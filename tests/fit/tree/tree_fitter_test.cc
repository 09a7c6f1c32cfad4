// fit --init on blended models: the truth is a smooth CSG tree, the cloud is sampled from it
// (datasets/generators/model_sampler), the initial model is the truth perturbed; the fit must
// recover the primitives and the blend's delta and epsilon.
#include "fit/tree/tree_fitter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "datasets/clouds/cloud_file.h"
#include "datasets/generators/model_sampler.h"
#include "fit/tree/tree_parameters.h"
#include "support/sample_in_box.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

// A wedge: intersection of the half-spaces z <= 0 and x <= 0 with a rounded crease along y.
Model Wedge(Vec n1, double d1, Vec n2, double d2, double delta, double epsilon) {
  Model m;
  const int a = m.AddPrimitive(NodeType::kPlane, {n1.x(), n1.y(), n1.z(), d1});
  const int b = m.AddPrimitive(NodeType::kPlane, {n2.x(), n2.y(), n2.z(), d2});
  m.AddOperator(NodeType::kIntersection, {a, b}, delta, epsilon, 3);
  return m;
}

TEST(TreeParameters, KeepZeroLessThanEpsilonAtMostDeltaForAnyFreeValues) {
  const Model m = Wedge(Vec(0, 0, 1), 0, Vec(1, 0, 0), 0, 0.3, 0.2);
  TreeParameters tp(m);
  // The round trip reproduces the model's parameters.
  const std::vector<double> flat = tp.ToFlat();
  for (size_t i = 0; i < flat.size(); ++i) EXPECT_NEAR(flat[i], m.parameters()[i], 1e-12) << i;
  // Arbitrary free values still give a valid blend.
  for (double a : {-20.0, -1.0, 0.0, 3.0})
    for (double b : {-30.0, -2.0, 0.0, 2.0, 30.0}) {
      tp.blocks()[tp.blocks().size() - 2][0] = a;
      tp.blocks()[tp.blocks().size() - 1][0] = b;
      const std::vector<double> p = tp.ToFlat();
      const double delta = p[8], epsilon = p[9];
      EXPECT_GT(delta, 0.0);
      EXPECT_GT(epsilon, 0.0);
      EXPECT_LE(epsilon, delta);
    }
}

TEST(TreeFitter, RecoversTwoPlanesAndTheBlendOfARoundedCrease) {
  const double delta = 0.2, epsilon = 0.12;
  const Model truth = Wedge(Vec(0, 0, 1), 0.0, Vec(1, 0, 0), 0.0, delta, epsilon);
  SampleOptions so = testsupport::SampleInBox(3000, 0.002, 3, Vec(-1, -1, -1), Vec(0.5, 1, 0.5));
  const SampledCloud s = SampleModel(truth, so);
  const Vec n1 = Vec(0.05, 0.03, 1).normalized(), n2 = Vec(1, -0.04, 0.06).normalized();
  const Model init = Wedge(n1, 0.03, n2, -0.02, 0.35, 0.2);
  const TreeFitResult r = FitModelTree(init, s.cloud.points, s.cloud.normals, TreeFitOptions{});
  ASSERT_TRUE(r.success) << r.message;
  const std::vector<double>& p = r.model.parameters();
  EXPECT_LT(std::acos(std::min(1.0, Vec(p[0], p[1], p[2]).normalized().z())), 2e-3);
  EXPECT_LT(std::acos(std::min(1.0, Vec(p[4], p[5], p[6]).normalized().x())), 2e-3);
  EXPECT_NEAR(p[3] / Vec(p[0], p[1], p[2]).norm(), 0.0, 1e-3);
  EXPECT_NEAR(p[7] / Vec(p[4], p[5], p[6]).norm(), 0.0, 1e-3);
  EXPECT_NEAR(p[8], delta, 0.1 * delta);
  EXPECT_NEAR(p[9], epsilon, 0.2 * epsilon);
  EXPECT_LT(r.rms, 1.5 * so.noise);
  std::printf("  delta %.4f (truth %.3f)  epsilon %.4f (truth %.3f)  rms %.5f  sigma %.5f\n", p[8],
              delta, p[9], epsilon, r.rms, r.sigma);
}

// A rounded box: the intersection of six planes (a cube of half-size 1) with one blend for
// all its edges, folded left to right.
Model RoundedBox(const std::vector<Vec>& normals, const std::vector<double>& offsets, double delta,
                 double epsilon) {
  Model m;
  std::vector<int> faces;
  for (size_t i = 0; i < normals.size(); ++i)
    faces.push_back(m.AddPrimitive(NodeType::kPlane,
                                   {normals[i].x(), normals[i].y(), normals[i].z(), offsets[i]}));
  m.AddOperator(NodeType::kIntersection, faces, delta, epsilon, 2);
  return m;
}

TEST(TreeFitter, RecoversARoundedBoxFromASampledScan) {
  const std::vector<Vec> n = {Vec(1, 0, 0),  Vec(-1, 0, 0), Vec(0, 1, 0),
                              Vec(0, -1, 0), Vec(0, 0, 1),  Vec(0, 0, -1)};
  const Model truth = RoundedBox(n, std::vector<double>(6, 1.0), 0.15, 0.1);
  SampleOptions so;
  so.count = 6000;
  so.noise = 0.003;
  so.seed = 11;
  const SampledCloud s = SampleModel(truth, so);
  std::vector<Vec> tilted;
  for (size_t i = 0; i < n.size(); ++i)
    tilted.push_back((n[i] + Vec(0.03, -0.02, 0.025)).normalized());
  const Model init = RoundedBox(tilted, {1.05, 0.96, 1.04, 0.97, 1.03, 0.95}, 0.25, 0.1);
  const TreeFitResult r = FitModelTree(init, s.cloud.points, s.cloud.normals, TreeFitOptions{});
  ASSERT_TRUE(r.success) << r.message;
  const std::vector<double>& p = r.model.parameters();
  for (int f = 0; f < 6; ++f) {
    const Vec normal(p[4 * f], p[4 * f + 1], p[4 * f + 2]);
    EXPECT_LT(std::acos(std::min(1.0, normal.normalized().dot(n[f]))), 2e-3) << "face " << f;
    EXPECT_NEAR(p[4 * f + 3] / normal.norm(), 1.0, 1e-3) << "face " << f;
  }
  EXPECT_NEAR(p[24], 0.15, 0.015);
  EXPECT_NEAR(p[25], 0.1, 0.02);
  EXPECT_LT(r.rms, 1.5 * so.noise);
  std::printf("  rounded box: delta %.4f (0.15) epsilon %.4f (0.1) rms %.5f\n", p[24], p[25],
              r.rms);
}

TEST(TreeFitter, FixedFieldsKeepTheirValues) {
  const Model truth = Wedge(Vec(0, 0, 1), 0.0, Vec(1, 0, 0), 0.0, 0.2, 0.1);
  SampleOptions so;
  so.count = 800;
  so.noise = 0.001;
  so.has_box = true;
  so.box_min = Vec(-1, -1, -1);
  so.box_max = Vec(0.5, 1, 0.5);
  const SampledCloud s = SampleModel(truth, so);
  Model init = Wedge(Vec(0, 0.05, 1), 0.02, Vec(1, 0, 0), 0.0, 0.3, 0.15);
  init.mutable_nodes()[2].fixed = {"epsilon"};
  init.mutable_nodes()[1].fixed = {"normal", "offset"};
  const TreeFitResult r = FitModelTree(init, s.cloud.points, s.cloud.normals, TreeFitOptions{});
  const std::vector<double>& p = r.model.parameters();
  EXPECT_EQ(p[9], 0.15);
  for (int k = 4; k < 8; ++k) EXPECT_EQ(p[k], init.parameters()[k]);
  EXPECT_GE(p[8], p[9]);
}

TEST(TreeFitter, FitsTheRealFin90CreaseScan) {
  const std::string path =
      std::string(IMPLICITFIT_SHARED_DATA) + "/cgal/cgal_fin90_two_planes_crease.xyz";
  if (!std::ifstream(path)) GTEST_SKIP() << "shared data absent: " << path;
  const PointCloud cloud = ReadCloudFile(path);
  // Initial guess, as a user would make it: split the normals into two groups (2-means on the
  // normal directions, sign-insensitive), one plane per group through its centroid; a convex
  // crease (each group inside the other's half-space) is an intersection, else a union.
  std::vector<int> group(cloud.size(), 0);
  Vec m[2] = {cloud.normals[0], cloud.normals[0]};
  for (const auto& n : cloud.normals)
    if (std::abs(n.dot(m[0])) < std::abs(m[1].dot(m[0]))) m[1] = n;
  Vec c[2];
  for (int iteration = 0; iteration < 10; ++iteration) {
    Vec sum[2] = {Vec::Zero(), Vec::Zero()};
    c[0] = c[1] = Vec::Zero();
    int count[2] = {0, 0};
    for (size_t i = 0; i < cloud.size(); ++i) {
      const Vec& n = cloud.normals[i];
      group[i] = std::abs(n.dot(m[1])) > std::abs(n.dot(m[0])) ? 1 : 0;
      sum[group[i]] += n.dot(m[group[i]]) < 0 ? -n : n;
      c[group[i]] += cloud.points[i];
      ++count[group[i]];
    }
    ASSERT_GT(count[0], 0);
    ASSERT_GT(count[1], 0);
    for (int g = 0; g < 2; ++g) m[g] = sum[g].normalized(), c[g] /= count[g];
  }
  const bool convex = m[0].dot(c[1] - c[0]) < 0 && m[1].dot(c[0] - c[1]) < 0;
  Model init;
  const int a = init.AddPrimitive(NodeType::kPlane, {m[0].x(), m[0].y(), m[0].z(), m[0].dot(c[0])});
  const int b = init.AddPrimitive(NodeType::kPlane, {m[1].x(), m[1].y(), m[1].z(), m[1].dot(c[1])});
  Vec lo = cloud.points[0], hi = lo;
  for (const auto& x : cloud.points) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  const double size = (hi - lo).norm();
  init.AddOperator(convex ? NodeType::kIntersection : NodeType::kUnion, {a, b}, 0.05 * size,
                   0.025 * size, 2);
  TreeFitOptions o;
  const TreeFitResult r = FitModelTree(init, cloud.points, cloud.normals, o);
  ASSERT_TRUE(r.success) << r.message;
  const std::vector<double>& p = r.model.parameters();
  const double angle = std::acos(
      std::abs(Vec(p[0], p[1], p[2]).normalized().dot(Vec(p[4], p[5], p[6]).normalized())));
  std::printf(
      "  fin90: planes at %.2f deg, rms %.3g (%.3g of the extent), inliers %d of %zu, delta %.3g "
      "eps %.3g\n",
      angle * 180 / M_PI, r.rms, r.rms / size, r.inliers, cloud.size(), p[8], p[9]);
  // The file is described as two planes at 90 degrees, but its PCA normals turn continuously
  // over most of the scan: two planes and one blend leave an RMS of ~2.4% of the extent and
  // the planes come out near 73 degrees (an open question). What is checked:
  // the fit never does worse than its start, keeps > 90% of the points, and 0 < eps <= delta.
  double ss0 = 0;
  for (const auto& x : cloud.points) {
    double f;
    const Vec g = init.Gradient(x, &f);
    ss0 += f * f / g.squaredNorm();
  }
  const double rms0 = std::sqrt(ss0 / cloud.size());
  std::printf("  fin90: initial rms %.3g -> fitted %.3g\n", rms0, r.rms);
  EXPECT_LE(r.rms, rms0);
  EXPECT_GT(r.inliers, 0.9 * cloud.size());
  EXPECT_GT(p[9], 0.0);
  EXPECT_LE(p[9], p[8]);
}

}  // namespace
}  // namespace implicitfit
