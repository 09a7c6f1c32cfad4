// `implicitfit batch` end to end: clouds sampled by `implicitfit sample` from spheres of known
// centre and radius; the batch must recover each, isolate bad inputs, survive kill -9 (no partial
// file, --resume completes), not depend on --jobs, and split inputs exactly with --shard.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/types.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <thread>

#include "support/read_json.h"
#include "support/run_command.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using testsupport::RunCommand;
using testsupport::Slurp;
using testsupport::WriteText;
const std::string kCli = IMPLICITFIT_CLI;

struct Truth {
  std::string path, name;
  double center[3], radius;
};

// n clouds cloud_000.xyz ... of 1500 points (noise 0.002) on spheres of different centres/radii.
std::vector<Truth> MakeClouds(const std::string& dir, int n) {
  std::vector<Truth> truths;
  for (int i = 0; i < n; ++i) {
    Truth t;
    char name[32];
    std::snprintf(name, sizeof name, "cloud_%03d", i);
    t.name = name;
    t.path = dir + "/" + t.name + ".xyz";
    t.center[0] = 0.5 * (i % 7) - 1.0;
    t.center[1] = 0.3 * (i % 3);
    t.center[2] = -0.2 * (i % 5);
    t.radius = 0.8 + 0.1 * (i % 6);
    const json model = {{"format", "implicitfit-model"},
                        {"version", 1},
                        {"root",
                         {{"type", "sphere"},
                          {"center", {t.center[0], t.center[1], t.center[2]}},
                          {"radius", t.radius}}}};
    const std::string truth_file = dir + "/" + t.name + ".truth";
    WriteText(truth_file, model.dump());
    const auto r =
        RunCommand(kCli + " sample " + truth_file + " --count 1500 --noise 0.002 --seed " +
                   std::to_string(i + 1) + " --out " + t.path);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    truths.push_back(t);
  }
  return truths;
}

std::vector<std::vector<std::string>> ReadCsv(const std::string& path) {
  const std::string text = Slurp(path);
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> row;
  std::string field;
  bool quoted = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"')
        field += text[++i];
      else if (c == '"')
        quoted = false;
      else
        field += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      row.push_back(field), field.clear();
    } else if (c == '\n') {
      row.push_back(field), field.clear();
      rows.push_back(row), row.clear();
    } else {
      field += c;
    }
  }
  return rows;
}

// Rows of summary.csv by input path (header checked).
std::map<std::string, std::vector<std::string>> SummaryRows(const std::string& csv) {
  const auto rows = ReadCsv(csv);
  EXPECT_FALSE(rows.empty()) << csv;
  std::map<std::string, std::vector<std::string>> by_input;
  if (rows.empty()) return by_input;
  EXPECT_EQ(rows[0], (std::vector<std::string>{"input", "status", "rms", "inliers", "points",
                                               "seconds", "error"}));
  for (size_t i = 1; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].size(), 7u) << csv << " row " << i;
    by_input[rows[i][0]] = rows[i];
  }
  return by_input;
}

using testsupport::ReadJson;

std::string Join(const std::vector<Truth>& truths, size_t count) {
  std::string s;
  for (size_t i = 0; i < count && i < truths.size(); ++i) s += " " + truths[i].path;
  return s;
}

class BatchCommand : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    clouds_dir_ = new std::string(testsupport::ScratchDir("batch_clouds"));
    truths_ = new std::vector<Truth>(MakeClouds(*clouds_dir_, 10));
  }
  static void TearDownTestSuite() {
    fs::remove_all(*clouds_dir_);
    delete clouds_dir_;
    delete truths_;
  }
  static std::string* clouds_dir_;
  static std::vector<Truth>* truths_;
};
std::string* BatchCommand::clouds_dir_ = nullptr;
std::vector<Truth>* BatchCommand::truths_ = nullptr;

