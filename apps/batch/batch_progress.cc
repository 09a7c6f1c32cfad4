#include "apps/batch/batch_progress.h"

namespace implicitfit {

BatchProgress::BatchProgress(size_t total, bool terminal, bool quiet, std::FILE* out)
    : total_(total), terminal_(terminal && !quiet), quiet_(quiet), out_(out) {}

void BatchProgress::Done(const BatchOutcome& o) {
  ++done_;
  if (o.status != BatchStatus::kSkipped) ++fitted_;
  const bool failed = !o.Succeeded();
  if ((!terminal_ && !quiet_) || failed) {
    if (terminal_) std::fputs("\r\033[K", out_);
    std::fprintf(out_, "[%zu/%zu] %s %s%s%s\n", done_, total_, o.name.c_str(),
                 BatchStatusName(o.status), failed ? ": " : "", failed ? o.Failure().c_str() : "");
  }
  if (terminal_) {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double rate = elapsed > 0 ? fitted_ / elapsed : 0.0;
    std::fprintf(out_, "\r\033[K[%zu/%zu] %.2f inputs/s", done_, total_, rate);
    if (rate > 0 && done_ < total_) std::fprintf(out_, ", ETA %.0f s", (total_ - done_) / rate);
  }
  std::fflush(out_);
}

void BatchProgress::Finish() {
  if (terminal_ && done_ > 0) std::fputs("\n", out_);
  std::fflush(out_);
}

}  // namespace implicitfit
