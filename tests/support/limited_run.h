// Runs a shell command the way a hostile-input test needs: in its own process group, under a
// CPU and (outside sanitized builds) an address-space limit, killed after a wall-clock bound,
// with its exit status, signal, peak resident memory and time recorded and stdout/stderr
// captured. A command that outlives its bound counts as a hang; one killed by a signal other
// than the timeout's as a crash.
#pragma once

#include <signal.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

#include "support/run_command.h"

namespace testsupport {

struct LimitedRun {
  int exit_code = -1;     // -1 when killed by a signal
  int signal = 0;         // the signal that ended it (0: exited)
  bool timed_out = false;  // killed at the wall-clock bound
  double seconds = 0.0;
  long max_rss_kb = 0;  // peak resident set (getrusage of the child)
  std::string out, err;
};

struct RunLimits {
  double wall_seconds = 20.0;
  long cpu_seconds = 120;
  long long address_space_bytes = 0;  // 0: no RLIMIT_AS (sanitizers reserve terabytes)
};

// `command` runs as `/bin/sh -c command` in `dir`, stdin /dev/null.
inline LimitedRun RunLimited(const std::string& command, const std::string& dir,
                             const RunLimits& limits) {
  static int counter = 0;
  const std::string base = "/tmp/implicitfit_limited_" + std::to_string(::getpid()) + "_" +
                           std::to_string(counter++);
  const std::string out_path = base + ".out", err_path = base + ".err";
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::setpgid(0, 0);
    if (limits.address_space_bytes > 0) {
      const rlimit as = {static_cast<rlim_t>(limits.address_space_bytes),
                         static_cast<rlim_t>(limits.address_space_bytes)};
      ::setrlimit(RLIMIT_AS, &as);
    }
    const rlimit cpu = {static_cast<rlim_t>(limits.cpu_seconds),
                        static_cast<rlim_t>(limits.cpu_seconds)};
    ::setrlimit(RLIMIT_CPU, &cpu);
    if (!std::freopen("/dev/null", "r", stdin) || !std::freopen(out_path.c_str(), "w", stdout) ||
        !std::freopen(err_path.c_str(), "w", stderr) || ::chdir(dir.c_str()) != 0)
      ::_exit(127);
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  LimitedRun r;
  int status = 0;
  rusage usage{};
  while (true) {
    const pid_t done = ::wait4(pid, &status, WNOHANG, &usage);
    if (done == pid) break;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (elapsed > limits.wall_seconds && !r.timed_out) {
      r.timed_out = true;
      ::kill(-pid, SIGKILL);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (r.timed_out) ::kill(-pid, SIGKILL);  // anything the shell left behind
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.max_rss_kb = usage.ru_maxrss;
  if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  r.out = Slurp(out_path);
  r.err = Slurp(err_path);
  std::remove(out_path.c_str());
  std::remove(err_path.c_str());
  return r;
}

}  // namespace testsupport