TEST_F(BatchCommand, FitsEveryInputNearTheTruthWithReportsAndSummary) {
  const std::string out = testsupport::ScratchDir("batch_all");
  const auto& truths = *truths_;
  const size_t n = 6;
  const auto r = RunCommand(kCli + " batch" + Join(truths, n) + " --model sphere --out-dir " + out +
                            " --jobs 2");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("6 inputs: 6 fitted, 0 skipped, 0 failed"), std::string::npos) << r.out;
  const auto rows = SummaryRows(out + "/summary.csv");
  EXPECT_EQ(rows.size(), n);
  for (size_t i = 0; i < n; ++i) {
    const Truth& t = truths[i];
    const json model = ReadJson(out + "/" + t.name + ".model.json");
    ASSERT_EQ(model["root"]["type"], "sphere");
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(model["root"]["center"][k].get<double>(), t.center[k], 0.005) << t.name;
    EXPECT_NEAR(model["root"]["radius"].get<double>(), t.radius, 0.005) << t.name;
    const json report = ReadJson(out + "/" + t.name + ".report.json");
    EXPECT_TRUE(report["success"].get<bool>());
    EXPECT_EQ(report["points"], 1500);
    EXPECT_NEAR(report["rms_distance"].get<double>(), 0.002, 0.001);
    ASSERT_EQ(rows.count(t.path), 1u) << t.path;
    const auto& row = rows.at(t.path);
    EXPECT_EQ(row[1], "ok");
    EXPECT_NEAR(std::stod(row[2]), report["rms_distance"].get<double>(), 1e-8);
    EXPECT_EQ(row[3], std::to_string(report["inliers"].get<size_t>()));
    EXPECT_EQ(row[4], "1500");
    EXPECT_EQ(row[6], "");
    EXPECT_NE(r.err.find(t.name + " ok"), std::string::npos)
        << "a plain progress line per input: " << r.err;
  }
  EXPECT_NE(r.err.find("[6/6]"), std::string::npos) << r.err;
}

TEST_F(BatchCommand, WritesWhatFitWritesForTheSameCloud) {
  const std::string out = testsupport::ScratchDir("batch_same_as_fit");
  const Truth& t = (*truths_)[3];
  ASSERT_EQ(RunCommand(kCli + " batch " + t.path + " --model sphere --out-dir " + out +
                       " --jobs 1 --seed 7")
                .exit_code,
            0);
  const auto f = RunCommand(kCli + " fit " + t.path + " --model sphere --seed 7 --out " + out +
                            "/fit.json --report " + out + "/fit_report.json");
  ASSERT_EQ(f.exit_code, 0) << f.err;
  EXPECT_EQ(Slurp(out + "/fit.json"), Slurp(out + "/" + t.name + ".model.json"));
  json a = ReadJson(out + "/fit_report.json"), b = ReadJson(out + "/" + t.name + ".report.json");
  a.erase("seconds");
  b.erase("seconds");
  // The batch adds its settings (what --resume compares), nothing else; the report headers
  // (apps/report_header.h) name each its own job and that job's options.
  ASSERT_TRUE(b.contains("batch_settings")) << b.dump();
  EXPECT_FALSE(a.contains("batch_settings"));
  b.erase("batch_settings");
  EXPECT_EQ(a["job"], "fit");
  EXPECT_EQ(b["job"], "batch");
  EXPECT_EQ(a["settings"]["model"], b["settings"]["model"]);
  EXPECT_EQ(a["settings"]["seed"], b["settings"]["seed"]);
  for (json* r : {&a, &b}) r->erase("job"), r->erase("settings");
  EXPECT_EQ(a, b);
}

