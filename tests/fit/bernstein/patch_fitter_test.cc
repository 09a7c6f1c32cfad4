// Bernstein patch fitting, unconstrained and --convex, on clouds sampled from known quadrics.
// Convexity of results is judged by the certificate (tested on its own in
// tests/model/certificates/convexity_certificate_test.cc) and by the sampled tangent-plane test.
#include "fit/bernstein/patch_fitter.h"

#include <gtest/gtest.h>

#include <cmath>

#include "datasets/generators/model_sampler.h"
#include "model/certificates/convexity_certificate.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

SampledCloud Sample(NodeType type, const std::vector<double>& params, double noise, unsigned seed,
                    Vec view, double angle, Vec lo = Vec::Zero(), Vec hi = Vec::Zero()) {
  Model m;
  m.AddPrimitive(type, params);
  SampleOptions so;
  so.count = 1500;
  so.noise = noise;
  so.seed = seed;
  so.view_dir = view;
  so.view_angle_deg = angle;
  if (lo != hi) {
    so.has_box = true;
    so.box_min = lo;
    so.box_max = hi;
  }
  return SampleModel(m, so);
}

struct ConvexCase {
  const char* name;
  NodeType type;
  std::vector<double> params;
  Vec view;
  double angle;
  Vec lo, hi;
};

std::vector<ConvexCase> ConvexCases() {
  return {
      {"ellipsoid cap",
       NodeType::kEllipsoid,
       {0, 0, 0, 1.5, 1.0, 0.7, 1, 0, 0, 0, 1, 0},
       Vec(0, 0, 1),
       50,
       Vec::Zero(),
       Vec::Zero()},
      {"paraboloid",
       NodeType::kQuadric,
       {1, 1, 0, 0, 0, 0, 0, 0, -0.5, 0},
       Vec::Zero(),
       180,
       Vec(-0.6, -0.6, -0.1),
       Vec(0.6, 0.6, 0.8)},
      {"sphere from one side",
       NodeType::kSphere,
       {0.2, 0.1, 0.0, 1.0},
       Vec(1, 0.5, 0),
       60,
       Vec::Zero(),
       Vec::Zero()},
  };
}

TEST(PatchFitter, ExactQuadricDataIsFittedExactlyByAQuadricPatch) {
  const SampledCloud s = Sample(NodeType::kQuadric, {1, 1, 0, 0, 0, 0, 0, 0, -0.5, 0}, 0.0, 1,
                                Vec::Zero(), 180, Vec(-0.6, -0.6, -0.1), Vec(0.6, 0.6, 0.8));
  PatchFitOptions o;
  const PatchFitResult r = FitBernsteinPatch(s.cloud.points, s.cloud.normals, o);
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_LT(r.rms, 1e-7);
  EXPECT_LT(r.mean_normal_angle_deg, 1e-3);
}

TEST(PatchFitter, ConvexFitsOfNoisyConvexCapsAreCertifiedAndAsCloseAsUnconstrained) {
  const double sigma = 0.005;
  for (const ConvexCase& c : ConvexCases())
    for (int degree : {2, 3}) {
      const SampledCloud s = Sample(c.type, c.params, sigma, 7, c.view, c.angle, c.lo, c.hi);
      PatchFitOptions o;
      o.degree = degree;
      o.convex = true;
      const PatchFitResult r = FitBernsteinPatch(s.cloud.points, s.cloud.normals, o);
      ASSERT_TRUE(r.success) << c.name << " degree " << degree << ": " << r.message;
      EXPECT_TRUE(r.certified_convex);
      EXPECT_TRUE(CertifyConvexity(degree, r.control_points.data()).convex);
      EXPECT_LE(r.rms, 1.1 * r.unconstrained_rms + 1e-12) << c.name << " degree " << degree;
      EXPECT_LE(r.rms, 1.5 * sigma) << c.name << " degree " << degree;
      std::printf("  %-22s k=%d  rms %.5f  unconstrained %.5f  min eigenvalue %.3g  %.2f s\n",
                  c.name, degree, r.rms, r.unconstrained_rms, r.min_eigenvalue, r.seconds);
    }
}

