#include "datasets/io/atomic_file.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <vector>

#include "datasets/io/io_error.h"
#include "datasets/io/output_path.h"

namespace implicitfit {
namespace {

struct Staged {
  std::string path, temporary, target;
  int fd = -1;  // open until renamed: it holds the flock that marks the temporary as live
};

struct TransactionState {
  std::mutex mutex;
  bool active = false;
  std::vector<Staged> staged;
  bool has_stdout = false;
  std::string stdout_content;
  int stdout_fd = 1;
};

TransactionState& State() {
  static TransactionState state;
  return state;
}

bool WriteAll(int fd, const char* data, size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data += n;
    size -= static_cast<size_t>(n);
  }
  return true;
}

void Discard(Staged* s) {
  if (!s->temporary.empty()) ::unlink(s->temporary.c_str());
  if (s->fd >= 0) ::close(s->fd);
  s->fd = -1;
}

void SyncFolderOf(const std::string& target) {
  const size_t slash = target.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "." : slash == 0 ? "/" : target.substr(0, slash);
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}

// Writes `content` to a fresh locked temporary beside the target; the open descriptor.
Staged WriteTemporary(const OutputTarget& out, const std::string& content) {
  Staged s;
  s.path = out.path;
  s.target = out.target;
  s.temporary = TemporaryPathFor(out.target);
  s.fd = ::open(s.temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (s.fd < 0) throw FileError(out.path, std::string("cannot write: ") + std::strerror(errno));
  ::flock(s.fd, LOCK_EX);
  if (out.exists) {  // the replacement keeps the file's permissions (and owner when allowed)
    ::fchmod(s.fd, out.mode);
    if (::fchown(s.fd, out.owner, out.group) != 0) ::fchmod(s.fd, out.mode);
  }
  if (!WriteAll(s.fd, content.data(), content.size()) || ::fsync(s.fd) != 0) {
    const std::string why = std::strerror(errno);
    Discard(&s);
    throw FileError(out.path, "cannot write: " + why);
  }
  return s;
}

void RenameIntoPlace(Staged* s) {
  if (::rename(s->temporary.c_str(), s->target.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    Discard(s);
    throw FileError(s->path, "cannot write: " + why);
  }
  s->temporary.clear();
  SyncFolderOf(s->target);
  ::close(s->fd);
  s->fd = -1;
}

}  // namespace

void WriteFileAtomically(const std::string& path, const std::string& content) {
  const OutputTarget out = ResolveOutputPath(path);
  TransactionState& state = State();
  if (out.stdout_) {
    std::lock_guard<std::mutex> lock(state.mutex);
    if (state.active) {
      state.has_stdout = true;
      state.stdout_content += content;
      return;
    }
    std::fflush(stdout);
    if (!WriteAll(1, content.data(), content.size()))
      throw FileError("-", std::string("cannot write to standard output: ") + std::strerror(errno));
    return;
  }
  Staged s = WriteTemporary(out, content);
  std::lock_guard<std::mutex> lock(state.mutex);
  if (!state.active) {
    RenameIntoPlace(&s);
    return;
  }
  for (Staged& earlier : state.staged)
    if (earlier.target == s.target) {  // written twice in one run: the last content wins
      Discard(&earlier);
      earlier = s;
      return;
    }
  state.staged.push_back(s);
}

std::string CurrentFileLocation(const std::string& path) {
  TransactionState& state = State();
  std::lock_guard<std::mutex> lock(state.mutex);
  if (state.active)
    for (const Staged& s : state.staged)
      if (s.path == path || s.target == path) return s.temporary;
  return path;
}

OutputTransaction::OutputTransaction() {
  TransactionState& state = State();
  std::lock_guard<std::mutex> lock(state.mutex);
  state.active = true;
  state.staged.clear();
  state.has_stdout = false;
  state.stdout_content.clear();
  state.stdout_fd = 1;
}

OutputTransaction::~OutputTransaction() {
  TransactionState& state = State();
  std::lock_guard<std::mutex> lock(state.mutex);
  for (Staged& s : state.staged) Discard(&s);
  state.staged.clear();
  state.active = false;
  state.has_stdout = false;
  state.stdout_content.clear();
}

void OutputTransaction::SetStdoutDescriptor(int fd) {
  std::lock_guard<std::mutex> lock(State().mutex);
  State().stdout_fd = fd;
}

void OutputTransaction::Commit() {
  TransactionState& state = State();
  std::lock_guard<std::mutex> lock(state.mutex);
  if (state.has_stdout &&
      !WriteAll(state.stdout_fd, state.stdout_content.data(), state.stdout_content.size()))
    throw FileError("-", std::string("cannot write to standard output: ") + std::strerror(errno));
  state.has_stdout = false;
  for (Staged& s : state.staged) RenameIntoPlace(&s);
  state.staged.clear();
  state.active = false;
}

}  // namespace implicitfit
