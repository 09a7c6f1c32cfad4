// implicitfit detect CLOUD --out SCENE.json [--labels LABELS.txt] [--ply SEGMENTED.ply]
//                    [--report R.json] [--kinds plane,sphere,cylinder,cone,torus]
//                    [--threshold t] [--min-points m] [--seed s] [--threads n] [--freeform]
//                    [--score | --truth TRUTH.txt] [--truth-kinds LIST] [--truth-none V]
//                    [--quiet]
// Every primitive of a multi-primitive cloud, with its points (fit/detect/primitive_detector.h);
// --freeform: the smooth remainder as B-spline surfaces (docs/splines.md); --score / --truth: the
// result against ground-truth labels (implicitfit/detect.h). Progress on stderr unless --quiet.
// Exit 0 with at least one primitive, 1 when none is found (no scene written), 2 for invalid
// usage or input.
#include <cstdio>
#include <iostream>

#include "apps/command.h"
#include "apps/report_header.h"
#include "apps/view_outputs.h"
#include "datasets/io/atomic_file.h"
#include "datasets/io/io_error.h"
#include "implicitfit/detect.h"

namespace implicitfit {
namespace {

struct DetectArgs {
  std::string cloud, out, labels, ply, view, report, kinds = "plane,sphere,cylinder,cone,torus";
  double threshold = 0.0;
  int min_points = 0, threads = 0;
  unsigned seed = 1;
  bool score = false, quiet = false;
  TruthRequest truth;
  bool freeform = false;
};

}  // namespace

CommandAction AddDetectCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "detect", "Find every primitive of a multi-primitive cloud, with its points");
  auto a = std::make_shared<DetectArgs>();
  cmd->add_option("CLOUD", a->cloud,
                  "Point cloud (.xyz/.pwn/.txt/.xyzl, .ply, .pcd); normals estimated when absent")
      ->required();
  cmd->add_option("--out", a->out, "Output scene file (JSON, docs/scene-file.md)")->required();
  cmd->add_option("--labels", a->labels,
                  "Per-point labels: primitive index, -1 unassigned, one a line");
  cmd->add_option("--ply", a->ply,
                  "Segmented cloud: PLY with double coordinates, normals, a colour per primitive, "
                  "label (and scalar_label) and scalar_residual");
  cmd->add_option("--view", a->view, "A page of the segmentation (docs/view.md)");
  cmd->add_option("--report", a->report,
                  "JSON report (scales estimated from the cloud, counts, time, score)");
  cmd->add_option("--kinds", a->kinds, "Kinds to detect, comma separated (default: all five)");
  cmd->add_option("--threshold", a->threshold,
                  "Distance band (default: from the cloud's noise and spacing)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--min-points", a->min_points, "Smallest primitive (default: max(10, N/500))")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--seed", a->seed, "Random seed (the result depends on it only, not on threads)");
  cmd->add_option("--threads", a->threads, "Threads (default: all cores; at most 256 are used)")
      ->check(CLI::NonNegativeNumber);
  auto* score = cmd->add_flag("--score", a->score,
                              "Score the detection against the cloud's own labels (.xyzl column, "
                              "PLY/PCD label, scalar_label or segment_index)");
  cmd->add_option("--truth", a->truth.file,
                  "Score against these labels (one a line, negative: no primitive; a comment "
                  "'# kinds: plane,...' gives their kinds)")
      ->excludes(score);
  cmd->add_option("--truth-kinds", a->truth.kinds,
                  "Kinds of the truth primitives, in increasing label order (plane,cylinder,...)");
  cmd->add_option("--truth-none", a->truth.none,
                  "A label value that means 'on no primitive' (besides negative values)");
  cmd->add_flag("--quiet", a->quiet, "No progress on stderr");
  cmd->add_flag("--freeform", a->freeform,
                "Smooth regions no primitive explains become B-spline surfaces (docs/detect.md)");
  return [a]() {
    DetectionOptions options;
    options.kinds = DetectionKindsFromList(a->kinds);
    options.threshold = a->threshold;
    options.min_points = a->min_points;
    options.seed = a->seed;
    options.num_threads = a->threads;
    if (!a->quiet)
      options.progress = [](const std::string& message) {
        std::cerr << "implicitfit detect: " << message << std::endl;
      };
    const bool scoring = a->score || !a->truth.file.empty();
    if (!scoring && (!a->truth.kinds.empty() || a->truth.none != -1))
      throw InputError("--truth-kinds and --truth-none apply with --score or --truth");
    if (!a->truth.file.empty()) ReadTruthFile(a->truth.file);  // a bad file fails before the work
    CloudDetection d = DetectCloudFile(a->cloud, options, a->freeform);
    // The truth is read (and refused) before anything is written.
    if (scoring && !d.degenerate) {
      const TruthLabels truth = LoadTruth(d, a->truth);
      const DetectionScore s = ScoreDetection(d, truth);
      d.report["score"] = s.ToJson();
      d.report["score"]["truth"] = truth.source;
      std::printf("score against %s: %s\n", truth.source.c_str(), s.Line().c_str());
    }
    if (!a->report.empty()) WriteReportFile(a->report, d.ToJson(CommandReportHeader()));
    if (!d.success) {
      std::cerr << "implicitfit detect: " << a->cloud << ": " << d.message << "\n";
      return 1;
    }
    WriteDetection(d, a->out, a->labels, a->ply);
    if (!a->view.empty()) WriteDetectionView(d, a->view);
    for (const ScenePrimitive& p : d.scene.primitives)
      std::printf("%s %s points %d rms %.6g normals %s\n", p.name.c_str(),
                  NodeTypeName(p.model.nodes()[0].type), p.points, p.rms_distance,
                  p.normal_side.c_str());
    std::printf("%s\n", d.BriefReport().c_str());
    return 0;
  };
}

}  // namespace implicitfit
