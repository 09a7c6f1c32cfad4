// `implicitfit fit` and `batch` on coordinate-measuring-machine sets (few points, no normals):
// the points-only path, --estimator, the reports, and the refusals of degenerate sets (exit 1).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/read_json.h"
#include "support/run_command.h"

namespace {

using nlohmann::json;
using testsupport::RunCommand;
using testsupport::WriteText;
const std::string kCli = IMPLICITFIT_CLI;

using testsupport::ReadJson;

// 9 points spread over the sphere |x - (1, -2, 0.5)| = 2 (golden-angle spiral) and one stray
// point inside it, as a CMM probes a ball; x y z only.
std::string TenPointSphere(bool with_stray) {
  std::ostringstream s;
  s.precision(17);
  const double golden = M_PI * (3 - std::sqrt(5.0));
  for (int i = 0; i < 9; ++i) {
    const double z = 1 - 2 * (i + 0.5) / 9, r = std::sqrt(1 - z * z);
    s << 1 + 2 * r * std::cos(golden * i) << " " << -2 + 2 * r * std::sin(golden * i) << " "
      << 0.5 + 2 * z << "\n";
    if (i == 4 && with_stray) s << 1.7 << " " << -1.6 << " " << 0.2 << "\n";
  }
  return s.str();
}

TEST(MetrologyCli, TenPointSphereWithAStrayPoint) {
  const std::string dir = testsupport::ScratchDir("cmm_sphere");
  WriteText(dir + "/ball.xyz", TenPointSphere(true));
  const auto r = RunCommand(kCli + " fit " + dir + "/ball.xyz --model sphere --out " + dir +
                            "/fit.json --report " + dir + "/report.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json m = ReadJson(dir + "/fit.json")["root"];
  EXPECT_NEAR(m["center"][0].get<double>(), 1.0, 1e-3);
  EXPECT_NEAR(m["center"][1].get<double>(), -2.0, 1e-3);
  EXPECT_NEAR(m["center"][2].get<double>(), 0.5, 1e-3);
  EXPECT_NEAR(m["radius"].get<double>(), 2.0, 1e-3);
  const json report = ReadJson(dir + "/report.json");
  EXPECT_EQ(report["estimator"], "robust");
  EXPECT_TRUE(report["points_only"].get<bool>());
  EXPECT_EQ(report["inliers"], 9);
  EXPECT_NE(report["normals"].get<std::string>().find("not trusted"), std::string::npos)
      << report["normals"];
}

TEST(MetrologyCli, LeastSquaresAndMinimumZoneReports) {
  const std::string dir = testsupport::ScratchDir("cmm_estimators");
  WriteText(dir + "/ball.xyz", TenPointSphere(false));
  for (const std::string e : {"least-squares", "minimum-zone"}) {
    const auto r = RunCommand(kCli + " fit " + dir + "/ball.xyz --model sphere --estimator " + e +
                              " --out " + dir + "/fit.json --report " + dir + "/report.json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("estimator " + e), std::string::npos) << r.out;
    const json report = ReadJson(dir + "/report.json");
    EXPECT_EQ(report["estimator"], e);
    EXPECT_EQ(report["inliers"], 9);
    // Exact points: every figure at rounding level.
    EXPECT_LT(report["form"]["form_error"].get<double>(), 1e-12);
    EXPECT_NEAR(ReadJson(dir + "/fit.json")["root"]["radius"].get<double>(), 2.0, 1e-12);
    if (e == "minimum-zone") {
      EXPECT_TRUE(report["zone"]["optimality_verified"].get<bool>());
      // A zone at rounding level (exact points): no meaningful contact set; at most k + 1.
      EXPECT_LE(report["zone"]["contacts"].size(), 5u);
      EXPECT_LT(report["zone"]["width"].get<double>(), 1e-12);
    }
  }
}

TEST(MetrologyCli, DegenerateSetsExitOneWithTheReason) {
  const std::string dir = testsupport::ScratchDir("cmm_degenerate");
  std::ostringstream line, flat;
  for (int i = 0; i < 8; ++i) line << 1 + i << " " << 2 + 2 * i << " " << -i << "\n";
  for (int i = 0; i < 12; ++i)
    flat << std::cos(i) * (1 + 0.1 * i) << " " << std::sin(i) * (1 + 0.1 * i) << " 3\n";
  WriteText(dir + "/line.xyz", line.str());
  WriteText(dir + "/flat.xyz", flat.str());
  auto r = RunCommand(kCli + " fit " + dir + "/line.xyz --model plane --out " + dir + "/p.json");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("collinear"), std::string::npos) << r.err;
  r = RunCommand(kCli + " fit " + dir +
                 "/flat.xyz --model sphere --estimator least-squares --out " + dir + "/s.json");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("coplanar"), std::string::npos) << r.err;
  WriteText(dir + "/four.xyz", "1 0 0\n0 1 0\n0 0 1\n-1 0 0\n");
  r = RunCommand(kCli + " fit " + dir + "/four.xyz --model sphere --out " + dir + "/s.json");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("at least 5 points"), std::string::npos) << r.err;
  EXPECT_FALSE(testsupport::FileExists(dir + "/s.json"));
  r = RunCommand(kCli + " fit " + dir + "/four.xyz --model sphere --estimator chebyshev --out " +
                 dir + "/s.json");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--estimator"), std::string::npos) << r.err;
}

