// Primitive fits on the real scans of ../shared/data (skipped when the folder is absent):
//   - CGAL spheres.ply: each of the 10 spheres, its points selected with the reference sphere
//     (reference_spheres.txt, an algebraic fit by the data's curators, not by this project);
//   - PCL cturtle: a partial spherical cap without normals (normals estimated), r = 2 at 0;
//   - Fit4CAD: every labelled plane, sphere, cylinder and cone of the eight parts, compared
//     with the benchmark's own implicit equations (NAME_implicit.txt): the fitted surface, at
//     the projections of the primitive's points onto it, must lie on the ground-truth surface.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

#include "datasets/clouds/cloud_file.h"
#include "datasets/clouds/cloud_file_info.h"
#include "datasets/normals/normal_estimation.h"
#include "datasets/normals/oriented_cloud.h"
#include "fit/primitive/primitive_fitter.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;
const std::string kData = IMPLICITFIT_SHARED_DATA;

bool Exists(const std::string& path) { return static_cast<bool>(std::ifstream(path)); }

TEST(RealScans, CgalSpheresMatchTheReferenceSpheres) {
  const std::string cloud_path = kData + "/cgal/cgal_spheres_10.ply",
                    ref_path = kData + "/cgal/reference_spheres.txt";
  if (!Exists(cloud_path) || !Exists(ref_path)) GTEST_SKIP() << "shared data absent";
  const PointCloud cloud = ReadCloudFile(cloud_path);
  ASSERT_TRUE(cloud.has_normals());
  std::ifstream ref(ref_path);
  std::string line;
  int spheres = 0;
  while (std::getline(ref, line)) {
    if (line.empty() || line[0] == '#' || line.find("cgal_spheres_10.ply") == std::string::npos)
      continue;
    std::istringstream in(line);
    std::string file;
    Vec c;
    double r;
    in >> file >> c.x() >> c.y() >> c.z() >> r;
    std::vector<Vec> pts, nrm;
    for (size_t i = 0; i < cloud.size(); ++i)
      if (std::abs((cloud.points[i] - c).norm() - r) < 1e-4) {
        pts.push_back(cloud.points[i]);
        nrm.push_back(cloud.normals[i]);
      }
    ASSERT_GE(pts.size(), 100u);
    PrimitiveFitOptions o;
    o.kind = NodeType::kSphere;
    const PrimitiveFitResult f = FitPrimitive(pts, nrm, o);
    ASSERT_TRUE(f.success) << f.message;
    // The reference is printed with 6 decimals: agreement to 1e-5 is all it can show.
    EXPECT_LT((Vec(f.parameters[0], f.parameters[1], f.parameters[2]) - c).norm(), 1e-5) << line;
    EXPECT_NEAR(f.parameters[3], r, 1e-5) << line;
    ++spheres;
  }
  EXPECT_EQ(spheres, 10);
}

TEST(RealScans, CturtleCapWithEstimatedNormalsIsTheRadius2Sphere) {
  const std::string path = kData + "/pcl/pcl_cturtle_sphere_cap_r2.pcd";
  if (!Exists(path)) GTEST_SKIP() << "shared data absent";
  std::string normals;
  const PointCloud cloud = ReadOrientedCloud(path, &normals);
  EXPECT_NE(normals.find("estimated"), std::string::npos) << normals;
  PrimitiveFitOptions o;
  o.kind = NodeType::kSphere;
  const PrimitiveFitResult f = FitPrimitive(cloud.points, cloud.normals, o);
  ASSERT_TRUE(f.success) << f.message;
  EXPECT_LT(Vec(f.parameters[0], f.parameters[1], f.parameters[2]).norm(), 1e-4);
  EXPECT_NEAR(f.parameters[3], 2.0, 1e-4);
  EXPECT_GT(f.inliers.size(), 0.99 * cloud.size());
}

struct GroundTruth {
  std::string type;
  std::vector<double> coefficients;
};

// "Primitive3 :=[Plane, [a b c d]];" -> {3: {"Plane", {...}}}.
std::map<int, GroundTruth> ReadImplicit(const std::string& path) {
  std::map<int, GroundTruth> out;
  std::ifstream in(path);
  std::string line;
  const std::regex pattern(R"(Primitive(\d+)\s*:=\s*\[(\w+),\s*\[([^\]]*)\]\];)");
  while (std::getline(in, line)) {
    std::smatch m;
    if (!std::regex_search(line, m, pattern)) continue;
    GroundTruth g{m[2], {}};
    std::istringstream values(m[3]);
    double v;
    while (values >> v) g.coefficients.push_back(v);
    out[std::stoi(m[1])] = g;
  }
  return out;
}

