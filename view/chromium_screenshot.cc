#include "view/chromium_screenshot.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

#include "datasets/io/atomic_file.h"
#include "datasets/io/io_error.h"

extern char** environ;

namespace implicitfit {
namespace {

namespace fs = std::filesystem;

bool IsExecutable(const std::string& path) {
  struct stat st;
  return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(path.c_str(), X_OK) == 0;
}

std::string OnPath(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/bin:/bin");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::string candidate = (dir.empty() ? std::string(".") : dir) + "/" + name;
    if (IsExecutable(candidate)) return candidate;
  }
  return "";
}

// file:// URL of an absolute path: bytes outside the unreserved set and '/' percent-encoded.
std::string FileUrl(const std::string& path) {
  static const char kHex[] = "0123456789ABCDEF";
  std::string url = "file://";
  for (unsigned char c : fs::absolute(path).lexically_normal().string()) {
    if (std::isalnum(c) || c == '/' || c == '-' || c == '_' || c == '.' || c == '~') {
      url += static_cast<char>(c);
    } else {
      url += '%';
      url += kHex[c >> 4];
      url += kHex[c & 15];
    }
  }
  return url;
}

std::string Slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string LogTail(const std::string& log_path) {
  const std::string log = Slurp(log_path);
  std::vector<std::string> lines;
  std::stringstream in(log);
  std::string line;
  while (std::getline(in, line))
    if (line.find("dbus") == std::string::npos && !line.empty()) lines.push_back(line);
  std::string tail;
  for (size_t i = lines.size() > 6 ? lines.size() - 6 : 0; i < lines.size(); ++i)
    tail += "\n  " + lines[i].substr(0, 300);
  return tail;
}

// A scratch folder removed on destruction.
struct ScratchFolder {
  std::string path;
  ScratchFolder() {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/implicitfit-view-XXXXXX";
    if (!::mkdtemp(pattern.data())) throw std::runtime_error("cannot create a scratch folder in /tmp");
    path = pattern;
  }
  ~ScratchFolder() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

// Runs argv in its own process group with stdout and stderr to log_path; the exit status, or
// -1 after a kill at the deadline. The whole group is killed when the leader ends.
int RunWithDeadline(const std::vector<std::string>& argv, const std::string& log_path,
                    double timeout_seconds) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attributes, 0);
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = -1;
  const int spawned = posix_spawn(&pid, argv[0].c_str(), &actions, &attributes, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (spawned != 0) throw std::runtime_error("cannot start " + argv[0]);
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::milliseconds(static_cast<long>(timeout_seconds * 1000));
  int status = 0;
  while (true) {
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (done < 0) {
      status = -1;
      break;
    }
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(-pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      return -1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ::kill(-pid, SIGKILL);  // helpers Chromium left behind (ESRCH when there are none)
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

}  // namespace

std::string FindChromium() {
  const char* chosen = std::getenv("IMPLICITFIT_CHROMIUM");
  if (chosen && *chosen) return IsExecutable(chosen) ? chosen : "";
  for (const char* name : {"chromium", "chromium-browser", "google-chrome", "google-chrome-stable"}) {
    const std::string path = OnPath(name);
    if (!path.empty()) return path;
  }
  return "";
}

std::string RequireChromium() {
  const std::string chromium = FindChromium();
  if (!chromium.empty()) return chromium;
  const char* chosen = std::getenv("IMPLICITFIT_CHROMIUM");
  if (chosen && *chosen)
    throw InputError(std::string("--png: IMPLICITFIT_CHROMIUM=") + chosen +
                     " is not an executable file");
  throw InputError(
      "--png needs headless Chromium, which is not installed: none of chromium, "
      "chromium-browser, google-chrome, google-chrome-stable is on PATH (Debian: apt-get install "
      "chromium; or set IMPLICITFIT_CHROMIUM). The page itself (--out) needs no browser to write.");
}

namespace {

void Screenshot(const std::string& chromium, const ScratchFolder& scratch,
                const std::string& page_path, const std::string& png_path,
                const ScreenshotOptions& options) {
  if (options.width < 16 || options.height < 16 || options.width > 8192 || options.height > 8192)
    throw std::invalid_argument("picture size " + std::to_string(options.width) + "x" +
                                std::to_string(options.height) + ": 16..8192 pixels a side");
  const std::string profile = scratch.path + "/profile", shot = scratch.path + "/shot.png",
                    log = scratch.path + "/chromium.log";
  fs::create_directory(profile);
  std::string url = FileUrl(page_path);
  if (!options.fragment.empty()) url += "#" + options.fragment;
  const std::vector<std::string> argv = {
      chromium, "--headless", "--no-sandbox", "--disable-gpu", "--enable-unsafe-swiftshader",
      "--use-angle=swiftshader", "--disable-background-networking", "--disable-component-update",
      "--disable-sync", "--no-first-run", "--no-default-browser-check", "--disable-extensions",
      "--disable-dev-shm-usage", "--hide-scrollbars", "--force-device-scale-factor=1",
      "--mute-audio", "--user-data-dir=" + profile, "--screenshot=" + shot,
      "--window-size=" + std::to_string(options.width) + "," + std::to_string(options.height), url};
  const int code = RunWithDeadline(argv, log, options.timeout_seconds);
  if (code == -1)
    throw std::runtime_error("Chromium did not finish the picture within " +
                             std::to_string(static_cast<int>(options.timeout_seconds)) + " s" +
                             LogTail(log));
  const std::string png = Slurp(shot);
  if (code != 0 || png.size() < 8 || png.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0)
    throw std::runtime_error(chromium + " wrote no picture (exit code " + std::to_string(code) +
                             ")" + LogTail(log));
  WriteFileAtomically(png_path, png);
}

}  // namespace

void ScreenshotPage(const std::string& chromium, const std::string& page_path,
                    const std::string& png_path, const ScreenshotOptions& options) {
  ScratchFolder scratch;
  Screenshot(chromium, scratch, page_path, png_path, options);
}

void ScreenshotHtml(const std::string& chromium, const std::string& html,
                    const std::string& png_path, const ScreenshotOptions& options) {
  ScratchFolder scratch;
  const std::string page = scratch.path + "/page.html";
  WriteFileAtomically(page, html);
  Screenshot(chromium, scratch, page, png_path, options);
}

}  // namespace implicitfit