TEST(PatchFitter, ConvexFitOfASaddleIsCertifiedAndStillFollowsTheNormals) {
  // z = x^2 - y^2 (hyperbolic paraboloid): no convex patch fits it exactly.
  const SampledCloud s = Sample(NodeType::kQuadric, {1, -1, 0, 0, 0, 0, 0, 0, -0.5, 0}, 0.002, 3,
                                Vec::Zero(), 180, Vec(-0.5, -0.5, -0.5), Vec(0.5, 0.5, 0.5));
  // Reference: the best plane (z = 0 by symmetry), the simplest convex surface; its mean
  // normal angle is computed from the data's normals.
  double plane_angle = 0;
  for (const Vec& n : s.cloud.normals) plane_angle += std::acos(std::abs(n.z())) * 180 / M_PI;
  plane_angle /= s.cloud.size();
  for (int degree : {2, 3}) {
    PatchFitOptions o;
    o.degree = degree;
    o.convex = true;
    const PatchFitResult r = FitBernsteinPatch(s.cloud.points, s.cloud.normals, o);
    ASSERT_TRUE(r.success) << r.message;
    EXPECT_TRUE(CertifyConvexity(degree, r.control_points.data()).convex);
    EXPECT_GT(r.min_eigenvalue, 0.0);
    EXPECT_LT(r.mean_normal_angle_deg, plane_angle)
        << "worse than the best plane (" << plane_angle << " deg)";
    std::printf(
        "  saddle k=%d  rms %.4f (unconstrained %.5f)  normal angle %.1f deg (best plane %.1f)  "
        "min eigenvalue %.3g\n",
        degree, r.rms, r.unconstrained_rms, r.mean_normal_angle_deg, plane_angle, r.min_eigenvalue);
  }
}

TEST(PatchFitter, EnclosingTetrahedronContainsTheCloud) {
  const SampledCloud s = Sample(NodeType::kSphere, {3, -2, 1, 2}, 0.0, 2, Vec::Zero(), 180);
  const Tetrahedron t = EnclosingTetrahedron(s.cloud.points);
  for (const Vec& p : s.cloud.points) {
    double tau[4];
    t.Barycentric(p.data(), tau);
    for (double v : tau) EXPECT_GE(v, 0.0);
  }
}

// The patch fitter says when the iteration limit stopped it (it used to say "converged"): one
// iteration from the linear start on a noisy cubic fit cannot meet Ceres' tolerances.
TEST(PatchFitter, ReportsNoConvergenceWhenTheIterationLimitStopsIt) {
  const ConvexCase c = ConvexCases()[0];
  const SampledCloud s = Sample(c.type, c.params, 0.005, 7, c.view, c.angle, c.lo, c.hi);
  PatchFitOptions o;
  o.degree = 3;
  const PatchFitResult full = FitBernsteinPatch(s.cloud.points, s.cloud.normals, o);
  ASSERT_TRUE(full.success) << full.message;
  EXPECT_EQ(full.termination, FitTermination::kConverged) << full.message;
  EXPECT_EQ(full.message, "converged");
  o.max_iterations = 1;
  const PatchFitResult cut = FitBernsteinPatch(s.cloud.points, s.cloud.normals, o);
  EXPECT_TRUE(cut.success) << cut.message;  // usable, not converged
  EXPECT_EQ(cut.termination, FitTermination::kNoConvergence) << cut.message;
  EXPECT_NE(cut.message.find("no convergence within 1 iterations"), std::string::npos)
      << cut.message;
  EXPECT_STREQ(FitTerminationName(cut.termination), "NO_CONVERGENCE");
}

}  // namespace
}  // namespace implicitfit
