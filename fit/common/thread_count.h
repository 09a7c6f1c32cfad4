// The number of threads a fit uses when its options say 0: every core the system reports
// (std::thread::hardware_concurrency), at least 1 (it may report 0 when unknown).
#pragma once

#include <algorithm>
#include <thread>

namespace implicitfit {

inline int DefaultThreadCount() {
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

// `requested` when positive, else DefaultThreadCount().
inline int ThreadCountOrDefault(int requested) {
  return requested > 0 ? requested : DefaultThreadCount();
}

}  // namespace implicitfit
