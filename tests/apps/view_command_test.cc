// `implicitfit view` and the --view pages of fit, detect, reconstruct and batch, end to end, on
// what the pages hold (the drawing is tested in a browser by tests/view/): bad input exits 2
// naming the file and writes no page (an existing page untouched); --png without Chromium
// exits 2 saying so before anything is written; `fit --ply` writes f of the fitted model at
// every point with the inliers labelled; detect's page carries its labels and legend; the
// pages of reconstruct and batch, and batch's index linking them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "datasets/clouds/cloud_file.h"
#include "datasets/clouds/xyz_writer.h"
#include "datasets/generators/scene_generator.h"
#include "datasets/io/model_file.h"
#include "datasets/io/scene_file.h"
#include "support/base64_decode.h"
#include "support/run_command.h"

namespace implicitfit {
namespace {

using nlohmann::json;
using testsupport::FileExists;
using testsupport::RunCommand;
using testsupport::ScratchDir;
using testsupport::Slurp;
using testsupport::WriteText;

const std::string kCli = IMPLICITFIT_CLI;
const std::string kSphere =
    R"({"format": "implicitfit-model", "version": 1, "root": {"type": "sphere", "center": [0, 0, 0], "radius": 1}})";

json PageData(const std::string& page) {
  const std::string html = Slurp(page);
  const std::string open = "<script id=\"implicitfit-view-data\" type=\"application/json\">";
  const size_t begin = html.find(open);
  if (begin == std::string::npos) return json();
  const size_t end = html.find("</script>", begin);
  return json::parse(html.substr(begin + open.size(), end - begin - open.size()));
}

template <typename T>
std::vector<T> Array(const std::string& base64) {
  const std::vector<unsigned char> bytes = testsupport::Base64Decode(base64);
  std::vector<T> out(bytes.size() / sizeof(T));
  std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
  return out;
}

TEST(ViewCli, BadInputExits2NamingTheFileAndWritesNoPage) {
  const std::string dir = ScratchDir("view_bad");
  WriteText(dir + "/sphere.json", kSphere);
  WriteText(dir + "/other.json", R"({"format": "something-else"})");
  WriteText(dir + "/bad.xyz", "0 0 0\n1 2 x\n");
  WriteText(dir + "/lost.json", R"({"format": "implicitfit-scene", "version": 1, "cloud": "nowhere.xyz",
    "points": 3, "unassigned": 0, "primitives": [{"name": "p0", "model": {"type": "plane",
    "normal": [0, 0, 1], "offset": 0}, "points": 3, "rms_distance": 0.001, "normal_side": "outward"}]})");
  WriteText(dir + "/page.html", "an earlier page");
  const struct {
    std::string input, named;
  } cases[] = {{dir + "/missing.xyz", "missing.xyz"},
               {dir + "/other.json", "other.json"},
               {dir + "/bad.xyz", "bad.xyz:2"},
               {dir + "/lost.json", "nowhere.xyz"},
               {dir + "/unreadable_dir.ply", "unreadable_dir.ply"}};
  std::filesystem::create_directory(dir + "/unreadable_dir.ply");
  for (const auto& c : cases) {
    const auto r = RunCommand(kCli + " view " + dir + "/sphere.json " + c.input + " --out " + dir +
                              "/page.html");
    EXPECT_EQ(r.exit_code, 2) << c.input << r.err;
    EXPECT_NE(r.err.find(c.named), std::string::npos) << r.err;
    EXPECT_EQ(Slurp(dir + "/page.html"), "an earlier page") << c.input;
  }
  // Usage: no output, a bad clipping plane, a bad colour mode.
  EXPECT_EQ(RunCommand(kCli + " view " + dir + "/sphere.json").exit_code, 2);
  for (const std::string& option : {"--clip w,0.5", "--clip z,2", "--color rainbow"}) {
    const auto r = RunCommand(kCli + " view " + dir + "/sphere.json --out " + dir + "/p2.html " + option);
    EXPECT_EQ(r.exit_code, 2) << option;
    EXPECT_FALSE(FileExists(dir + "/p2.html")) << option;
  }
}

TEST(ViewCli, PngWithoutChromiumExits2SayingSoAndWritesNothing) {
  const std::string dir = ScratchDir("view_no_chromium");
  WriteText(dir + "/sphere.json", kSphere);
  const auto r = RunCommand("PATH=/nonexistent IMPLICITFIT_CHROMIUM= " + kCli + " view " + dir +
                            "/sphere.json --out " + dir + "/page.html --png " + dir + "/p.png");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("Chromium"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("apt-get install chromium"), std::string::npos) << r.err;
  EXPECT_FALSE(FileExists(dir + "/page.html"));
  EXPECT_FALSE(FileExists(dir + "/p.png"));
  // The page alone needs no browser.
  const auto page = RunCommand("PATH=/nonexistent " + kCli + " view " + dir + "/sphere.json --out " +
                               dir + "/page.html --quiet");
  EXPECT_EQ(page.exit_code, 0) << page.err;
  const json data = PageData(dir + "/page.html");
  ASSERT_EQ(data["layers"].size(), 1u);
  EXPECT_EQ(data["layers"][0]["type"], "mesh");
  EXPECT_GT(data["layers"][0]["triangle_count"].get<int>(), 1000);
}

TEST(ViewCli, FitWritesItsPageAndTheResidualCloud) {
  const std::string dir = ScratchDir("view_fit");
  WriteText(dir + "/truth.json", kSphere);
  ASSERT_EQ(RunCommand(kCli + " sample " + dir + "/truth.json --count 2000 --noise 0.01 --outliers 0.1 "
                       "--seed 2 --out " + dir + "/cloud.xyz").exit_code, 0);
  const auto r = RunCommand(kCli + " fit " + dir + "/cloud.xyz --model sphere --out " + dir +
                            "/fit.json --report " + dir + "/report.json --view " + dir +
                            "/fit.html --ply " + dir + "/residuals.ply");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Model model = ReadModelFile(dir + "/fit.json");
  CloudFileInfo info;
  const PointCloud cloud = ReadCloudFile(dir + "/residuals.ply", &info);
  const PointCloud input = ReadCloudFile(dir + "/cloud.xyz");
  ASSERT_EQ(cloud.size(), input.size());
  ASSERT_EQ(info.residuals.size(), cloud.size());
  ASSERT_EQ(info.labels.size(), cloud.size());
  int inliers = 0;
  for (size_t i = 0; i < cloud.size(); ++i) {
    EXPECT_NEAR(info.residuals[i], model.Value(input.points[i]), 1e-12) << i;
    inliers += info.labels[i] == 0;
    EXPECT_TRUE(info.labels[i] == 0 || info.labels[i] == -1);
  }
  EXPECT_EQ(inliers, json::parse(Slurp(dir + "/report.json"))["inliers"].get<int>());
  const json data = PageData(dir + "/fit.html");
  ASSERT_EQ(data["layers"].size(), 2u);
  EXPECT_EQ(data["layers"][0]["count"], 2000);
  EXPECT_EQ(data["layers"][0]["legend"][0]["points"], inliers);
  EXPECT_EQ(Array<float>(data["layers"][0]["residuals"]).size(), 2000u);
  EXPECT_GT(data["layers"][1]["triangle_count"].get<int>(), 1000);
}

TEST(ViewCli, DetectPageCarriesTheLabelsAndTheLegend) {
  const std::string dir = ScratchDir("view_detect");
  GeneratedSceneOptions o;
  o.seed = 2;
  WriteXyzFile(GenerateScene(o).cloud, dir + "/scene.xyz");
  const auto r = RunCommand(kCli + " detect " + dir + "/scene.xyz --out " + dir +
                            "/scene.json --labels " + dir + "/labels.txt --view " + dir +
                            "/detect.html --ply " + dir + "/seg.ply --seed 3");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Scene scene = ReadSceneFile(dir + "/scene.json");
  const std::vector<int> labels = ReadLabelsFile(dir + "/labels.txt", scene.primitives.size());
  for (const std::string& page : {dir + "/detect.html", dir + "/view.html"}) {
    if (page == dir + "/view.html")  // `view` of the scene and its segmented cloud
      ASSERT_EQ(RunCommand(kCli + " view " + dir + "/scene.json " + dir + "/seg.ply --out " + page +
                           " --quiet").exit_code, 0);
    const json data = PageData(page);
    ASSERT_EQ(data["layers"].size(), 1u) << page;
    const json& layer = data["layers"][0];
    EXPECT_EQ(layer["legend"].size(), scene.primitives.size()) << page;
    for (size_t k = 0; k < scene.primitives.size(); ++k) {
      EXPECT_EQ(layer["legend"][k]["name"], scene.primitives[k].name);
      EXPECT_EQ(layer["legend"][k]["points"], scene.primitives[k].points);
    }
    const std::vector<std::int16_t> shown = Array<std::int16_t>(layer["labels"]["data"]);
    EXPECT_EQ(std::vector<int>(shown.begin(), shown.end()), labels) << page;
  }
  // A scene on its own finds its cloud by the path it names.
  ASSERT_EQ(RunCommand("cd / && " + kCli + " view " + dir + "/scene.json --out " + dir +
                       "/alone.html --quiet").exit_code, 0);
  EXPECT_EQ(PageData(dir + "/alone.html")["layers"][0]["count"], scene.points);
}

TEST(ViewCli, ReconstructPageShowsTheCloudAndTheSolid) {
  const std::string dir = ScratchDir("view_reconstruct");
  // A unit cube as the intersection of six planes, and its scene.
  std::string faces, primitives;
  for (int k = 0; k < 6; ++k) {
    double n[3] = {0, 0, 0};
    n[k / 2] = k % 2 ? 1 : -1;
    const std::string plane = R"({"type": "plane", "normal": [)" + std::to_string(n[0]) + "," +
                              std::to_string(n[1]) + "," + std::to_string(n[2]) +
                              R"(], "offset": 0.5})";
    faces += (k ? "," : "") + plane;
    primitives += std::string(k ? "," : "") + R"({"name": "p)" + std::to_string(k) +
                  R"(", "model": )" + plane + R"(, "points": 100, "rms_distance": 0.003, "normal_side": "outward"})";
  }
  WriteText(dir + "/truth.json", R"({"format": "implicitfit-model", "version": 1, "root":
    {"type": "intersection", "delta": 0.1, "epsilon": 0.05, "order": 3, "children": [)" + faces + "]}}");
  WriteText(dir + "/scene.json", R"({"format": "implicitfit-scene", "version": 1, "cloud": "cloud.xyz",
    "points": 3000, "unassigned": 0, "primitives": [)" + primitives + "]}");
  ASSERT_EQ(RunCommand(kCli + " sample " + dir + "/truth.json --count 3000 --noise 0.003 --seed 3 --out " +
                       dir + "/cloud.xyz").exit_code, 0);
  const auto r = RunCommand(kCli + " reconstruct " + dir + "/cloud.xyz --scene " + dir +
                            "/scene.json --out " + dir + "/solid.json --view " + dir + "/solid.html");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json data = PageData(dir + "/solid.html");
  ASSERT_EQ(data["layers"].size(), 2u);
  const json& cloud = data["layers"][0];
  EXPECT_EQ(cloud["count"], 3000);
  EXPECT_EQ(cloud["legend"].size(), 6u);
  EXPECT_EQ(cloud["colour"], "residual");
  const Model solid = ReadModelFile(dir + "/solid.json");
  const PointCloud points = ReadCloudFile(dir + "/cloud.xyz");
  const std::vector<float> residuals = Array<float>(cloud["residuals"]);
  ASSERT_EQ(residuals.size(), 3000u);
  for (size_t i = 0; i < 3000; i += 97)
    EXPECT_EQ(residuals[i], static_cast<float>(solid.Value(points.points[i])));
  EXPECT_GT(data["layers"][1]["triangle_count"].get<int>(), 1000);
}

