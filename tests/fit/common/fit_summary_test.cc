// The result shape the three fitters share (fit/common/fit_summary.h): options refused by IsValid
// with a reason that names the option and never a command-line flag, the termination status
// of converged, cut-short and failed fits, and BriefReport / ToJson reading the result.
#include "fit/common/fit_summary.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fit/bernstein/patch_fitter.h"
#include "fit/primitive/primitive_fitter.h"
#include "fit/tree/tree_fitter.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

// n points on the sphere |x - c| = r with noise of standard deviation `noise`, outward normals.
void Sphere(int n, double noise, std::vector<Vec>* x, std::vector<Vec>* normals) {
  std::mt19937 rng(17);
  std::normal_distribution<double> g;
  const Vec c(0.3, -0.2, 0.1);
  for (int i = 0; i < n; ++i) {
    const Vec u = Vec(g(rng), g(rng), g(rng)).normalized();
    x->push_back(c + (1.2 + noise * g(rng)) * u);
    normals->push_back(u);
  }
}

void ExpectRefused(bool valid, const std::string& error, const std::string& names) {
  EXPECT_FALSE(valid);
  EXPECT_NE(error.find(names), std::string::npos) << error;
  EXPECT_EQ(error.find("--"), std::string::npos) << "names a flag: " << error;
}

TEST(FitOptions, PrimitiveOptionsRefusedWithTheirName) {
  std::string e;
  EXPECT_TRUE(PrimitiveFitOptions{}.IsValid(&e)) << e;
  auto check = [](auto change, const std::string& names) {
    PrimitiveFitOptions o;
    change(o);
    std::string error;
    const bool valid = o.IsValid(&error);
    ExpectRefused(valid, error, names);
  };
  check([](PrimitiveFitOptions& o) { o.hypotheses = 0; }, "hypotheses");
  check([](PrimitiveFitOptions& o) { o.confidence = 1.0; }, "confidence");
  check([](PrimitiveFitOptions& o) { o.normal_cos = 1.5; }, "normal_cos");
  check([](PrimitiveFitOptions& o) { o.band_sigmas = 0.0; }, "band_sigmas");
  check([](PrimitiveFitOptions& o) { o.max_rounds = 0; }, "max_rounds");
  check([](PrimitiveFitOptions& o) { o.score_subsample = 3; }, "subsample");
  check([](PrimitiveFitOptions& o) { o.kind = NodeType::kEllipsoid; }, "ellipsoid");
  check([](PrimitiveFitOptions& o) { o.fixed["height"] = {1.0}; }, "height");
  check([](PrimitiveFitOptions& o) { o.fixed["center"] = {1.0}; }, "center");
  check([](PrimitiveFitOptions& o) { o.initial = {1, 2, 3}; }, "initial");
}

TEST(FitOptions, TreeOptionsRefusedWithTheirName) {
  std::string e;
  EXPECT_TRUE(TreeFitOptions{}.IsValid(&e)) << e;
  TreeFitOptions o;
  o.normal_weight = -0.1;
  ExpectRefused(o.IsValid(&e), e, "normal_weight");
  o.normal_weight = NAN;
  ExpectRefused(o.IsValid(&e), e, "normal_weight");
  o = TreeFitOptions{};
  o.max_iterations = 0;
  ExpectRefused(o.IsValid(&e), e, "max_iterations");
  o = TreeFitOptions{};
  o.num_threads = -2;
  ExpectRefused(o.IsValid(&e), e, "num_threads");
  // The fitter refuses them too, as a FAILURE with the same reason.
  std::vector<Vec> x, n;
  Sphere(200, 0.0, &x, &n);
  Model m;
  m.AddPrimitive(NodeType::kSphere, {0, 0, 0, 1});
  const TreeFitResult r = FitModelTree(m, x, n, o);
  EXPECT_FALSE(r.success);
  EXPECT_EQ(r.termination, FitTermination::kFailure);
  EXPECT_NE(r.message.find("num_threads"), std::string::npos) << r.message;
}

TEST(FitOptions, PatchOptionsRefusedWithoutNamingFlags) {
  std::string e;
  EXPECT_TRUE(PatchFitOptions{}.IsValid(&e)) << e;
  PatchFitOptions o;
  o.degree = 5;
  ExpectRefused(o.IsValid(&e), e, "degree");
  o = PatchFitOptions{};
  o.max_iterations = 0;
  ExpectRefused(o.IsValid(&e), e, "max_iterations");
  o = PatchFitOptions{};
  o.normal_weight = -1.0;
  ExpectRefused(o.IsValid(&e), e, "normal_weight");
  // A convex patch may pass through a vertex (shape control with convexity, issue 28), not
  // along an edge of its tetrahedron (f = 0 on a segment of the boundary).
  o = PatchFitOptions{};
  o.convex = true;
  o.constraints.through_vertices = {0};
  EXPECT_TRUE(o.IsValid(&e)) << e;
  o.constraints.through_vertices.clear();
  o.constraints.through_edges = {{0, 1}};
  ExpectRefused(o.IsValid(&e), e, "convex");
}

