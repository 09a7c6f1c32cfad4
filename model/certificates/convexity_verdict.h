// The convexity verdict of a whole model file, as `implicitfit check` and the Python module's
// check() give it: the CONJUNCTION of
//   - the tree certificate of the root (model/certificates/tree_certificate.h),
//   - every bernstein_patch's A^mu certificate (model/certificates/convexity_certificate.h),
//   - every bernstein_mesh's "convex on the box" certificate (bernstein_mesh_certificate.h),
// so a certified patch in a union with a far sphere is not convex (the union is refused), and a
// certified mesh, a convex-function node on its box, composes like any convex leaf.
// The verdict says what it rests on:
//   rests_on: convex -> every node of the root's subtree with the certificate it contributes;
//             not convex -> the node that refused and why (descending from the root through
//             the intersections and morphs whose only fault is a child);
//   domain:   where the claim holds: "everywhere", or the intersection of the listed patches'
//             tetrahedra (their four vertices) and meshes' boxes (min, max corners);
//   reason:   one sentence when not convex.
// patches_only (the old verdict, `check --patches-only`): only the patches and meshes count, a
// file without them is convex vacuously.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "model/model.h"

namespace implicitfit {

struct ConvexityVerdict {
  bool convex = false;
  std::string reason;          // empty when convex
  std::vector<int> rests_on;   // node indices (see above)
  std::vector<std::string> certificates;  // one per rests_on entry: the rule it contributes
  std::vector<int> domain;     // patch / mesh nodes bounding the claim; empty: everywhere
};

ConvexityVerdict JudgeConvexity(const Model& model, bool patches_only = false);

// {"convex", "reason" (when not convex), "rests_on": [{"node", "type", "certificate"}],
//  "domain": "everywhere" | [{"node", "tetrahedron": [4 x 3]} | {"node", "box": {"min", "max"}}]}
nlohmann::ordered_json ConvexityVerdictJson(const Model& model, const ConvexityVerdict& verdict);

}  // namespace implicitfit
