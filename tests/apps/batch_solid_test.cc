// `implicitfit batch --model solid`: one `reconstruct` (detect, then the solid) per cloud. Two
// sharp boxes of known sizes sampled by `sample` must come back as solids whose face planes are
// the truth's (normals and offsets compared with the generating boxes), an unreadable cloud is
// an error row without outputs, and --resume skips complete inputs and redoes one whose model was
// deleted or whose report a kill truncated.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_command.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using testsupport::FileExists;
using testsupport::RunCommand;
using testsupport::ScratchDir;
using testsupport::Slurp;
using testsupport::WriteText;

const std::string kCli = IMPLICITFIT_CLI;

struct Box {
  std::string name;
  double half[3];
};

void WriteSharpBox(const std::string& path, const Box& box) {
  std::string planes;
  for (int a = 0; a < 3; ++a)
    for (int s = -1; s <= 1; s += 2) {
      double n[3] = {0, 0, 0};
      n[a] = s;
      planes += std::string(planes.empty() ? "" : ",") + R"({"type": "plane", "normal": [)" +
                std::to_string(n[0]) + "," + std::to_string(n[1]) + "," + std::to_string(n[2]) +
                R"(], "offset": )" + std::to_string(box.half[a]) + "}";
    }
  WriteText(path,
            R"({"format": "implicitfit-model", "version": 1, "root": {"type": "intersection",)"
            R"( "delta": 0.1, "epsilon": 0.05, "order": 0, "children": [)" +
                planes + "]}}");
}

// Every plane of a model file (any depth of the tree): unit normal and offset (n . x = offset).
void CollectPlanes(const json& node, std::vector<std::pair<Eigen::Vector3d, double>>* planes) {
  if (node.value("type", "") == "plane") {
    Eigen::Vector3d n(node["normal"][0].get<double>(), node["normal"][1].get<double>(),
                      node["normal"][2].get<double>());
    const double scale = n.norm();
    planes->emplace_back(n / scale, node["offset"].get<double>() / scale);
  }
  if (node.contains("children"))
    for (const json& child : node["children"]) CollectPlanes(child, planes);
}

// The status field of the summary.csv row of an input (paths here have no commas or quotes).
std::string Status(const std::string& csv, const std::string& input) {
  std::istringstream lines(Slurp(csv));
  std::string line;
  while (std::getline(lines, line))
    if (line.rfind(input + ",", 0) == 0) {
      const size_t start = input.size() + 1;
      return line.substr(start, line.find(',', start) - start);
    }
  return "(no row)";
}

TEST(BatchSolid, ReconstructsEachCloudAndResumes) {
  const std::string dir = ScratchDir("batch_solid");
  const double noise = 0.002;
  const std::vector<Box> boxes = {{"wide", {0.5, 0.4, 0.3}}, {"tall", {0.3, 0.35, 0.6}}};
  std::vector<std::string> clouds;
  for (const Box& b : boxes) {
    WriteSharpBox(dir + "/" + b.name + ".truth.json", b);
    clouds.push_back(dir + "/" + b.name + ".xyz");
    ASSERT_EQ(RunCommand(kCli + " sample " + dir + "/" + b.name + ".truth.json --count 6000" +
                         " --noise " + std::to_string(noise) + " --seed 5 --out " + clouds.back())
                  .exit_code,
              0);
  }
  const std::string bad = dir + "/broken.xyz";
  WriteText(bad, "1 2 3\nnot a number\n");
  const std::string out = dir + "/out";
  const std::string command = kCli + " batch " + clouds[0] + " " + clouds[1] +
                              " --model solid --out-dir " + out + " --jobs 2";
  const auto r = RunCommand(command + " " + bad);
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;  // one input failed
  EXPECT_EQ(Status(out + "/summary.csv", clouds[0]), "ok");
  EXPECT_EQ(Status(out + "/summary.csv", clouds[1]), "ok");
  EXPECT_EQ(Status(out + "/summary.csv", bad), "error");
  EXPECT_FALSE(FileExists(out + "/broken.model.json"));
  EXPECT_FALSE(FileExists(out + "/broken.report.json"));

  for (size_t i = 0; i < boxes.size(); ++i) {
    const json report = json::parse(Slurp(out + "/" + boxes[i].name + ".report.json"));
    EXPECT_TRUE(report["success"].get<bool>());
    EXPECT_TRUE(report["bounded"].get<bool>());
    EXPECT_GE(report["normal_sign_agreement"].get<double>(), 0.99);
    EXPECT_LE(report["rms_distance"].get<double>(), 1.5 * noise);
    // Each face of the generating box is a plane of the model (normal within 1 degree, offset
    // within 3 noise levels).
    std::vector<std::pair<Eigen::Vector3d, double>> planes;
    CollectPlanes(json::parse(Slurp(out + "/" + boxes[i].name + ".model.json"))["root"], &planes);
    for (int a = 0; a < 3; ++a)
      for (int s : {-1, 1}) {
        Eigen::Vector3d n = Eigen::Vector3d::Zero();
        n[a] = s;
        bool found = false;
        for (const auto& [m, offset] : planes)
          found |=
              m.dot(n) > std::cos(M_PI / 180) && std::abs(offset - boxes[i].half[a]) < 3 * noise;
        EXPECT_TRUE(found) << boxes[i].name << " face " << a << (s > 0 ? "+" : "-");
      }
  }

  // Resume after a kill: one model deleted, one report truncated, a temporary left behind.
  const std::string wide_model = out + "/wide.model.json";
  const auto wide_time = fs::last_write_time(out + "/tall.model.json");
  const std::string first = Slurp(wide_model);
  fs::remove(wide_model);
  WriteText(out + "/tall.report.json", "{\"success\": tr");
  WriteText(out + "/.tall.model.json.implicitfit-99999999-0.tmp", "{");
  auto again = RunCommand(command + " --resume");
  EXPECT_EQ(again.exit_code, 0) << again.out << again.err;
  EXPECT_EQ(Status(out + "/summary.csv", clouds[0]), "ok");
  EXPECT_EQ(Status(out + "/summary.csv", clouds[1]), "ok");
  EXPECT_EQ(Slurp(wide_model), first) << "same seed, same solid";
  EXPECT_TRUE(json::parse(Slurp(out + "/tall.report.json"))["success"].get<bool>());
  EXPECT_NE(fs::last_write_time(out + "/tall.model.json"), wide_time) << "redone";
  EXPECT_FALSE(FileExists(out + "/.tall.model.json.implicitfit-99999999-0.tmp"));
  // Everything complete now: nothing is redone.
  const auto tall_time = fs::last_write_time(out + "/tall.model.json");
  again = RunCommand(command + " --resume");
  EXPECT_EQ(again.exit_code, 0);
  EXPECT_EQ(Status(out + "/summary.csv", clouds[0]), "skipped");
  EXPECT_EQ(Status(out + "/summary.csv", clouds[1]), "skipped");
  EXPECT_EQ(fs::last_write_time(out + "/tall.model.json"), tall_time);
}

TEST(BatchSolid, OptionsOfOtherKindsAreRefused) {
  const std::string dir = ScratchDir("batch_solid_bad");
  const auto r = RunCommand(kCli + " batch " + dir + " --model solid --fix radius=1 --out-dir " +
                            dir + "/out");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--fix"), std::string::npos) << r.err;
}

}  // namespace
