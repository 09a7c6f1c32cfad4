// What every fitter's result shares, in the style of ceres::Solver::Summary: whether the result
// can be used, how the solve ended, the input size and the time. The three fitters' results
// (fit/primitive/primitive_fitter.h, fit/tree/tree_fitter.h, fit/bernstein/patch_fitter.h) derive from it and each adds
// its figures, a one-line BriefReport() (what `implicitfit fit` prints) and ToJson(normals)
// (the report of fit/common/fit_report.h, what `fit --report` writes and Python returns).
//   termination  CONVERGENCE, NO_CONVERGENCE or FAILURE (fit/common/fit_termination.h); FAILURE
//                whenever success is false for want of a usable result (bad options, too few
//                points or inliers, no hypothesis, a failed solve)
//   success      the result is what was asked for; each fitter's header says whether a
//                NO_CONVERGENCE result counts (the patch fitter: yes; the primitive and tree
//                fitters: no, as `fit` has always exited 1 then)
// Messages never name command-line flags: they describe options and data.
#pragma once

#include <cstddef>
#include <string>

#include "fit/common/fit_termination.h"

namespace implicitfit {

struct FitSummary {
  bool success = false;
  std::string message;  // "converged", or why not
  FitTermination termination = FitTermination::kFailure;
  size_t points = 0;     // points given to the fitter
  double seconds = 0.0;  // wall time of the fit
};

}  // namespace implicitfit
