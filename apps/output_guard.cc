#include "apps/output_guard.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <map>
#include <set>
#include <unordered_map>

#include "datasets/io/atomic_file.h"
#include "datasets/io/io_error.h"
#include "datasets/io/output_path.h"

namespace implicitfit {
namespace {

std::set<const CLI::Option*>& Marked(bool output) {
  static std::set<const CLI::Option*> outputs, inputs;
  return output ? outputs : inputs;
}

// Per command: the options naming files it writes, and those naming files it reads besides its
// positional arguments (an option's name alone does not tell: `sample --view` is a direction,
// `view --labels` an input, `detect --labels` an output).
struct FileOptions {
  std::set<std::string> outputs, inputs;
};
const std::map<std::string, FileOptions> kFileOptions = {
    {"fit", {{"--out", "--report", "--view", "--ply"}, {"--init"}}},
    {"detect", {{"--out", "--labels", "--ply", "--report", "--view"}, {"--truth"}}},
    {"reconstruct", {{"--out", "--mesh", "--report", "--view"}, {"--scene"}}},
    {"mesh", {{"--out"}, {}}},
    {"sample", {{"--out", "--truth"}, {}}},
    {"design", {{"--out"}, {}}},
    {"view", {{"--out", "--png"}, {"--labels"}}},
    {"eval", {{}, {}}},
    {"check", {{}, {}}},
    {"batch", {{}, {"--manifest"}}},
};
// A command not in the table (a new one): these.
const FileOptions kDefaultFileOptions = {{"--out", "--report"}, {}};

std::string FolderOf(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

}  // namespace

CLI::Option* OutputFileOption(CLI::Option* option) {
  Marked(true).insert(option);
  return option;
}

CLI::Option* InputFileOption(CLI::Option* option) {
  Marked(false).insert(option);
  return option;
}

CommandFiles FilesOfCommand(const CLI::App& command) {
  CommandFiles files;
  const auto known = kFileOptions.find(command.get_name());
  const FileOptions& names = known == kFileOptions.end() ? kDefaultFileOptions : known->second;
  for (const CLI::Option* option : command.get_options()) {
    if (option->count() == 0) continue;
    const std::string name = option->get_name();
    const bool marked_input = Marked(false).count(option) > 0;
    const bool output = !marked_input && (Marked(true).count(option) || names.outputs.count(name));
    const bool input = !output && (marked_input || names.inputs.count(name) ||
                                   !option->nonpositional());
    if (!output && !input) continue;
    for (const std::string& value : option->results())
      (output ? files.outputs : files.inputs).push_back(value);
  }
  return files;
}

namespace {

// Files seen so far, by normalised path and by device/inode (hashed: batch compares 10^5).
class FileSet {
 public:
  // The given path of an earlier file that is the same as `id`, or nullptr.
  const std::string* Find(const FileIdentity& id) const {
    const auto p = by_path_.find(id.normalised);
    if (p != by_path_.end()) return &p->second;
    if (!id.exists) return nullptr;
    const auto i = by_inode_.find({id.device, id.inode});
    return i == by_inode_.end() ? nullptr : &i->second;
  }
  void Add(const FileIdentity& id, const std::string& given) {
    by_path_.emplace(id.normalised, given);
    if (id.exists) by_inode_.emplace(std::make_pair(id.device, id.inode), given);
  }

 private:
  std::unordered_map<std::string, std::string> by_path_;
  std::map<std::pair<dev_t, ino_t>, std::string> by_inode_;
};

}  // namespace

void RefuseOverlaps(const std::vector<std::string>& inputs,
                    const std::vector<std::string>& outputs) {
  FileSet in, out;
  for (const std::string& p : inputs) in.Add(IdentifyFile(p), p);
  bool stdout_taken = false;
  for (const std::string& p : outputs) {
    if (p == "-") {
      if (stdout_taken) throw InputError("-: standard output is given as two outputs");
      stdout_taken = true;
      continue;
    }
    const FileIdentity id = IdentifyFile(p);
    if (const std::string* input = in.Find(id))
      throw FileError(p, "is also an input (" + *input +
                             "): refused, writing it would destroy the input");
    if (const std::string* earlier = out.Find(id))
      throw FileError(p, "is given as two outputs (also " + *earlier +
                             "): refused, one would overwrite the other");
    out.Add(id, p);
  }
}

void GuardOutputs(const CommandFiles& files) {
  RefuseOverlaps(files.inputs, files.outputs);
  std::set<std::string> folders;
  for (const std::string& path : files.outputs) {
    const OutputTarget target = ResolveOutputPath(path);
    if (target.stdout_) continue;
    ProbeOutputFolder(target);
    folders.insert(FolderOf(target.target));
  }
  for (const std::string& folder : folders) RemoveStaleTemporaries(folder);
}

bool GuardsItsOwnFiles(const std::string& name) { return name == "batch"; }

// view --png screenshots the page --out has just written: its outputs cannot wait for the end.
bool WritesAsItGoes(const std::string& name) { return name == "batch" || name == "view"; }

void ReopenClosedStandardDescriptors() {
  for (int fd = 0; fd <= 2; ++fd) {
    if (::fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
    // stdout read-only: writing to a closed stdout must fail, not vanish.
    const int opened = ::open("/dev/null", fd == 2 ? O_WRONLY : O_RDONLY);
    if (opened >= 0 && opened != fd) {
      ::dup2(opened, fd);
      ::close(opened);
    }
  }
}

struct CommandRun::State {
  std::unique_ptr<OutputTransaction> transaction;
  int saved_stdout = -1;  // the real stdout while "-" is an output (the command prints to stderr)
};

CommandRun::CommandRun(const std::string& name, const CLI::App& command)
    : state_(std::make_unique<State>()) {
  if (GuardsItsOwnFiles(name)) return;
  const CommandFiles files = FilesOfCommand(command);
  if (!WritesAsItGoes(name)) state_->transaction = std::make_unique<OutputTransaction>();
  GuardOutputs(files);
  if (!state_->transaction) return;
  for (const std::string& path : files.outputs)
    if (path == "-") {
      std::fflush(stdout);
      state_->saved_stdout = ::fcntl(1, F_DUPFD_CLOEXEC, 3);
      if (state_->saved_stdout < 0)
        throw InputError(std::string("-: cannot use standard output: ") + std::strerror(errno));
      ::dup2(2, 1);
      state_->transaction->SetStdoutDescriptor(state_->saved_stdout);
      break;
    }
}

CommandRun::~CommandRun() {
  state_->transaction.reset();  // discards what was not committed
  if (state_->saved_stdout >= 0) {
    std::fflush(stdout);
    ::dup2(state_->saved_stdout, 1);
    ::close(state_->saved_stdout);
  }
}

int CommandRun::Finish(int exit_code) {
  std::cout.flush();
  errno = 0;
  const bool flushed = std::fflush(stdout) == 0;
  if (!flushed || std::ferror(stdout) || !std::cout) {
    const std::string why = errno ? std::strerror(errno) : "write error";
    throw InputError("standard output: cannot write: " + why);
  }
  if (state_->transaction) state_->transaction->Commit();
  return exit_code;
}

}  // namespace implicitfit
