// The patch-mesh job through the public headers only, on a sampled sphere: the grid's size in
// closed form (6 Kuhn tetrahedra per cube) and a zero set that encloses the sphere's centre.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "implicitfit/model.h"
#include "implicitfit/patch_mesh.h"
#include "implicitfit/sample.h"

namespace implicitfit {
namespace {

// 1500 points sampled on `model` (its own normals).
SampleJobResult Sample1500(const Model& model, unsigned seed) {
  SampleJobOptions sample;
  sample.sample.count = 1500;
  sample.sample.seed = seed;
  return SampleModelJob(model, sample);
}

TEST(PatchMeshJob, SphereOnTwoCubesPerAxis) {
  const Eigen::Vector3d c(0.1, -0.2, 0.3);
  Model sphere;
  sphere.AddPrimitive(NodeType::kSphere, {c.x(), c.y(), c.z(), 1.0});
  const SampleJobResult scan = Sample1500(sphere, 2);
  ASSERT_TRUE(scan.success) << scan.message;
  PatchMeshJobOptions options;
  options.fit.cells = 2;
  std::string error;
  ASSERT_TRUE(options.IsValid(&error)) << error;
  const PatchMeshJobResult job =
      FitPatchMeshJob(scan.sampled.cloud.points, scan.sampled.cloud.normals, options);
  ASSERT_TRUE(job.success) << job.message;
  // The sampled sphere's box is nearly a cube: with the cube edge h half its longest (grown)
  // extent, every axis takes ceil(extent / h) = 2 cubes, each split into 3! = 6 tetrahedra (one
  // per axis order): 48 patches.
  const nlohmann::json report = job.ToJson();
  EXPECT_EQ(report["grid"]["cells"], nlohmann::json({2, 2, 2}));
  EXPECT_EQ(report["patches"], 48);
  EXPECT_EQ(report["points"], 1500);
  EXPECT_EQ(report["inliers"], 1500);
  EXPECT_EQ(report["degree"], 3);
  EXPECT_EQ(report["normals"], "given");
  EXPECT_EQ(report["job"], "fit");
  EXPECT_EQ(report["settings"]["cells"], 2);
  // f < 0 inside: at the centre, and > 0 beyond the sphere (1.5 r out along each axis).
  const Model model = job.ToModel();
  EXPECT_LT(model.Value(c), 0);
  for (int a = 0; a < 3; ++a) EXPECT_GT(model.Value(c + 1.5 * Eigen::Vector3d::Unit(a)), 0);
  EXPECT_NE(job.BriefReport().find("patches 48 (2x2x2 cubes, degree 3, C1)"), std::string::npos)
      << job.BriefReport();
}

// Normals the reader estimated ("estimated, ..." in normals_action) lighten the normal rows of
// the crease leaves (MeshFitOptions::normals_estimated); normals given or read from the file do
// not. On a sampled box refined once, the estimated-normals fit differs, the other two agree.
TEST(PatchMeshJob, EstimatedNormalsChangeTheFitAtTheCreasesOnly) {
  Model box;
  box.AddPrimitive(NodeType::kBox, {0, 0, 0, 1, 0, 0, 0, 0.5, 0.4, 0.3});
  const SampleJobResult scan = Sample1500(box, 3);
  ASSERT_TRUE(scan.success) << scan.message;
  PatchMeshJobOptions options;
  options.fit.cells = 3;
  options.fit.continuity = 0;
  options.fit.adaptive = true;
  options.fit.max_levels = 1;
  const auto fit = [&](const std::string& action) {
    return FitPatchMeshJob(scan.sampled.cloud.points, scan.sampled.cloud.normals, options,
                           action);
  };
  const PatchMeshJobResult given = fit("given"), read = fit("read from file"),
                           estimated = fit("estimated, MST-oriented");
  for (const PatchMeshJobResult* j : {&given, &read, &estimated})
    ASSERT_TRUE(j->success) << j->message;
  ASSERT_GT(given.result.sharp_faces, 0);  // crease leaves exist
  EXPECT_EQ(given.result.control_points, read.result.control_points);
  ASSERT_EQ(given.result.control_points.size(), estimated.result.control_points.size());
  double largest = 0;
  for (size_t i = 0; i < given.result.control_points.size(); ++i)
    largest = std::max(largest, std::abs(given.result.control_points[i] -
                                         estimated.result.control_points[i]));
  EXPECT_GT(largest, 1e-6);
}

TEST(PatchMeshJob, InvalidOptionsAreRefused) {
  PatchMeshJobOptions options;
  options.fit.degree = 7;
  std::string error;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("degree"), std::string::npos) << error;
  const std::vector<Eigen::Vector3d> none;
  EXPECT_THROW(FitPatchMeshJob(none, none, options), std::invalid_argument);
}

}  // namespace
}  // namespace implicitfit
