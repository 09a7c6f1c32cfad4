// The spline nodes and fits through the command line (issue 30): eval, sample, mesh and check
// on bspline_surface, bspline_volume and curve tubes; fit --model bspline-surface and
// bspline-volume (with --convex, certified by check); bad options exit 2 with no file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

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
  r = RunCommand(kCli + " mesh " + dir + "/cyl.json --cell 0.03 --out " + dir + "/cyl.ply");
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
    const auto m = RunCommand(kCli + " mesh " + dir + "/" + name + ".json --cell 0.05 --out " +
                              dir + "/" + name + ".ply");
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
  {  // 2000 points of the quarter cylinder rho = 1, 0 <= z <= 1, noise 0.001 along the normals
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    std::normal_distribution<double> noise(0.0, 0.001);
    std::ostringstream xyz;
    xyz.precision(10);
    for (int i = 0; i < 2000; ++i) {
      const double a = 0.5 * M_PI * u01(rng), rho = 1.0 + noise(rng);
      xyz << rho * std::cos(a) << " " << rho * std::sin(a) << " " << u01(rng) << " "
          << std::cos(a) << " " << std::sin(a) << " 0\n";
    }
    WriteText(dir + "/cyl.xyz", xyz.str());
  }
  auto r = RunCommand(kCli + " fit " + dir + "/cyl.xyz --model bspline-surface --grid 6x5 --out " + dir +
                      "/surface.json --report " + dir + "/surface.report.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(Slurp(dir + "/surface.json").find("bspline_surface"), std::string::npos);
  const nlohmann::json report = nlohmann::json::parse(Slurp(dir + "/surface.report.json"));
  EXPECT_LE(report.at("rms_distance").get<double>(), 1.5e-3);  // the noise: 1e-3
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

// detect --freeform on a plane beside a curved sheet (x y z nx ny nz, noise 0.001 along the
// normals; the sheet's curvature is nowhere zero, so that planes of --min-points 60 cover little
// of it): the plane is a plane primitive; the sheet's points that no plane takes become
// B-spline surfaces in the scene, the labels and the segmented PLY; none of the plane's.
TEST(SplineCli, DetectFreeformAssignsTheSheet) {
  const std::string dir = ScratchDir("spline_detect");
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.001);
  std::ostringstream cloud;
  cloud.precision(10);
  const int plane_points = 2500, sheet_points = 3500;
  for (int i = 0; i < plane_points; ++i)
    cloud << u(rng) << " " << u(rng) << " " << noise(rng) << " 0 0 1\n";
  for (int i = 0; i < sheet_points; ++i) {  // z = 0.8 - a^2 / 2 - 0.3 y^2 + a^3 / 20, a = x - 3
    const double a = u(rng), y = u(rng);
    double n[3] = {a - 0.15 * a * a, 0.6 * y, 1};
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + 1);
    for (double& c : n) c /= len;
    const double e = noise(rng), z = 0.8 - 0.5 * a * a - 0.3 * y * y + 0.05 * a * a * a;
    cloud << 3 + a + e * n[0] << " " << y + e * n[1] << " " << z + e * n[2] << " " << n[0] << " "
          << n[1] << " " << n[2] << "\n";
  }
  WriteText(dir + "/scene.xyz", cloud.str());
  const std::string base =
      kCli + " detect " + dir + "/scene.xyz --kinds plane --min-points 60 --threads 2";
  auto r = RunCommand(base + " --out " + dir + "/plain.json --labels " + dir + "/plain.txt");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = RunCommand(base + " --freeform --out " + dir + "/free.json --labels " + dir +
                 "/free.txt --ply " + dir + "/free.ply --report " + dir + "/free.report.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json scene = nlohmann::json::parse(Slurp(dir + "/free.json"));
  std::vector<bool> spline;
  for (const auto& p : scene.at("primitives")) {
    const std::string dump = p.dump();
    spline.push_back(dump.find("bspline_surface") != std::string::npos);
  }
  ASSERT_GE(std::count(spline.begin(), spline.end(), true), 1) << scene.dump();
  const auto labels = [&](const std::string& path) {
    std::vector<int> l;
    std::istringstream in(Slurp(path));
    for (int x; in >> x;) l.push_back(x);
    return l;
  };
  const std::vector<int> plain = labels(dir + "/plain.txt"), free = labels(dir + "/free.txt");
  ASSERT_EQ(free.size(), static_cast<size_t>(plane_points + sheet_points));
  ASSERT_EQ(plain.size(), free.size());
  int sheet_left = 0, sheet_spline = 0, plane_spline = 0;
  for (int i = 0; i < plane_points + sheet_points; ++i) {
    const bool is_spline = free[i] >= 0 && spline.at(free[i]);
    if (!is_spline) EXPECT_EQ(free[i], plain[i]) << i;  // the primitives are the same
    if (is_spline) EXPECT_EQ(plain[i], -1) << i;       // splines take only what was left
    if (i < plane_points) {
      plane_spline += is_spline;
    } else {
      sheet_left += plain[i] < 0;
      sheet_spline += is_spline;
    }
  }
  EXPECT_EQ(plane_spline, 0);
  EXPECT_GE(sheet_spline, 0.5 * sheet_left) << sheet_left;
  const nlohmann::json report = nlohmann::json::parse(Slurp(dir + "/free.report.json"));
  EXPECT_EQ(report.at("freeform").at("points").get<int>(), sheet_spline);
  const std::string ply = Slurp(dir + "/free.ply");
  EXPECT_NE(ply.find("property int label"), std::string::npos);
  EXPECT_NE(ply.find("residual"), std::string::npos);
}

}  // namespace
