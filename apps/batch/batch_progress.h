// Progress of `implicitfit batch` on stderr. Not a terminal: one plain line per finished input,
//   [k/n] name ok|skipped|failed: message|error: message
// On a terminal: one line rewritten in place, "[k/n] r inputs/s, ETA t s" (r over the inputs
// fitted in this run, so skipped ones do not inflate it), with failures printed above it.
// quiet (`batch --quiet`): the failures' lines only.
// Not thread-safe: the caller serialises calls (RunBatch does).
#pragma once

#include <chrono>
#include <cstdio>

#include "apps/batch/batch_runner.h"

namespace implicitfit {

class BatchProgress {
 public:
  BatchProgress(size_t total, bool terminal, bool quiet = false, std::FILE* out = stderr);
  void Done(const BatchOutcome& outcome);
  void Finish();  // ends the in-place line

 private:
  size_t total_, done_ = 0, fitted_ = 0;
  bool terminal_, quiet_;
  std::FILE* out_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace implicitfit
