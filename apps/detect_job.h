// The detection of one cloud file, shared by the `detect` command (and `batch --model scene`):
// read the cloud with oriented normals (datasets/normals/oriented_cloud.h: estimated and oriented when
// the file has none), its k-nearest-neighbour graph and spacing (datasets/normals/neighbourhoods.h),
// detect every primitive (fit/detect/primitive_detector.h), and build the scene (datasets/io/scene_file.h)
// and the JSON report:
//   {"cloud", "points", "normals", "primitives", "unassigned", "spacing", "noise", "threshold",
//    "normal_angle_deg", "min_points", "seeds", "candidates_accepted", "merges", "seconds",
//    "kinds": {kind: count}}
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "datasets/clouds/point_cloud.h"
#include "datasets/io/scene_file.h"
#include "fit/detect/primitive_detector.h"

namespace implicitfit {

struct CloudDetection {
  PointCloud cloud;  // as read, with the normals the detection used
  DetectionResult result;
  Scene scene;
  nlohmann::json report;
  bool degenerate = false;  // too few points for normals: nothing could be detected
};

// Throws InputError (naming the file) when the cloud cannot be read. freeform: the smooth
// regions left unassigned become bspline_surface primitives (fit/splines/freeform_detection.h,
// after the primitives in the scene; report "freeform": {...}).
CloudDetection DetectCloudFile(const std::string& path, const DetectionOptions& options,
                               bool freeform = false);

// "plane,cylinder" -> kinds; InputError naming the unknown kind.
std::vector<NodeType> DetectionKindsFromList(const std::string& list);

// Writes the scene, and the labels and segmented PLY when their paths are not empty (each
// atomically).
void WriteDetection(const CloudDetection& detection, const std::string& scene_path,
                    const std::string& labels_path, const std::string& ply_path);

}  // namespace implicitfit
