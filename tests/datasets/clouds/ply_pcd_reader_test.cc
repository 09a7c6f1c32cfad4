// PLY and PCD readers on files written here byte by byte (independently of the code under
// test): every encoding and type, extra properties, and hostile input.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "datasets/clouds/cloud_file.h"
#include "datasets/io/io_error.h"
#include "support/run_command.h"

namespace implicitfit {
namespace {

template <typename T>
void Append(std::string* out, T v, bool big_endian) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof v);
  if (big_endian) std::reverse(b, b + sizeof v);
  out->append(b, sizeof v);
}

// A PLY with x y z, colours (uchar red green blue) in the middle, then nx ny nz, in the given
// encoding.
template <typename T>
std::string MakePly(const std::string& format, const std::vector<Eigen::Vector3d>& p,
                    const std::vector<Eigen::Vector3d>& n) {
  const char* type = sizeof(T) == 4 ? "float" : "double";
  std::string s = "ply\nformat " + format + " 1.0\ncomment test\nelement vertex " +
                  std::to_string(p.size()) + "\n";
  for (const char* name : {"x", "y", "z"}) s += std::string("property ") + type + " " + name + "\n";
  s += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  for (const char* name : {"nx", "ny", "nz"})
    s += std::string("property ") + type + " " + name + "\n";
  s += "end_header\n";
  const bool big = format == "binary_big_endian";
  for (size_t i = 0; i < p.size(); ++i) {
    if (format == "ascii") {
      char line[256];
      std::snprintf(line, sizeof line, "%.17g %.17g %.17g 7 8 9 %.17g %.17g %.17g\n", p[i].x(),
                    p[i].y(), p[i].z(), n[i].x(), n[i].y(), n[i].z());
      s += line;
    } else {
      for (int k = 0; k < 3; ++k) Append<T>(&s, static_cast<T>(p[i][k]), big);
      for (std::uint8_t c : {7, 8, 9}) Append<std::uint8_t>(&s, c, big);
      for (int k = 0; k < 3; ++k) Append<T>(&s, static_cast<T>(n[i][k]), big);
    }
  }
  return s;
}

struct Sample {
  std::vector<Eigen::Vector3d> points, normals;
};

Sample RandomSample(int count) {
  std::mt19937 rng(7);
  std::normal_distribution<double> g(0.0, 3.0);
  Sample s;
  for (int i = 0; i < count; ++i) {
    s.points.emplace_back(g(rng), g(rng), g(rng));
    s.normals.push_back(Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized());
  }
  return s;
}

template <typename T>
void ExpectSameCloud(const PointCloud& c, const Sample& s) {
  ASSERT_EQ(c.size(), s.points.size());
  ASSERT_TRUE(c.has_normals());
  for (size_t i = 0; i < c.size(); ++i) {
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(c.points[i][k], static_cast<double>(static_cast<T>(s.points[i][k])));
    EXPECT_LT((c.normals[i] - s.normals[i]).norm(), sizeof(T) == 4 ? 1e-6 : 1e-12);
  }
}

TEST(PlyReader, ReadsEveryEncodingAndScalarType) {
  const std::string dir = testsupport::ScratchDir("ply_encodings");
  const Sample s = RandomSample(50);
  for (const std::string format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
    SCOPED_TRACE(format);
    testsupport::WriteText(dir + "/f.ply", MakePly<float>(format, s.points, s.normals));
    CloudFileInfo info;
    const PointCloud f = ReadCloudFile(dir + "/f.ply", &info);
    EXPECT_EQ(info.format, "ply " + format);
    EXPECT_EQ(info.ignored_properties, std::vector<std::string>{"rgb"});  // PCL packs the colours
    if (format == "ascii") {
      // ASCII holds the %.17g text: the values are the doubles themselves, rounded by PCL to float.
      ExpectSameCloud<float>(f, s);
    } else {
      ExpectSameCloud<float>(f, s);
      testsupport::WriteText(dir + "/d.ply", MakePly<double>(format, s.points, s.normals));
      ExpectSameCloud<double>(ReadCloudFile(dir + "/d.ply"), s);
    }
  }
}

