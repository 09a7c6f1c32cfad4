// The convexity certificates of every Bernstein patch of a model (model/certificates/convexity_certificate.h)
// and their JSON form, as `implicitfit check --json` prints it per file and the Python module's
// check() returns it:
//   {"convex": bool, "patches": [{"degree": k, "convex": bool, "min_eigenvalue": x, ...}],
//    "tree": {...}, "nodes": [...], "verdict": {...}}
// (the additive per-patch, "tree" and "nodes" fields: model/certificates/convexity_fields.h).
// "convex" is the verdict of model/certificates/convexity_verdict.h: the tree's certificate AND
// every patch's and mesh's, with what it rests on in "verdict".
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "model/certificates/convexity_certificate.h"
#include "model/model.h"

namespace implicitfit {

struct PatchConvexity {
  int node = 0;       // index into Model::nodes
  std::string label;  // Model::NodeLabel
  int degree = 0;
  ConvexityCertificate certificate;
};

// One entry per Bernstein patch node, in node order.
std::vector<PatchConvexity> CertifyModelPatches(const Model& model);

// {"degree", "convex", "min_eigenvalue"} of one patch.
nlohmann::ordered_json PatchConvexityJson(int degree, const ConvexityCertificate& certificate);
// {"convex", "patches", "tree", "nodes", "verdict"} of a whole model (no sampling fields).
nlohmann::ordered_json ModelConvexityJson(const Model& model);

}  // namespace implicitfit
