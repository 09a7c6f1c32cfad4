#include "apps/batch/batch_runner.h"
#include "apps/report_header.h"

#include <sys/resource.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <mutex>
#include <new>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <thread>

#include "apps/batch/batch_job.h"
#include "apps/fit/fit_job.h"
#include "datasets/io/atomic_file.h"
#include "datasets/io/model_file.h"
#include "datasets/io/output_path.h"
#include "datasets/io/io_error.h"
#include "datasets/io/text_file.h"
#include "model/worker_threads.h"

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
    const nlohmann::json report = ReadBatchReport(ReportPath(o, in));
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
    const nlohmann::json report = ReadBatchReport(ReportPath(o, in));
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

nlohmann::json ReadBatchReport(const std::string& path) {
  return nlohmann::json::parse(ReadTextFile(path));
}

namespace {

// The stored settings of an earlier report: null when there is none (or no readable report).
nlohmann::json StoredSettings(const std::string& report_path) {
  try {
    const nlohmann::json report = ReadBatchReport(report_path);
    if (report.is_object() && report.contains("batch_settings")) return report["batch_settings"];
  } catch (const std::exception&) {
  }
  return nullptr;
}

std::string SettingsDifference(const nlohmann::json& stored, const nlohmann::json& current) {
  std::string diff;
  for (auto it = current.begin(); it != current.end(); ++it) {
    const nlohmann::json there = stored.is_object() && stored.contains(it.key())
                                     ? stored.at(it.key())
                                     : nlohmann::json("(absent)");
    if (there != it.value())
      diff += (diff.empty() ? "" : ", ") + it.key() + " " + there.dump() + " there, " +
              it.value().dump() + " now";
  }
  if (stored.is_object())
    for (auto it = stored.begin(); it != stored.end(); ++it)
      if (!current.contains(it.key()))
        diff += (diff.empty() ? "" : ", ") + it.key() + " " + it.value().dump() + " there only";
  return diff;
}

}  // namespace

void RefuseChangedSettings(const std::vector<BatchInput>& inputs, const BatchOptions& o) {
  for (const BatchInput& in : inputs) {
    const std::string report = ReportPath(o, in);
    const nlohmann::json stored = StoredSettings(report);
    if (stored.is_null() || stored == o.settings) continue;
    throw FileError(report, "made with other settings (" + SettingsDifference(stored, o.settings) +
                                "): --resume would mix results; use another --out-dir, the "
                                "same options, or drop --resume");
  }
}

std::vector<std::string> BatchOutputPaths(const std::vector<BatchInput>& inputs,
                                          const BatchOptions& o, const std::string& summary_path) {
  std::vector<std::string> paths;
  for (const BatchInput& in : inputs) {
    paths.push_back(ReportPath(o, in));
    if (o.scene) {
      paths.push_back(BatchOutputPath(o, in, ".scene.json"));
      paths.push_back(BatchOutputPath(o, in, ".labels.txt"));
    } else {
      paths.push_back(ModelPath(o, in));
    }
  }
  paths.push_back(summary_path);
  return paths;
}

BatchOutcome RunBatchJob(const BatchInput& in, const BatchOptions& o, const BatchJob& job) {
  BatchOutcome out;
  out.input = in.path;
  out.name = in.name;
  if (!job.refusal.empty()) {
    out.error = job.refusal;
    return out;
  }
  if (o.resume && StoredSettings(ReportPath(o, in)) == o.settings && job.read_complete(&out)) {
    out.status = BatchStatus::kSkipped;
    return out;
  }
  const auto start = std::chrono::steady_clock::now();
  const std::string report_path = ReportPath(o, in);
  std::error_code ignored;
  try {
    nlohmann::json report = job.run(&out);
    if (out.status != BatchStatus::kOk)
      for (const std::string& path : job.results) fs::remove(path, ignored);
    report["batch_settings"] = o.settings;
    WriteReportFile(report_path, report, in.path);
  } catch (const std::exception& e) {
    for (const std::string& path : job.results) fs::remove(path, ignored);
    fs::remove(report_path, ignored);
    out.status = BatchStatus::kError;
    out.error = e.what();
    out.out_of_memory = dynamic_cast<const std::bad_alloc*>(&e) != nullptr;
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

namespace {

// Under an address-space limit (ulimit -v, RLIMIT_AS), each thread's stack reserves
// RLIMIT_STACK of it (glibc's default for new threads; 8 MiB when unlimited): at most a quarter
// of the limit goes to stacks, the rest is left to the fits. `--jobs 300` under 1.2 GiB had 140
// threads start, their stacks taking 1.1 GiB, and the fits failed with std::bad_alloc.
size_t ThreadsThatFitTheAddressSpace() {
  rlimit space{}, stack{};
  if (getrlimit(RLIMIT_AS, &space) != 0 || space.rlim_cur == RLIM_INFINITY)
    return std::numeric_limits<size_t>::max();
  rlim_t stack_bytes = 8u << 20;
  if (getrlimit(RLIMIT_STACK, &stack) == 0 && stack.rlim_cur != RLIM_INFINITY &&
      stack.rlim_cur > 0)
    stack_bytes = stack.rlim_cur;
  return std::max<size_t>(1, static_cast<size_t>(space.rlim_cur / 4 / stack_bytes));
}

}  // namespace

std::vector<BatchOutcome> RunBatch(const std::vector<BatchInput>& inputs,
                                   const BatchOptions& options,
                                   const BatchProgressCallback& on_done) {
  // Temporaries of killed runs only: a concurrent batch's are locked (datasets/io/output_path.h).
  RemoveStaleTemporaries(options.out_dir);
  std::vector<BatchOutcome> outcomes(inputs.size());
  std::atomic<size_t> next{0};
  std::mutex report_mutex;
  std::vector<size_t> retry;  // out of memory beside other inputs
  retry.reserve(inputs.size());  // no allocation while memory is short
  const auto worker = [&]() {
    for (size_t i = next++; i < inputs.size(); i = next++) {
      try {
        outcomes[i] = ProcessBatchInput(inputs[i], options);
      } catch (const std::bad_alloc&) {  // outside the job itself (its outcome's strings)
        outcomes[i].out_of_memory = true;
      }
      std::lock_guard<std::mutex> lock(report_mutex);
      if (outcomes[i].out_of_memory) {
        retry.push_back(i);
        continue;
      }
      try {
        if (on_done) on_done(outcomes[i]);
      } catch (const std::bad_alloc&) {  // the progress line: the summary still has it
      }
    }
  };
  const size_t threads =
      std::max<size_t>(1, std::min({static_cast<size_t>(options.jobs), inputs.size(),
                                    ThreadsThatFitTheAddressSpace()}));
  // Threads that cannot start (system limits) leave their share to the others: the queue is
  // shared, so every input is still processed.
  RunWorkers(static_cast<int>(threads), [&](int) { worker(); });
  // Inputs that ran out of memory beside the others (many jobs under an address-space limit:
  // each thread's stack takes its share) run again one at a time, every worker finished.
  std::sort(retry.begin(), retry.end());
  for (size_t i : retry) {
    outcomes[i] = ProcessBatchInput(inputs[i], options);
    if (on_done) on_done(outcomes[i]);
  }
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
