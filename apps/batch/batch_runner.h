// Runs `implicitfit batch`: one primitive fit per input cloud (apps/fit/fit_job.h), each input on its
// own, over a bounded pool of threads that take the next input as they finish (dynamic load
// balancing; a cloud is read only when its job starts, so memory is bounded by the pool).
// For an input named <name> (apps/batch/batch_inputs.h) in out_dir:
//   ok       <name>.model.json and <name>.report.json (the `fit --report` content) are written,
//            each atomically (temporary name, then rename: a kill -9 leaves no partial file);
//   failed   the fit gave a negative result (e.g. too few inliers): the report (success false)
//            is written, no model (a stale model of an earlier run is removed);
//   error    the cloud could not be read, an output not written, or the options do not suit the
//            input's kind (a manifest's KIND with a --fix field it lacks): no model, no report;
//   skipped  (resume) the model and report of an earlier run are complete: the model parses
//            and is of the requested kind, the report parses and says success. Nothing is
//            refitted; failed and error inputs are retried.
// Temporaries left by a killed run are removed before the run; those of a concurrent run (in
// the same folder) are locked and kept (datasets/io/output_path.h).
// The summary (SummaryCsv) has one row per input, in input order:
//   input,status,rms,inliers,points,seconds,error
// rms/inliers/points from the fit (for skipped inputs from the earlier report; empty for error),
// seconds the wall time spent on the input in this run (0 when skipped), error the message.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "apps/batch/batch_inputs.h"
#include "apps/fit/fit_model_kinds.h"
#include "fit/detect/primitive_detector.h"
#include "fit/primitive/primitive_fitter.h"

namespace implicitfit {

enum class BatchStatus { kOk, kFailed, kError, kSkipped };
const char* BatchStatusName(BatchStatus status);

struct BatchOutcome {
  std::string input, name;  // the cloud path and its output name
  BatchStatus status = BatchStatus::kError;
  double rms = 0.0;
  size_t inliers = 0, points = 0;
  double seconds = 0.0;  // wall time in this run
  std::string error;     // why it failed (empty when ok or skipped)
  // It ran out of memory (std::bad_alloc) while other inputs ran beside it: RunBatch runs it
  // again alone once every worker has finished (--jobs above what memory allows).
  bool out_of_memory = false;
  bool HasFigures() const { return status != BatchStatus::kError; }
  bool Succeeded() const { return status == BatchStatus::kOk || status == BatchStatus::kSkipped; }
  // "<input>: <error>" (the input named once, also when the error already starts with it).
  std::string Failure() const {
    return error.rfind(input + ":", 0) == 0 ? error : input + ": " + error;
  }
};

struct BatchOptions {
  PrimitiveFitOptions fit;  // used for every input, with the input's own kind when it
                            // has one (same seed: results do not depend on the order
                            // or the number of jobs)
  std::string out_dir;      // must exist
  int jobs = 1;             // threads of the pool, >= 1
  bool resume = false;      // skip inputs whose outputs are complete
  bool scene = false;       // `--model scene`: one detection per input (implicitfit/detect.h)
  DetectionOptions detect;  // used for every input when scene is set
  bool solid = false;       // `--model solid`: one reconstruction per input (detect.seed used)
  // Bernstein kinds (quadric-patch, cubic-patch, patch-mesh; apps/fit/fit_model_kinds.h): when set,
  // every input is fitted by model_fit(cloud path) instead of `fit`; resume then also requires
  // the model's root to be model_kind and, with require_certified (--convex), the report to
  // say certified_convex.
  std::function<ModelKindFit(const std::string& cloud)> model_fit;
  NodeType model_kind = NodeType::kBernsteinPatch;
  bool require_certified = false;
  // The options the results depend on ({"model": ..., "seed": ..., ...}), stored in every report
  // as "batch_settings": --resume skips an input only when its report has the same settings
  // (RefuseChangedSettings refuses the run when an earlier report has other ones).
  nlohmann::json settings = nlohmann::json::object();
};

// Called (serialised, from any pool thread) when an input is done.
using BatchProgressCallback = std::function<void(const BatchOutcome&)>;

// Fits every input; never throws for a bad input (it becomes a failed or error row).
std::vector<BatchOutcome> RunBatch(const std::vector<BatchInput>& inputs,
                                   const BatchOptions& options,
                                   const BatchProgressCallback& on_done);

// One input: the resume check (when options.resume), the fit and its outputs.
BatchOutcome ProcessBatchInput(const BatchInput& input, const BatchOptions& options);

// `--model scene` (apps/batch/batch_scene.cc): <name>.scene.json, <name>.labels.txt and
// <name>.report.json (the `detect --report` content) per input. ok: at least one primitive;
// failed: none (report only; a stale scene and labels are removed); skipped (resume): the scene
// parses, the labels parse with one per point of it, and the report counts its primitives.
// inliers = points assigned to a primitive, rms = the largest primitive RMS.
BatchOutcome ProcessSceneInput(const BatchInput& input, const BatchOptions& options);

// `--model solid` (apps/batch/batch_solid.cc): `reconstruct` without a scene (detect, then the
// solid; implicitfit/reconstruct.h): <name>.model.json and <name>.report.json (the `reconstruct
// --report` content). ok: the reconstruction succeeded; failed: it did not (report only; a stale
// model is removed); skipped (resume): the model parses and the report parses and says success.
// rms, inliers and points from the report.
BatchOutcome ProcessSolidInput(const BatchInput& input, const BatchOptions& options);

// --resume: InputError naming the first report in out_dir whose "batch_settings" differ from
// options.settings, with the difference (a resumed run must not mix results of other
// settings); reports without settings (or unreadable) are refitted, not refused.
void RefuseChangedSettings(const std::vector<BatchInput>& inputs, const BatchOptions& options);

// Every file the batch may write for these inputs (models, reports, scenes, labels, summary).
std::vector<std::string> BatchOutputPaths(const std::vector<BatchInput>& inputs,
                                          const BatchOptions& options,
                                          const std::string& summary_path);

// The summary.csv text (RFC 4180 quoting), header included.
std::string SummaryCsv(const std::vector<BatchOutcome>& outcomes);

}  // namespace implicitfit
