// JSON form of a bernstein_mesh node (docs/model-file.md, additive):
//   {"type": "bernstein_mesh", "degree": k, "grid": {"origin": [3], "cell": h, "cells": [3]},
//    "continuity": 0|1, "control_points": [6 nx ny nz (k+1)(k+2)(k+3)/6 numbers]}
// Additive, optional: grid "splits" (adaptive refinement, model/bernstein/grid_refinement.h: then
// 6 x leaves x N(k) control points, leaf after leaf) and "c0_faces": [[tetrahedron, face], ...]
// (faces declared C0 only, face = the opposite vertex 0..3; model/bernstein/bernstein_mesh.h).
// Tetrahedra are implied by the Kuhn rule (model/bernstein/bernstein_mesh.h), control points per
// tetrahedron in docs/design.md order. Errors are ModelFormatError naming the JSON path.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "model/model.h"

namespace implicitfit {

// Reads the mesh-specific fields of `node` (type already checked) and adds the node.
int ReadBernsteinMeshNode(const nlohmann::json& node, const std::string& path,
                          const std::string& name, Model* model);
// Writes the mesh-specific fields of node into *out.
void WriteBernsteinMeshNode(const Model& model, const ModelNode& node, nlohmann::json* out);

}  // namespace implicitfit
