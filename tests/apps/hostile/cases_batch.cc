// Batch runs a careless user sets up: special files in the input folder, more jobs than threads
// can start, --resume after changing the settings, outputs colliding with inputs, two batches
// sharing a folder.
#include <sys/file.h>
#include <fcntl.h>
#include <unistd.h>

#include <filesystem>

#include "apps/hostile/hostile_case.h"

namespace hostile {
namespace {

void Clouds(const std::string& dir, int count, int points = 60) {
  std::filesystem::create_directories(dir + "/in");
  for (int i = 0; i < count; ++i)
    Write(dir + "/in/s" + std::to_string(i) + ".xyz", SphereXyz(points, 1.0 + 0.01 * i));
}

Case Batch(const std::string& name, const std::string& args, int exit_code,
           const std::string& mention, const std::string& defect) {
  Case c;
  c.family = "batch";
  c.name = name;
  c.args = args;
  c.exit_code = exit_code;
  if (!mention.empty()) c.mention = {mention};
  c.outputs = {"out"};  // the out-dir and everything in it
  c.defect = defect;
  c.seconds = 30;
  c.sanitized = true;
  return c;
}

}  // namespace

std::vector<Case> BatchCases() {
  std::vector<Case> cases;
  Case fifo = Batch("batch_fifo_in_folder", "batch in --model sphere --out-dir out", 1, "FIFO",
                    "a FIFO in a batch folder hangs the batch");
  fifo.setup = [](const std::string& dir) {
    Clouds(dir, 3);
    MakeFifo(dir + "/in/pipe.xyz");
  };
  cases.push_back(fifo);
  Case zero = Batch("batch_devzero_in_folder", "batch in --model sphere --out-dir out", 1,
                    "device", "");
  zero.setup = [](const std::string& dir) {
    Clouds(dir, 2);
    MakeSymlink("/dev/zero", dir + "/in/zero.xyz");
  };
  cases.push_back(zero);
  // More jobs than threads can start (their stacks do not fit the address-space limit).
  Case jobs = Batch("batch_threads_cannot_start", "batch in --model sphere --out-dir out --jobs 300",
                    0, "", "batch --jobs N aborts (SIGABRT) when the threads cannot all start");
  jobs.setup = [](const std::string& dir) { Clouds(dir, 300, 40); };
  jobs.address_space = 1200LL << 20;
  jobs.seconds = 90;
  jobs.sanitized = false;  // no address-space limit under the sanitizers
  jobs.must_exist = {"out/summary.csv", "out/s299.model.json"};
  cases.push_back(jobs);
  // --resume after a change of the settings the results depend on: refused with the difference.
  const std::vector<std::pair<std::string, std::string>> changes = {
      {"threshold", "--threshold 0.05"}, {"seed", "--seed 7"}, {"fix", "--fix radius=1"},
      {"estimator", "--estimator least-squares"}};
  for (const auto& [id, option] : changes) {
    Case c = Batch("batch_resume_changed_" + id,
                   "{cli} batch in --model sphere --out-dir out > /dev/null && {cli} batch in "
                   "--model sphere --out-dir out --resume " + option,
                   2, "settings",
                   "--resume reuses results made with a different --threshold, --seed or --fix");
    c.setup = [](const std::string& dir) { Clouds(dir, 2); };
    cases.push_back(c);
  }
  Case same = Batch("batch_resume_same_settings",
                    "{cli} batch in --model sphere --out-dir out --seed 3 > /dev/null && {cli} "
                    "batch in --model sphere --out-dir out --seed 3 --resume | grep -q '2 skipped'",
                    0, "", "");
  same.setup = [](const std::string& dir) { Clouds(dir, 2); };
  cases.push_back(same);
  // Outputs colliding with inputs: a manifest that is the summary, a cloud named like labels.
  Case manifest = Batch("batch_manifest_is_summary",
                        "batch --manifest out/summary.csv --model sphere --out-dir out", 2,
                        "input", "");
  manifest.setup = [](const std::string& dir) {
    Clouds(dir, 2);
    std::filesystem::create_directories(dir + "/out");
    Write(dir + "/out/summary.csv", "../in/s0.xyz\n../in/s1.xyz\n");
  };
  manifest.outputs = {};
  cases.push_back(manifest);
  Case labels = Batch("batch_cloud_named_like_labels", "batch a.txt a.labels.txt --model scene "
                      "--out-dir .", 2, "input", "");
  labels.setup = [](const std::string& dir) {
    Write(dir + "/a.txt", SphereXyz(200));
    Write(dir + "/a.labels.txt", SphereXyz(200, 2.0));
  };
  labels.outputs = {};
  cases.push_back(labels);
  Case out_file = Batch("batch_out_dir_is_file", "batch in --model sphere --out-dir in/s0.xyz",
                        2, "s0.xyz", "");
  out_file.setup = [](const std::string& dir) { Clouds(dir, 2); };
  out_file.outputs = {};
  cases.push_back(out_file);
  // A live run's temporary in the shared folder (this test holds its lock): never deleted.
  Case live = Batch("batch_keeps_live_temporaries", "batch in --model sphere --out-dir out", 0,
                    "", "two batches in one folder delete each other's temporaries");
  live.setup = [](const std::string& dir) {
    Clouds(dir, 2);
    std::filesystem::create_directories(dir + "/out");
    const std::string pid = std::to_string(::getpid());
    for (const std::string& name :
         {"/out/.s0.model.json.implicitfit-" + pid + "-7.tmp", "/out/s0.model.json.tmp." + pid}) {
      Write(dir + name, "{\"being\": \"written\"");
      const int fd = ::open((dir + name).c_str(), O_RDONLY);
      ::flock(fd, LOCK_EX);  // held (and the file open) until this test process ends
    }
  };
  live.check = [](const std::string& dir, const RunOutcome&) {
    std::vector<std::string> p;
    const std::string pid = std::to_string(::getpid());
    for (const std::string& name :
         {"/out/.s0.model.json.implicitfit-" + pid + "-7.tmp", "/out/s0.model.json.tmp." + pid})
      if (::access((dir + name).c_str(), F_OK) != 0)
        p.push_back(name + ", a live process's temporary, was deleted");
    return p;
  };
  cases.push_back(live);
  // Two shards of one batch in one folder at the same time: both complete, every result there.
  Case shards = Batch("batch_two_shards_one_folder",
                      "{cli} batch in --model sphere --out-dir out --shard 1/2 --jobs 2 > /dev/null"
                      " & {cli} batch in --model sphere --out-dir out --shard 2/2 --jobs 2 > "
                      "/dev/null & wait %1 && wait %2 && test $(ls out/*.model.json | wc -l) = 40",
                      0, "", "");
  shards.setup = [](const std::string& dir) { Clouds(dir, 40, 40); };
  shards.seconds = 60;
  cases.push_back(shards);
  return cases;
}

}  // namespace hostile