TEST(MetrologyCli, BatchPassesTheEstimatorThrough) {
  const std::string dir = testsupport::ScratchDir("cmm_batch");
  WriteText(dir + "/ball.xyz", TenPointSphere(false));
  const auto r = RunCommand(
      kCli + " batch " + dir +
      "/ball.xyz --model sphere --estimator minimum-zone --jobs 1 --out-dir " + dir + "/out");
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  const json report = ReadJson(dir + "/out/ball.report.json");
  EXPECT_EQ(report["estimator"], "minimum-zone");
  EXPECT_TRUE(report["zone"]["optimality_verified"].get<bool>());
}

// --resume keeps an earlier result only when it was made with the same estimator: a robust
// result is refitted for --estimator minimum-zone, and the minimum-zone result then kept.
// --resume reuses only results made with the same settings (issue 26): a changed estimator is
// refused, naming it, and the stored results stay; a run without --resume refits.
TEST(MetrologyCli, BatchResumeRefusesAChangedEstimator) {
  const std::string dir = testsupport::ScratchDir("cmm_batch_resume");
  WriteText(dir + "/ball.xyz", TenPointSphere(false));
  const std::string batch = kCli + " batch " + dir +
                            "/ball.xyz --model sphere --jobs 1 --out-dir " + dir + "/out";
  const auto robust = RunCommand(batch + " --resume");
  ASSERT_EQ(robust.exit_code, 0) << robust.err << robust.out;
  EXPECT_EQ(ReadJson(dir + "/out/ball.report.json")["estimator"], "robust");
  const auto changed = RunCommand(batch + " --resume --estimator minimum-zone");
  EXPECT_EQ(changed.exit_code, 2) << changed.err << changed.out;
  EXPECT_NE(changed.err.find("estimator"), std::string::npos) << changed.err;
  EXPECT_EQ(ReadJson(dir + "/out/ball.report.json")["estimator"], "robust");
  const auto zone = RunCommand(batch + " --estimator minimum-zone");
  ASSERT_EQ(zone.exit_code, 0) << zone.err << zone.out;
  EXPECT_NE(zone.out.find("1 fitted, 0 skipped"), std::string::npos) << zone.out;
  EXPECT_EQ(ReadJson(dir + "/out/ball.report.json")["estimator"], "minimum-zone");
  const auto again = RunCommand(batch + " --resume --estimator minimum-zone");
  ASSERT_EQ(again.exit_code, 0) << again.err << again.out;
  EXPECT_NE(again.out.find("0 fitted, 1 skipped"), std::string::npos) << again.out;
}

}  // namespace
