// How a fit's solve ended, in the words of ceres::TerminationType:
//   kConverged     CONVERGENCE: a tolerance was met (ceres::CONVERGENCE or USER_SUCCESS);
//   kNoConvergence NO_CONVERGENCE: the iteration (or time) limit came first; the result is
//                  usable, but not converged: more iterations would change it;
//   kFailure       FAILURE: the solver could not produce a usable result.
#pragma once

namespace implicitfit {

enum class FitTermination { kConverged, kNoConvergence, kFailure };

// "CONVERGENCE", "NO_CONVERGENCE" or "FAILURE" (as Ceres spells them).
inline const char* FitTerminationName(FitTermination termination) {
  switch (termination) {
    case FitTermination::kConverged:
      return "CONVERGENCE";
    case FitTermination::kNoConvergence:
      return "NO_CONVERGENCE";
    case FitTermination::kFailure:
      return "FAILURE";
  }
  return "FAILURE";
}

}  // namespace implicitfit