TEST(FitTermination, PrimitiveFitterStatus) {
  std::vector<Vec> x, n;
  Sphere(3000, 0.002, &x, &n);
  PrimitiveFitOptions o;
  o.kind = NodeType::kSphere;
  const PrimitiveFitResult good = FitPrimitive(x, n, o);
  ASSERT_TRUE(good.success) << good.message;
  EXPECT_EQ(good.termination, FitTermination::kConverged);
  EXPECT_EQ(good.message, "converged");
  EXPECT_EQ(good.points, x.size());
  EXPECT_EQ(good.kind, NodeType::kSphere);

  // The inlier set is never "stable" (stable_fraction < 0): the rounds run out.
  o.stable_fraction = -1.0;
  o.max_rounds = 2;
  const PrimitiveFitResult cut = FitPrimitive(x, n, o);
  EXPECT_TRUE(cut.success) << cut.message;
  EXPECT_EQ(cut.termination, FitTermination::kNoConvergence);
  EXPECT_NE(cut.message.find("2 rounds"), std::string::npos) << cut.message;

  // Uniform noise in a cube holds no sphere: too few inliers.
  std::vector<Vec> noise, noise_normals;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 400; ++i) {
    noise.push_back(Vec(u(rng), u(rng), u(rng)));
    noise_normals.push_back(Vec(u(rng), u(rng), u(rng)).normalized());
  }
  PrimitiveFitOptions strict;
  strict.kind = NodeType::kSphere;
  strict.min_inlier_fraction = 0.5;
  const PrimitiveFitResult bad = FitPrimitive(noise, noise_normals, strict);
  EXPECT_FALSE(bad.success);
  EXPECT_EQ(bad.termination, FitTermination::kFailure) << bad.message;

  PrimitiveFitOptions invalid;
  invalid.max_rounds = 0;
  const PrimitiveFitResult refused = FitPrimitive(x, n, invalid);
  EXPECT_EQ(refused.termination, FitTermination::kFailure);
  EXPECT_NE(refused.message.find("max_rounds"), std::string::npos);
}

TEST(FitTermination, TreeFitterStatus) {
  std::vector<Vec> x, n;
  Sphere(500, 0.001, &x, &n);
  Model start;
  start.AddPrimitive(NodeType::kSphere, {0.0, 0.0, 0.0, 1.0});
  const TreeFitResult good = FitModelTree(start, x, n, TreeFitOptions{});
  ASSERT_TRUE(good.success) << good.message;
  EXPECT_EQ(good.termination, FitTermination::kConverged);
  EXPECT_NEAR(good.model.parameters()[3], 1.2, 1e-3);
  TreeFitOptions one;
  one.max_iterations = 1;  // far from the solution: Ceres stops at its iteration limit
  const TreeFitResult cut = FitModelTree(start, x, n, one);
  EXPECT_FALSE(cut.success);
  EXPECT_EQ(cut.termination, FitTermination::kNoConvergence) << cut.message;
}

TEST(FitReports, BriefReportAndJsonReadTheResult) {
  std::vector<Vec> x, n;
  Sphere(1000, 0.002, &x, &n);
  PrimitiveFitOptions o;
  o.kind = NodeType::kSphere;
  const PrimitiveFitResult r = FitPrimitive(x, n, o);
  ASSERT_TRUE(r.success);
  const nlohmann::json j = r.ToJson("given");
  EXPECT_EQ(j["termination"], "CONVERGENCE");
  EXPECT_EQ(j["points"], 1000);
  EXPECT_EQ(j["inliers"], r.inliers.size());
  EXPECT_EQ(j["normals"], "given");
  EXPECT_DOUBLE_EQ(j["parameters"]["radius"].get<double>(), r.parameters[3]);
  const std::string brief = r.BriefReport();
  EXPECT_EQ(brief.rfind("points 1000  inliers " + std::to_string(r.inliers.size()), 0), 0u)
      << brief;
  EXPECT_NE(brief.find("\nestimator robust"), std::string::npos) << brief;

  PatchFitOptions p;
  p.max_iterations = 1;
  const PatchFitResult cut = FitBernsteinPatch(x, n, p);
  ASSERT_TRUE(cut.success) << cut.message;  // usable, not converged
  EXPECT_EQ(cut.ToJson("given")["termination"], "NO_CONVERGENCE");
  EXPECT_EQ(cut.ToJson("given")["degree"], 2);
  EXPECT_EQ(cut.BriefReport().rfind("points 1000  rms ", 0), 0u) << cut.BriefReport();
}

}  // namespace
}  // namespace implicitfit
