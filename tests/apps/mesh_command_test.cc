// `implicitfit mesh` end to end: a sphere, a sharp blend and a Bernstein patch give binary PLY
// meshes (header counts match the file size); bad input exits 2 and leaves no file.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_command.h"
#include "support/usage_errors.h"

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

// Progress on stderr: the stage with the cell, the grid sampled, the triangles at the end (as many
// as the file holds); nothing with --quiet, and the same file.
TEST(MeshCommand, ReportsEachStepOnStderrUnlessQuiet) {
  const std::string dir = ScratchDir("mesh_progress");
  WriteText(
      dir + "/sphere.json",
      R"({"format": "implicitfit-model", "version": 1, "root": {"type": "sphere", "center": [0, 0, 0], "radius": 1}})");
  const auto loud = RunCommand(kCli + " mesh " + dir + "/sphere.json --cell 0.1 --out " + dir +
                               "/loud.ply");
  ASSERT_EQ(loud.exit_code, 0) << loud.err;
  EXPECT_NE(loud.err.find("implicitfit mesh: mesh (cell 0.1) ..."), std::string::npos)
      << loud.err;
  EXPECT_NE(loud.err.find("implicitfit mesh: mesh: grid "), std::string::npos) << loud.err;
  const long triangles = HeaderCount(Slurp(dir + "/loud.ply"), "face");
  EXPECT_NE(loud.err.find("(" + std::to_string(triangles) + " triangles)"), std::string::npos)
      << loud.err;
  const auto quiet = RunCommand(kCli + " mesh " + dir + "/sphere.json --cell 0.1 --out " + dir +
                                "/quiet.ply --quiet");
  ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
  EXPECT_EQ(Slurp(dir + "/quiet.ply"), Slurp(dir + "/loud.ply"));
}

TEST(MeshCommand, BadInputExitsTwoWithoutAFile) {
  const std::string dir = ScratchDir("mesh_bad");
  WriteText(
      dir + "/sphere.json",
      R"({"format": "implicitfit-model", "version": 1, "root": {"type": "sphere", "center": [0, 0, 0], "radius": 1}})");
  WriteText(dir + "/broken.json",
            R"({"format": "implicitfit-model", "version": 1, "root": {"type": "sphere"}})");
  testsupport::ExpectUsageErrors(
      kCli + " mesh",
      {
          {dir + "/missing.json --out " + dir + "/m.ply", "missing.json"},
          {dir + "/broken.json --out " + dir + "/m.ply", "broken.json"},
          {dir + "/sphere.json --out " + dir + "/m.ply --box 1,1,1,0,0,0", "--box"},
          {dir + "/sphere.json --out " + dir + "/m.ply --cell -1", "--cell"},
          {dir + "/sphere.json --out " + dir + "/m.ply --cell 1e-5", "too fine"},
          {dir + "/sphere.json --out " + dir + "/m.obj", "m.obj"},
      },
      dir + "/m.ply");
}

}  // namespace

namespace {

// Guo's object S(f) ∩ V (issue 28): the ball |x|^2 < 0.25 as a degree-2 patch on the corner
// tetrahedron (1,0,0), (0,1,0), (0,0,1), (0,0,0) is, clipped, the closed octant of the ball:
// every vertex in the tetrahedron (barycentric coordinates >= -1e-9), every edge in exactly two
// triangles, Euler characteristic 2. Unclipped, the surface leaves the tetrahedron. `eval
// --clip-to-tetrahedron` agrees: positive outside the tetrahedron, the patch's f inside.
TEST(MeshCommand, ClipToTetrahedronMeshesGuosObject) {
  const std::string dir = ScratchDir("mesh_clip");
  WriteText(dir + "/ball.json",
            R"({"format": "implicitfit-model", "version": 1, "root": {"type": "bernstein_patch",
    "degree": 2, "vertices": [[1, 0, 0], [0, 1, 0], [0, 0, 1], [0, 0, 0]],
    "control_points": [0.75, -0.25, -0.25, -0.25, 0.75, -0.25, -0.25, 0.75, -0.25, -0.25]}})");
  struct Mesh {
    std::vector<std::array<double, 3>> v;
    std::vector<std::array<int, 3>> f;
  };
  auto read = [](const std::string& ply) {
    Mesh m;
    const long nv = HeaderCount(ply, "vertex"), nf = HeaderCount(ply, "face");
    const char* p = ply.data() + ply.find("end_header\n") + 11;
    for (long i = 0; i < nv; ++i, p += 48) {
      double x[6];
      std::memcpy(x, p, 48);
      m.v.push_back({x[0], x[1], x[2]});
    }
    for (long i = 0; i < nf; ++i, p += 13) {
      int t[3];
      std::memcpy(t, p + 1, 12);
      m.f.push_back({t[0], t[1], t[2]});
    }
    return m;
  };
  auto outside = [](const std::array<double, 3>& x) {  // largest violation of the tetrahedron
    return std::max({-x[0], -x[1], -x[2], x[0] + x[1] + x[2] - 1.0});
  };
  const std::string box = " --box -0.5,-0.5,-0.5,1.2,1.2,1.2 --cell 0.02";
  auto r = RunCommand(kCli + " mesh " + dir + "/ball.json --out " + dir + "/c.ply" + box +
                      " --clip-to-tetrahedron");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Mesh clipped = read(Slurp(dir + "/c.ply"));
  double worst = 0;
  for (const auto& x : clipped.v) worst = std::max(worst, outside(x));
  EXPECT_LT(worst, 1e-9);
  std::map<std::pair<int, int>, int> uses;
  for (const auto& t : clipped.f)
    for (int k = 0; k < 3; ++k)
      ++uses[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
  long open = 0;
  for (const auto& [edge, n] : uses) open += n != 2;
  EXPECT_EQ(open, 0);
  EXPECT_EQ(static_cast<long>(clipped.v.size()) - static_cast<long>(uses.size()) +
                static_cast<long>(clipped.f.size()),
            2);
  r = RunCommand(kCli + " mesh " + dir + "/ball.json --out " + dir + "/u.ply" + box);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  double unclipped_worst = 0;
  for (const auto& x : read(Slurp(dir + "/u.ply")).v)
    unclipped_worst = std::max(unclipped_worst, outside(x));
  EXPECT_GT(unclipped_worst, 0.1);
  WriteText(dir + "/p.xyz", "-0.1 0.1 0.1\n0.25 0.25 0.25\n");
  const auto e =
      RunCommand(kCli + " eval " + dir + "/ball.json " + dir + "/p.xyz --clip-to-tetrahedron");
  ASSERT_EQ(e.exit_code, 0) << e.err;
  std::istringstream values(e.out);
  double outside_value, inside_value;
  values >> outside_value >> inside_value;
  EXPECT_NEAR(outside_value, 0.1, 1e-12);  // the face plane x = 0 (the patch's f is < 0 there)
  EXPECT_NEAR(inside_value, 0.1875 - 0.25, 1e-12);  // the patch: the faces are farther
  // A model without a patch: exit 2, no file.
  WriteText(
      dir + "/s.json",
      R"({"format": "implicitfit-model", "version": 1, "root": {"type": "sphere", "center": [0, 0, 0], "radius": 1}})");
  EXPECT_EQ(
      RunCommand(kCli + " mesh " + dir + "/s.json --out " + dir + "/s.ply --clip-to-tetrahedron")
          .exit_code,
      2);
  EXPECT_FALSE(FileExists(dir + "/s.ply"));
}

}  // namespace
