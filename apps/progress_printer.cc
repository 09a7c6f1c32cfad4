#include "apps/progress_printer.h"

#include <cstdio>
#include <iostream>

namespace implicitfit {

ProgressCallback StderrProgress(const std::string& command, bool quiet) {
  if (quiet) return {};
  return [command](const ProgressEvent& e) {
    std::string line = "implicitfit " + command + ": " + e.stage;
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.2f", e.seconds);
    switch (e.kind) {
      case ProgressEvent::Kind::kBegin:
        line += (e.detail.empty() ? "" : " (" + e.detail + ")") + " ...";
        break;
      case ProgressEvent::Kind::kUpdate:
        line += ": " + e.detail;
        break;
      case ProgressEvent::Kind::kEnd:
        line += " done in " + std::string(seconds) + " s" +
                (e.detail.empty() ? "" : " (" + e.detail + ")");
        break;
    }
    std::cerr << line << std::endl;
  };
}

void PrintSummary(const std::string& command, bool quiet, bool ok, const std::string& verdict,
                  double seconds, const std::string& details) {
  if (quiet && ok) return;
  char s[32];
  std::snprintf(s, sizeof s, "%.2f", seconds);
  std::cerr << "implicitfit " << command << ": " << verdict << " in " << s << " s"
            << (details.empty() ? "" : ": " + details) << std::endl;
}

}  // namespace implicitfit
