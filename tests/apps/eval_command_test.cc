// `implicitfit eval` end to end against the independent oracle (tests/oracle): random smooth
// CSG models of spheres and planes (union, intersection, difference, nested, any delta,
// epsilon <= delta, order 0-4) are written as model files, evaluated by the tool at random
// points, and every printed value must agree with the oracle to 1e-9.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "oracle/li_phillips_oracle.h"
#include "support/run_command.h"

namespace {

using nlohmann::json;
using testsupport::RunCommand;
using testsupport::WriteText;
const std::string kCli = IMPLICITFIT_CLI;

// A random tree, as JSON and as an oracle closure over a point.
struct RandomTree {
  json node;
  std::function<double(const double*)> f;
};

RandomTree MakeTree(std::mt19937& rng, int depth) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), pos(0.05, 1.0);
  std::uniform_int_distribution<int> pick(0, 2);
  if (depth == 0 || pick(rng) == 0) {
    if (pick(rng) < 2) {
      std::array<double, 3> c = {u(rng), u(rng), u(rng)};
      const double r = 0.3 + pos(rng);
      return {{{"type", "sphere"}, {"center", c}, {"radius", r}},
              [c, r](const double* x) { return oracle::Sphere(c.data(), r, x); }};
    }
    std::array<double, 3> n = {u(rng), u(rng), u(rng) + 2.0};  // never zero
    const double d = u(rng);
    return {{{"type", "plane"}, {"normal", n}, {"offset", d}},
            [n, d](const double* x) { return oracle::Plane(n.data(), d, x); }};
  }
  const RandomTree a = MakeTree(rng, depth - 1), b = MakeTree(rng, depth - 1);
  const double delta = pos(rng);
  const double eps = delta * pos(rng);
  const int order = std::uniform_int_distribution<int>(0, 4)(rng);
  const int op = pick(rng);
  const char* names[3] = {"union", "intersection", "difference"};
  auto fa = a.f, fb = b.f;
  std::function<double(const double*)> f = [=](const double* x) {
    if (op == 0) return oracle::Union(fa(x), fb(x), delta, eps, order);
    if (op == 1) return oracle::Intersection(fa(x), fb(x), delta, eps, order);
    return oracle::Difference(fa(x), fb(x), delta, eps, order);
  };
  return {{{"type", names[op]},
           {"children", {a.node, b.node}},
           {"delta", delta},
           {"epsilon", eps},
           {"order", order}},
          f};
}

TEST(EvalCommand, AgreesWithTheIndependentOracleOnRandomSmoothCsgModels) {
  const std::string dir = testsupport::ScratchDir("eval_oracle");
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  int points_checked = 0;
  for (int model_index = 0; model_index < 40; ++model_index) {
    const RandomTree tree = MakeTree(rng, 3);
    const json doc = {{"format", "implicitfit-model"}, {"version", 1}, {"root", tree.node}};
    WriteText(dir + "/model.json", doc.dump(2));
    std::ostringstream points;
    points.precision(17);
    std::vector<std::array<double, 3>> xs;
    for (int i = 0; i < 100; ++i) {
      xs.push_back({u(rng), u(rng), u(rng)});
      points << xs.back()[0] << " " << xs.back()[1] << " " << xs.back()[2] << "\n";
    }
    WriteText(dir + "/points.xyz", points.str());
    const auto r = RunCommand(kCli + " eval " + dir + "/model.json " + dir + "/points.xyz");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::istringstream values(r.out);
    for (const auto& x : xs) {
      double v;
      ASSERT_TRUE(values >> v);
      EXPECT_NEAR(v, tree.f(x.data()), 1e-9 * (1.0 + std::abs(v))) << doc.dump();
      ++points_checked;
    }
    double extra;
    EXPECT_FALSE(values >> extra) << "one value per point";
  }
  EXPECT_EQ(points_checked, 4000);
}

TEST(EvalCommand, PrintsFullPrecision) {
  const std::string dir = testsupport::ScratchDir("eval_precision");
  WriteText(dir + "/m.json", R"({"format": "implicitfit-model", "version": 1,
    "root": {"type": "sphere", "center": [0, 0, 0], "radius": 1}})");
  WriteText(dir + "/p.xyz", "0.1 0.2 0.3\n");
  const auto r = RunCommand(kCli + " eval " + dir + "/m.json " + dir + "/p.xyz");
  ASSERT_EQ(r.exit_code, 0);
  char expected[64];
  std::snprintf(expected, sizeof expected, "%.17g\n", std::sqrt(0.14) - 1.0);
  EXPECT_EQ(r.out, expected);
}

TEST(EvalCommand, BadInputsExit2NamingTheFileWithNoOutput) {
  const std::string dir = testsupport::ScratchDir("eval_bad");
  WriteText(dir + "/good.json", R"({"format": "implicitfit-model", "version": 1,
    "root": {"type": "sphere", "center": [0, 0, 0], "radius": 1}})");
  WriteText(dir + "/good.xyz", "0 0 0\n1 1 1\n");
  WriteText(dir + "/broken.json",
            "{\"format\": \"implicitfit-model\",\n \"version\": 1,\n \"root\": {");
  WriteText(dir + "/negative.json", R"({"format": "implicitfit-model", "version": 1,
    "root": {"type": "sphere", "center": [0, 0, 0], "radius": -1}})");
  WriteText(dir + "/bad.xyz", "0 0 0\n1 1 nan\n");
  WriteText(dir + "/empty.xyz", "");
  struct Case {
    std::string model, points, fragment;
  } cases[] = {
      {dir + "/broken.json", dir + "/good.xyz", "broken.json: invalid JSON"},
      {dir + "/negative.json", dir + "/good.xyz", "negative.json: invalid model: root.radius"},
      {dir + "/missing.json", dir + "/good.xyz", "missing.json"},
      {dir, dir + "/good.xyz", "is a directory"},
      {dir + "/good.json", dir + "/bad.xyz", "bad.xyz:2:"},
      {dir + "/good.json", dir + "/empty.xyz", "empty.xyz: no points"},
      {dir + "/good.json", dir + "/points.bin", "unsupported cloud format"},
  };
  for (const Case& c : cases) {
    const auto r = RunCommand(kCli + " eval " + c.model + " " + c.points);
    EXPECT_EQ(r.exit_code, 2) << c.fragment;
    EXPECT_NE(r.err.find(c.fragment), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << "no partial output";
  }
}

}  // namespace
