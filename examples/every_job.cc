// Every job of the library through its public header, as a program built against the installed
// package calls them (examples/CMakeLists.txt declares only CXX): a scan of a known sphere from
// the sample job; detect finds the sphere in it; reconstruct builds and verifies the solid from
// the raw points; the mesh job meshes that solid; the design job builds Li & Phillips' model of
// the same points and the patch-mesh job fits a Bernstein mesh to them. Each result is checked
// against the truth (radius 1.5 at the origin) before the next step; any failure exits 1.
//   every_job
#include <cmath>
#include <cstdio>
#include <string>

#include "implicitfit/design.h"
#include "implicitfit/detect.h"
#include "implicitfit/mesh.h"
#include "implicitfit/model.h"
#include "implicitfit/patch_mesh.h"
#include "implicitfit/reconstruct.h"
#include "implicitfit/sample.h"

namespace {

constexpr double kRadius = 1.5;

int Fail(const char* job, const std::string& why) {
  std::fprintf(stderr, "%s: %s\n", job, why.c_str());
  return 1;
}

// The largest |f| of a model over points on the true sphere: how far its zero set strays.
double WorstValueOnSphere(const implicitfit::Model& model) {
  double worst = 0;
  for (int i = 0; i < 200; ++i) {  // a Fibonacci spiral over the sphere
    const double z = 1 - (2 * i + 1) / 200.0, r = std::sqrt(1 - z * z), phi = i * 2.39996323;
    const Eigen::Vector3d x = kRadius * Eigen::Vector3d(r * std::cos(phi), r * std::sin(phi), z);
    worst = std::max(worst, std::abs(model.Value(x)));
  }
  return worst;
}

}  // namespace

int main() {
  using namespace implicitfit;
  Model truth;
  truth.AddPrimitive(NodeType::kSphere, {0, 0, 0, kRadius});
  SampleJobOptions sample;
  sample.sample.count = 4000;
  sample.sample.noise = 0.005;
  sample.sample.seed = 3;
  const SampleJobResult scan = SampleModelJob(truth, sample);
  if (!scan.success) return Fail("sample", scan.message);
  std::printf("sample:      %s\n", scan.BriefReport().c_str());
  const PointCloud& cloud = scan.sampled.cloud;

  const CloudDetection detection = DetectCloud(cloud, "sphere scan", "given", DetectionOptions{});
  if (!detection.success) return Fail("detect", detection.message);
  std::printf("detect:      %s\n", detection.BriefReport().c_str());
  if (detection.scene.primitives.size() != 1 ||
      detection.scene.primitives[0].model.nodes()[0].type != NodeType::kSphere)
    return Fail("detect", "expected one sphere");

  const CloudReconstruction solid = ReconstructCloud(cloud, "sphere scan", "given");
  if (!solid.success) return Fail("reconstruct", solid.message);
  std::printf("reconstruct: %s\n", solid.BriefReport().c_str());
  const double off = WorstValueOnSphere(solid.result.model);
  if (off > 0.05) return Fail("reconstruct", "the solid strays " + std::to_string(off));

  MeshJobOptions mesh_options;
  mesh_options.mesh.cell = 0.1;
  const MeshJobResult mesh = MeshModelJob(solid.result.model, mesh_options);
  if (!mesh.success) return Fail("mesh", mesh.message);
  std::printf("mesh:        %s\n", mesh.BriefReport().c_str());

  DesignJobOptions design;
  design.design.count = 12;
  const DesignJobResult designed = DesignModelJob(cloud.points, cloud.normals, design);
  if (!designed.success) return Fail("design", designed.message);
  std::printf("design:      %s\n", designed.BriefReport().c_str());

  PatchMeshJobOptions patches;
  patches.fit.cells = 4;
  const PatchMeshJobResult patched = FitPatchMeshJob(cloud.points, cloud.normals, patches);
  if (!patched.success) return Fail("patch mesh", patched.message);
  std::printf("patch mesh:  %s\n", patched.BriefReport().c_str());
  return 0;
}