TEST_F(BatchCommand, BadInputsFailAloneAndAreNamed) {
  const std::string out = testsupport::ScratchDir("batch_bad");
  const std::string bad_dir = testsupport::ScratchDir("batch_bad_inputs");
  WriteText(bad_dir + "/garbage.xyz", "this is not a point cloud\n\x01\x02\n");
  std::string tiny;  // 12 points: too few for a sphere fit (a negative result, not an error)
  for (int i = 0; i < 12; ++i)
    tiny += std::to_string(std::cos(i)) + " " + std::to_string(std::sin(i)) + " 0 0 0 1\n";
  WriteText(bad_dir + "/tiny.xyz", tiny);
  const auto& truths = *truths_;
  const std::string missing = bad_dir + "/missing.xyz";
  const auto r = RunCommand(kCli + " batch " + truths[0].path + " " + bad_dir + "/garbage.xyz " +
                            truths[1].path + " " + missing + " " + bad_dir + "/tiny.xyz " +
                            truths[2].path + " --model sphere --out-dir " + out + " --jobs 2");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  const auto rows = SummaryRows(out + "/summary.csv");
  ASSERT_EQ(rows.size(), 6u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(rows.at(truths[i].path)[1], "ok");
    EXPECT_NO_THROW(ReadJson(out + "/" + truths[i].name + ".model.json"));
  }
  EXPECT_EQ(rows.at(bad_dir + "/garbage.xyz")[1], "error");
  EXPECT_NE(rows.at(bad_dir + "/garbage.xyz")[6].find("garbage.xyz:1:"), std::string::npos)
      << rows.at(bad_dir + "/garbage.xyz")[6];
  EXPECT_EQ(rows.at(missing)[1], "error");
  EXPECT_FALSE(rows.at(missing)[6].empty());
  EXPECT_EQ(rows.at(bad_dir + "/tiny.xyz")[1], "failed");
  EXPECT_NE(rows.at(bad_dir + "/tiny.xyz")[6].find("fit failed"), std::string::npos);
  EXPECT_FALSE(testsupport::FileExists(out + "/garbage.model.json"));
  EXPECT_FALSE(testsupport::FileExists(out + "/garbage.report.json"));
  EXPECT_FALSE(testsupport::FileExists(out + "/tiny.model.json"));
  EXPECT_FALSE(ReadJson(out + "/tiny.report.json")["success"].get<bool>());
  for (const char* name : {"garbage.xyz", "missing.xyz", "tiny.xyz"}) {
    EXPECT_NE(r.err.find(name), std::string::npos) << "stderr names " << name << ": " << r.err;
    EXPECT_NE(r.out.find(name), std::string::npos) << "the summary names " << name << ": " << r.out;
  }
  EXPECT_NE(r.out.find("6 inputs: 3 fitted, 0 skipped, 3 failed"), std::string::npos) << r.out;
}

TEST_F(BatchCommand, ResumeRefitsOnlyMissingOrBrokenOutputs) {
  const std::string out = testsupport::ScratchDir("batch_resume");
  const auto& truths = *truths_;
  const std::string command =
      kCli + " batch" + Join(truths, 5) + " --model sphere --out-dir " + out + " --jobs 2";
  ASSERT_EQ(RunCommand(command).exit_code, 0);
  std::vector<fs::file_time_type> times;
  for (int i = 0; i < 5; ++i)
    times.push_back(fs::last_write_time(out + "/" + truths[i].name + ".model.json"));
  const std::string first_model = Slurp(out + "/" + truths[1].name + ".model.json");
  fs::remove(out + "/" + truths[1].name + ".model.json");
  WriteText(out + "/" + truths[3].name + ".report.json", "{\"success\": tr");  // truncated
  const auto r = RunCommand(command + " --resume");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("5 inputs: 2 fitted, 3 skipped, 0 failed"), std::string::npos) << r.out;
  for (int i : {0, 2, 4})
    EXPECT_EQ(fs::last_write_time(out + "/" + truths[i].name + ".model.json"), times[i])
        << "not rewritten";
  EXPECT_NE(fs::last_write_time(out + "/" + truths[3].name + ".model.json"), times[3])
      << "refitted";
  EXPECT_EQ(Slurp(out + "/" + truths[1].name + ".model.json"), first_model);
  EXPECT_TRUE(ReadJson(out + "/" + truths[3].name + ".report.json")["success"].get<bool>());
  const auto rows = SummaryRows(out + "/summary.csv");
  EXPECT_EQ(rows.at(truths[0].path)[1], "skipped");
  EXPECT_EQ(rows.at(truths[0].path)[4], "1500")
      << "figures of a skipped input come from its report";
  EXPECT_EQ(rows.at(truths[1].path)[1], "ok");

  const auto again = RunCommand(command + " --resume");
  EXPECT_EQ(again.exit_code, 0);
  EXPECT_NE(again.out.find("5 inputs: 0 fitted, 5 skipped, 0 failed"), std::string::npos)
      << again.out;
  // Results of another kind are not reused for --model plane: --resume refuses them, naming the
  // report and the changed setting (issue 26), and leaves them as they were.
  const std::string before = Slurp(out + "/" + truths[1].name + ".model.json");
  const auto plane = RunCommand(kCli + " batch" + Join(truths, 1) + " --model plane --out-dir " +
                                out + " --resume");
  EXPECT_EQ(plane.exit_code, 2) << plane.out << plane.err;
  EXPECT_NE(plane.err.find("made with other settings"), std::string::npos) << plane.err;
  EXPECT_NE(plane.err.find("plane"), std::string::npos) << plane.err;
  EXPECT_EQ(Slurp(out + "/" + truths[1].name + ".model.json"), before);
}

