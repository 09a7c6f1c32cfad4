#include "apps/batch/batch_runner.h"

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <thread>

#include "apps/batch/batch_job.h"
#include "apps/fit_job.h"
#include "datasets/io/atomic_file.h"
#include "datasets/io/model_file.h"

namespace implicitfit {
namespace fs = std::filesystem;
namespace {

std::string ModelPath(const BatchOptions& o, const BatchInput& in) {
  return BatchOutputPath(o, in, ".model.json");
}
std::string ReportPath(const BatchOptions& o, const BatchInput& in) {
  return BatchOutputPath(o, in, ".report.json");
}

// The figures of a complete earlier result, or false when it must be (re)fitted (also when it
// was made with another estimator: a report without "estimator" predates the option, robust).
bool ReadCompleteOutputs(const BatchInput& in, const BatchOptions& o, NodeType kind,
                         Estimator estimator, BatchOutcome* out) {
  try {
    const Model model = ReadModelFile(ModelPath(o, in));
    if (model.root() < 0 || model.nodes()[model.root()].type != kind) return false;
    std::ifstream report_file(ReportPath(o, in));
    if (!report_file) return false;
    const nlohmann::json report = nlohmann::json::parse(report_file);
    if (!report.value("success", false)) return false;
    if (report.value("estimator", std::string("robust")) != EstimatorName(estimator)) return false;
    out->rms = report.at("rms_distance").get<double>();
    out->inliers = report.at("inliers").get<size_t>();
    out->points = report.at("points").get<size_t>();
    return true;
  } catch (const std::exception&) {
    return false;  // missing, truncated or of another kind: fit again
  }
}

std::string CsvField(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) {
    if (c == '"') q += '"';
    q += c;
  }
  return q + "\"";
}

std::string Number(const char* format, double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, v);
  return buffer;
}

