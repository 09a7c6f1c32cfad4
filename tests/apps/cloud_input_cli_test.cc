// Hostile cloud files through the command line: `fit` and `eval` exit 2 with a one-line message
// that names the file (and, for text, the line), and write no output file.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <random>
#include <string>

#include "support/run_command.h"

namespace {

using testsupport::RunCommand;
const std::string kCli = IMPLICITFIT_CLI;

struct Hostile {
  std::string name, content, message;  // message: expected after the file name
};

std::vector<Hostile> HostileFiles() {
  std::mt19937 rng(17);
  std::string noise(3000, '\0');
  for (char& c : noise) c = static_cast<char>(rng());
  const std::string ply_head =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float "
      "z\nend_header\n";
  const std::string ply_binary_head =
      "ply\nformat binary_little_endian 1.0\nelement vertex 100\nproperty float x\nproperty float "
      "y\n"
      "property float z\nend_header\n";
  const std::string pcd_head =
      "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 3\nHEIGHT 1\nPOINTS "
      "3\nDATA ascii\n";
  return {
      {"empty.ply", "", ": empty file"},
      {"empty.pcd", "", ": empty file"},
      {"empty.xyz", "", ": no points"},
      {"garbage.ply", "this is not a cloud\n", ":1: not a PLY file"},
      {"garbage.pcd", "this is not a cloud\n", ":1: not a PCD file"},
      {"garbage.xyz", "this is not a cloud\n", ":1: 'this' is not a number"},
      {"random.ply", noise, ":"},
      {"random.pcd", noise, ":"},
      {"truncated.ply", ply_binary_head + std::string(100 * 12 - 7, '\1'), ": truncated"},
      {"header_only.ply", ply_binary_head, ": truncated"},
      {"fewer.ply", ply_head + "1 2 3\n4 5 6\n", ":10: data ends after 2 of the 3"},
      {"more.ply", ply_head + "1 2 3\n4 5 6\n7 8 9\n0 0 0\n",
       ":11: more data than the header declares"},
      {"nan.ply", ply_head + "1 2 3\nnan 5 6\n7 8 9\n", ":9: NaN or infinite coordinate"},
      {"inf.pcd", pcd_head + "1 2 3\n4 5 inf\n7 8 9\n", ":11: infinite coordinate"},
      {"fewer.pcd", pcd_head + "1 2 3\n", ":11: data ends after 1 of the 3"},
      {"nan.xyz", "1 2 3\n4 nan 6\n", ":2: NaN or infinite coordinate"},
  };
}

TEST(CloudInputCli, HostileCloudsExit2NamingTheFileWithoutOutput) {
  const std::string dir = testsupport::ScratchDir("cloud_input_cli");
  ::mkdir((dir + "/folder.ply").c_str(), 0755);
  std::vector<Hostile> cases = HostileFiles();
  for (const Hostile& h : cases) testsupport::WriteText(dir + "/" + h.name, h.content);
  cases.push_back({"folder.ply", "", ": is a directory"});
  cases.push_back({"missing.pcd", "", ": No such file"});
  for (const Hostile& h : cases) {
    const std::string path = dir + "/" + h.name;
    const auto fit = RunCommand(kCli + " fit '" + path + "' --model sphere --out '" + dir +
                                "/out.json' --report '" + dir + "/report.json'");
    EXPECT_EQ(fit.exit_code, 2) << h.name << ": " << fit.err;
    EXPECT_NE(fit.err.find(path + h.message), std::string::npos) << h.name << ": " << fit.err;
    EXPECT_EQ(fit.err.find('\n'), fit.err.size() - 1) << h.name << ": not one line: " << fit.err;
    EXPECT_FALSE(testsupport::FileExists(dir + "/out.json")) << h.name;
    EXPECT_FALSE(testsupport::FileExists(dir + "/report.json")) << h.name;

    testsupport::WriteText(
        dir + "/m.json",
        R"({"format": "implicitfit-model", "version": 1, "root": {"type": "sphere", "center": [0, 0, 0], "radius": 1}})");
    const auto eval = RunCommand(kCli + " eval '" + dir + "/m.json' '" + path + "'");
    EXPECT_EQ(eval.exit_code, 2) << h.name << ": " << eval.err;
    EXPECT_NE(eval.err.find(path + h.message), std::string::npos) << h.name << ": " << eval.err;
    EXPECT_TRUE(eval.out.empty()) << h.name;
  }
}

TEST(CloudInputCli, EvalReadsEveryFormat) {
  const std::string dir = testsupport::ScratchDir("cloud_input_cli_ok");
  testsupport::WriteText(
      dir + "/m.json",
      R"({"format": "implicitfit-model", "version": 1, "root": {"type": "sphere", "center": [0, 0, 0], "radius": 1}})");
  testsupport::WriteText(dir + "/a.xyz", "3 0 0\n0 0 0.5\n");
  testsupport::WriteText(
      dir + "/a.ply",
      "ply\nformat ascii 1.0\nelement vertex 2\nproperty double x\nproperty double y\n"
      "property double z\nproperty uchar intensity\nend_header\n3 0 0 7\n0 0 0.5 7\n");
  testsupport::WriteText(
      dir + "/a.pcd",
      "VERSION 0.7\nFIELDS x y z\nSIZE 8 8 8\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 3\nHEIGHT 1\n"
      "POINTS 3\nDATA ascii\n3 0 0\nnan nan nan\n0 0 0.5\n");
  for (const char* file : {"a.xyz", "a.ply", "a.pcd"}) {
    const auto r = RunCommand(kCli + " eval '" + dir + "/m.json' '" + dir + "/" + file + "'");
    EXPECT_EQ(r.exit_code, 0) << file << r.err;
    EXPECT_EQ(r.out, "2\n-0.5\n") << file;
  }
}

}  // namespace
