// The number of threads a fit uses when its options say 0: every core the system reports
// (std::thread::hardware_concurrency), at least 1 (it may report 0 when unknown).
#pragma once

#include <algorithm>
#include <cstddef>
#include <thread>
#include <vector>

namespace implicitfit {

inline int DefaultThreadCount() {
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

// `requested` when positive, else DefaultThreadCount().
inline int ThreadCountOrDefault(int requested) {
  return requested > 0 ? requested : DefaultThreadCount();
}

// Runs body(begin, end) over [0, n) in at most `threads` contiguous chunks (one per 256 items
// at least), the first on the calling thread.
template <typename Body>
void ParallelFor(size_t n, int threads, const Body& body) {
  const size_t chunks = std::max<size_t>(1, std::min<size_t>(std::max(threads, 1), n / 256 + 1));
  std::vector<std::thread> pool;
  for (size_t c = 1; c < chunks; ++c)
    pool.emplace_back([&body, n, c, chunks] { body(n * c / chunks, n * (c + 1) / chunks); });
  body(0, n / chunks);
  for (std::thread& t : pool) t.join();
}

}  // namespace implicitfit
