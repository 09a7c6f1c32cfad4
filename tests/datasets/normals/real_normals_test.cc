// Normals on real scans (PLY/PCD, so built with PCL): estimated normals face the scanner,
// random signs on oriented scans are re-oriented like the file. Skips when the shared data
// folder is absent.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>

#include "datasets/clouds/cloud_file.h"
#include "datasets/normals/normal_estimation.h"
#include "datasets/normals/normal_orientation.h"

namespace implicitfit {
namespace {

void RandomiseSigns(PointCloud* c, unsigned seed) {
  std::mt19937 rng(seed);
  for (Eigen::Vector3d& n : c->normals)
    if (rng() & 1) n = -n;
}

double AgreeingSigns(const std::vector<Eigen::Vector3d>& normals,
                     const std::vector<Eigen::Vector3d>& truth) {
  size_t ok = 0;
  for (size_t i = 0; i < truth.size(); ++i) ok += normals[i].dot(truth[i]) > 0;
  return static_cast<double>(ok) / static_cast<double>(truth.size());
}

const std::string kData = IMPLICITFIT_SHARED_DATA;

bool Have(const std::string& path) {
  struct stat st;
  return ::stat(path.c_str(), &st) == 0;
}

class RealScanViewpoint : public ::testing::TestWithParam<const char*> {};

TEST_P(RealScanViewpoint, EstimatedNormalsFaceTheScannerAndAgreeLocally) {
  const std::string path = kData + "/" + GetParam();
  if (!Have(path)) GTEST_SKIP() << path << " is absent";
  const auto start = std::chrono::steady_clock::now();
  CloudFileInfo info;
  PointCloud cloud = ReadCloudFile(path, &info);
  const double read_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(info.viewpoint.has_value());
  NormalOptions options;
  options.viewpoint = info.viewpoint;
  const NormalResult r = EnsureOrientedNormals(&cloud, options);
  const double total_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.action, "estimated, oriented toward viewpoint");
  size_t facing = 0;
  for (size_t i = 0; i < cloud.size(); ++i)
    facing += cloud.normals[i].dot(*info.viewpoint - cloud.points[i]) >= 0;
  EXPECT_EQ(facing, cloud.size());
  // Independent of how they were oriented: neighbouring normals rarely oppose each other.
  const double opposed =
      OpposedNeighbourFraction(cloud.normals, FindNeighbourhoods(cloud.points).indices);
  EXPECT_LT(opposed, 0.05);
  std::printf("%s: %zu points, read %.2f s, with normals %.2f s, mean k %.1f, opposed pairs %.4f\n",
              GetParam(), cloud.size(), read_seconds, total_seconds, r.mean_neighbours, opposed);
}

class RealOrientedScan : public ::testing::TestWithParam<const char*> {};

TEST_P(RealOrientedScan, RandomSignsAreReorientedLikeTheFile) {
  const std::string path = kData + "/" + GetParam();
  if (!Have(path)) GTEST_SKIP() << path << " is absent";
  const PointCloud truth = ReadCloudFile(path);  // README: outward/oriented normals
  PointCloud cloud = truth;
  RandomiseSigns(&cloud, 21);
  const NormalResult r = EnsureOrientedNormals(&cloud);
  EXPECT_EQ(r.action, "read from file, MST-re-oriented");
  const double agree = AgreeingSigns(cloud.normals, truth.normals);
  EXPECT_GT(agree, 0.99);
  std::printf("%s: %.2f%% of random-sign normals re-oriented as in the file\n", GetParam(),
              100 * agree);
}

INSTANTIATE_TEST_SUITE_P(SharedData, RealOrientedScan,
                         // Not cgal_spheres_10.ply: two of its spheres interpenetrate and one of
                         // them comes out inverted (a known limit, normal_orientation.h).
                         ::testing::Values("cgal/cgal_kitten.xyz", "cgal/cgal_oni.pwn",
                                           "cgal/cgal_ball_icosahedron_20planes_labeled.ply",
                                           "cgal/cgal_point_set_3_box_on_ground.xyz"));

INSTANTIATE_TEST_SUITE_P(SharedData, RealScanViewpoint,
                         ::testing::Values("pcl/pcl_table_scene_mug_stereo_textured.pcd",
                                           "pcl/pcl_milk_carton_kinect.pcd"));

}  // namespace
}  // namespace implicitfit