TEST_F(BatchCommand, KillDashNineLeavesNoPartialFileAndResumeCompletes) {
  // 80 inputs: 8 copies of each of the 10 clouds (each process start of `sample` is slow).
  const std::string out = testsupport::ScratchDir("batch_kill"),
                    in = testsupport::ScratchDir("batch_kill_in");
  std::vector<Truth> copies;
  for (int k = 0; k < 8; ++k)
    for (const Truth& t : *truths_) {
      Truth c = t;
      c.name = t.name + "_copy" + std::to_string(k);
      c.path = in + "/" + c.name + ".xyz";
      fs::copy_file(t.path, c.path);
      copies.push_back(c);
    }
  const size_t n = copies.size();
  const std::string command =
      kCli + " batch " + in + " --model sphere --out-dir " + out + " --jobs 2";
  ASSERT_EQ(std::system((command + " > " + out + ".log 2>&1 & echo $! > " + out + ".pid").c_str()),
            0);
  const pid_t pid = std::stoi(Slurp(out + ".pid"));
  const auto count_models = [&]() {
    size_t models = 0;
    for (const auto& e : fs::directory_iterator(out))
      models += e.path().string().size() > 11 &&
                e.path().string().substr(e.path().string().size() - 11) == ".model.json";
    return models;
  };
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (count_models() < 3 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  ASSERT_EQ(::kill(pid, SIGKILL), 0);
  std::system(
      ("while kill -0 " + std::to_string(pid) + " 2>/dev/null; do sleep 0.01; done").c_str());
  const size_t done_before = count_models();
  ASSERT_GE(done_before, 3u);
  ASSERT_LT(done_before, n) << "the batch finished before it was killed: the test proves nothing";
  EXPECT_FALSE(testsupport::FileExists(out + "/summary.csv"));
  for (const auto& e : fs::directory_iterator(out)) {
    if (e.path().extension() != ".json") continue;
    const json j = json::parse(Slurp(e.path().string()), nullptr, false);
    EXPECT_FALSE(j.is_discarded()) << "partial file " << e.path();
  }

  const auto r = RunCommand(command + " --resume");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(count_models(), n);
  const auto rows = SummaryRows(out + "/summary.csv");
  EXPECT_EQ(rows.size(), n);
  size_t skipped = 0;
  for (const auto& [input, row] : rows) skipped += row[1] == "skipped";
  EXPECT_GE(skipped, done_before - 2) << "at most the models being written at the kill are redone";
  EXPECT_LE(skipped, done_before);
  for (const Truth& t : copies) {
    const json model = ReadJson(out + "/" + t.name + ".model.json");
    EXPECT_NEAR(model["root"]["radius"].get<double>(), t.radius, 0.005) << t.name;
  }
  for (const auto& e : fs::directory_iterator(out))
    EXPECT_EQ(e.path().string().find(".implicitfit-"), std::string::npos)
        << "stale temporary " << e.path();
  const auto again = RunCommand(command + " --resume");
  EXPECT_NE(again.out.find("0 fitted, " + std::to_string(n) + " skipped"), std::string::npos)
      << again.out;
}

TEST_F(BatchCommand, OneJobAndTwoJobsGiveIdenticalModels) {
  const std::string one = testsupport::ScratchDir("batch_jobs1"),
                    two = testsupport::ScratchDir("batch_jobs2");
  const auto& truths = *truths_;
  ASSERT_EQ(RunCommand(kCli + " batch" + Join(truths, 8) + " --model sphere --out-dir " + one +
                       " --jobs 1")
                .exit_code,
            0);
  ASSERT_EQ(RunCommand(kCli + " batch" + Join(truths, 8) + " --model sphere --out-dir " + two +
                       " --jobs 2")
                .exit_code,
            0);
  for (size_t i = 0; i < 8; ++i) {
    const std::string a = Slurp(one + "/" + truths[i].name + ".model.json");
    EXPECT_FALSE(a.empty());
    EXPECT_EQ(a, Slurp(two + "/" + truths[i].name + ".model.json")) << truths[i].name;
  }
}

TEST_F(BatchCommand, ShardsAreDisjointAndCoverEveryInput) {
  const std::string out = testsupport::ScratchDir("batch_shards");
  const std::string list = out + "/inputs.list";
  const size_t n = 10;
  std::string manifest = "# ten clouds\n\n";
  for (size_t i = 0; i < n; ++i)
    manifest += "  " + fs::relative((*truths_)[i].path, out).string() + "\n";
  WriteText(list, manifest);
  std::set<std::string> seen;
  for (int shard = 1; shard <= 3; ++shard) {
    const auto r = RunCommand(kCli + " batch --manifest " + list + " --model sphere --out-dir " +
                              out + " --jobs 2 --shard " + std::to_string(shard) + "/3");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto rows = SummaryRows(out + "/summary-" + std::to_string(shard) + "-of-3.csv");
    for (size_t i = 0; i < n; ++i) {
      const bool mine = i % 3 == static_cast<size_t>(shard - 1);
      const std::string path = out + "/" + fs::relative((*truths_)[i].path, out).string();
      EXPECT_EQ(rows.count(path), mine ? 1u : 0u) << "shard " << shard << " input " << i;
    }
    for (const auto& [input, row] : rows) {
      EXPECT_TRUE(seen.insert(input).second) << input << " in two shards";
      EXPECT_EQ(row[1], "ok");
    }
  }
  EXPECT_EQ(seen.size(), n);
  for (size_t i = 0; i < n; ++i)
    EXPECT_TRUE(testsupport::FileExists(out + "/" + (*truths_)[i].name + ".model.json"));
  for (const std::string bad : {"0/3", "4/3", "1/0", "x/3", "1-3", "2/3x"})
    EXPECT_EQ(RunCommand(kCli + " batch --manifest " + list + " --model sphere --out-dir " + out +
                         " --shard " + bad)
                  .exit_code,
              2)
        << bad;
}

TEST_F(BatchCommand, ListsDirectoriesSortedThenManifestsInOrder) {
  const std::string out = testsupport::ScratchDir("batch_order"),
                    dir = testsupport::ScratchDir("batch_order_dir");
  const auto& t = *truths_;
  for (int i : {2, 0, 1}) fs::copy_file(t[i].path, dir + "/" + t[i].name + ".xyz");
  WriteText(dir + "/notes.md", "not a cloud: ignored in a directory\n");
  WriteText(out + "/m.list",
            "# comment\n\n" + t[4].path + "\n  " + fs::relative(t[3].path, out).string() + "  \n");
  // A word after --manifest FILE is an input again, not a second manifest.
  const auto r = RunCommand(kCli + " batch --manifest " + out + "/m.list " + t[5].path + " " + dir +
                            " --model sphere --out-dir " + out + "/res");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = ReadCsv(out + "/res/summary.csv");
  std::vector<std::string> inputs;
  for (size_t i = 1; i < rows.size(); ++i) inputs.push_back(rows[i][0]);
  EXPECT_EQ(inputs, (std::vector<std::string>{t[5].path, dir + "/" + t[0].name + ".xyz",
                                              dir + "/" + t[1].name + ".xyz",
                                              dir + "/" + t[2].name + ".xyz", t[4].path,
                                              out + "/" + fs::relative(t[3].path, out).string()}));
}

TEST_F(BatchCommand, AManifestLineMayNameItsOwnKind) {
  const std::string out = testsupport::ScratchDir("batch_kinds");
  WriteText(out + "/cyl.truth",
            R"({"format": "implicitfit-model", "version": 1, "root": {"type": "cylinder",
    "point": [0.5, -0.2, 0], "axis": [0, 0.6, 0.8], "radius": 0.7}})");
  ASSERT_EQ(RunCommand(kCli + " sample " + out + "/cyl.truth --count 1500 --noise 0.002 --out '" +
                       out + "/my cyl.xyz'")
                .exit_code,
            0);
  WriteText(out + "/m.list", (*truths_)[0].path + "\n" + "my cyl.xyz\tcylinder\n");
  const auto r = RunCommand(kCli + " batch --manifest " + out +
                            "/m.list --model sphere --out-dir " + out + "/res");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(ReadJson(out + "/res/" + (*truths_)[0].name + ".model.json")["root"]["type"], "sphere");
  const json cylinder = ReadJson(out + "/res/my cyl.model.json")["root"];
  ASSERT_EQ(cylinder["type"], "cylinder");
  EXPECT_NEAR(cylinder["radius"].get<double>(), 0.7, 0.005);
  EXPECT_NEAR(std::abs(cylinder["axis"][1].get<double>()), 0.6, 0.01);
  // --resume checks the kind of the line, not --model.
  const auto again = RunCommand(kCli + " batch --manifest " + out +
                                "/m.list --model sphere --out-dir " + out + "/res --resume");
  EXPECT_NE(again.out.find("0 fitted, 2 skipped"), std::string::npos) << again.out;
  // A --fix field the line's kind lacks fails that input alone.
  const auto fixed = RunCommand(
      kCli + " batch --manifest " + out +
      "/m.list --model sphere --fix radius=1 --fix center=0,0,0 --out-dir " + out + "/fixed");
  EXPECT_EQ(fixed.exit_code, 1) << fixed.out << fixed.err;
  EXPECT_EQ(SummaryRows(out + "/fixed/summary.csv").at(out + "/my cyl.xyz")[1], "error");
  WriteText(out + "/bad.list", (*truths_)[0].path + "\n\n" + (*truths_)[1].path + "\tblob\n");
  const auto bad = RunCommand(kCli + " batch --manifest " + out +
                              "/bad.list --model sphere --out-dir " + out + "/bad");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("bad.list:3: unknown kind 'blob'"), std::string::npos) << bad.err;
}

