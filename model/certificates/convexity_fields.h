// The additive fields of `implicitfit check --json` and Python check()
// (docs/maths.md LP-4 c, G-2, G-3, G-4), kept apart from check_command.cc:
//   per file:  "tree": {"class", "certified", "domain"} and "nodes": [{"node", "type", "class",
//              "rule", "domain"}] (model/certificates/tree_certificate.h);
//   per patch: "min_eigenvalue_cartesian", "hessian_lower_bound" (G-2), "finsler": {"convex",
//              "c", "margin", "degree"} (G-4 a), "locally_convex" (G-4 b), "edges":
//              [{"vertices": [i, j], "sign_changes": V}], "faces_without_crossing" (G-3).
#pragma once

#include <nlohmann/json.hpp>

#include "model/model.h"

namespace implicitfit {

// The per-node tree certificate of a model; *certified is true when the root's solid is
// certified convex (class convex-function or convex-solid).
nlohmann::ordered_json TreeNodesJson(const Model& model, nlohmann::ordered_json* tree_verdict,
                                     bool* certified);

// The extra fields of one bernstein_patch node, appended to `patch`.
void AppendPatchCertificates(const Model& model, int node, nlohmann::ordered_json* patch);

}  // namespace implicitfit
