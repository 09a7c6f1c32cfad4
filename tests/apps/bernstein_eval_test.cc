// `implicitfit eval` on Bernstein patches of degree 2-4, end to end, against the naive oracle
// (explicit multinomial sum, tests/oracle/bernstein_oracle.h): 1e-9 relative.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "oracle/bernstein_oracle.h"
#include "support/random_patches.h"
#include "support/run_command.h"

namespace {

using nlohmann::json;
using testsupport::RunCommand;
using testsupport::WriteText;
const std::string kCli = IMPLICITFIT_CLI;

TEST(BernsteinEval, AgreesWithTheNaiveMultinomialSum) {
  const std::string dir = testsupport::ScratchDir("bernstein_eval");
  std::mt19937 rng(61);
  std::uniform_real_distribution<double> u(-1.0, 1.0), w(-0.5, 1.5);
  int checked = 0;
  for (int model_index = 0; model_index < 30; ++model_index) {
    const int k = 2 + model_index % 3;
    const auto corners = testsupport::RandomCorners(rng);
    std::vector<double> b(static_cast<size_t>((k + 1) * (k + 2) * (k + 3) / 6));
    for (double& x : b) x = u(rng);
    json vertices = json::array();
    for (const auto& v : corners) vertices.push_back({v[0], v[1], v[2]});
    const json doc = {{"format", "implicitfit-model"},
                      {"version", 1},
                      {"root",
                       {{"type", "bernstein_patch"},
                        {"degree", k},
                        {"vertices", vertices},
                        {"control_points", b}}}};
    WriteText(dir + "/model.json", doc.dump());
    std::ostringstream points;
    points.precision(17);
    std::vector<Eigen::Vector3d> xs;
    for (int i = 0; i < 100; ++i) {
      // Inside and around the tetrahedron: barycentric weights in [-0.5, 1.5], normalised.
      double t[4], sum = 0.0;
      for (double& x : t) sum += (x = w(rng));
      if (std::abs(sum) < 0.5) continue;
      Eigen::Vector3d x = Eigen::Vector3d::Zero();
      for (int j = 0; j < 4; ++j) x += t[j] / sum * corners[j];
      xs.push_back(x);
      points << x[0] << " " << x[1] << " " << x[2] << "\n";
    }
    WriteText(dir + "/points.xyz", points.str());
    const auto r = RunCommand(kCli + " eval " + dir + "/model.json " + dir + "/points.xyz");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::istringstream values(r.out);
    for (const Eigen::Vector3d& x : xs) {
      double v, magnitude;
      ASSERT_TRUE(values >> v);
      const double expected = oracle::Patch(k, b, corners, x, &magnitude);
      EXPECT_NEAR(v, expected, 1e-9 * std::abs(expected) + 1e-13 * magnitude) << "k " << k;
      ++checked;
    }
  }
  EXPECT_GT(checked, 2000);
}

}  // namespace
