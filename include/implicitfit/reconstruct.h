// Public API: the reconstruct job on one cloud, shared by `reconstruct` and `batch --model solid`
// (and the Python module) — read the cloud (ReconstructCloudFile, or take one already read:
// ReconstructCloud) with oriented normals (datasets/normals/oriented_cloud.h: estimated and
// oriented when it has none), take the primitives of a scene file or, without one, of `detect`
// run on the cloud with its defaults and the given seed (implicitfit/detect.h), reconstruct the
// solid (fit/reconstruct/solid_reconstruction.h), verify it, and build the JSON report the
// command line's `reconstruct` writes (ReconstructJobOptions; CloudReconstruction with
// BriefReport and ToJson):
//   {"success", "message", "points", "normals", "expression", "bounded", "rms_distance", "sigma",
//    "inliers", "normal_sign_agreement", "unassigned", "seconds", "primitives": [{"name",
//    "side", "points"}], "blends": [{"node", "type", "delta", "epsilon", "standard_deviations",
//    "crease_angle_deg", "fillet_radius", "fillet_radius_standard_deviation",
//    "transition_points"}], "closures": [{"name", "normal", "offset", "measured": false}],
//    "separators": [same]} (fit/reconstruct/solid_bounding.h: planes no data lie on),
//    "verification": SolidVerification::ToJson() (fit/reconstruct/solid_verification.h; absent
//    when the reconstruction stopped before a solid was built). "success" and "bounded" are true
//    only when the verification passed / proved it.
// Progress (stages "detect", "orientation", ..., "verification") goes to options.progress.
// Only include/implicitfit/*.h is public API (see implicitfit/model.h).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "datasets/clouds/point_cloud.h"
#include "fit/common/fit_summary.h"
#include "fit/common/progress.h"
#include "fit/reconstruct/solid_reconstruction.h"
#include "jobs/report_header.h"

namespace implicitfit {

struct ReconstructJobOptions {
  std::string scene;  // ReconstructCloudFile: the scene file of the primitives; empty: detect
  unsigned seed = 1;  // detect's and the reconstruction's
  ProgressCallback progress;
  // True: every seed is valid, and the scene file is checked when read (InputError).
  bool IsValid(std::string* error) const;
  // The "settings" of the report: seed (files left out, as in every report).
  nlohmann::json Settings() const;
};

// success: the solid was built and verified (termination CONVERGENCE), else FAILURE with the
// reason in message; points: the cloud's; seconds: the reconstruction's (the report's).
struct CloudReconstruction : FitSummary {
  PointCloud cloud;       // as read (with the normals the reconstruction used)
  std::string name;       // the cloud's path or name (the report's input)
  std::string normals;    // how the normals were obtained
  bool detected = false;  // primitives from detect (no scene given)
  std::vector<SolidPrimitive> primitives;
  std::vector<int> labels;  // per point, detect's (empty with a scene file)
  SolidReconstruction result;
  nlohmann::json report;          // the report above (without the header; ToJson adds it)
  ReconstructJobOptions options;  // as given
  // "14 primitives, 1 solid piece(s), 0 cavities, rms 0.0123" (one line).
  std::string BriefReport() const;
  // The report with `header` (its settings: ReconstructJobOptions::Settings() when empty).
  nlohmann::json ToJson(const ReportHeader& header = {}) const;
};

// Throws InputError naming the file when the cloud or the scene cannot be read or do not match.
// A cloud without normals, or on which detect finds nothing, gives result.success false and
// its reason in result.message (and the report).
CloudReconstruction ReconstructCloudFile(const std::string& cloud_path,
                                         const ReconstructJobOptions& options = {});
// The same without a scene (options.scene is not read) on a cloud already read (`name` for the
// report; normals oriented, e.g. by datasets/normals/normal_estimation.h, and `normals` saying
// how): detect, then the solid. The end-to-end path of a raw scan.
CloudReconstruction ReconstructCloud(PointCloud cloud, const std::string& name,
                                     const std::string& normals,
                                     const ReconstructJobOptions& options = {});

}  // namespace implicitfit