TEST(ViewCli, BatchWritesOnePagePerResultAndAnIndexLinkingThem) {
  const std::string dir = ScratchDir("view_batch"), out = dir + "/out";
  WriteText(dir + "/truth.json", kSphere);
  for (int k = 0; k < 3; ++k)
    ASSERT_EQ(RunCommand(kCli + " sample " + dir + "/truth.json --count 500 --noise 0.01 --seed " +
                         std::to_string(k + 1) + " --out " + dir + "/s" + std::to_string(k) + ".xyz")
                  .exit_code, 0);
  WriteText(dir + "/broken.xyz", "0 0 0\n1 1\n");
  const auto r = RunCommand(kCli + " batch " + dir + "/s0.xyz " + dir + "/s1.xyz " + dir +
                            "/s2.xyz " + dir + "/broken.xyz --model sphere --view --out-dir " + out);
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;  // broken.xyz is an error row
  const std::string index = Slurp(out + "/index.html");
  for (int k = 0; k < 3; ++k) {
    const std::string name = "s" + std::to_string(k);
    EXPECT_NE(index.find("<a href=\"" + name + ".view.html\">" + name + "</a>"), std::string::npos);
    const json data = PageData(out + "/" + name + ".view.html");
    ASSERT_EQ(data["layers"].size(), 2u) << name;
    EXPECT_EQ(data["layers"][0]["count"], 500);
    EXPECT_GT(data["layers"][1]["triangle_count"].get<int>(), 100);
  }
  EXPECT_FALSE(FileExists(out + "/broken.view.html"));
  EXPECT_NE(index.find("broken"), std::string::npos);
  EXPECT_EQ(index.find("broken.view.html"), std::string::npos);
}

}  // namespace
}  // namespace implicitfit
