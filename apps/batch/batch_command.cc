// implicitfit batch INPUTS... [--manifest FILE]... --model KIND --out-dir DIR [--jobs N]
//                  [--resume] [--quiet] [--shard i/N] [--seed s] [--threshold t] [--fix FIELD=V ...]
//                  [--estimator robust|least-squares|minimum-zone]
// Fits one primitive per cloud (apps/batch/batch_runner.h), inputs listed as in apps/batch/batch_inputs.h.
// Writes DIR/<name>.model.json and DIR/<name>.report.json per input, then DIR/summary.csv
// (DIR/summary-<i>-of-<N>.csv with --shard, so shards can share DIR), and prints a human summary
// naming the failures. Exit 0 all inputs ok, 1 some failed, 2 invalid usage (nothing fitted).
// Built with MPI, `mpirun -np P implicitfit batch ...` distributes the inputs (apps/batch/batch_mpi.h).
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <thread>

#include "apps/batch/batch_inputs.h"
#include "apps/batch/batch_job.h"
#ifdef IMPLICITFIT_WITH_MPI
#include "apps/batch/batch_mpi.h"
#endif
#include "apps/batch/batch_progress.h"
#include "apps/batch/batch_runner.h"
#include "apps/batch/batch_view.h"
#include "apps/command.h"
#include "apps/output_guard.h"
#include "apps/fit/fit_job.h"
#include "datasets/io/atomic_file.h"
#include "datasets/io/io_error.h"
#include "datasets/io/output_path.h"
#include "fit/common/thread_count.h"

