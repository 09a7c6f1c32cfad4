// `implicitfit check` end to end: verdicts and min_eigenvalue on thousands of random patches
// against A^mu built longhand and Eigen's iterative eigen solver (tests/oracle), quadrics of
// known definiteness (A = 2/(k(k-1)) E^T Q E), the exact JSON shape, the human table, exit
// codes, and the --sample second opinion (never contradicts a certificate).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <nlohmann/json.hpp>
#include <random>

#include "oracle/bernstein_oracle.h"
#include "support/random_patches.h"
#include "support/run_command.h"

namespace {

using nlohmann::json;
using testsupport::RunCommand;
using testsupport::WriteText;
const std::string kCli = IMPLICITFIT_CLI;

json PatchNode(int k, const std::array<Eigen::Vector3d, 4>& corners, const std::vector<double>& b) {
  json vertices = json::array();
  for (const auto& v : corners) vertices.push_back({v[0], v[1], v[2]});
  return {
      {"type", "bernstein_patch"}, {"degree", k}, {"vertices", vertices}, {"control_points", b}};
}

json Document(const std::vector<json>& patches) {
  json root;
  if (patches.size() == 1) {
    root = patches[0];
  } else {
    root = {{"type", "union"}, {"delta", 0.1}, {"epsilon", 0.1}, {"order", 2}};
    root["children"] = patches;
  }
  return {{"format", "implicitfit-model"}, {"version", 1}, {"root", root}};
}

struct Expected {
  int degree;
  oracle::Certificate certificate;
};

TEST(CheckCommand, VerdictsAndMarginsOnThousandsOfRandomPatches) {
  const std::string dir = testsupport::ScratchDir("check_random");
  std::mt19937 rng(71);
  std::vector<std::vector<Expected>> expected(4);
  std::string files;
  int convex = 0, total = 0;
  for (int f = 0; f < 4; ++f) {
    std::vector<json> patches;
    for (int i = 0; i < 600; ++i) {
      const int k = 2 + (i % 4);
      const std::vector<double> b = testsupport::RandomMixedPatch(rng, k);
      patches.push_back(PatchNode(k, testsupport::RandomCorners(rng), b));
      expected[f].push_back({k, oracle::Certify(k, b)});
      convex += expected[f].back().certificate.convex;
      ++total;
    }
    const std::string path = dir + "/m" + std::to_string(f) + ".json";
    WriteText(path, Document(patches).dump());
    files += " " + path;
  }
  ASSERT_GT(convex, total / 10);
  ASSERT_LT(convex, total - total / 10);

  const auto r = RunCommand(kCli + " check --json" + files);
  EXPECT_EQ(r.exit_code, 1) << r.err;  // some are not convex
  const json report = json::parse(r.out);
  EXPECT_EQ(report["convex"], false);
  ASSERT_EQ(report["files"].size(), 4u);
  for (int f = 0; f < 4; ++f) {
    const json& file = report["files"][f];
    EXPECT_EQ(file["file"], dir + "/m" + std::to_string(f) + ".json");
    ASSERT_EQ(file["patches"].size(), expected[f].size());
    bool all = true;
    for (size_t i = 0; i < expected[f].size(); ++i) {
      const json& p = file["patches"][i];
      const oracle::Certificate& e = expected[f][i].certificate;
      EXPECT_EQ(p["degree"], expected[f][i].degree);
      EXPECT_EQ(p["convex"], e.convex) << "file " << f << " patch " << i;
      EXPECT_NEAR(p["min_eigenvalue"].get<double>(), e.min_eigenvalue,
                  1e-9 * std::abs(e.min_eigenvalue) + 1e-14 * e.scale);
      all &= e.convex;
    }
    EXPECT_EQ(file["convex"], all);
  }
}

TEST(CheckCommand, JsonHasExactlyTheContractShape) {
  const std::string dir = testsupport::ScratchDir("check_shape");
  std::mt19937 rng(72);
  WriteText(dir + "/a.json", Document({PatchNode(2, testsupport::RandomCorners(rng),
                                                 testsupport::RandomMixedPatch(rng, 2))})
                                 .dump());
  const auto r = RunCommand(kCli + " check --json " + dir + "/a.json");
  ASSERT_NE(r.exit_code, 2) << r.err;
  const nlohmann::ordered_json report = nlohmann::ordered_json::parse(r.out);
  auto keys = [](const nlohmann::ordered_json& o) {
    std::vector<std::string> k;
    for (auto it = o.begin(); it != o.end(); ++it) k.push_back(it.key());
    return k;
  };
  // The contract's keys come first, in order; later fields are additive (issue #12: "tree",
  // "nodes" per file, the G-2/G-3/G-4 fields per patch).
  auto starts_with = [](std::vector<std::string> all, const std::vector<std::string>& head) {
    all.resize(std::min(all.size(), head.size()));
    return all == head;
  };
  EXPECT_TRUE(starts_with(keys(report), {"convex", "files"}));
  EXPECT_TRUE(starts_with(keys(report["files"][0]), {"file", "convex", "patches"}));
  EXPECT_TRUE(
      starts_with(keys(report["files"][0]["patches"][0]), {"degree", "convex", "min_eigenvalue"}));
}

// A quadric x^T Q x + 2 b.x + c has Hessian 2Q = k(k-1) E^-T A E^-1, so A^mu = 2/(k(k-1)) E^T Q E.
// Its degree-2 control points are b_ij = X_i^T G X_j (homogeneous vertices; derived here
// independently of model/bernstein/bernstein_conversion).
TEST(CheckCommand, QuadricPatchesGetTheirMatrixVerdict) {
  const std::string dir = testsupport::ScratchDir("check_quadric");
  std::mt19937 rng(73);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Eigen::Vector3d spectra[] = {Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(-1, 2, 3),
                                     Eigen::Vector3d(0.2, 0.3, -0.1),
                                     Eigen::Vector3d(0.5, 0.5, 0.5)};
  for (const Eigen::Vector3d& spectrum : spectra) {
    const auto corners = testsupport::RandomCorners(rng);
    const Eigen::Matrix3d q = testsupport::RandomSymmetric(rng, spectrum);
    Eigen::Matrix4d g = Eigen::Matrix4d::Zero();
    g.topLeftCorner<3, 3>() = q;
    g.topRightCorner<3, 1>() = g.bottomLeftCorner<1, 3>().transpose() =
        Eigen::Vector3d(u(rng), u(rng), u(rng));
    g(3, 3) = u(rng);
    std::vector<double> b;
    for (const oracle::MultiIndex& l : oracle::DesignOrder(2)) {
      std::vector<int> ij;
      for (int i = 0; i < 4; ++i)
        for (int m = 0; m < l[i]; ++m) ij.push_back(i);
      Eigen::Vector4d xi, xj;
      xi << corners[ij[0]], 1.0;
      xj << corners[ij[1]], 1.0;
      b.push_back(xi.dot(g * xj));
    }
    WriteText(dir + "/q.json", Document({PatchNode(2, corners, b)}).dump());
    const auto r = RunCommand(kCli + " check --json " + dir + "/q.json");
    Eigen::Matrix3d e;
    for (int i = 0; i < 3; ++i) e.col(i) = corners[i] - corners[3];
    const double lmin =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(e.transpose() * q * e).eigenvalues()(0);
    const bool definite = spectrum.minCoeff() > 0;
    EXPECT_EQ(r.exit_code, definite ? 0 : 1) << r.err;
    const json report = json::parse(r.out);
    EXPECT_EQ(report["convex"], definite);
    EXPECT_NEAR(report["files"][0]["patches"][0]["min_eigenvalue"].get<double>(), lmin,
                1e-9 * std::abs(lmin));
  }
}

TEST(CheckCommand, ConvexFilesExit0AndDegreeOneIsConvexWithZeroMargin) {
  const std::string dir = testsupport::ScratchDir("check_convex");
  std::mt19937 rng(74);
  std::vector<json> patches = {PatchNode(1, testsupport::RandomCorners(rng), {1, -2, 0.5, 3})};
  while (patches.size() < 20) {
    const std::vector<double> b = testsupport::RandomMixedPatch(rng, 3);
    if (oracle::Certify(3, b).convex)
      patches.push_back(PatchNode(3, testsupport::RandomCorners(rng), b));
  }
  // One file per patch: each is certified convex on its tetrahedron (issue 28: the union of
  // all of them in one file is not convex, whatever its patches are).
  std::string files;
  for (size_t i = 0; i < patches.size(); ++i) {
    WriteText(dir + "/c" + std::to_string(i) + ".json", Document({patches[i]}).dump());
    files += " " + dir + "/c" + std::to_string(i) + ".json";
  }
  const auto r = RunCommand(kCli + " check --json" + files);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const json report = json::parse(r.out);
  EXPECT_EQ(report["convex"], true);
  EXPECT_EQ(report["files"][0]["patches"][0]["degree"], 1);
  EXPECT_EQ(report["files"][0]["patches"][0]["convex"], true);
  EXPECT_EQ(report["files"][0]["patches"][0]["min_eigenvalue"], 0.0);
  // The human table: one row per patch and a verdict line.
  const auto h = RunCommand(kCli + " check" + files);
  EXPECT_EQ(h.exit_code, 0);
  EXPECT_NE(h.out.find("c0.json"), std::string::npos) << h.out;
  EXPECT_NE(h.out.find("every file certified convex"), std::string::npos) << h.out;
  // All of them in one union: every patch certified, the file not (the union is refused).
  WriteText(dir + "/u.json", Document(patches).dump());
  const auto u = RunCommand(kCli + " check --json " + dir + "/u.json");
  EXPECT_EQ(u.exit_code, 1) << u.err;
  const json ur = json::parse(u.out);
  EXPECT_EQ(ur["convex"], false);
  for (const json& p : ur["files"][0]["patches"]) EXPECT_EQ(p["convex"], true);
}

TEST(CheckCommand, UnreadableOrInvalidInputExits2NamingTheFileWithNoOutput) {
  const std::string dir = testsupport::ScratchDir("check_bad");
  std::mt19937 rng(75);
  WriteText(dir + "/good.json", Document({PatchNode(2, testsupport::RandomCorners(rng),
                                                    testsupport::RandomMixedPatch(rng, 2))})
                                    .dump());
  json flat =
      Document({PatchNode(2, testsupport::RandomCorners(rng), std::vector<double>(10, 1.0))});
  flat["root"]["vertices"][3] = flat["root"]["vertices"][0];
  WriteText(dir + "/flat.json", flat.dump());
  json short_cp =
      Document({PatchNode(3, testsupport::RandomCorners(rng), std::vector<double>(10, 1.0))});
  WriteText(dir + "/short.json", short_cp.dump());
  WriteText(dir + "/broken.json", "{\"format\": ");
  struct Case {
    std::string args, fragment;
  } cases[] = {
      {dir + "/missing.json", "missing.json"},
      {dir + "/good.json " + dir + "/flat.json",
       "flat.json: invalid model: root.vertices: tetrahedron is degenerate"},
      {dir + "/short.json",
       "short.json: invalid model: root.control_points: must be an array of 20"},
      {dir + "/broken.json --json", "broken.json: invalid JSON"},
  };
  for (const Case& c : cases) {
    const auto r = RunCommand(kCli + " check " + c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args;
    EXPECT_NE(r.err.find(c.fragment), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
  EXPECT_EQ(RunCommand(kCli + " check").exit_code, 2);
  EXPECT_EQ(RunCommand(kCli + " check --sample 0 " + dir + "/good.json").exit_code, 2);
}

TEST(CheckCommand, SamplingNeverContradictsTheCertificate) {
  const std::string dir = testsupport::ScratchDir("check_sample");
  std::mt19937 rng(76);
  std::vector<json> patches;
  for (int i = 0; i < 400; ++i) {
    const int k = 2 + i % 3;
    // Every patch on the tetrahedron around the origin, where the random patches have zeros.
    const std::array<Eigen::Vector3d, 4> corners = {
        Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(1, -1, -1), Eigen::Vector3d(-1, 1, -1),
        Eigen::Vector3d(-1, -1, 1)};
    patches.push_back(PatchNode(k, corners, testsupport::RandomMixedPatch(rng, k)));
  }
  WriteText(dir + "/s.json", Document(patches).dump());
  const auto r = RunCommand(kCli + " check --json --sample 200 " + dir + "/s.json");
  ASSERT_NE(r.exit_code, 2) << r.err;
  const json report = json::parse(r.out);
  const json& s = report["sample"];
  EXPECT_EQ(s["contradictions"], 0);
  int certified = 0;
  for (const json& p : report["files"][0]["patches"]) {
    certified += p["convex"].get<bool>();
    if (p["convex"].get<bool>()) {
      EXPECT_EQ(p["sample"]["violations"], 0);
    }
  }
  EXPECT_EQ(s["conservative"].get<int>() + s["confirmed"].get<int>() + s["undecided"].get<int>(),
            400 - certified);
  EXPECT_GT(s["confirmed"].get<int>(), 0);  // the sampler does find non-convex zero sets
  std::cout << "[ sample   ] certified " << certified << " of 400; not certified: confirmed "
            << s["confirmed"] << ", conservative " << s["conservative"] << ", undecided "
            << s["undecided"] << "\n";
}

}  // namespace
