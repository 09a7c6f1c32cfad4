#include "datasets/io/model_file.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "datasets/io/io_error.h"
#include "support/run_command.h"

namespace implicitfit {
namespace {

TEST(ModelFile, WriteThenReadGivesTheSameParameters) {
  const std::string dir = testsupport::ScratchDir("model_file");
  Model m;
  const int a = m.AddPrimitive(NodeType::kSphere, {0.1, 0.2, 0.3, 0.7});
  const int b = m.AddPrimitive(NodeType::kTorus, {1, 2, 3, 0, 0, 1, 2, 0.25});
  m.AddOperator(NodeType::kUnion, {a, b}, 0.2, 0.1, 3);
  WriteModelFile(m, dir + "/m.json");
  EXPECT_EQ(ReadModelFile(dir + "/m.json").parameters(), m.parameters());
  for (const auto& e : std::filesystem::directory_iterator(dir))  // no temporary left
    EXPECT_EQ(e.path().filename().string().find(".implicitfit-"), std::string::npos) << e.path();
}

TEST(ModelFile, MalformedJsonNamesTheFileAndLine) {
  const std::string dir = testsupport::ScratchDir("model_file_bad");
  testsupport::WriteText(dir + "/bad.json",
                         "{\n  \"format\": \"implicitfit-model\",\n  \"version\": ,\n}");
  try {
    ReadModelFile(dir + "/bad.json");
    FAIL();
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("bad.json: invalid JSON"), std::string::npos) << what;
    EXPECT_NE(what.find("line 3"), std::string::npos) << what;
  }
}

TEST(ModelFile, WritingIntoAMissingFolderFailsWithoutLeavingFiles) {
  Model m;
  m.AddPrimitive(NodeType::kSphere, {0, 0, 0, 1});
  EXPECT_THROW(WriteModelFile(m, "/nonexistent_folder_xyz/m.json"), InputError);
}

}  // namespace
}  // namespace implicitfit