TEST_F(BatchCommand, InvalidUsageExits2AndWritesNothing) {
  const std::string out = testsupport::ScratchDir("batch_usage") + "/out";
  const std::string in = Join(*truths_, 2);
  const std::string dup_dir = testsupport::ScratchDir("batch_dup");
  fs::copy_file((*truths_)[0].path, dup_dir + "/" + (*truths_)[0].name + ".xyz");
  struct Case {
    std::string args, fragment;
  } cases[] = {
      {in + " --model sphere", "--out-dir"},
      {in + " --model blob --out-dir " + out, "blob"},
      {" --model sphere --out-dir " + out, "no INPUTS"},
      {" --manifest /nonexistent/list.txt --model sphere --out-dir " + out, "list.txt"},
      {in + " --model sphere --out-dir " + out + " --jobs 0", "jobs"},
      {in + " " + dup_dir + " --model sphere --out-dir " + out, "cloud_000"},
      {" " + testsupport::ScratchDir("batch_empty") + " --model sphere --out-dir " + out,
       "no cloud files"},
  };
  for (const Case& c : cases) {
    const auto r = RunCommand(kCli + " batch" + c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.fragment), std::string::npos) << r.err;
    EXPECT_FALSE(testsupport::FileExists(out + "/summary.csv")) << c.args;
  }
}

}  // namespace

