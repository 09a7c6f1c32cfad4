// `implicitfit mesh` end to end: a sphere, a sharp blend and a Bernstein patch give binary PLY
// meshes (header counts match the file size); bad input exits 2 and leaves no file.
#include <gtest/gtest.h>

#include <string>

#include "support/run_command.h"

namespace {

using testsupport::FileExists;
using testsupport::RunCommand;
using testsupport::ScratchDir;
using testsupport::Slurp;
using testsupport::WriteText;

const std::string kCli = IMPLICITFIT_CLI;

long HeaderCount(const std::string& ply, const std::string& element) {
  const size_t at = ply.find("element " + element + " ");
  if (at == std::string::npos) return -1;
  return std::stol(ply.substr(at + element.size() + 9));
}

TEST(MeshCommand, MeshesEveryModelKindIntoABinaryPlyWithFaces) {
  const std::string dir = ScratchDir("mesh_kinds");
  WriteText(
      dir + "/sphere.json",
      R"({"format": "implicitfit-model", "version": 1, "root": {"type": "sphere", "center": [0, 0, 0], "radius": 1}})");
  WriteText(dir + "/half.json",
            R"({"format": "implicitfit-model", "version": 1, "root": {"type": "intersection",
    "delta": 0.1, "epsilon": 0.1, "order": 0, "children": [{"type": "sphere", "center": [0, 0, 0], "radius": 1},
    {"type": "plane", "normal": [0, 0, 1], "offset": 0}]}})");
  WriteText(dir + "/patch.json",
            R"({"format": "implicitfit-model", "version": 1, "root": {"type": "bernstein_patch",
    "degree": 2, "vertices": [[1, 0, 0], [0, 1, 0], [0, 0, 1], [0, 0, 0]],
    "control_points": [0.5, -0.2, -0.2, -0.3, 0.5, -0.2, -0.3, 0.5, -0.3, -0.1]}})");
  for (const std::string name : {"sphere", "half", "patch"}) {
    const auto r =
        RunCommand(kCli + " mesh " + dir + "/" + name + ".json --out " + dir + "/" + name + ".ply");
    ASSERT_EQ(r.exit_code, 0) << name << ": " << r.err;
    const std::string ply = Slurp(dir + "/" + name + ".ply");
    ASSERT_EQ(ply.rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u) << name;
    const long v = HeaderCount(ply, "vertex"), f = HeaderCount(ply, "face");
    EXPECT_GT(v, 100) << name;
    EXPECT_GT(f, 100) << name;
    const size_t header = ply.find("end_header\n") + 11;
    EXPECT_EQ(ply.size() - header, static_cast<size_t>(v * 48 + f * 13)) << name;
  }
}

TEST(MeshCommand, BadInputExitsTwoWithoutAFile) {
  const std::string dir = ScratchDir("mesh_bad");
  WriteText(
      dir + "/sphere.json",
      R"({"format": "implicitfit-model", "version": 1, "root": {"type": "sphere", "center": [0, 0, 0], "radius": 1}})");
  WriteText(dir + "/broken.json",
            R"({"format": "implicitfit-model", "version": 1, "root": {"type": "sphere"}})");
  struct Case {
    std::string args, message;
  } cases[] = {
      {dir + "/missing.json --out " + dir + "/m.ply", "missing.json"},
      {dir + "/broken.json --out " + dir + "/m.ply", "broken.json"},
      {dir + "/sphere.json --out " + dir + "/m.ply --box 1,1,1,0,0,0", "--box"},
      {dir + "/sphere.json --out " + dir + "/m.ply --cell -1", "--cell"},
      {dir + "/sphere.json --out " + dir + "/m.ply --cell 1e-5", "too fine"},
      {dir + "/sphere.json --out " + dir + "/m.obj", "m.obj"},
  };
  for (const Case& c : cases) {
    const auto r = RunCommand(kCli + " mesh " + c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
    EXPECT_FALSE(FileExists(dir + "/m.ply")) << c.args;
  }
}

}  // namespace