// First-order distance to the ground-truth surface (Fit4CAD quadric or plane).
double GroundTruthDistance(const GroundTruth& g, const Vec& x) {
  const auto& q = g.coefficients;
  if (g.type == "Plane")
    return (q[0] * x.x() + q[1] * x.y() + q[2] * x.z() + q[3]) / Vec(q[0], q[1], q[2]).norm();
  Eigen::Matrix3d A;
  A << q[0], q[3], q[4], q[3], q[1], q[5], q[4], q[5], q[2];
  const Vec b(q[6], q[7], q[8]);
  const double value = x.dot(A * x) + 2 * b.dot(x) + q[9];
  return value / (2 * (A * x + b).norm());
}

TEST(RealScans, Fit4CadPrimitivesLieOnTheGroundTruthSurfaces) {
  const std::vector<std::string> parts = {"test_PC33",   "test_PC34",   "test_PC35",
                                          "test_PC21",   "train_PC124", "train_PC131",
                                          "train_PC145", "train_PC155"};
  int checked = 0;
  for (const std::string& part : parts) {
    const std::string cloud_path = kData + "/fit4cad/fit4cad_" + part + ".xyzl";
    const std::string truth_path =
        kData + "/fit4cad/fit4cad_" + part + "/" + part + "_implicit.txt";
    if (!Exists(cloud_path) || !Exists(truth_path)) GTEST_SKIP() << "shared data absent";
    CloudFileInfo info;
    PointCloud cloud = ReadCloudFile(cloud_path, &info);
    ASSERT_EQ(info.labels.size(), cloud.size());
    EnsureOrientedNormals(&cloud);
    Vec lo = cloud.points[0], hi = lo;
    for (const Vec& p : cloud.points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    const double diagonal = (hi - lo).norm();
    for (const auto& [label, truth] : ReadImplicit(truth_path)) {
      NodeType kind;
      if (truth.type == "Plane")
        kind = NodeType::kPlane;
      else if (truth.type == "Sphere")
        kind = NodeType::kSphere;
      else if (truth.type == "Cylinder")
        kind = NodeType::kCylinder;
      else if (truth.type == "Cone")
        kind = NodeType::kCone;
      else
        continue;  // tori: 35 quartic coefficients in an unchecked order
      std::vector<Vec> pts, nrm;
      for (size_t i = 0; i < cloud.size(); ++i)
        if (info.labels[i] == label)
          pts.push_back(cloud.points[i]), nrm.push_back(cloud.normals[i]);
      if (pts.size() < 50) continue;
      PrimitiveFitOptions o;
      o.kind = kind;
      o.compute_covariance = false;
      const PrimitiveFitResult f = FitPrimitive(pts, nrm, o);
      ASSERT_TRUE(f.success) << part << " primitive " << label << " (" << truth.type
                             << "): " << f.message;
      Model m;
      m.AddPrimitive(kind, f.parameters);
      double ss = 0, ss_fit = 0;
      for (const Vec& p : pts) {
        double v;
        const Vec g = m.Gradient(p, &v);
        ss_fit += v * v;
        const Vec on_fit = p - v * g / g.squaredNorm();
        const double d = GroundTruthDistance(truth, on_fit);
        ss += d * d;
      }
      const double rms = std::sqrt(ss / pts.size());
      EXPECT_LT(rms, 1e-4 * diagonal)
          << part << " primitive " << label << " (" << truth.type << ", " << pts.size()
          << " points): fitted surface is " << rms << " from the ground truth";
      // Noise-free CAD samples: every labelled point is on the fitted surface, including those
      // the fitter left out as inliers because their estimated normals at the primitive's
      // border mix in the neighbouring surface.
      EXPECT_LT(std::sqrt(ss_fit / pts.size()), 1e-4 * diagonal) << part << " primitive " << label;
      ++checked;
    }
  }
  EXPECT_GT(checked, 40);
  std::printf("  Fit4CAD primitives checked: %d\n", checked);
}

}  // namespace
}  // namespace implicitfit