namespace implicitfit {
namespace {

struct BatchArgs {
  std::vector<std::string> inputs, manifests, fixes;
  std::string kind, out_dir, shard;
  int jobs = 0;
  bool resume = false, view = false, quiet = false;
  unsigned seed = 1;
  double threshold = 0.0;
  std::string estimator = "robust";
  bool convex = false;  // Bernstein kinds (apps/fit/fit_model_kinds.h)
  int degree = 0, cells = 0, continuity = 1, levels = 0;
  double cell = 0.0;
};

// Writes the summary, prints the human summary; the exit code.
int Finish(const std::vector<BatchOutcome>& outcomes, const std::string& summary_path,
           double seconds) {
  WriteFileAtomically(summary_path, SummaryCsv(outcomes));
  size_t ok = 0, skipped = 0, failed = 0, points = 0;
  for (const BatchOutcome& o : outcomes) {
    ok += o.status == BatchStatus::kOk;
    skipped += o.status == BatchStatus::kSkipped;
    failed += !o.Succeeded();
    if (o.status != BatchStatus::kSkipped) points += o.points;
  }
  const size_t processed = outcomes.size() - skipped;
  std::printf(
      "batch: %zu inputs: %zu fitted, %zu skipped, %zu failed in %.2f s (%.2f inputs/s, %.0f "
      "points/s)\n",
      outcomes.size(), ok, skipped, failed, seconds, seconds > 0 ? processed / seconds : 0.0,
      seconds > 0 ? points / seconds : 0.0);
  for (const BatchOutcome& o : outcomes)
    if (!o.Succeeded()) std::printf("  %s %s\n", BatchStatusName(o.status), o.Failure().c_str());
  std::printf("summary: %s\n", summary_path.c_str());
  return failed > 0 ? 1 : 0;
}

// The options the results depend on, per kind (BatchOptions::settings).
nlohmann::json BatchSettings(const BatchArgs& a, bool scene, bool solid, bool model_kind) {
  nlohmann::json s = {{"model", a.kind}};
  if (model_kind) {
    s["degree"] = a.degree;
    s["convex"] = a.convex;
    s["cells"] = a.cells;
    s["cell"] = a.cell;
    s["continuity"] = a.continuity;
    s["levels"] = a.levels;
    return s;
  }
  s["seed"] = a.seed;
  if (solid) return s;
  s["threshold"] = a.threshold;
  if (scene) return s;
  std::vector<std::string> fixes = a.fixes;
  std::sort(fixes.begin(), fixes.end());
  s["fix"] = fixes;
  s["estimator"] = a.estimator;
  return s;
}

// The Bernstein kinds (quadric-patch, cubic-patch, patch-mesh): each input fitted as `fit
// --model KIND` with the same options would (apps/fit/fit_model_kinds.h).
void SetBernsteinFit(const BatchArgs& a, BatchOptions* options) {
  if (!a.fixes.empty()) throw InputError("--fix applies to primitive kinds");
  ModelFitRequest request;
  request.kind = a.kind;
  request.degree = a.degree;
  request.convex = a.convex;
  request.cells = a.cells;
  request.cell = a.cell;
  request.continuity = a.continuity;
  request.levels = a.levels;
  const bool mesh = IsMeshKind(a.kind);
  options->model_kind = mesh ? NodeType::kBernsteinMesh : NodeType::kBernsteinPatch;
  options->require_certified = a.convex;
  options->model_fit = [request, mesh](const std::string& cloud) {
    ModelFitRequest r = request;
    r.cloud = cloud;
    return mesh ? FitMeshCloud(r) : FitPatchCloud(r);
  };
}

// Before any fit: no output may be an input (a cloud named like another's labels, a manifest
// in the out-dir), the folder must take files, results of other settings must not be resumed.
void CheckOutputsBeforeAnyFit(const BatchArgs& a, const std::vector<BatchInput>& all,
                              const std::vector<BatchInput>& inputs, const BatchOptions& options,
                              const std::string& summary_path, const std::string& index_name) {
  std::vector<std::string> input_paths = a.manifests;
  for (const BatchInput& in : all) input_paths.push_back(in.path);
  std::vector<std::string> outputs = BatchOutputPaths(inputs, options, summary_path);
  if (a.view) {
    for (const BatchInput& in : inputs)
      outputs.push_back(BatchOutputPath(options, in, ".view.html"));
    outputs.push_back((std::filesystem::path(a.out_dir) / index_name).string());
  }
  RefuseOverlaps(input_paths, outputs);
  ProbeOutputFolder(ResolveOutputPath(summary_path));
  if (options.resume) RefuseChangedSettings(inputs, options);
}

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

CommandAction AddBatchCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "batch", "Fit one model per cloud over many clouds, in parallel, resumably");
  auto a = std::make_shared<BatchArgs>();
  cmd->add_option("INPUTS", a->inputs,
                  "Cloud files and directories (every supported cloud directly inside)");
  cmd->add_option("--manifest", a->manifests,
                  "A text file listing one cloud path per line (relative to it); repeatable")
      ->allow_extra_args(false);  // one file per --manifest: later words stay INPUTS
  cmd->add_option(
         "--model", a->kind,
         "Kind to fit: plane, sphere, cylinder, cone, torus, quadric-patch, cubic-patch, "
         "patch-mesh; or scene (detect every primitive of each cloud); or solid (reconstruct "
         "each cloud's solid)")
      ->required();
  cmd->add_flag("--convex", a->convex, "Bernstein kinds: constrain and certify convexity")
      ->group("Bernstein patches");
  cmd->add_option("--degree", a->degree, "Bernstein kinds: patch degree (as `fit --degree`)")
      ->check(CLI::Range(2, 5))
      ->group("Bernstein patches");
  auto* cells_opt =
      cmd->add_option("--cells", a->cells, "patch-mesh: cubes along the longest box edge")
          ->check(CLI::Range(1, 200))
          ->group("Bernstein patches");
  cmd->add_option("--cell", a->cell, "patch-mesh: cube edge length")
      ->check(CLI::PositiveNumber)
      ->excludes(cells_opt)
      ->group("Bernstein patches");
  cmd->add_option("--continuity", a->continuity, "patch-mesh: 0 or 1 (default)")
      ->check(CLI::Range(0, 1))
      ->group("Bernstein patches");
  cmd->add_option("--levels", a->levels, "patch-mesh: refinement levels (as `fit --levels`)")
      ->check(CLI::Range(0, 6))
      ->group("Bernstein patches");
  cmd->add_option("--out-dir", a->out_dir,
                  "Folder of the models, reports and summary.csv (created)")
      ->required();
  cmd->add_option("--jobs", a->jobs,
                  "Inputs fitted at once (default: the number of cores; at most 256 and the "
                  "number of inputs; under MPI one per rank)")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--view", a->view,
                "Also write DIR/<name>.view.html per result and DIR/index.html linking them");
  cmd->add_flag("--quiet", a->quiet,
                "No progress on stderr: only the inputs that failed (and the summary)");
  cmd->add_flag("--resume", a->resume,
                "Skip inputs whose model and successful report are already complete");
  cmd->add_option("--shard", a->shard,
                  "i/N: only the inputs whose 0-based index k has k mod N = i - 1 (1 <= i <= N)");
  cmd->add_option("--seed", a->seed, "Random seed, the same for every input (as `fit --seed`)");
  cmd->add_option("--threshold", a->threshold,
                  "Initial inlier band (default: 1% of each cloud's bounding-box diagonal)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--fix", a->fixes,
                  "Keep a parameter constant in every fit, e.g. --fix radius=2; repeatable")
      ->allow_extra_args(false);
  cmd->add_option("--estimator", a->estimator,
                  "robust (default), least-squares or minimum-zone, as `fit --estimator`");
  return [a]() {
    if (a->inputs.empty() && a->manifests.empty()) throw InputError("no INPUTS and no --manifest");
    const bool solid = a->kind == "solid";  // one reconstruction per input (apps/batch/batch_solid.cc)
    const bool scene = a->kind == "scene" || solid;  // one detection per input (batch_scene.cc)
    if (scene && !a->fixes.empty()) throw InputError("--fix does not apply to --model " + a->kind);
    if (solid && a->threshold > 0)  // reconstruct runs detect with its defaults
      throw InputError("--threshold does not apply to --model solid");
    const bool model_kind = IsPatchKind(a->kind) || IsMeshKind(a->kind);
    if (!model_kind && a->convex)
      throw InputError("--convex applies to quadric-patch, cubic-patch and patch-mesh");
    PrimitiveFitOptions fit = model_kind
                                  ? PrimitiveFitOptions{}
                                  : FitOptionsFromArguments(scene ? "plane" : a->kind, a->seed,
                                                            scene ? 0.0 : a->threshold, a->fixes);
    SetEstimatorFromArgument(a->estimator, &fit);

    const std::vector<BatchInput> all = ExpandBatchInputs(a->inputs, a->manifests);
    if (all.empty()) throw InputError("no cloud files in the given inputs");
    std::vector<BatchInput> inputs = all;
    std::string summary_name = "summary.csv";
    std::string index_name = "index.html";
    if (!a->shard.empty()) {
      const Shard shard = ParseShard(a->shard);
      inputs = SelectShard(all, shard);
      summary_name =
          "summary-" + std::to_string(shard.index) + "-of-" + std::to_string(shard.count) + ".csv";
      index_name =
          "index-" + std::to_string(shard.index) + "-of-" + std::to_string(shard.count) + ".html";
    }
    std::error_code ec;
    std::filesystem::create_directories(a->out_dir, ec);
    if (!std::filesystem::is_directory(a->out_dir))
      throw FileError(a->out_dir, "cannot create the output folder" +
                                      (ec ? ": " + ec.message() : std::string()));

    BatchOptions options;
    options.out_dir = a->out_dir;
    options.resume = a->resume;
    options.scene = scene && !solid;
    options.solid = solid;
    options.detect.seed = a->seed;
    options.detect.threshold = scene ? a->threshold : 0.0;
    // Clamped: threads beyond 256 (or the inputs) do not fit faster; those the system refuses
    // to start leave their share to the others (apps/batch/batch_runner.cc).
    options.jobs = std::min({ThreadCountOrDefault(a->jobs), 256,
                             static_cast<int>(std::max<size_t>(1, inputs.size()))});
    options.fit = fit;
    options.fit.num_threads =
        options.jobs > 1 ? 1 : 0;  // parallel over inputs, or inside the one fit
    options.detect.num_threads = options.fit.num_threads;
    if (model_kind) SetBernsteinFit(*a, &options);

    const std::string summary_path = (std::filesystem::path(a->out_dir) / summary_name).string();
    options.settings = BatchSettings(*a, scene, solid, model_kind);
    CheckOutputsBeforeAnyFit(*a, all, inputs, options, summary_path, index_name);
    const auto start = std::chrono::steady_clock::now();
    BatchProgress progress(inputs.size(), ::isatty(STDERR_FILENO) == 1, a->quiet);
    const auto on_done = [&](const BatchOutcome& o) { progress.Done(o); };
#ifdef IMPLICITFIT_WITH_MPI
    if (LaunchedUnderMpi()) {
      MpiSession mpi;
      options.fit.num_threads = 1;  // the ranks are the parallelism
      options.detect.num_threads = 1;
      const std::vector<BatchOutcome> outcomes = RunBatchOverMpi(inputs, options, on_done);
      if (mpi.rank() != 0) return 0;  // rank 0 reports (mpirun exits with its code)
      progress.Finish();
      const int code = Finish(outcomes, summary_path, SecondsSince(start));
      if (a->view) WriteBatchViews(inputs, outcomes, options, index_name, a->quiet);
      return code;
    }
#endif
    const std::vector<BatchOutcome> outcomes = RunBatch(inputs, options, on_done);
    progress.Finish();
    const int code = Finish(outcomes, summary_path, SecondsSince(start));
    if (a->view) WriteBatchViews(inputs, outcomes, options, index_name, a->quiet);
    return code;
  };
}

}  // namespace implicitfit
