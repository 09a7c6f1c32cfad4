// PLY writer: the bytes are checked by hand (header, record size, little-endian values), then
// the file is read back through the PLY reader.
#include "datasets/clouds/ply_writer.h"

#include <gtest/gtest.h>

#include <filesystem>

#include <cstdint>
#include <cstring>
#include <random>

#include "datasets/clouds/cloud_file.h"
#include "datasets/generators/ground_truth.h"
#include "datasets/io/io_error.h"
#include "support/run_command.h"

namespace implicitfit {
namespace {

PointCloud RandomCloud(int n, bool normals) {
  std::mt19937 rng(4);
  std::normal_distribution<double> g(0, 1);
  PointCloud c;
  for (int i = 0; i < n; ++i) {
    c.points.emplace_back(1e6 + g(rng), g(rng), g(rng) / 3);  // far-off x: precision matters
    if (normals) c.normals.push_back(Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized());
  }
  return c;
}

TEST(PlyWriter, BinaryIsLittleEndianDoubleWithNormalsAndResidual) {
  const std::string dir = testsupport::ScratchDir("ply_writer");
  const PointCloud cloud = RandomCloud(30, true);
  std::vector<double> residual(cloud.size());
  for (size_t i = 0; i < residual.size(); ++i) residual[i] = 0.001 * static_cast<double>(i) - 0.01;
  WritePlyFile(cloud, dir + "/out.ply", residual);
  const std::string bytes = testsupport::Slurp(dir + "/out.ply");
  const std::string header =
      "ply\nformat binary_little_endian 1.0\ncomment written by implicitfit\nelement vertex 30\n"
      "property double x\nproperty double y\nproperty double z\nproperty double nx\nproperty "
      "double ny\n"
      "property double nz\nproperty double residual\nend_header\n";
  ASSERT_EQ(bytes.substr(0, header.size()), header);
  ASSERT_EQ(bytes.size(), header.size() + 30 * 7 * 8);
  // Point 5's y and residual, decoded here (the test machine is little endian, as is x86).
  double y, r;
  std::memcpy(&y, bytes.data() + header.size() + (5 * 7 + 1) * 8, 8);
  std::memcpy(&r, bytes.data() + header.size() + (5 * 7 + 6) * 8, 8);
  EXPECT_EQ(y, cloud.points[5].y());
  EXPECT_EQ(r, residual[5]);

  CloudFileInfo info;
  const PointCloud back = ReadCloudFile(dir + "/out.ply", &info);
  EXPECT_EQ(back.points, cloud.points);  // exact: double in, double out
  ASSERT_TRUE(back.has_normals());
  for (size_t i = 0; i < cloud.size(); ++i)
    EXPECT_LT((back.normals[i] - cloud.normals[i]).norm(), 1e-15);
  EXPECT_EQ(info.ignored_properties, std::vector<std::string>{"residual"});
  for (const auto& e : std::filesystem::directory_iterator(dir))  // no temporary left
    EXPECT_EQ(e.path().filename().string().find(".implicitfit-"), std::string::npos) << e.path();
}

TEST(PlyWriter, AsciiAndFloatRoundTrip) {
  const std::string dir = testsupport::ScratchDir("ply_writer_ascii");
  const PointCloud cloud = RandomCloud(20, false);
  WritePlyFile(cloud, dir + "/a.ply", {}, PlyWriteOptions{true, false});
  const std::string text = testsupport::Slurp(dir + "/a.ply");
  EXPECT_NE(text.find("format ascii 1.0\n"), std::string::npos);
  EXPECT_EQ(text.find("nx"), std::string::npos);
  EXPECT_EQ(ReadCloudFile(dir + "/a.ply").points, cloud.points);  // %.17g is exact
  WritePlyFile(cloud, dir + "/f.ply", {}, PlyWriteOptions{false, true});
  const PointCloud f = ReadCloudFile(dir + "/f.ply");
  ASSERT_EQ(f.size(), cloud.size());
  for (size_t i = 0; i < f.size(); ++i)
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(f.points[i][k], static_cast<double>(static_cast<float>(cloud.points[i][k])));
}

TEST(PlyWriter, LabelsAreAnIntPropertyBeforeTheResidual) {
  const std::string dir = testsupport::ScratchDir("ply_writer_labels");
  const PointCloud cloud = RandomCloud(12, true);
  PlyWriteOptions o;
  o.ascii = true;
  for (int i = 0; i < 12; ++i) o.labels.push_back(i % 3 - 1);
  const std::vector<double> residual(12, 0.25);
  WritePlyFile(cloud, dir + "/l.ply", residual, o);
  // The label column read by the ground-truth reader, and the points by the cloud reader.
  EXPECT_EQ(ReadPlyIntProperty(dir + "/l.ply", "label"), o.labels);
  CloudFileInfo info;
  EXPECT_EQ(ReadCloudFile(dir + "/l.ply", &info).points, cloud.points);
  EXPECT_EQ(info.ignored_properties, (std::vector<std::string>{"label", "residual"}));
  // Binary, no residual: the label is the last 4 bytes of each record (6 doubles before it).
  o.ascii = false;
  WritePlyFile(cloud, dir + "/b.ply", {}, o);
  const std::string bytes = testsupport::Slurp(dir + "/b.ply");
  const size_t body = bytes.find("end_header\n") + 11;
  ASSERT_EQ(bytes.size(), body + 12 * (6 * 8 + 4));
  std::int32_t label;
  std::memcpy(&label, bytes.data() + body + 7 * (6 * 8 + 4) + 6 * 8, 4);
  EXPECT_EQ(label, o.labels[7]);
  EXPECT_EQ(ReadCloudFile(dir + "/b.ply").points, cloud.points);
  o.labels.pop_back();
  EXPECT_THROW(WritePlyFile(cloud, dir + "/c.ply", {}, o), std::invalid_argument);
  EXPECT_FALSE(testsupport::FileExists(dir + "/c.ply"));
}

TEST(PlyWriter, FailuresLeaveNoFile) {
  const std::string dir = testsupport::ScratchDir("ply_writer_fail");
  const PointCloud cloud = RandomCloud(3, false);
  EXPECT_THROW(WritePlyFile(cloud, dir + "/x.ply", {1.0, 2.0}), std::invalid_argument);
  PointCloud bad = cloud;
  bad.points[1].z() = std::nan("");
  EXPECT_THROW(WritePlyFile(bad, dir + "/x.ply"), std::invalid_argument);
  EXPECT_FALSE(testsupport::FileExists(dir + "/x.ply"));
  try {
    WritePlyFile(cloud, dir + "/no/such/dir/x.ply");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(dir + "/no/such/dir/x.ply: cannot write", 0), 0u)
        << e.what();
  }
}

}  // namespace
}  // namespace implicitfit
