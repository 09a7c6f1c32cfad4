// One lock for every GLPK call of the library (fit/metrology/chebyshev_lp.h,
// fit/reconstruct/polytope_box.h): GLPK keeps its environment per thread only when built with
// thread-local storage, so the lock makes the solvers safe whichever way the library was built
// (their programmes take well under 1 ms).
#pragma once

#include <mutex>

namespace implicitfit {

inline std::mutex& GlpkMutex() {
  static std::mutex m;
  return m;
}

}  // namespace implicitfit
