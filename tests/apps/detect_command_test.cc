// `implicitfit detect` end to end: a generated scene gives a scene file that the scene reader
// accepts, labels that match it and a segmented PLY; random points exit 1 without output;
// hostile inputs exit 2 naming the file, without output.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>
#include <string>

#include "datasets/io/scene_file.h"
#include "datasets/generators/scene_generator.h"
#include "datasets/clouds/xyz_writer.h"
#include "support/run_command.h"

namespace implicitfit {
namespace {

using testsupport::FileExists;
using testsupport::RunCommand;
const std::string kCli = IMPLICITFIT_CLI;

TEST(DetectCli, GeneratedSceneWritesSceneLabelsAndPly) {
  const std::string dir = testsupport::ScratchDir("detect_cli_scene");
  GeneratedSceneOptions o;
  o.seed = 2;
  const GeneratedScene g = GenerateScene(o);
  WriteXyzFile(g.cloud, dir + "/scene.xyz");
  const auto r = RunCommand(kCli + " detect " + dir + "/scene.xyz --out " + dir +
                            "/scene.json --labels " + dir + "/labels.txt --ply " + dir +
                            "/seg.ply --report " + dir + "/report.json --seed 3");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Scene scene = ReadSceneFile(dir + "/scene.json");
  EXPECT_EQ(scene.points, static_cast<int>(g.cloud.size()));
  EXPECT_GE(scene.primitives.size(), 5u);
  const std::vector<int> labels =
      ReadLabelsFile(dir + "/labels.txt", static_cast<int>(scene.primitives.size()),
                     static_cast<long>(g.cloud.size()));
  std::vector<int> count(scene.primitives.size(), 0);
  int unassigned = 0;
  for (int l : labels) l >= 0 ? ++count[l] : ++unassigned;
  EXPECT_EQ(unassigned, scene.unassigned);
  for (size_t k = 0; k < scene.primitives.size(); ++k) {
    const ScenePrimitive& p = scene.primitives[k];
    EXPECT_EQ(count[k], p.points);
    EXPECT_EQ(p.name, "p" + std::to_string(k));
    EXPECT_FALSE(p.standard_deviations.empty());
    // The generated normals are outward: every primitive's side is known and outward.
    EXPECT_EQ(p.normal_side, "outward") << p.name;
    // RMS recomputed from the labels through the model.
    double ss = 0;
    for (size_t i = 0; i < labels.size(); ++i)
      if (labels[i] == static_cast<int>(k)) ss += std::pow(p.model.Value(g.cloud.points[i]), 2);
    EXPECT_NEAR(std::sqrt(ss / p.points), p.rms_distance, 1e-9 + 1e-6 * p.rms_distance);
  }
  const std::string ply = testsupport::Slurp(dir + "/seg.ply");
  EXPECT_NE(ply.find("property int label"), std::string::npos);
  EXPECT_NE(ply.find("residual"), std::string::npos);
  EXPECT_TRUE(FileExists(dir + "/report.json"));
}

TEST(DetectCli, RandomPointsExit1WithoutScene) {
  const std::string dir = testsupport::ScratchDir("detect_cli_random");
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-1, 1);
  std::ofstream out(dir + "/random.xyz");
  for (int i = 0; i < 2000; ++i) out << u(rng) << " " << u(rng) << " " << u(rng) << "\n";
  out.close();
  const auto r = RunCommand(kCli + " detect " + dir + "/random.xyz --out " + dir +
                            "/scene.json --labels " + dir + "/labels.txt");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.err.find("random.xyz"), std::string::npos);
  EXPECT_FALSE(FileExists(dir + "/scene.json"));
  EXPECT_FALSE(FileExists(dir + "/labels.txt"));
}