// Resume check for the Bernstein kinds (see BatchOptions::model_fit).
bool ReadCompleteModelKindOutputs(const BatchInput& in, const BatchOptions& o, BatchOutcome* out) {
  try {
    const Model model = ReadModelFile(ModelPath(o, in));
    if (model.root() < 0 || model.nodes()[model.root()].type != o.model_kind) return false;
    std::ifstream report_file(ReportPath(o, in));
    if (!report_file) return false;
    const nlohmann::json report = nlohmann::json::parse(report_file);
    if (!report.value("success", false)) return false;
    if (o.require_certified && !report.value("certified_convex", false)) return false;
    out->rms = report.at("rms_distance").get<double>();
    out->points = report.at("points").get<size_t>();
    out->inliers = report.value("inliers", out->points);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

BatchOutcome ProcessModelKindInput(const BatchInput& in, const BatchOptions& o) {
  BatchJob job;
  job.results = {ModelPath(o, in)};
  job.read_complete = [&](BatchOutcome* out) { return ReadCompleteModelKindOutputs(in, o, out); };
  job.run = [&](BatchOutcome* out) {
    const ModelKindFit fit = o.model_fit(in.path);
    out->points = out->inliers = fit.points;
    out->rms = fit.rms;
    if (fit.success) {
      WriteModelFile(fit.model, ModelPath(o, in));
      out->status = BatchStatus::kOk;
    } else {
      out->status = BatchStatus::kFailed;
      out->error = "fit failed: " + fit.message;
    }
    return fit.report;
  };
  return RunBatchJob(in, o, job);
}

}  // namespace

const char* BatchStatusName(BatchStatus status) {
  switch (status) {
    case BatchStatus::kOk:
      return "ok";
    case BatchStatus::kFailed:
      return "failed";
    case BatchStatus::kError:
      return "error";
    case BatchStatus::kSkipped:
      return "skipped";
  }
  return "error";
}

std::string BatchOutputPath(const BatchOptions& o, const BatchInput& in, const char* suffix) {
  return (fs::path(o.out_dir) / (in.name + suffix)).string();
}

BatchOutcome RunBatchJob(const BatchInput& in, const BatchOptions& o, const BatchJob& job) {
  BatchOutcome out;
  out.input = in.path;
  out.name = in.name;
  if (!job.refusal.empty()) {
    out.error = job.refusal;
    return out;
  }
  if (o.resume && job.read_complete(&out)) {
    out.status = BatchStatus::kSkipped;
    return out;
  }
  const auto start = std::chrono::steady_clock::now();
  const std::string report_path = ReportPath(o, in);
  std::error_code ignored;
  try {
    const nlohmann::json report = job.run(&out);
    if (out.status != BatchStatus::kOk)
      for (const std::string& path : job.results) fs::remove(path, ignored);
    WriteFileAtomically(report_path, report.dump(2) + "\n");
  } catch (const std::exception& e) {
    for (const std::string& path : job.results) fs::remove(path, ignored);
    fs::remove(report_path, ignored);
    out.status = BatchStatus::kError;
    out.error = e.what();
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

BatchOutcome ProcessBatchInput(const BatchInput& in, const BatchOptions& o) {
  if (o.scene) return ProcessSceneInput(in, o);
  if (o.solid) return ProcessSolidInput(in, o);
  if (o.model_fit) return ProcessModelKindInput(in, o);
  PrimitiveFitOptions fit_options = o.fit;
  BatchJob job;
  std::string invalid;
  if (!in.kind.empty() && !FittableKindFromName(in.kind, &fit_options.kind))
    job.refusal = "unknown kind " + in.kind;
  else if (!fit_options.IsValid(&invalid))  // e.g. a --fix field the manifest's kind lacks
    job.refusal =
        std::string("options invalid for a ") + NodeTypeName(fit_options.kind) + " fit: " + invalid;
  job.results = {ModelPath(o, in)};
  job.read_complete = [&](BatchOutcome* out) {
    return ReadCompleteOutputs(in, o, fit_options.kind, fit_options.estimator, out);
  };
  job.run = [&](BatchOutcome* out) {
    const CloudFit fit = FitCloudFile(in.path, fit_options);
    out->points = fit.points;
    out->rms = fit.result.rms;
    out->inliers = fit.result.inliers.size();
    if (fit.result.success) {
      WriteModelFile(fit.result.ToModel(fit_options.kind), ModelPath(o, in));
      out->status = BatchStatus::kOk;
    } else {
      out->status = BatchStatus::kFailed;
      out->error =
          std::string(NodeTypeName(fit_options.kind)) + " fit failed: " + fit.result.message;
    }
    return fit.report;
  };
  return RunBatchJob(in, o, job);
}

void RemoveStaleTemporaries(const std::vector<BatchInput>& inputs, const std::string& out_dir) {
  std::set<std::string> prefixes;
  for (const BatchInput& in : inputs) {
    prefixes.insert(in.name + ".model.json.tmp.");
    prefixes.insert(in.name + ".report.json.tmp.");
    prefixes.insert(in.name + ".scene.json.tmp.");
    prefixes.insert(in.name + ".labels.txt.tmp.");
    prefixes.insert(in.name + ".view.html.tmp.");
  }
  std::error_code ec;
  std::vector<fs::path> stale;
  for (fs::directory_iterator it(out_dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string file = it->path().filename().string();
    const size_t tmp = file.rfind(".tmp.");
    if (tmp != std::string::npos && prefixes.count(file.substr(0, tmp + 5)))
      stale.push_back(it->path());
  }
  for (const fs::path& p : stale) fs::remove(p, ec);
}

std::vector<BatchOutcome> RunBatch(const std::vector<BatchInput>& inputs,
                                   const BatchOptions& options,
                                   const BatchProgressCallback& on_done) {
  RemoveStaleTemporaries(inputs, options.out_dir);
  std::vector<BatchOutcome> outcomes(inputs.size());
  std::atomic<size_t> next{0};
  std::mutex report_mutex;
  const auto worker = [&]() {
    for (size_t i = next++; i < inputs.size(); i = next++) {
      outcomes[i] = ProcessBatchInput(inputs[i], options);
      std::lock_guard<std::mutex> lock(report_mutex);
      if (on_done) on_done(outcomes[i]);
    }
  };
  const size_t threads = std::max<size_t>(1, std::min<size_t>(options.jobs, inputs.size()));
  std::vector<std::thread> pool;
  for (size_t t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  return outcomes;
}

std::string SummaryCsv(const std::vector<BatchOutcome>& outcomes) {
  std::ostringstream csv;
  csv << "input,status,rms,inliers,points,seconds,error\n";
  for (const BatchOutcome& o : outcomes) {
    csv << CsvField(o.input) << ',' << BatchStatusName(o.status) << ',';
    if (o.HasFigures())
      csv << Number("%.9g", o.rms) << ',' << o.inliers << ',' << o.points << ',';
    else
      csv << ",,,";
    csv << Number("%.3f", o.seconds) << ',' << CsvField(o.error) << '\n';
  }
  return csv.str();
}

}  // namespace implicitfit
