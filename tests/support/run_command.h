// Runs a shell command for end-to-end tests of the `implicitfit` tool and captures its exit
// code, stdout and stderr. Also makes scratch folders for test files.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace testsupport {

struct CommandResult {
  int exit_code = -1;
  std::string out, err;
};

inline std::string Slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void WriteText(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

inline bool FileExists(const std::string& path) { return ::access(path.c_str(), F_OK) == 0; }

// A fresh folder under /tmp, unique to this process and name.
inline std::string ScratchDir(const std::string& name) {
  std::string dir = "/tmp/implicitfit_test_" + std::to_string(::getpid()) + "_" + name;
  std::system(("rm -rf '" + dir + "' && mkdir -p '" + dir + "'").c_str());
  return dir;
}

inline CommandResult RunCommand(const std::string& command) {
  static int counter = 0;
  const std::string base =
      "/tmp/implicitfit_run_" + std::to_string(::getpid()) + "_" + std::to_string(counter++);
  const int status =
      std::system((command + " > " + base + ".out 2> " + base + ".err < /dev/null").c_str());
  CommandResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = Slurp(base + ".out");
  r.err = Slurp(base + ".err");
  std::remove((base + ".out").c_str());
  std::remove((base + ".err").c_str());
  return r;
}

}  // namespace testsupport
