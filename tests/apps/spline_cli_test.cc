// The spline nodes and fits through the command line (issue 30): eval, sample, mesh and check
// on bspline_surface, bspline_volume and curve tubes; fit --model bspline-surface and
// bspline-volume (with --convex, certified by check); bad options exit 2 with no file.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_command.h"

namespace {

using testsupport::FileExists;
using testsupport::RunCommand;
using testsupport::ScratchDir;
using testsupport::Slurp;
using testsupport::WriteText;

const std::string kCli = IMPLICITFIT_CLI;

const char* kQuarterCylinder =
    R"({"format": "implicitfit-model", "version": 1, "root": {"type": "bspline_surface",
  "degree": [2, 1], "knots_u": [0, 0, 0, 1, 1, 1], "knots_v": [0, 0, 1, 1],
  "control_points": [[[1, 0, 0], [1, 0, 1]], [[1, 1, 0], [1, 1, 1]], [[0, 1, 0], [0, 1, 1]]],
  "weights": [[1, 1], [0.7071067811865476, 0.7071067811865476], [1, 1]]}})";

// x^2 + 2 y^2 + 3 z^2 - 1 on a degree-2 volume over [-1.2, 1.2]^3, 1 cell: the Bernstein
// coefficients of a quadric on one cell are its blossom at the corners (b_ijl per axis:
// x^2 -> [1.44, -1.44, 1.44] at t = 0, 1/2, 1 of [-1.2, 1.2]), summed per axis.
std::string QuadricVolume(double a, double b, double c) {
  const double sq[3] = {1.44, -1.44, 1.44};
  std::ostringstream s;
  s << R"({"format": "implicitfit-model", "version": 1, "root": {"type": "bspline_volume",
  "degree": 2, "box": [-1.2, -1.2, -1.2, 1.2, 1.2, 1.2], "cells": [1, 1, 1], "coefficients": [)";
  for (int l = 0; l < 3; ++l)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
        s << (i + j + l ? ", " : "") << a * sq[i] + b * sq[j] + c * sq[l] - 1.0;
  s << "]}}";
  return s.str();
}

std::vector<std::vector<double>> ReadXyz(const std::string& path) {
  std::vector<std::vector<double>> rows;
  std::istringstream in(Slurp(path));
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream l(line);
    std::vector<double> v;
    double x;
    while (l >> x) v.push_back(x);
    if (v.size() >= 3) rows.push_back(v);
  }
  return rows;
}

TEST(SplineCli, EvalSampleAndMeshTheQuarterCylinder) {
  const std::string dir = ScratchDir("spline_cylinder");
  WriteText(dir + "/cyl.json", kQuarterCylinder);
  WriteText(dir + "/points.xyz", "0.5 0.5 0.5\n2 0.1 0.3\n0.1 0.3 0.9\n");
  auto r = RunCommand(kCli + " eval " + dir + "/cyl.json " + dir + "/points.xyz");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream values(r.out);
  for (const double rho : {std::sqrt(0.5), std::hypot(2.0, 0.1), std::hypot(0.1, 0.3)}) {
    double f;
    values >> f;
    EXPECT_NEAR(f, rho - 1.0, 1e-9);
  }
  r = RunCommand(kCli + " sample " + dir + "/cyl.json --count 400 --out " + dir + "/s.xyz");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = ReadXyz(dir + "/s.xyz");
  ASSERT_EQ(rows.size(), 400u);
  for (const auto& p : rows) {
    EXPECT_NEAR(std::hypot(p[0], p[1]), 1.0, 1e-9);
    if (p.size() >= 6) EXPECT_NEAR(p[3] * p[0] + p[4] * p[1], 1.0, 1e-6);  // normal outward
  }
  r = RunCommand(kCli + " mesh " + dir + "/cyl.json --out " + dir + "/cyl.ply");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string ply = Slurp(dir + "/cyl.ply");
  const size_t at = ply.find("element vertex ");
  ASSERT_NE(at, std::string::npos);
  const long vertices = std::stol(ply.substr(at + 15));
  const size_t body = ply.find("end_header\n") + 11;
  ASSERT_GT(vertices, 100);
  int on = 0;
  for (long v = 0; v < vertices; ++v) {
    double x[6];
    std::memcpy(x, ply.data() + body + 48 * v, sizeof x);
    on += std::abs(std::hypot(x[0], x[1]) - 1.0) < 1e-6;
  }
  // The sign jump beyond the patch's edges leaves no sheet: the vertices lie on the cylinder,
  // except those of cells cut by the patch's boundary.
  EXPECT_GE(on, 0.9 * vertices);
}