TEST(DetectCli, HostileInputsExit2NamingTheFileWithoutOutput) {
  const std::string dir = testsupport::ScratchDir("detect_cli_hostile");
  std::mt19937 rng(5);
  std::string noise(2000, '\0');
  for (char& c : noise) c = static_cast<char>(rng());
  const std::vector<std::pair<std::string, std::string>> files = {
      {"empty.xyz", ""},
      {"garbage.xyz", "not a cloud\n"},
      {"nan.xyz", "1 2 3\n4 nan 6\n7 8 9\n"},
      {"random.ply", noise},
      {"truncated.ply",
       "ply\nformat binary_little_endian 1.0\nelement vertex 100\nproperty float x\n"
       "property float y\nproperty float z\nend_header\n" +
           std::string(50, '\1')},
  };
  for (const auto& [name, content] : files) testsupport::WriteText(dir + "/" + name, content);
  std::vector<std::string> names;
  for (const auto& f : files) names.push_back(f.first);
  names.push_back("missing.xyz");
  for (const std::string& name : names) {
    const auto r =
        RunCommand(kCli + " detect " + dir + "/" + name + " --out " + dir +
                   "/scene.json --labels " + dir + "/labels.txt --ply " + dir + "/seg.ply");
    EXPECT_EQ(r.exit_code, 2) << name << ": " << r.err;
    EXPECT_NE(r.err.find(name), std::string::npos) << r.err;
    EXPECT_FALSE(FileExists(dir + "/scene.json")) << name;
    EXPECT_FALSE(FileExists(dir + "/labels.txt")) << name;
    EXPECT_FALSE(FileExists(dir + "/seg.ply")) << name;
  }
  // Bad options: an unknown kind exits 2 before reading anything.
  testsupport::WriteText(dir + "/ok.xyz", "0 0 0\n1 0 0\n0 1 0\n");
  const auto k = RunCommand(kCli + " detect " + dir + "/ok.xyz --out " + dir +
                            "/scene.json --kinds plane,blob");
  EXPECT_EQ(k.exit_code, 2);
  EXPECT_NE(k.err.find("blob"), std::string::npos);
}

TEST(DetectCli, BatchSceneWritesSceneAndLabelsPerInputAndResumes) {
  const std::string dir = testsupport::ScratchDir("detect_cli_batch");
  for (unsigned seed : {4u, 5u}) {
    GeneratedSceneOptions o;
    o.seed = seed;
    o.ground_points = 2000;
    o.object_points = 600;
    WriteXyzFile(GenerateScene(o).cloud, dir + "/s" + std::to_string(seed) + ".xyz");
  }
  testsupport::WriteText(dir + "/bad.xyz", "not a cloud\n");
  const std::string command = kCli + " batch " + dir + "/s4.xyz " + dir + "/s5.xyz " + dir +
                              "/bad.xyz --model scene --out-dir " + dir + "/out --jobs 2";
  const auto r = RunCommand(command);
  EXPECT_EQ(r.exit_code, 1) << r.err;  // one input failed
  for (const std::string name : {"s4", "s5"}) {
    const Scene scene = ReadSceneFile(dir + "/out/" + name + ".scene.json");
    EXPECT_GE(scene.primitives.size(), 5u) << name;
    const std::vector<int> labels =
        ReadLabelsFile(dir + "/out/" + name + ".labels.txt",
                       static_cast<int>(scene.primitives.size()), scene.points);
    EXPECT_EQ(static_cast<int>(labels.size()), scene.points);
  }
  EXPECT_FALSE(FileExists(dir + "/out/bad.scene.json"));
  const std::string summary = testsupport::Slurp(dir + "/out/summary.csv");
  EXPECT_NE(summary.find("s4.xyz,ok"), std::string::npos) << summary;
  EXPECT_NE(summary.find("bad.xyz,error"), std::string::npos) << summary;
  // Resume: the complete inputs are skipped, the bad one retried.
  const auto again = RunCommand(command + " --resume");
  EXPECT_EQ(again.exit_code, 1);
  const std::string resumed = testsupport::Slurp(dir + "/out/summary.csv");
  EXPECT_NE(resumed.find("s4.xyz,skipped"), std::string::npos) << resumed;
  EXPECT_NE(resumed.find("s5.xyz,skipped"), std::string::npos) << resumed;
}

}  // namespace
}  // namespace implicitfit