namespace {

// --quiet: no line for the inputs that fitted, a line for each that failed (here a garbage file),
// the summary on stdout as without it.
TEST_F(BatchCommand, QuietPrintsOnlyTheFailures) {
  const std::string out = testsupport::ScratchDir("batch_quiet");
  const std::string bad_dir = testsupport::ScratchDir("batch_quiet_inputs");
  WriteText(bad_dir + "/garbage.xyz", "this is not a point cloud\n");
  const auto r = RunCommand(kCli + " batch" + Join(*truths_, 3) + " " + bad_dir +
                            "/garbage.xyz --model sphere --out-dir " + out + " --jobs 2 --quiet");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.err.find("garbage error: "), std::string::npos) << r.err;
  for (size_t i = 0; i < 3; ++i)
    EXPECT_EQ(r.err.find((*truths_)[i].name), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("4 inputs: 3 fitted, 0 skipped, 1 failed"), std::string::npos) << r.out;
}

TEST_F(BatchCommand, ProgressOnATerminalIsOneUpdatingLine) {
  if (RunCommand("command -v script").exit_code != 0)
    GTEST_SKIP() << "no `script` to give a terminal";
  const std::string out = testsupport::ScratchDir("batch_tty");
  // script(1) runs the batch with a pseudo-terminal as stdout and stderr.
  const auto r = RunCommand("script -qec '" + kCli + " batch" + Join(*truths_, 4) +
                            " --model sphere --out-dir " + out + " --jobs 2' /dev/null");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("\r\033[K[4/4]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("inputs/s"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("ETA"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("cloud_000 ok"), std::string::npos)
      << "no per-input lines on a terminal: " << r.out;
}

#ifdef IMPLICITFIT_MPIEXEC
TEST_F(BatchCommand, MpiRanksGiveTheSameModelsAsOneProcess) {
  const std::string mpi = testsupport::ScratchDir("batch_mpi"),
                    single = testsupport::ScratchDir("batch_mpi_single");
  const std::string bad = mpi + "_garbage.xyz";
  WriteText(bad, "not a cloud\n");
  const std::string inputs = Join(*truths_, 10) + " " + bad;
  // Open MPI refuses root unless told; --oversubscribe: more ranks than cores.
  const std::string mpirun =
      std::string("OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ") +
      IMPLICITFIT_MPIEXEC + " --oversubscribe -np 3 ";
  const auto r = RunCommand(mpirun + kCli + " batch" + inputs + " --model sphere --out-dir " + mpi);
  EXPECT_EQ(r.exit_code, 1) << "one bad input: " << r.out << r.err;
  EXPECT_NE(r.out.find("11 inputs: 10 fitted, 0 skipped, 1 failed"), std::string::npos)
      << r.out << r.err;
  EXPECT_NE(r.out.find("_garbage.xyz"), std::string::npos) << r.out;
  const size_t first = r.out.find("batch: 11 inputs");
  EXPECT_EQ(r.out.find("batch: 11 inputs", first + 1), std::string::npos)
      << "one batch over the ranks, not three: " << r.out;
  ASSERT_EQ(
      RunCommand(kCli + " batch" + inputs + " --model sphere --out-dir " + single + " --jobs 2")
          .exit_code,
      1);
  const auto mpi_rows = SummaryRows(mpi + "/summary.csv"),
             single_rows = SummaryRows(single + "/summary.csv");
  ASSERT_EQ(mpi_rows.size(), 11u);
  for (const auto& [input, row] : single_rows) {
    ASSERT_EQ(mpi_rows.count(input), 1u) << input;
    for (int column : {1, 2, 3, 4, 6}) EXPECT_EQ(mpi_rows.at(input)[column], row[column]) << input;
  }
  for (size_t i = 0; i < 10; ++i) {
    const std::string name = (*truths_)[i].name + ".model.json";
    EXPECT_FALSE(Slurp(mpi + "/" + name).empty());
    EXPECT_EQ(Slurp(mpi + "/" + name), Slurp(single + "/" + name)) << name;
  }
  const auto again = RunCommand(mpirun + kCli + " batch" + inputs + " --model sphere --out-dir " +
                                mpi + " --resume");
  EXPECT_NE(again.out.find("11 inputs: 0 fitted, 10 skipped, 1 failed"), std::string::npos)
      << again.out << again.err;
}
#endif

}  // namespace

