// `batch --model scene`: one detection per input (declared in apps/batch_runner.h).
#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "apps/batch_runner.h"
#include "apps/detect_job.h"
#include "datasets/atomic_file.h"
#include "datasets/scene_file.h"

namespace implicitfit {
namespace fs = std::filesystem;
namespace {

std::string OutPath(const BatchOptions& o, const BatchInput& in, const char* suffix) {
  return (fs::path(o.out_dir) / (in.name + suffix)).string();
}

// The figures of a complete earlier detection, or false when it must be run again.
bool ReadCompleteScene(const BatchInput& in, const BatchOptions& o, BatchOutcome* out) {
  try {
    const Scene scene = ReadSceneFile(OutPath(o, in, ".scene.json"));
    ReadLabelsFile(OutPath(o, in, ".labels.txt"), static_cast<int>(scene.primitives.size()),
                   scene.points);
    std::ifstream report_file(OutPath(o, in, ".report.json"));
    if (!report_file) return false;
    const nlohmann::json report = nlohmann::json::parse(report_file);
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
  BatchOutcome out;
  out.input = in.path;
  out.name = in.name;
  if (!in.kind.empty() && in.kind != "scene") {
    out.error = "manifest kind " + in.kind + " with --model scene";
    return out;
  }
  if (o.resume && ReadCompleteScene(in, o, &out)) {
    out.status = BatchStatus::kSkipped;
    return out;
  }
  const auto start = std::chrono::steady_clock::now();
  const std::string scene_path = OutPath(o, in, ".scene.json"),
                    labels_path = OutPath(o, in, ".labels.txt"),
                    report_path = OutPath(o, in, ".report.json");
  std::error_code ignored;
  try {
    const CloudDetection d = DetectCloudFile(in.path, o.detect);
    out.points = d.cloud.size();
    out.inliers = static_cast<size_t>(d.scene.points - d.scene.unassigned);
    for (const ScenePrimitive& p : d.scene.primitives) out.rms = std::max(out.rms, p.rms_distance);
    if (!d.scene.primitives.empty()) {
      WriteDetection(d, scene_path, labels_path, "");
      out.status = BatchStatus::kOk;
    } else {
      fs::remove(scene_path, ignored);
      fs::remove(labels_path, ignored);
      out.status = BatchStatus::kFailed;
      out.error = "no primitive found";
    }
    WriteFileAtomically(report_path, d.report.dump(2) + "\n");
  } catch (const std::exception& e) {
    fs::remove(scene_path, ignored);
    fs::remove(labels_path, ignored);
    fs::remove(report_path, ignored);
    out.status = BatchStatus::kError;
    out.error = e.what();
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace implicitfit
