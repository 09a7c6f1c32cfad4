// Fits a sphere to a point cloud file and prints it with its standard deviations.
//   fit_sphere CLOUD   (.xyz/.pwn/.txt, .ply, .pcd; normals estimated when the file has none)
#include <cstdio>
#include <exception>

#include "implicitfit/implicitfit.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s CLOUD\n", argv[0]);
    return 2;
  }
  implicitfit::PointCloud cloud;
  try {
    cloud = implicitfit::ReadCloudFile(argv[1]);
  } catch (const implicitfit::InputError& e) {  // names the file (and the line)
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  const implicitfit::NormalResult normals = implicitfit::EnsureOrientedNormals(&cloud);

  implicitfit::PrimitiveFitOptions options;
  options.kind = implicitfit::NodeType::kSphere;
  const implicitfit::PrimitiveFitResult fit =
      implicitfit::FitPrimitive(cloud.points, cloud.normals, options);
  if (!fit.success) {
    std::fprintf(stderr, "no sphere: %s\n", fit.message.c_str());
    return 1;
  }
  // Sphere parameters: center (3), radius (1); standard deviations in the same layout.
  const std::vector<double>& p = fit.parameters;
  const std::vector<double>& s = fit.standard_deviations;
  std::printf("normals: %s\n", normals.action.c_str());
  std::printf("center  %.6f %.6f %.6f  (+- %.2g %.2g %.2g)\n", p[0], p[1], p[2], s[0], s[1], s[2]);
  std::printf("radius  %.6f  (+- %.2g)\n", p[3], s[3]);
  std::printf("inliers %zu of %zu, RMS distance %.3g, max %.3g\n", fit.inliers.size(), cloud.size(),
              fit.rms, fit.max_abs);
  return 0;
}