std::string PcdHeader(const std::string& fields, const std::string& size, const std::string& type,
                      int width, int height, const std::string& data) {
  return "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS " + fields + "\nSIZE " +
         size + "\nTYPE " + type + "\nCOUNT " +
         [&] {
           std::string c;
           for (size_t i = 0; i < size.size(); i += 2) c += i ? " 1" : "1";
           return c;
         }() +
         "\nWIDTH " + std::to_string(width) + "\nHEIGHT " + std::to_string(height) +
         "\nVIEWPOINT 1 2 3 1 0 0 0\nPOINTS " + std::to_string(width * height) + "\nDATA " + data +
         "\n";
}

TEST(PcdReader, ReadsAsciiAndBinaryDroppingNanCells) {
  const std::string dir = testsupport::ScratchDir("pcd_formats");
  // An organized 2 x 2 cloud with one "no measurement" cell, and an intensity field.
  testsupport::WriteText(dir + "/a.pcd",
                         PcdHeader("x y z intensity", "4 4 4 4", "F F F F", 2, 2, "ascii") +
                             "1 2 3 9\nnan nan nan 9\n4 5 6 9\n7 8 9.5 9\n");
  CloudFileInfo info;
  const PointCloud a = ReadCloudFile(dir + "/a.pcd", &info);
  ASSERT_EQ(a.size(), 3u);
  EXPECT_EQ(a.points[2], Eigen::Vector3d(7, 8, 9.5));
  EXPECT_EQ(info.records, 4u);
  EXPECT_EQ(info.dropped_missing, 1u);
  EXPECT_EQ(info.grid_width, 2u);
  EXPECT_EQ(*info.viewpoint, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(info.ignored_properties, std::vector<std::string>{"intensity"});
  EXPECT_FALSE(a.has_normals());

  std::string b =
      PcdHeader("x y z normal_x normal_y normal_z", "8 8 8 4 4 4", "F F F F F F", 3, 1, "binary");
  const double xyz[3][3] = {{1.25, -2, 3}, {0.1, 0.2, 0.3}, {1e6, 2e6, -3e6}};
  for (const auto& p : xyz) {
    for (double v : p) Append<double>(&b, v, false);
    for (float v : {0.f, 0.f, 2.f}) Append<float>(&b, v, false);
  }
  testsupport::WriteText(dir + "/b.pcd", b);
  const PointCloud c = ReadCloudFile(dir + "/b.pcd", &info);
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(c.points[2], Eigen::Vector3d(1e6, 2e6, -3e6));
  EXPECT_EQ(c.points[1], Eigen::Vector3d(0.1, 0.2, 0.3));
  EXPECT_EQ(c.normals[0], Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(info.format, "pcd binary");
}

// Hostile input: refused with InputError whose message starts with the file name (and, for
// text, "<file>:<line>:") and contains the expected words.
void ExpectRefused(const std::string& path, const std::string& prefix, const std::string& words) {
  try {
    ReadCloudFile(path);
    ADD_FAILURE() << "accepted " << path;
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(prefix, 0), 0u) << what;
    EXPECT_NE(what.find(words), std::string::npos) << what;
  }
}

const char kPlyAsciiHeader[] =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float "
    "z\nend_header\n";

TEST(HostileInput, RefusedWithTheFileAndLine) {
  const std::string d = testsupport::ScratchDir("hostile");
  auto file = [&](const std::string& name, const std::string& content) {
    testsupport::WriteText(d + "/" + name, content);
    return d + "/" + name;
  };
  std::mt19937 rng(3);
  std::string noise(4096, '\0');
  for (char& c : noise) c = static_cast<char>(rng());
  const Sample s = RandomSample(40);
  const std::string binary = MakePly<float>("binary_little_endian", s.points, s.normals);

  for (const std::string ext : {"ply", "pcd"}) {
    ExpectRefused(file("empty." + ext, ""), d + "/empty." + ext + ":", "empty file");
    ExpectRefused(file("garbage." + ext, "hello, I am not a cloud\n1 2 3\n"),
                  d + "/garbage." + ext + ":1:", "not a");
    ExpectRefused(file("random." + ext, noise), d + "/random." + ext + ":", "");
    ExpectRefused(
        file("random_after_magic." + ext, (ext == "ply" ? "ply\n" : "VERSION 0.7\n") + noise),
        d + "/random_after_magic." + ext + ":", "");
  }
  ExpectRefused(file("trunc.ply", binary.substr(0, binary.size() - 5)),
                d + "/trunc.ply: ", "truncated");
  ExpectRefused(file("header_only.ply", binary.substr(0, binary.find("end_header\n") + 11)),
                d + "/header_only.ply: ", "truncated");
  ExpectRefused(file("header_cut.ply", binary.substr(0, binary.find("end_header"))),
                d + "/header_cut.ply: ", "end_header");
  ExpectRefused(file("extra.ply", binary + std::string(25, '\0')),
                d + "/extra.ply: ", "wrong vertex count");
  ExpectRefused(file("fewer.ply", std::string(kPlyAsciiHeader) + "1 2 3\n4 5 6\n"),
                d + "/fewer.ply:10:", "data ends after 2 of the 3");
  ExpectRefused(file("more.ply", std::string(kPlyAsciiHeader) + "1 2 3\n4 5 6\n7 8 9\n1 1 1\n"),
                d + "/more.ply:11:", "wrong vertex count");
  ExpectRefused(file("nan.ply", std::string(kPlyAsciiHeader) + "1 2 3\n4 nan 6\n7 8 9\n"),
                d + "/nan.ply:9:", "NaN or infinite");
  ExpectRefused(file("inf.ply", std::string(kPlyAsciiHeader) + "1 2 3\n4 5 6\n-inf 8 9\n"),
                d + "/inf.ply:10:", "NaN or infinite");
  ExpectRefused(file("lone_red.ply",
                     "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\n"
                     "property float y\nproperty float z\nproperty uchar red\nend_header\n" +
                         std::string(13, '\0')),
                d + "/lone_red.ply: ", "red green blue");
  ExpectRefused(file("word.ply", std::string(kPlyAsciiHeader) + "1 2 3\n4 five 6\n7 8 9\n"),
                d + "/word.ply:9:", "'five' is not a number");
  ExpectRefused(file("cols.ply", std::string(kPlyAsciiHeader) + "1 2 3\n4 5\n7 8 9\n"),
                d + "/cols.ply:9:", "too few values");
  std::string nan_binary = MakePly<float>("binary_little_endian", s.points, s.normals);
  const float nan = std::nanf("");
  std::memcpy(&nan_binary[nan_binary.find("end_header\n") + 11 + 27 * 3 + 4], &nan, 4);
  ExpectRefused(file("nan_binary.ply", nan_binary), d + "/nan_binary.ply: ", "point 3 has a NaN");

  const std::string pcd_head = PcdHeader("x y z", "4 4 4", "F F F", 3, 1, "ascii");
  ExpectRefused(file("fewer.pcd", pcd_head + "1 2 3\n4 5 6\n"),
                d + "/fewer.pcd:14:", "data ends after 2 of the 3");
  ExpectRefused(file("more.pcd", pcd_head + "1 2 3\n4 5 6\n7 8 9\n1 1 1\n"),
                d + "/more.pcd:15:", "more data");
  ExpectRefused(file("word.pcd", pcd_head + "1 2 3\n4 abc 6\n7 8 9\n"),
                d + "/word.pcd:13:", "'abc' is not a number");
  ExpectRefused(file("inf.pcd", pcd_head + "1 2 3\n4 inf 6\n7 8 9\n"),
                d + "/inf.pcd:13:", "infinite coordinate");
  ExpectRefused(file("header_only.pcd", PcdHeader("x y z", "4 4 4", "F F F", 3, 1, "binary")),
                d + "/header_only.pcd: ", "truncated");
  ExpectRefused(file("count.pcd",
                     PcdHeader("x y z", "4 4 4", "F F F", 3, 1, "binary") + std::string(40, '\0')),
                d + "/count.pcd: ", "wrong POINTS");
  ExpectRefused(
      file("compressed.pcd", PcdHeader("x y z", "4 4 4", "F F F", 3, 1, "binary_compressed") +
                                 std::string("\x30\0\0\0\x24\0\0\0abc", 11)),
      d + "/compressed.pcd: ", "truncated");
  ExpectRefused(file("noxyz.pcd", PcdHeader("a b c", "4 4 4", "F F F", 1, 1, "ascii") + "1 2 3\n"),
                d + "/noxyz.pcd: ", "no x, y and z");

  ::mkdir((d + "/folder.ply").c_str(), 0755);
  ExpectRefused(d + "/folder.ply", d + "/folder.ply: ", "directory");
  ExpectRefused(d + "/missing.pcd", d + "/missing.pcd: ", "No such file");
  ExpectRefused(file("cloud.obj", "v 1 2 3\n"), d + "/cloud.obj: ", "unsupported cloud format");
}

}  // namespace
}  // namespace implicitfit
