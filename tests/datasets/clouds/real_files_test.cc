// Every real scan in ../shared/data is read with the point count and normals its README table
// states (the expectations below are copied from that table, not from this code). Skips when
// the shared folder is absent.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "datasets/clouds/cloud_file.h"
#include "datasets/clouds/pcd_reader.h"
#include "datasets/clouds/xyz_reader.h"

namespace implicitfit {
namespace {

const std::string kData = IMPLICITFIT_SHARED_DATA;

bool HaveSharedData() {
  struct stat st;
  return ::stat(kData.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

#define REQUIRE_SHARED_DATA()                                     \
  do {                                                            \
    if (!HaveSharedData()) GTEST_SKIP() << kData << " is absent"; \
  } while (0)

struct RealFile {
  const char* path;  // relative to the shared data folder
  size_t points;     // README table (finite points)
  bool normals;      // README: outward/oriented/estimated normals present
};

class RealFiles : public ::testing::TestWithParam<RealFile> {};

TEST_P(RealFiles, ReadWithTheDocumentedCountAndNormals) {
  REQUIRE_SHARED_DATA();
  const RealFile& f = GetParam();
  CloudFileInfo info;
  const PointCloud cloud = ReadCloudFile(kData + "/" + f.path, &info);
  EXPECT_EQ(cloud.size(), f.points);
  EXPECT_EQ(cloud.has_normals(), f.normals);
  for (size_t i = 0; i < cloud.size(); ++i) {
    ASSERT_TRUE(cloud.points[i].allFinite()) << i;
    if (f.normals) {
      ASSERT_NEAR(cloud.normals[i].norm(), 1.0, 1e-6) << i;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    SharedData, RealFiles,
    ::testing::Values(RealFile{"cgal/cgal_ball_icosahedron_20planes_labeled.ply", 31374, true},
                      RealFile{"cgal/cgal_spheres_10.ply", 5969, true},
                      RealFile{"cgal/cgal_fin90_two_planes_crease.xyz", 757, true},
                      RealFile{"cgal/cgal_point_set_3_box_on_ground.xyz", 8075, true},
                      RealFile{"cgal/cgal_kitten.xyz", 5210, true},
                      RealFile{"cgal/cgal_oni.pwn", 1435, true},
                      RealFile{"pcl/pcl_table_scene_mug_stereo_textured.pcd", 209280, false},
                      RealFile{"pcl/pcl_table_scene_mug_stereo_textured_finite.ply", 209280, false},
                      RealFile{"pcl/pcl_milk_carton_kinect.pcd", 13704, false},
                      RealFile{"pcl/pcl_milk_carton_kinect.xyz", 13704, false},
                      RealFile{"pcl/pcl_cturtle_sphere_cap_r2.pcd", 167198, false},
                      RealFile{"pcl/pcl_cturtle_sphere_cap_r2.ply", 167198, false},
                      RealFile{"pcl/pcl_sac_plane_test.pcd", 3283, true},
                      RealFile{"pcl/pcl_sac_plane_test.xyz", 3283, true},
                      RealFile{"pcl/pcl_bun0_bunny397.pcd", 397, true},
                      RealFile{"pcl/pcl_bun0_bunny397.xyz", 397, true},
                      RealFile{"stanford/stanford_bunny_bun000_rangescan.ply", 40256, false}),
    [](const ::testing::TestParamInfo<RealFile>& p) {
      std::string name = p.param.path;
      for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      return name;
    });

struct Fit4Cad {
  const char* name;  // folder fit4cad_<name>, files <name>.txt and <name>_primitives.txt
  size_t points;     // README table
};

class Fit4CadFiles : public ::testing::TestWithParam<Fit4Cad> {};

// The labelled copy fit4cad_<name>.xyzl: the README's point count, and each point's label is
// one of the primitives whose list in <name>_primitives.txt (1-based indices) holds the point
// (points on an intersection curve are listed under both primitives).
TEST_P(Fit4CadFiles, LabelledCopyHasTheCountAndThePrimitiveLabels) {
  REQUIRE_SHARED_DATA();
  const Fit4Cad& f = GetParam();
  CloudFileInfo info;
  const std::string base = kData + "/fit4cad/fit4cad_" + f.name;
  const PointCloud cloud = ReadCloudFile(base + ".xyzl", &info);
  EXPECT_EQ(cloud.size(), f.points);
  ASSERT_EQ(info.labels.size(), cloud.size());
  std::ifstream in(base + "/" + f.name + "_primitives.txt");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::vector<int>> listed_under(cloud.size());
  size_t pos = 0;
  while ((pos = text.find("Primitive", pos)) != std::string::npos) {
    const int label = std::stoi(text.substr(pos + 9));
    const size_t open = text.find('[', pos), close = text.find(']', pos);
    std::istringstream numbers(text.substr(open + 1, close - open - 1));
    for (size_t index; numbers >> index;) {
      ASSERT_GE(index, 1u);
      ASSERT_LE(index, cloud.size());
      listed_under[index - 1].push_back(label);
    }
    pos = close;
  }
  for (size_t i = 0; i < cloud.size(); ++i) {
    const std::vector<int>& l = listed_under[i];
    ASSERT_NE(std::find(l.begin(), l.end(), info.labels[i]), l.end()) << "point " << i + 1;
  }
}

INSTANTIATE_TEST_SUITE_P(
    SharedData, Fit4CadFiles,
    ::testing::Values(Fit4Cad{"test_PC33", 1500}, Fit4Cad{"test_PC34", 12089},
                      Fit4Cad{"test_PC35", 24068}, Fit4Cad{"test_PC21", 1000},
                      Fit4Cad{"train_PC124", 17945}, Fit4Cad{"train_PC131", 15930},
                      Fit4Cad{"train_PC145", 1500}, Fit4Cad{"train_PC155", 20185}),
    [](const ::testing::TestParamInfo<Fit4Cad>& p) { return std::string(p.param.name); });

TEST(RealFiles, OrganizedStereoScanDropsItsNanCellsAndKeepsTheViewpoint) {
  REQUIRE_SHARED_DATA();
  CloudFileInfo info;
  const PointCloud cloud =
      ReadCloudFile(kData + "/pcl/pcl_table_scene_mug_stereo_textured.pcd", &info);
  EXPECT_EQ(info.format, "pcd binary_compressed");
  EXPECT_EQ(info.records, 640u * 480u);
  EXPECT_EQ(info.dropped_missing, 640u * 480u - 209280u);
  EXPECT_EQ(info.grid_width, 640u);
  EXPECT_EQ(info.grid_height, 480u);
  ASSERT_TRUE(info.viewpoint.has_value());
  EXPECT_EQ(*info.viewpoint, Eigen::Vector3d::Zero());
  EXPECT_EQ(info.ignored_properties, std::vector<std::string>{"rgba"});
}

TEST(RealFiles, StanfordRangeGridGivesItsVerticesOnly) {
  REQUIRE_SHARED_DATA();
  CloudFileInfo info;
  const PointCloud cloud =
      ReadCloudFile(kData + "/stanford/stanford_bunny_bun000_rangescan.ply", &info);
  EXPECT_EQ(cloud.size(), 40256u);
  EXPECT_EQ(info.grid_width, 512u);
  EXPECT_EQ(info.grid_height, 400u);
  EXPECT_EQ(info.dropped_missing, 512u * 400u - 40256u);
}

TEST(RealFiles, CompressedPcdAndItsLosslessCopiesAgree) {
  REQUIRE_SHARED_DATA();
  // The README states the .xyz/.ply copies are lossless conversions of the kept fields.
  const PointCloud pcd = ReadCloudFile(kData + "/pcl/pcl_milk_carton_kinect.pcd");
  const PointCloud xyz = ReadCloudFile(kData + "/pcl/pcl_milk_carton_kinect.xyz");
  ASSERT_EQ(pcd.size(), xyz.size());
  for (size_t i = 0; i < pcd.size(); ++i)
    ASSERT_LT((pcd.points[i] - xyz.points[i]).norm(), 1e-6) << i;
  const PointCloud cap_pcd = ReadCloudFile(kData + "/pcl/pcl_cturtle_sphere_cap_r2.pcd");
  const PointCloud cap_ply = ReadCloudFile(kData + "/pcl/pcl_cturtle_sphere_cap_r2.ply");
  ASSERT_EQ(cap_pcd.size(), cap_ply.size());
  for (size_t i = 0; i < cap_pcd.size(); ++i) ASSERT_EQ(cap_pcd.points[i], cap_ply.points[i]) << i;
  // Ground truth of the README: the cap lies on the sphere of centre 0 and radius 2.
  for (size_t i = 0; i < cap_pcd.size(); i += 97) EXPECT_NEAR(cap_pcd.points[i].norm(), 2.0, 1e-5);
}

TEST(RealFiles, InvalidNormalsAreListedByTheFormatReaders) {
  REQUIRE_SHARED_DATA();
  // pcl_sac_plane_test has points whose normal is "nan nan nan": count them independently.
  const std::string xyz_path = kData + "/pcl/pcl_sac_plane_test.xyz";
  std::ifstream in(xyz_path);
  size_t nan_lines = 0;
  for (std::string line; std::getline(in, line);)
    nan_lines += line.find("nan") != std::string::npos;
  ASSERT_GT(nan_lines, 0u);
  CloudFileInfo xyz_info, pcd_info;
  ReadXyzFile(xyz_path, &xyz_info);
  ReadPcdFile(kData + "/pcl/pcl_sac_plane_test.pcd", &pcd_info);
  EXPECT_EQ(xyz_info.invalid_normals.size(), nan_lines);
  EXPECT_EQ(pcd_info.invalid_normals, xyz_info.invalid_normals);
}

TEST(RealFiles, PlyReadsExtraPropertiesAsIgnoredAndNormalsAsUnit) {
  REQUIRE_SHARED_DATA();
  CloudFileInfo info;
  const PointCloud cloud =
      ReadCloudFile(kData + "/cgal/cgal_ball_icosahedron_20planes_labeled.ply", &info);
  EXPECT_EQ(info.format, "ply ascii");
  EXPECT_TRUE(info.normals_in_file);
  EXPECT_EQ(info.ignored_properties, std::vector<std::string>{"segment_index"});
  // First vertex line of the file, read here as text.
  std::ifstream in(kData + "/cgal/cgal_ball_icosahedron_20planes_labeled.ply");
  std::string line;
  while (std::getline(in, line) && line.rfind("end_header", 0) != 0) {
  }
  double x, y, z;
  in >> x >> y >> z;
  // Stored as float: equal up to float rounding (relative 2^-24).
  EXPECT_NEAR(cloud.points[0].x(), x, 1e-7 * std::abs(x) + 1e-9);
  EXPECT_NEAR(cloud.points[0].y(), y, 1e-7 * std::abs(y) + 1e-9);
  EXPECT_NEAR(cloud.points[0].z(), z, 1e-7 * std::abs(z) + 1e-9);
}

}  // namespace
}  // namespace implicitfit
