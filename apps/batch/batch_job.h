// What every `batch` job kind (primitive fit, Bernstein kinds, scene, solid) shares, so each kind
// states only its own part: the outcome named after the input, a refusal before anything runs,
// the resume check, the wall time, the report <name>.report.json written atomically, and the
// cleanup: on a negative result the job's results are removed (a stale model of an earlier run
// must not survive beside a failed report), on an exception its results and the report too.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "apps/batch/batch_runner.h"

namespace implicitfit {

struct BatchJob {
  std::string refusal;               // non-empty: an error row with this message, nothing run
  std::vector<std::string> results;  // the files run() writes on success (besides the report)
  // With --resume: true when the outputs of an earlier run are complete (figures then set).
  std::function<bool(BatchOutcome*)> read_complete;
  // Runs the job, writes its results when it succeeds and sets the figures, status (kOk or
  // kFailed) and error; returns the report's content.
  std::function<nlohmann::json(BatchOutcome*)> run;
};

// <out_dir>/<name><suffix>.
std::string BatchOutputPath(const BatchOptions& options, const BatchInput& input,
                            const char* suffix);

// An earlier report (datasets/io/text_file.h: a regular file, size-capped; never a FIFO that
// would hang the batch); throws on anything unreadable or not JSON.
nlohmann::json ReadBatchReport(const std::string& path);

BatchOutcome RunBatchJob(const BatchInput& input, const BatchOptions& options, const BatchJob& job);

}  // namespace implicitfit
