// implicitfit detect CLOUD --out SCENE.json [--labels LABELS.txt] [--ply SEGMENTED.ply]
//                    [--report R.json] [--kinds plane,sphere,cylinder,cone,torus]
//                    [--threshold t] [--min-points m] [--seed s] [--threads n]
// Every primitive of a multi-primitive cloud, with its points (fit/detect/primitive_detector.h).
// Exit 0 with at least one primitive, 1 when none is found (no scene written), 2 for invalid
// usage or input.
#include <cstdio>
#include <iostream>

#include "apps/command.h"
#include "apps/detect_job.h"
#include "apps/view_outputs.h"
#include "datasets/io/atomic_file.h"

namespace implicitfit {
namespace {

struct DetectArgs {
  std::string cloud, out, labels, ply, view, report, kinds = "plane,sphere,cylinder,cone,torus";
  double threshold = 0.0;
  int min_points = 0, threads = 0;
  unsigned seed = 1;
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
  cmd->add_option("--ply", a->ply, "Segmented cloud (PLY with normals, label and residual)");
  cmd->add_option("--view", a->view, "A page of the segmentation (docs/view.md)");
  cmd->add_option("--report", a->report,
                  "JSON report (scales estimated from the cloud, counts, time)");
  cmd->add_option("--kinds", a->kinds, "Kinds to detect, comma separated (default: all five)");
  cmd->add_option("--threshold", a->threshold,
                  "Distance band (default: from the cloud's noise and spacing)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--min-points", a->min_points, "Smallest primitive (default: max(10, N/500))")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--seed", a->seed, "Random seed (the result depends on it only, not on threads)");
  cmd->add_option("--threads", a->threads, "Threads (default: all cores)")
      ->check(CLI::NonNegativeNumber);
  return [a]() {
    DetectionOptions options;
    options.kinds = DetectionKindsFromList(a->kinds);
    options.threshold = a->threshold;
    options.min_points = a->min_points;
    options.seed = a->seed;
    options.num_threads = a->threads;
    const CloudDetection d = DetectCloudFile(a->cloud, options);
    if (!a->report.empty()) WriteFileAtomically(a->report, d.report.dump(2) + "\n");
    if (d.scene.primitives.empty()) {
      std::cerr << "implicitfit detect: " << a->cloud << ": no primitive found"
                << (d.degenerate ? " (too few points to estimate normals)" : "") << "\n";
      return 1;
    }
    WriteDetection(d, a->out, a->labels, a->ply);
    if (!a->view.empty()) WriteDetectionView(d, a->view);
    for (const ScenePrimitive& p : d.scene.primitives)
      std::printf("%s %s points %d rms %.6g normals %s\n", p.name.c_str(),
                  NodeTypeName(p.model.nodes()[0].type), p.points, p.rms_distance,
                  p.normal_side.c_str());
    std::printf("points %d  primitives %zu  unassigned %d  threshold %.6g  %.3f s\n",
                d.scene.points, d.scene.primitives.size(), d.scene.unassigned, d.result.threshold,
                d.result.seconds);
    return 0;
  };
}

}  // namespace implicitfit
