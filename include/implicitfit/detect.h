// Public API: the detect job on one cloud, shared by the `detect` command (and `batch --model
// scene`, `reconstruct`, the Python module) — read the cloud (DetectCloudFile, or take one
// already read: DetectCloud) with oriented normals (datasets/normals/oriented_cloud.h: estimated
// and oriented when the file has none) and the neighbourhoods the normals were checked or
// estimated with (datasets/normals/neighbourhoods.h: one k-nearest-neighbour search for both),
// detect every primitive (DetectionOptions, fit/detect/primitive_detector.h), and build the scene
// (datasets/io/scene_file.h) and the JSON report (CloudDetection with BriefReport and ToJson):
//   {"cloud", "points", "normals", "primitives", "unassigned", "spacing", "noise", "threshold",
//    "normal_angle_deg", "min_points", "seeds", "candidates_accepted", "merges", "seconds",
//    "kinds": {kind: count}}
// Scoring (`detect --score` / `--truth`; LoadTruth, ScoreDetection): the detection against
// ground-truth labels with the benchmark's definitions (fit/detect/segmentation_metrics.h):
// recall, precision, mean IoU, kind accuracy and coverage over the truth primitives holding >= 1%
// of the points.
// Only include/implicitfit/*.h is public API (see implicitfit/model.h).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "datasets/clouds/cloud_file_info.h"
#include "datasets/clouds/point_cloud.h"
#include "datasets/io/scene_file.h"
#include "datasets/io/truth_labels.h"
#include "fit/common/fit_summary.h"
#include "fit/detect/primitive_detector.h"
#include "fit/detect/segmentation_metrics.h"
#include "jobs/report_header.h"

namespace implicitfit {

// success: at least one primitive (termination CONVERGENCE), else FAILURE with message "no
// primitive found" (and why, for a degenerate cloud); points: the cloud's; seconds: the
// detection's (the report's "seconds"). Options: DetectionOptions (IsValid), and freeform.
struct CloudDetection : FitSummary {
  PointCloud cloud;  // as read, with the normals the detection used
  CloudFileInfo info;
  DetectionResult result;
  Scene scene;
  nlohmann::json report;     // the report above (without the header; ToJson adds it)
  bool degenerate = false;   // too few points for normals: nothing could be detected
  DetectionOptions options;  // as given
  bool freeform = false;
  // "points N  primitives P  unassigned U  threshold t  s s" (one line).
  std::string BriefReport() const;
  // The report with `header` (its settings, when empty: kinds, threshold, normal_angle_deg,
  // min_points, seed, threads, freeform).
  nlohmann::json ToJson(const ReportHeader& header = {}) const;
};

// Throws InputError (naming the file) when the cloud cannot be read. options.progress, when
// set, is also told about the reading and the neighbourhood search. freeform: the smooth
// regions left unassigned become bspline_surface primitives (fit/splines/freeform_detection.h,
// after the primitives in the scene; report "freeform": {...}).
CloudDetection DetectCloudFile(const std::string& path, const DetectionOptions& options,
                               bool freeform = false);
// The same on a cloud already read (oriented normals, or none: degenerate); `path` names it in
// the scene and report, `normals_action` says where its normals came from.
CloudDetection DetectCloud(PointCloud cloud, const std::string& path,
                           const std::string& normals_action, const DetectionOptions& options);

// "plane,cylinder" -> kinds; InputError naming the unknown kind.
std::vector<NodeType> DetectionKindsFromList(const std::string& list);

// Writes the scene, and the labels and segmented PLY when their paths are not empty (each
// atomically). The PLY: double x y z, the normals, a colour per primitive (red green blue;
// grey for unassigned points), the label as "label" (PCL's PointXYZL) and "scalar_label", and
// f of the point's primitive as "scalar_residual" (CloudCompare loads scalar_* properties).
void WriteDetection(const CloudDetection& detection, const std::string& scene_path,
                    const std::string& labels_path, const std::string& ply_path);

// Where the truth comes from: a truth file (datasets/io/truth_labels.h), else the cloud's own
// labels (.xyzl column, PLY/PCD "label" / "scalar_label" / "segment_index"); kinds: the
// file's kinds line or `kinds` ("plane,cylinder,...", one per truth primitive in increasing
// label order); `none`: one more label value meaning "on no primitive".
struct TruthRequest {
  std::string file;  // empty: the cloud's labels
  std::string kinds;
  long none = -1;
};
// InputError naming the file when the labels are missing or do not match the cloud.
TruthLabels LoadTruth(const CloudDetection& detection, const TruthRequest& request);

struct DetectionScore {
  SegmentationMetrics metrics;
  bool kinds_known = false;
  int truth_primitives = 0;  // all of them, counted or not
  nlohmann::json ToJson() const;
  // "recall 5/6 (83.3%)  precision 5/7 (71.4%)  mean IoU 0.912  kind accuracy 1.000 ..."
  std::string Line() const;
};
DetectionScore ScoreDetection(const CloudDetection& detection, const TruthLabels& truth);

}  // namespace implicitfit