TEST(SplineCli, CurveTubeAndVolumeThroughEverything) {
  const std::string dir = ScratchDir("spline_tube");
  WriteText(dir + "/helix.json",
            R"({"format": "implicitfit-model", "version": 1, "root": {"type": "skeleton_offset",
    "radius": 0.15, "skeleton": {"curve": {"helix": {"center": [0, 0, 0],
    "axes": [[1, 0, 0], [0, 1, 0]], "rise": [0, 0, 0.8], "turns": 1.5}}}}})");
  WriteText(dir + "/volume.json", QuadricVolume(1, 2, 3));
  for (const std::string name : {"helix", "volume"}) {
    const auto s = RunCommand(kCli + " sample " + dir + "/" + name + ".json --count 200 --out " +
                              dir + "/" + name + ".xyz");
    ASSERT_EQ(s.exit_code, 0) << name << ": " << s.err;
    const auto m = RunCommand(kCli + " mesh " + dir + "/" + name + ".json --out " + dir + "/" +
                              name + ".ply");
    ASSERT_EQ(m.exit_code, 0) << name << ": " << m.err;
  }
  // The helix samples lie at 0.15 from the curve: (rho - 1)^2 + (z - 0.8 t)^2 = 0.15^2 at the
  // nearest t; check rho in [0.85, 1.15] as a necessary condition.
  for (const auto& p : ReadXyz(dir + "/helix.xyz")) {
    const double rho = std::hypot(p[0], p[1]);
    EXPECT_GE(rho, 0.85 - 1e-9);
    EXPECT_LE(rho, 1.15 + 1e-9);
  }
  for (const auto& p : ReadXyz(dir + "/volume.xyz"))  // on x^2 + 2y^2 + 3z^2 = 1
    EXPECT_NEAR(p[0] * p[0] + 2 * p[1] * p[1] + 3 * p[2] * p[2], 1.0, 1e-9);
  auto c = RunCommand(kCli + " check " + dir + "/volume.json");
  EXPECT_EQ(c.exit_code, 0) << c.out << c.err;
  WriteText(dir + "/saddle.json", QuadricVolume(1, -0.5, 1));
  c = RunCommand(kCli + " check " + dir + "/saddle.json");
  EXPECT_EQ(c.exit_code, 1) << c.out << c.err;
}

TEST(SplineCli, FitsWriteModelsOrExitWithTheReason) {
  const std::string dir = ScratchDir("spline_fits");
  WriteText(dir + "/cyl.json", kQuarterCylinder);
  auto r = RunCommand(kCli + " sample " + dir + "/cyl.json --count 2000 --noise 0.001 --seed 3 --out " +
                      dir + "/cyl.xyz");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = RunCommand(kCli + " fit " + dir + "/cyl.xyz --model bspline-surface --grid 6x5 --out " + dir +
                 "/surface.json --report " + dir + "/surface.report.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(Slurp(dir + "/surface.json").find("bspline_surface"), std::string::npos);
  EXPECT_NE(Slurp(dir + "/surface.report.json").find("rms_distance"), std::string::npos);
  for (const std::string bad : {" --grid 3x3", " --grid 6", " --grid 6x5 --convex", ""}) {
    const auto b = RunCommand(kCli + " fit " + dir + "/cyl.xyz --model bspline-surface" + bad +
                              " --out " + dir + "/bad.json");
    EXPECT_EQ(b.exit_code, 2) << bad << ": " << b.err;
    EXPECT_FALSE(FileExists(dir + "/bad.json"));
  }
  WriteText(dir + "/ball.json",
            R"({"format": "implicitfit-model", "version": 1, "root": {"type": "ellipsoid",
    "center": [0, 0, 0], "radii": [1, 0.8, 0.6], "axes": [[1, 0, 0], [0, 1, 0]]}})");
  r = RunCommand(kCli + " sample " + dir + "/ball.json --count 2000 --noise 0.001 --seed 4 --out " +
                 dir + "/ball.xyz");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = RunCommand(kCli + " fit " + dir + "/ball.xyz --model bspline-volume --cells 4 --convex --out " +
                 dir + "/convex.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("certified convex yes"), std::string::npos) << r.out;
  r = RunCommand(kCli + " check " + dir + "/convex.json");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  r = RunCommand(kCli + " fit " + dir + "/ball.xyz --model bspline-volume --cells 4 --degree 1 "
                 "--convex --out " + dir + "/bad.json");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_FALSE(FileExists(dir + "/bad.json"));
}

}  // namespace
