// `batch --model solid`: one solid reconstruction per input (declared in apps/batch/batch_runner.h).
#include <fstream>
#include <nlohmann/json.hpp>

#include "apps/batch/batch_job.h"
#include "datasets/io/model_file.h"
#include "implicitfit/reconstruct.h"

namespace implicitfit {
namespace {

void TakeFigures(const nlohmann::json& report, BatchOutcome* out) {
  out->points = report.value("points", size_t{0});
  out->inliers = static_cast<size_t>(std::max(0, report.value("inliers", 0)));
  out->rms = report.value("rms_distance", 0.0);
}

// The figures of a complete earlier reconstruction, or false when it must be run again.
bool ReadCompleteSolid(const BatchInput& in, const BatchOptions& o, BatchOutcome* out) {
  try {
    ReadModelFile(BatchOutputPath(o, in, ".model.json"));
    const nlohmann::json report = ReadBatchReport(BatchOutputPath(o, in, ".report.json"));
    if (!report.value("success", false) || !report.contains("expression")) return false;
    TakeFigures(report, out);
    return true;
  } catch (const std::exception&) {
    return false;  // missing, truncated or not a solid report: reconstruct again
  }
}

}  // namespace

BatchOutcome ProcessSolidInput(const BatchInput& in, const BatchOptions& o) {
  BatchJob job;
  if (!in.kind.empty() && in.kind != "solid")
    job.refusal = "manifest kind " + in.kind + " with --model solid";
  const std::string model_path = BatchOutputPath(o, in, ".model.json");
  job.results = {model_path};
  job.read_complete = [&](BatchOutcome* out) { return ReadCompleteSolid(in, o, out); };
  job.run = [&](BatchOutcome* out) {
    ReconstructJobOptions options;
    options.seed = o.detect.seed;
    const CloudReconstruction r = ReconstructCloudFile(in.path, options);
    TakeFigures(r.report, out);
    if (r.result.success) {
      WriteModelFile(r.result.model, model_path);
      out->status = BatchStatus::kOk;
    } else {
      out->status = BatchStatus::kFailed;
      out->error = "reconstruct failed: " + r.result.message;
    }
    return r.report;
  };
  return RunBatchJob(in, o, job);
}

}  // namespace implicitfit
