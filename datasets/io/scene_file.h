// Scene files, version 1 (docs/scene-file.md, a public contract): what `detect` writes and `reconstruct`
// reads.
//   {"format": "implicitfit-scene", "version": 1, "cloud": path, "points": N,
//    "primitives": [{"name": "p0", "model": NODE, "points": n, "rms_distance": x,
//                    "standard_deviations": {...}, "normal_side": "outward"|"inward"|"unknown"}],
//    "unassigned": m}
// Each "model" is a model-file NODE (model/file/model_json.h), so it is read with the same strict
// rules; its errors name the scene's JSON path, e.g. "primitives[2].model.radius: must be > 0".
// Per-point labels (index into "primitives", -1 = unassigned) live in a separate text file,
// one integer a line, in the input order (ReadLabelsFile / WriteLabelsFile).
// Reading throws InputError "<file>: <problem>"; writing is atomic (never a partial file).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "model/model.h"

namespace implicitfit {

struct ScenePrimitive {
  std::string name;                                   // "p0", "p1", ...
  Model model;                                        // a one-node (or small-tree) model
  int points = 0;                                     // points assigned to it
  double rms_distance = 0.0;                          // RMS of their distances
  std::map<std::string, double> standard_deviations;  // parameter name -> sd (may be empty)
  std::string normal_side = "unknown";                // "outward", "inward" or "unknown"
};

struct Scene {
  std::string cloud;  // the cloud the scene was detected in
  int points = 0;     // points in that cloud
  std::vector<ScenePrimitive> primitives;
  int unassigned = 0;  // points of no primitive
};

Scene ReadSceneFile(const std::string& path);
void WriteSceneFile(const Scene& scene, const std::string& path);

// Labels: one integer per line, -1 .. primitives-1; `expected_count` < 0 skips the count check.
std::vector<int> ReadLabelsFile(const std::string& path, int num_primitives,
                                long expected_count = -1);
void WriteLabelsFile(const std::vector<int>& labels, const std::string& path);

}  // namespace implicitfit
