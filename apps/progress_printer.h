// Library progress (fit/common/progress.h) as lines on stderr, the same for every command:
//   implicitfit reconstruct: detect (13704 points) ...
//   implicitfit reconstruct: detect: 12 primitives
//   implicitfit reconstruct: detect done in 0.61 s (12 primitives)
// (begin, update, end). quiet: nothing. And the one-line summary every long command ends with:
//   implicitfit reconstruct: <verdict> in <seconds> s: <details>
#pragma once

#include <string>

#include "fit/common/progress.h"

namespace implicitfit {

ProgressCallback StderrProgress(const std::string& command, bool quiet);

// The summary line on stderr (always printed: quiet applies to progress only when ok is false).
void PrintSummary(const std::string& command, bool quiet, bool ok, const std::string& verdict,
                  double seconds, const std::string& details);

}  // namespace implicitfit
