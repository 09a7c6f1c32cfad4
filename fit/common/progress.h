// Progress of long library work, told to whoever listens: the library reports, the apps print
// (apps/progress_printer.h writes it on stderr, --quiet silences it). One small mechanism for
// every long job (detect, reconstruct's stages, verification, meshing), in the spirit of
// ceres::IterationCallback: an options struct carries a ProgressCallback, empty by default (no
// cost, nothing reported).
//   stage   a short lower-case name: "detect", "orientation", "separation", "tree fit",
//           "verification", "mesh", ...
//   kind    kBegin when the stage starts, kUpdate while it runs (optional), kEnd when it ends
//   detail  what the listener may show: the input size at kBegin, a figure at kUpdate/kEnd
//   seconds wall time since the stage began (0 at kBegin)
// ProgressStage sends kBegin when made and kEnd (once) on End() or when destroyed, so a stage
// left by an exception still ends. Callbacks are called on the thread that runs the stage.
#pragma once

#include <chrono>
#include <functional>
#include <string>
#include <utility>

namespace implicitfit {

struct ProgressEvent {
  enum class Kind { kBegin, kUpdate, kEnd };
  Kind kind = Kind::kBegin;
  std::string stage;
  std::string detail;
  double seconds = 0.0;
};

using ProgressCallback = std::function<void(const ProgressEvent&)>;

class ProgressStage {
 public:
  ProgressStage(ProgressCallback callback, std::string stage, std::string detail = "")
      : callback_(std::move(callback)), stage_(std::move(stage)) {
    Send(ProgressEvent::Kind::kBegin, std::move(detail));
  }
  ProgressStage(const ProgressStage&) = delete;
  ProgressStage& operator=(const ProgressStage&) = delete;
  ~ProgressStage() { End(); }

  void Update(std::string detail) {
    if (!ended_) Send(ProgressEvent::Kind::kUpdate, std::move(detail));
  }
  void End(std::string detail = "") {
    if (ended_) return;
    ended_ = true;
    Send(ProgressEvent::Kind::kEnd, std::move(detail));
  }
  double Seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  void Send(ProgressEvent::Kind kind, std::string detail) {
    if (!callback_) return;
    ProgressEvent e;
    e.kind = kind;
    e.stage = stage_;
    e.detail = std::move(detail);
    e.seconds = kind == ProgressEvent::Kind::kBegin ? 0.0 : Seconds();
    callback_(e);
  }

  ProgressCallback callback_;
  std::string stage_;
  bool ended_ = false;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace implicitfit
