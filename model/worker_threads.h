// Runs work on up to `count` threads without ever terminating the process when threads cannot
// start (std::thread throws std::system_error when the system refuses: too many threads, no
// memory for their stacks; a vector of joinable threads destroyed by that exception would call
// std::terminate). RunWorkers(count, work) calls work(t) exactly once for every t in
// [0, count): t = 1.. on new threads as long as they start, t = 0 and every t whose thread did
// not start on the calling thread, in order. The work must not throw. Returns the number of
// threads that ran (1 + the ones started).
#pragma once

#include <system_error>
#include <thread>
#include <vector>

namespace implicitfit {

template <typename Work>
int RunWorkers(int count, const Work& work) {
  std::vector<std::thread> pool;
  int started = 1;
  for (int t = 1; t < count; ++t) {
    try {
      pool.emplace_back([&work, t]() { work(t); });
      ++started;
    } catch (const std::system_error&) {
      break;
    }
  }
  work(0);
  for (int t = started; t < count; ++t) work(t);
  for (std::thread& thread : pool) thread.join();
  return started;
}

}  // namespace implicitfit
