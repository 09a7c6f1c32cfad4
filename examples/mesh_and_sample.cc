// Samples a noisy scan of a known sphere with the sample job, fits a sphere to it, and meshes
// the fit with the mesh job: the round trip model -> points -> model -> mesh of the library.
//   mesh_and_sample [MESH.ply]   (writes the mesh when a path is given)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

#include "implicitfit/mesh.h"
#include "implicitfit/model.h"
#include "implicitfit/primitive_fitter.h"
#include "implicitfit/sample.h"

int main(int argc, char** argv) {
  using implicitfit::NodeType;
  // Sphere parameters: center (3), radius (1).
  implicitfit::Model truth;
  truth.AddPrimitive(NodeType::kSphere, {0.5, -0.2, 1.0, 2.0});

  implicitfit::SampleJobOptions sample;
  sample.sample.count = 5000;
  sample.sample.noise = 0.01;  // sigma along the normal
  sample.sample.outlier_fraction = 0.05;
  sample.sample.seed = 7;
  std::string error;
  if (!sample.IsValid(&error)) {
    std::fprintf(stderr, "sample options: %s\n", error.c_str());
    return 2;
  }
  const implicitfit::SampleJobResult scan = implicitfit::SampleModelJob(truth, sample);
  if (!scan.success) {
    std::fprintf(stderr, "sample: %s\n", scan.message.c_str());
    return 1;
  }
  std::printf("sample: %s\n", scan.BriefReport().c_str());

  implicitfit::PrimitiveFitOptions fit_options;
  fit_options.kind = NodeType::kSphere;
  const implicitfit::PrimitiveFitResult fit =
      implicitfit::FitPrimitive(scan.sampled.cloud.points, scan.sampled.cloud.normals, fit_options);
  if (!fit.success) {
    std::fprintf(stderr, "fit: %s\n", fit.message.c_str());
    return 1;
  }
  const std::vector<double>& p = fit.parameters;
  std::printf("fit:    center %.4f %.4f %.4f  radius %.4f  (truth 0.5 -0.2 1 and 2)\n", p[0], p[1],
              p[2], p[3]);

  implicitfit::MeshJobOptions mesh_options;
  mesh_options.mesh.cell = 0.05;
  const implicitfit::MeshJobResult mesh =
      implicitfit::MeshModelJob(fit.ToModel(NodeType::kSphere), mesh_options);
  if (!mesh.success) {
    std::fprintf(stderr, "mesh: %s\n", mesh.message.c_str());
    return 1;
  }
  std::printf("mesh:   %s\n", mesh.BriefReport().c_str());
  // Every vertex is on the fitted sphere, so within the fit's error of the true one.
  double worst = 0;
  const Eigen::Vector3d c(0.5, -0.2, 1.0);
  for (const Eigen::Vector3d& v : mesh.result.mesh.vertices)
    worst = std::max(worst, std::abs((v - c).norm() - 2.0));
  std::printf("largest distance of a vertex to the true sphere: %.2g\n", worst);
  if (argc > 1) {
    try {
      implicitfit::WriteMeshPlyFile(mesh.result.mesh, argv[1]);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s\n", e.what());
      return 2;
    }
    std::printf("wrote %s\n", argv[1]);
  }
  return 0;
}
