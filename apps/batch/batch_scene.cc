// `batch --model scene`: one detection per input (declared in apps/batch/batch_runner.h).
#include <fstream>
#include <nlohmann/json.hpp>

#include "apps/batch/batch_job.h"
#include "datasets/io/scene_file.h"
#include "implicitfit/detect.h"

namespace implicitfit {
namespace {

// The figures of a complete earlier detection, or false when it must be run again.
bool ReadCompleteScene(const BatchInput& in, const BatchOptions& o, BatchOutcome* out) {
  try {
    const Scene scene = ReadSceneFile(BatchOutputPath(o, in, ".scene.json"));
    ReadLabelsFile(BatchOutputPath(o, in, ".labels.txt"), static_cast<int>(scene.primitives.size()),
                   scene.points);
    const nlohmann::json report = ReadBatchReport(BatchOutputPath(o, in, ".report.json"));
    if (report.value("primitives", 0) != static_cast<int>(scene.primitives.size()) ||
        scene.primitives.empty())
      return false;
    out->points = static_cast<size_t>(scene.points);
    out->inliers = static_cast<size_t>(scene.points - scene.unassigned);
    for (const ScenePrimitive& p : scene.primitives) out->rms = std::max(out->rms, p.rms_distance);
    return true;
  } catch (const std::exception&) {
    return false;  // missing, truncated or inconsistent: detect again
  }
}

}  // namespace

BatchOutcome ProcessSceneInput(const BatchInput& in, const BatchOptions& o) {
  BatchJob job;
  if (!in.kind.empty() && in.kind != "scene")
    job.refusal = "manifest kind " + in.kind + " with --model scene";
  const std::string scene_path = BatchOutputPath(o, in, ".scene.json"),
                    labels_path = BatchOutputPath(o, in, ".labels.txt");
  job.results = {scene_path, labels_path};
  job.read_complete = [&](BatchOutcome* out) { return ReadCompleteScene(in, o, out); };
  job.run = [&](BatchOutcome* out) {
    const CloudDetection d = DetectCloudFile(in.path, o.detect);
    out->points = d.cloud.size();
    out->inliers = static_cast<size_t>(d.scene.points - d.scene.unassigned);
    for (const ScenePrimitive& p : d.scene.primitives)
      out->rms = std::max(out->rms, p.rms_distance);
    if (!d.scene.primitives.empty()) {
      WriteDetection(d, scene_path, labels_path, "");
      out->status = BatchStatus::kOk;
    } else {
      out->status = BatchStatus::kFailed;
      out->error = "no primitive found";
    }
    return d.report;
  };
  return RunBatchJob(in, o, job);
}

}  // namespace implicitfit
