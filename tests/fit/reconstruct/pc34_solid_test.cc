// Fit4CAD test_PC34 (a screw: shank r = 6 along z from -40 to 0 with a chamfer cone at its end,
// a flange r = 10.5 over z 0..3.3, a domed head (sphere) cut flat at z = 6.59, a hexagon socket
// of inradius 4 from its floor z = 2 to the top), reconstructed from its ground-truth labels
// (each primitive fitted to its points by the primitive fitter; normals estimated and oriented
// as `reconstruct` does). The facts checked come from the part's parametric file, not from the
// code: the shank's axis (0, 0, z), z in [-35, -5], and the material under the socket's floor
// (z in [0.3, 1.7]) are inside; the socket's axis above its floor (z in [2.5, 6]) is outside;
// the solid is verified bounded, in one piece, without a cavity. Skips when the data set is
// absent.
#include <gtest/gtest.h>

#include <fstream>

#include "datasets/clouds/cloud_file.h"
#include "datasets/generators/ground_truth.h"
#include "datasets/normals/normal_estimation.h"
#include "fit/reconstruct/solid_reconstruction.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

TEST(Pc34Solid, FromLabelsShankInsideSocketOutsideOnePieceBounded) {
  const std::string root = std::string(IMPLICITFIT_SHARED_DATA) + "/fit4cad/";
  const std::string cloud_path = root + "fit4cad_test_PC34.xyzl";
  const std::string implicit_path = root + "fit4cad_test_PC34/test_PC34_implicit.txt";
  if (!std::ifstream(cloud_path) || !std::ifstream(implicit_path))
    GTEST_SKIP() << "Fit4CAD PC34 absent (" << cloud_path << ")";
  CloudFileInfo info;
  PointCloud cloud = ReadCloudFile(cloud_path, &info);
  EnsureOrientedNormals(&cloud);
  const std::vector<NodeType> kinds = ReadFit4CadKinds(implicit_path);
  std::vector<int> labels(cloud.size(), -1);
  for (size_t i = 0; i < cloud.size(); ++i) labels[i] = info.labels[i] - 1;
  const std::vector<SolidPrimitive> scene =
      FitLabelledPrimitives(cloud.points, cloud.normals, labels, kinds, 1);
  const SolidReconstruction r = ReconstructSolid(cloud.points, cloud.normals, scene);
  std::printf("  expression %s\n  %s\n", r.expression.c_str(),
              r.verification.BriefReport().c_str());
  for (double z = -35; z <= -5; z += 2.5) EXPECT_LT(r.model.Value(Vec(0, 0, z)), 0) << z;
  for (double z = 0.3; z <= 1.7; z += 0.35) EXPECT_LT(r.model.Value(Vec(0, 0, z)), 0) << z;
  for (double z = 2.5; z <= 6.0; z += 0.5) EXPECT_GT(r.model.Value(Vec(0, 0, z)), 0) << z;
  EXPECT_TRUE(r.verification.bounded) << r.verification.message;
  EXPECT_EQ(r.verification.components.solids, 1) << r.verification.message;
  EXPECT_EQ(r.verification.components.cavities, 0) << r.verification.message;
  EXPECT_TRUE(r.success) << r.message;
}

}  // namespace
}  // namespace implicitfit
