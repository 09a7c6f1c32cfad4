// The file-safety layer of datasets/io: inputs must be regular files (a FIFO is refused without
// blocking), lines are streamed across chunk boundaries and capped; outputs follow links and keep
// the target's mode, refuse devices, FIFOs and folders, take 255-byte names; a transaction
// renames all or nothing; stale temporaries of dead processes go, locked ones stay; JSON
// duplicate keys are refused with their path.
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <random>

#include "datasets/io/atomic_file.h"
#include "datasets/io/input_file.h"
#include "datasets/io/io_error.h"
#include "datasets/io/json_file.h"
#include "datasets/io/output_path.h"
#include "support/run_command.h"

namespace implicitfit {
namespace {

namespace fs = std::filesystem;
using testsupport::FileExists;
using testsupport::ScratchDir;
using testsupport::Slurp;
using testsupport::WriteText;

std::string ErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

bool AnyTemporary(const std::string& dir) {
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().find(".implicitfit-") != std::string::npos) return true;
  return false;
}

TEST(InputFile, RefusesFifosDevicesAndFoldersWithoutReading) {
  const std::string dir = ScratchDir("input_file_kinds");
  ASSERT_EQ(::mkfifo((dir + "/p.xyz").c_str(), 0644), 0);
  // A blocking open of a FIFO without a writer never returns: this must return at once.
  EXPECT_NE(ErrorOf([&] { InputFile f(dir + "/p.xyz"); }).find("FIFO"), std::string::npos);
  EXPECT_NE(ErrorOf([&] { InputFile f("/dev/zero"); }).find("character device"), std::string::npos);
  EXPECT_NE(ErrorOf([&] { InputFile f(dir); }).find("directory"), std::string::npos);
  EXPECT_NE(ErrorOf([&] { InputFile f(dir + "/missing"); }).find("No such file"), std::string::npos);
}

TEST(InputFile, StreamsLinesAcrossChunksLikeASplit) {
  const std::string dir = ScratchDir("input_file_lines");
  std::mt19937 rng(3);
  std::string text;
  std::vector<std::string> lines;
  for (int i = 0; i < 20000; ++i) {  // lines of 0..300 bytes: many cross the 64 KiB chunks
    std::string line(rng() % 301, 'a' + i % 26);
    lines.push_back(line);
    text += line + "\n";
  }
  text += "last line without a newline";
  lines.push_back("last line without a newline");
  WriteText(dir + "/t.txt", text);
  InputFile f(dir + "/t.txt");
  std::string line;
  size_t k = 0;
  while (f.ReadLine(&line, 1000)) {
    ASSERT_LT(k, lines.size());
    ASSERT_EQ(line, lines[k]) << "line " << k + 1;
    ++k;
  }
  EXPECT_EQ(k, lines.size());
  EXPECT_EQ(f.offset(), text.size());
  // A line over the cap is refused with its number, after the lines before it.
  WriteText(dir + "/long.txt", "short\n" + std::string(5000, 'x') + "\n");
  InputFile g(dir + "/long.txt");
  ASSERT_TRUE(g.ReadLine(&line, 1000));
  EXPECT_NE(ErrorOf([&] { g.ReadLine(&line, 1000); }).find("long.txt:2: line longer than 1000"),
            std::string::npos);
  InputFile h(dir + "/long.txt");
  EXPECT_NE(ErrorOf([&] { h.ReadAll(100, "--max-json-mb"); }).find("--max-json-mb"),
            std::string::npos);
}

TEST(OutputFiles, WriteThroughALinkKeepingTheTargetsMode) {
  const std::string dir = ScratchDir("output_link");
  WriteText(dir + "/target.json", "old");
  ::chmod((dir + "/target.json").c_str(), 0600);
  ASSERT_EQ(::symlink("target.json", (dir + "/link.json").c_str()), 0);
  WriteFileAtomically(dir + "/link.json", "new");
  struct stat st;
  ASSERT_EQ(::lstat((dir + "/link.json").c_str(), &st), 0);
  EXPECT_TRUE(S_ISLNK(st.st_mode)) << "the link was replaced by a file";
  EXPECT_EQ(Slurp(dir + "/target.json"), "new");
  ASSERT_EQ(::stat((dir + "/target.json").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 07777, 0600u);
  EXPECT_FALSE(AnyTemporary(dir));
}

TEST(OutputFiles, RefusesDevicesFifosFoldersAndMissingFolders) {
  const std::string dir = ScratchDir("output_kinds");
  ASSERT_EQ(::mkfifo((dir + "/p.json").c_str(), 0644), 0);
  ASSERT_EQ(::symlink("/dev/null", (dir + "/null.json").c_str()), 0);
  EXPECT_NE(ErrorOf([&] { WriteFileAtomically(dir + "/p.json", "x"); }).find("FIFO"),
            std::string::npos);
  EXPECT_NE(ErrorOf([&] { WriteFileAtomically(dir + "/null.json", "x"); }).find("device"),
            std::string::npos);
  EXPECT_NE(ErrorOf([&] { WriteFileAtomically(dir, "x"); }).find("directory"), std::string::npos);
  EXPECT_NE(ErrorOf([&] { ResolveOutputPath(dir + "/missing/m.json"); }).find("does not exist"),
            std::string::npos);
  struct stat st;
  ASSERT_EQ(::lstat((dir + "/p.json").c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
  EXPECT_FALSE(AnyTemporary(dir));
}

TEST(OutputFiles, TakesNamesOf255Bytes) {
  const std::string dir = ScratchDir("output_long");
  const std::string name = std::string(250, 'n') + ".json";  // 255 bytes
  EXPECT_LE(fs::path(TemporaryPathFor(dir + "/" + name)).filename().string().size(), 255u);
  WriteFileAtomically(dir + "/" + name, "ok");
  EXPECT_EQ(Slurp(dir + "/" + name), "ok");
}

TEST(OutputFiles, TransactionRenamesAllOrNothing) {
  const std::string dir = ScratchDir("output_transaction");
  WriteText(dir + "/a.json", "old a");
  {
    OutputTransaction t;
    WriteFileAtomically(dir + "/a.json", "new a");
    WriteFileAtomically(dir + "/b.json", "new b");
    EXPECT_EQ(Slurp(dir + "/a.json"), "old a");  // staged, not yet in place
    EXPECT_FALSE(FileExists(dir + "/b.json"));
  }  // no Commit: discarded
  EXPECT_EQ(Slurp(dir + "/a.json"), "old a");
  EXPECT_FALSE(FileExists(dir + "/b.json"));
  EXPECT_FALSE(AnyTemporary(dir));
  {
    OutputTransaction t;
    WriteFileAtomically(dir + "/a.json", "new a");
    WriteFileAtomically(dir + "/b.json", "new b");
    t.Commit();
  }
  EXPECT_EQ(Slurp(dir + "/a.json"), "new a");
  EXPECT_EQ(Slurp(dir + "/b.json"), "new b");
  EXPECT_FALSE(AnyTemporary(dir));
}

TEST(OutputFiles, StaleTemporariesOfDeadProcessesOnly) {
  const std::string dir = ScratchDir("output_stale");
  const std::string dead = dir + "/.m.json.implicitfit-99999999-3.tmp";  // no such process
  const std::string live = dir + "/.n.json.implicitfit-" + std::to_string(::getpid()) + "-9.tmp";
  const std::string unrelated = dir + "/m.json.tmp.99999999";  // not our name: never touched
  for (const std::string& p : {dead, live, unrelated}) WriteText(p, "partial");
  const int fd = ::open(live.c_str(), O_RDONLY);
  ASSERT_EQ(::flock(fd, LOCK_EX), 0);  // a live writer holds its lock
  EXPECT_EQ(RemoveStaleTemporaries(dir), 1);
  EXPECT_FALSE(FileExists(dead));
  EXPECT_TRUE(FileExists(live));
  EXPECT_TRUE(FileExists(unrelated));
  ::close(fd);
}

TEST(OutputFiles, IdentityThroughLinksAndNormalisation) {
  const std::string dir = ScratchDir("output_identity");
  WriteText(dir + "/c.xyz", "0 0 0\n");
  fs::create_directory(dir + "/sub");
  ASSERT_EQ(::symlink("c.xyz", (dir + "/soft").c_str()), 0);
  ASSERT_EQ(::link((dir + "/c.xyz").c_str(), (dir + "/hard").c_str()), 0);
  const FileIdentity c = IdentifyFile(dir + "/c.xyz");
  EXPECT_TRUE(IdentifyFile(dir + "/sub/../c.xyz").SameFileAs(c));
  EXPECT_TRUE(IdentifyFile(dir + "/soft").SameFileAs(c));
  EXPECT_TRUE(IdentifyFile(dir + "/hard").SameFileAs(c));
  EXPECT_FALSE(IdentifyFile(dir + "/other.xyz").SameFileAs(c));
  EXPECT_TRUE(IdentifyFile(dir + "/new.json").SameFileAs(IdentifyFile(dir + "/./new.json")));
}

TEST(JsonFile, RefusesDuplicateKeysWithTheirPath) {
  EXPECT_EQ(ParseJsonDocument("{\"a\": 1, \"b\": [1, {\"c\": 2}]}", "f.json")["b"][1]["c"], 2);
  EXPECT_NE(ErrorOf([] { ParseJsonDocument("{\"a\": 1, \"a\": 2}", "f.json"); })
                .find("f.json: invalid JSON: duplicate key \"a\" in the top-level object"),
            std::string::npos);
  EXPECT_NE(ErrorOf([] {
              ParseJsonDocument("{\"root\": {\"children\": [{}, {\"r\": 1, \"r\": 2}]}}", "f.json");
            }).find("duplicate key \"r\" in root.children[1]"),
            std::string::npos);
  // Equal keys in different objects are not duplicates.
  EXPECT_NO_THROW(ParseJsonDocument("[{\"r\": 1}, {\"r\": 2}]", "f.json"));
}

}  // namespace
}  // namespace implicitfit
