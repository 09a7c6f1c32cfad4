#include "datasets/io/scene_file.h"

#include <gtest/gtest.h>

#include "datasets/io/io_error.h"
#include "support/run_command.h"

namespace implicitfit {
namespace {

Scene TwoPrimitiveScene() {
  Scene scene;
  scene.cloud = "part.ply";
  scene.points = 100;
  scene.unassigned = 7;
  ScenePrimitive plane;
  plane.name = "p0";
  plane.model.AddPrimitive(NodeType::kPlane, {0, 0, 1, 0.25});
  plane.points = 60;
  plane.rms_distance = 0.0011;
  plane.standard_deviations = {{"offset", 1e-4}};
  plane.normal_side = "outward";
  ScenePrimitive sphere;
  sphere.name = "p1";
  sphere.model.AddPrimitive(NodeType::kSphere, {0.1, 0.2, 0.3, 0.7});
  sphere.points = 33;
  sphere.rms_distance = 0.002;
  sphere.normal_side = "inward";
  scene.primitives = {plane, sphere};
  return scene;
}

TEST(SceneFile, WriteThenReadKeepsEveryField) {
  const std::string dir = testsupport::ScratchDir("scene_file");
  const Scene scene = TwoPrimitiveScene();
  WriteSceneFile(scene, dir + "/s.json");
  const Scene back = ReadSceneFile(dir + "/s.json");
  EXPECT_EQ(back.cloud, "part.ply");
  EXPECT_EQ(back.points, 100);
  EXPECT_EQ(back.unassigned, 7);
  ASSERT_EQ(back.primitives.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(back.primitives[i].name, scene.primitives[i].name);
    EXPECT_EQ(back.primitives[i].model.parameters(), scene.primitives[i].model.parameters());
    EXPECT_EQ(back.primitives[i].model.nodes()[0].type, scene.primitives[i].model.nodes()[0].type);
    EXPECT_EQ(back.primitives[i].points, scene.primitives[i].points);
    EXPECT_EQ(back.primitives[i].rms_distance, scene.primitives[i].rms_distance);
    EXPECT_EQ(back.primitives[i].standard_deviations, scene.primitives[i].standard_deviations);
    EXPECT_EQ(back.primitives[i].normal_side, scene.primitives[i].normal_side);
  }
}

TEST(SceneFile, AnInvalidModelIsNamedByItsScenePath) {
  const std::string dir = testsupport::ScratchDir("scene_file_bad");
  testsupport::WriteText(dir + "/bad.json",
                         R"({"format": "implicitfit-scene", "version": 1, "cloud": "c.ply",
 "points": 10, "unassigned": 0, "primitives": [{"name": "p0", "points": 10, "rms_distance": 0,
 "normal_side": "outward", "model": {"type": "sphere", "center": [0, 0, 0], "radius": -1}}]})");
  try {
    ReadSceneFile(dir + "/bad.json");
    FAIL();
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("bad.json: invalid scene: primitives[0].model.radius"), std::string::npos)
        << what;
  }
}

TEST(SceneFile, LabelsRoundTripAndBadLabelsNameTheLine) {
  const std::string dir = testsupport::ScratchDir("labels_file");
  WriteLabelsFile({0, -1, 1, 1}, dir + "/l.txt");
  EXPECT_EQ(ReadLabelsFile(dir + "/l.txt", 2, 4), (std::vector<int>{0, -1, 1, 1}));
  EXPECT_THROW(ReadLabelsFile(dir + "/l.txt", 2, 5), InputError);
  testsupport::WriteText(dir + "/bad.txt", "0\n2\n");
  try {
    ReadLabelsFile(dir + "/bad.txt", 2);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.txt:2: label 2 is outside -1..1"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace implicitfit
