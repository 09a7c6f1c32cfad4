#include "datasets/clouds/xyz_reader.h"

#include <gtest/gtest.h>

#include "datasets/io/io_error.h"

namespace implicitfit {
namespace {

TEST(XyzReader, ReadsThreeAndSixColumnsWithCommentsAndCommas) {
  const PointCloud a = ParseXyzText("# header\n1 2 3\n\n4,5,6\n  7\t8 9\r\n", "a.xyz");
  ASSERT_EQ(a.size(), 3u);
  EXPECT_FALSE(a.has_normals());
  EXPECT_EQ(a.points[1], Eigen::Vector3d(4, 5, 6));
  EXPECT_EQ(a.points[2], Eigen::Vector3d(7, 8, 9));
  const PointCloud b = ParseXyzText("0 0 0 0 0 2\n1 1 1 3 0 4", "b.xyz");
  ASSERT_TRUE(b.has_normals());
  EXPECT_TRUE(b.normals[0].isApprox(Eigen::Vector3d(0, 0, 1)));
  EXPECT_TRUE(b.normals[1].isApprox(Eigen::Vector3d(0.6, 0, 0.8)));
}

void ExpectRefused(const std::string& text, const std::string& message) {
  try {
    ParseXyzText(text, "c.xyz");
    ADD_FAILURE() << "accepted: " << text;
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(message, 0), 0u) << e.what();
  }
}

TEST(XyzReader, RefusesHostileTextWithTheLineNumber) {
  ExpectRefused("", "c.xyz: no points");
  ExpectRefused("# only a comment\n\n", "c.xyz: no points");
  ExpectRefused("1 2 3\n1 2\n", "c.xyz:2: expected 3 or 6 numbers");
  ExpectRefused("1 2 3\n1 2 3 4 5 6\n", "c.xyz:2: found 6 numbers where earlier lines have 3");
  ExpectRefused("1 2 3 4 5 6 7 8\n", "c.xyz:1: expected 3 or 6 numbers, found more");
  ExpectRefused("1 2 x\n", "c.xyz:1: 'x' is not a number");
  ExpectRefused("1 2 3\n4 nan 6\n", "c.xyz:2: NaN or infinite coordinate");
  ExpectRefused("1 2 inf\n", "c.xyz:1: NaN or infinite coordinate");
  const char binary[] = "1 2 3\n\x01\x02\xff garbage\n\0 after a NUL\n";
  ExpectRefused(std::string(binary, sizeof binary - 1), "c.xyz:2:");
}

TEST(XyzReader, ListsUnusableNormalsInsteadOfRefusingThem) {
  CloudFileInfo info;
  const PointCloud c =
      ParseXyzText("1 2 3 0 0 1\n1 2 4 0 0 0\n1 2 5 nan nan nan\n1 2 6 0 inf 0\n", "d.xyz", &info);
  ASSERT_EQ(c.size(), 4u);
  EXPECT_EQ(info.invalid_normals, (std::vector<size_t>{1, 2, 3}));
  EXPECT_EQ(c.normals[0], Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(c.normals[2], Eigen::Vector3d::Zero());
  EXPECT_TRUE(info.normals_in_file);
  EXPECT_EQ(info.format, "xyz");
}

TEST(XyzReader, LabelledCloudsKeepTheirIntegerLabels) {
  CloudFileInfo info;
  const PointCloud c = ParseXyzText("1 2 3 4\n5 6 7 -1\n", "e.xyzl", &info, XyzColumns::kLabelled);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c.points[1], Eigen::Vector3d(5, 6, 7));
  EXPECT_FALSE(c.has_normals());
  EXPECT_EQ(info.labels, (std::vector<int>{4, -1}));
  EXPECT_EQ(info.format, "xyzl");
  EXPECT_THROW(ParseXyzText("1 2 3\n", "e.xyzl", &info, XyzColumns::kLabelled), InputError);
  EXPECT_THROW(ParseXyzText("1 2 3 0.5\n", "e.xyzl", &info, XyzColumns::kLabelled), InputError);
  EXPECT_THROW(ParseXyzText("1 2 3 4\n", "e.xyz"), InputError);
}

}  // namespace
}  // namespace implicitfit
