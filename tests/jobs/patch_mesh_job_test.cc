// The patch-mesh job through the public headers only, on a sampled sphere: the grid's size in
// closed form (6 Kuhn tetrahedra per cube) and a zero set that encloses the sphere's centre.
#include <gtest/gtest.h>

#include <string>

#include "implicitfit/model.h"
#include "implicitfit/patch_mesh.h"
#include "implicitfit/sample.h"

namespace implicitfit {
namespace {

TEST(PatchMeshJob, SphereOnTwoCubesPerAxis) {
  const Eigen::Vector3d c(0.1, -0.2, 0.3);
  Model sphere;
  sphere.AddPrimitive(NodeType::kSphere, {c.x(), c.y(), c.z(), 1.0});
  SampleJobOptions sample;
  sample.sample.count = 1500;
  sample.sample.seed = 2;
  const SampleJobResult scan = SampleModelJob(sphere, sample);
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
