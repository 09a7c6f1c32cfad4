// `batch --model solid`: one solid reconstruction per input (declared in apps/batch_runner.h).
#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "apps/batch_runner.h"
#include "apps/reconstruct_job.h"
#include "datasets/atomic_file.h"
#include "datasets/model_file.h"

namespace implicitfit {
namespace fs = std::filesystem;
namespace {

std::string OutPath(const BatchOptions& o, const BatchInput& in, const char* suffix) {
  return (fs::path(o.out_dir) / (in.name + suffix)).string();
}

void TakeFigures(const nlohmann::json& report, BatchOutcome* out) {
  out->points = report.value("points", size_t{0});
  out->inliers = static_cast<size_t>(std::max(0, report.value("inliers", 0)));
  out->rms = report.value("rms_distance", 0.0);
}

// The figures of a complete earlier reconstruction, or false when it must be run again.
bool ReadCompleteSolid(const BatchInput& in, const BatchOptions& o, BatchOutcome* out) {
  try {
    ReadModelFile(OutPath(o, in, ".model.json"));
    std::ifstream report_file(OutPath(o, in, ".report.json"));
    if (!report_file) return false;
    const nlohmann::json report = nlohmann::json::parse(report_file);
    if (!report.value("success", false) || !report.contains("expression")) return false;
    TakeFigures(report, out);
    return true;
  } catch (const std::exception&) {
    return false;  // missing, truncated or not a solid report: reconstruct again
  }
}

}  // namespace

BatchOutcome ProcessSolidInput(const BatchInput& in, const BatchOptions& o) {
  BatchOutcome out;
  out.input = in.path;
  out.name = in.name;
  if (!in.kind.empty() && in.kind != "solid") {
    out.error = "manifest kind " + in.kind + " with --model solid";
    return out;
  }
  if (o.resume && ReadCompleteSolid(in, o, &out)) {
    out.status = BatchStatus::kSkipped;
    return out;
  }
  const auto start = std::chrono::steady_clock::now();
  const std::string model_path = OutPath(o, in, ".model.json"),
                    report_path = OutPath(o, in, ".report.json");
  std::error_code ignored;
  try {
    const CloudReconstruction job = ReconstructCloudFile(in.path, "", o.detect.seed);
    TakeFigures(job.report, &out);
    if (job.result.success) {
      WriteModelFile(job.result.model, model_path);
      out.status = BatchStatus::kOk;
    } else {
      fs::remove(model_path, ignored);
      out.status = BatchStatus::kFailed;
      out.error = "reconstruct failed: " + job.result.message;
    }
    WriteFileAtomically(report_path, job.report.dump(2) + "\n");
  } catch (const std::exception& e) {
    fs::remove(model_path, ignored);
    fs::remove(report_path, ignored);
    out.status = BatchStatus::kError;
    out.error = e.what();
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace implicitfit