namespace {

// A folder stands for every cloud `fit` reads: the labelled .xyzl of Fit4CAD-style data and
// extensions in any case too (docs/batch.md), nothing else.
TEST_F(BatchCommand, FolderTakesEveryExtensionFitReads) {
  const std::string dir = testsupport::ScratchDir("batch_folder_kinds");
  const std::string out = testsupport::ScratchDir("batch_folder_kinds_out");
  std::istringstream cloud(Slurp((*truths_)[0].path));
  std::ostringstream labelled;
  for (std::string line; std::getline(cloud, line);) {
    std::istringstream fields(line);
    double x, y, z;
    if (fields >> x >> y >> z) labelled << x << " " << y << " " << z << " 3\n";
  }
  WriteText(dir + "/labelled.xyzl", labelled.str());
  fs::copy_file((*truths_)[1].path, dir + "/upper.XYZ");
  WriteText(dir + "/notes.md", "not a cloud\n");
  const auto r = RunCommand(kCli + " batch " + dir + " --model sphere --out-dir " + out);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("2 inputs: 2 fitted, 0 skipped, 0 failed"), std::string::npos) << r.out;
  const json model = ReadJson(out + "/labelled.model.json");
  EXPECT_NEAR(model["root"]["radius"].get<double>(), (*truths_)[0].radius, 0.01);
}

}  // namespace
