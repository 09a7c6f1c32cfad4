#include "datasets/io/output_path.h"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>

#include "datasets/io/io_error.h"

namespace implicitfit {
namespace fs = std::filesystem;
namespace {

const char kTag[] = ".implicitfit-";

std::string DirectoryOf(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

std::string NameOf(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

const char* KindOf(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a named pipe (FIFO)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

// Follows symbolic links from `path` to the name finally written.
std::string FollowLinks(const std::string& path) {
  std::string current = path;
  for (int hops = 0; hops < 40; ++hops) {
    struct stat st;
    if (::lstat(current.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return current;
    std::string link(PATH_MAX, '\0');
    const ssize_t n = ::readlink(current.c_str(), link.data(), link.size());
    if (n < 0) throw FileError(path, std::string("cannot read the link: ") + std::strerror(errno));
    link.resize(static_cast<size_t>(n));
    current = !link.empty() && link[0] == '/' ? link : DirectoryOf(current) + "/" + link;
  }
  throw FileError(path, "too many levels of symbolic links");
}

// A process that may still hold the temporary: alive, or not ours to judge.
bool ProcessAlive(long pid) {
  if (pid <= 0) return true;
  return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH;
}

// The pid of a temporary's name, or -1 when the name is not one of ours.
long TemporaryOwner(const std::string& name) {
  if (name.size() < 6 || name.compare(name.size() - 4, 4, ".tmp") != 0) return -1;
  const size_t tag = name.rfind(kTag);
  if (tag == std::string::npos) return -1;
  const char* p = name.c_str() + tag + sizeof kTag - 1;
  char* end = nullptr;
  const long pid = std::strtol(p, &end, 10);
  if (end == p || *end != '-') return -1;
  const char* q = end + 1;
  std::strtol(q, &end, 10);
  if (end == q || std::strcmp(end, ".tmp") != 0) return -1;
  return pid;
}

}  // namespace

bool FileIdentity::SameFileAs(const FileIdentity& other) const {
  if (exists && other.exists && device == other.device && inode == other.inode) return true;
  return normalised == other.normalised;
}

FileIdentity IdentifyFile(const std::string& path) {
  FileIdentity id;
  std::error_code ec;
  std::string target = path;
  try {
    target = FollowLinks(path);
  } catch (const InputError&) {
  }
  fs::path p = fs::absolute(target, ec);
  if (ec) p = target;
  const fs::path normal = fs::weakly_canonical(p, ec);
  id.normalised = (ec ? p.lexically_normal() : normal).string();
  struct stat st;
  if (::stat(target.c_str(), &st) == 0) {
    id.exists = true;
    id.device = st.st_dev;
    id.inode = st.st_ino;
  }
  return id;
}

OutputTarget ResolveOutputPath(const std::string& path) {
  OutputTarget out;
  out.path = path;
  if (path == "-") {
    out.stdout_ = true;
    out.target = "-";
    return out;
  }
  if (path.empty()) throw InputError("an output path is empty");
  if (path.back() == '/') throw FileError(path, "names a folder, not a file");
  out.target = FollowLinks(path);
  struct stat st;
  if (::stat(out.target.c_str(), &st) == 0) {
    if (!S_ISREG(st.st_mode))
      throw FileError(path, std::string("is ") + KindOf(st.st_mode) +
                                ", not a regular file: refused as an output (use '-' for "
                                "standard output)");
    out.exists = true;
    out.mode = st.st_mode & 07777;
    out.owner = st.st_uid;
    out.group = st.st_gid;
    out.device = st.st_dev;
    out.inode = st.st_ino;
  } else if (errno != ENOENT) {
    throw FileError(path, std::string("cannot write: ") + std::strerror(errno));
  }
  const std::string dir = DirectoryOf(out.target);
  struct stat ds;
  if (::stat(dir.c_str(), &ds) != 0)
    throw FileError(path, "cannot write: the folder " + dir + " does not exist");
  if (!S_ISDIR(ds.st_mode)) throw FileError(path, "cannot write: " + dir + " is not a folder");
  if (NameOf(out.target).size() > NAME_MAX)
    throw FileError(path, "cannot write: the file name is longer than " +
                              std::to_string(NAME_MAX) + " bytes");
  return out;
}

std::string TemporaryPathFor(const std::string& target) {
  static std::atomic<unsigned long> counter{0};
  const std::string name = NameOf(target);
  // 255-byte names leave room for ".<100 bytes>.implicitfit-<pid>-<n>.tmp".
  const std::string prefix = name.substr(0, 100);
  return DirectoryOf(target) + "/." + prefix + kTag + std::to_string(::getpid()) + "-" +
         std::to_string(counter++) + ".tmp";
}

void ProbeOutputFolder(const OutputTarget& target) {
  if (target.stdout_) return;
  const std::string probe = TemporaryPathFor(target.target);
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0)
    throw FileError(target.path, std::string("cannot write in its folder: ") + std::strerror(errno));
  ::close(fd);
  ::unlink(probe.c_str());
}

int RemoveStaleTemporaries(const std::string& dir) {
  DIR* d = ::opendir(dir.c_str());
  if (!d) return 0;
  int removed = 0;
  const std::time_t now = std::time(nullptr);
  while (const dirent* entry = ::readdir(d)) {
    const std::string name = entry->d_name;
    const long pid = TemporaryOwner(name);
    if (pid < 0) continue;
    const std::string path = dir + "/" + name;
    const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) continue;
    struct stat st;
    // The writer locks its temporary right after creating it: a free lock is a dead writer,
    // or one between open and flock (then its process is alive and its file new).
    const bool stale = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) &&
                       ::flock(fd, LOCK_EX | LOCK_NB) == 0 &&
                       (!ProcessAlive(pid) || (pid != ::getpid() && now - st.st_mtime > 3600));
    if (stale && ::unlink(path.c_str()) == 0) ++removed;
    ::close(fd);
  }
  ::closedir(d);
  return removed;
}

}  // namespace implicitfit
