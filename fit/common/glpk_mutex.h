// GLPK from several threads (fit/metrology/chebyshev_lp.h, fit/reconstruct/polytope_box.h,
// fit/bernstein/convex_feasible_start.h):
//   - one lock for every GLPK call of the library: GLPK keeps its environment per thread only
//     when built with thread-local storage, so the lock makes the solvers safe whichever way the
//     library was built (their programmes take well under 1 ms);
//   - that per-thread environment (allocated by a thread's first GLPK call) lives until
//     glp_free_env() in the same thread: a worker thread that ends without it leaks it
//     (LeakSanitizer: 176 bytes and its buffers per batch or verification thread). Every
//     function that creates a problem calls FreeGlpkEnvironmentAtThreadExit() first; a
//     thread_local guard frees the environment when the thread ends.
#pragma once

#include <glpk.h>

#include <mutex>

namespace implicitfit {

inline std::mutex& GlpkMutex() {
  static std::mutex m;
  return m;
}

inline void FreeGlpkEnvironmentAtThreadExit() {
  struct Guard {
    ~Guard() { glp_free_env(); }
  };
  thread_local Guard guard;
  (void)guard;
}

}  // namespace implicitfit
