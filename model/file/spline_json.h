// JSON forms of the spline nodes (docs/model-file.md), read strictly and within SplineLimits
// (model/splines/spline_structure.h); errors are ModelFormatError naming the JSON path.
//   {"type": "bspline_surface", "degree": [p, q], "knots_u": [...], "knots_v": [...],
//    "control_points": [[[x, y, z], ...], ...], "weights": [[...], ...]}
//     n_u rows of n_v points: control_points[i][j] = P_ij, i along u; knots optional (clamped
//     uniform on [0, 1] when absent, always written); weights optional (NURBS), > 0.
//   {"type": "bspline_volume", "degree": k, "box": [x0, y0, z0, x1, y1, z1],
//    "cells": [n_x, n_y, n_z], "coefficients": [(n_x + k)(n_y + k)(n_z + k) numbers, x fastest]}
//   skeleton_offset's "skeleton": {"curve": CURVE} with CURVE one of
//     {"bspline": {"degree": p, "knots": [...], "control_points": [[3], ...], "weights": [...]}}
//     {"bezier": {"control_points": [[3], ...], "weights": [...]}}   (degree n - 1; written as bspline)
//     {"ellipse": {"center": [3], "axes": [[3], [3]]}}               (conjugate semi-diameters)
//     {"helix": {"center": [3], "axes": [[3], [3]], "rise": [3], "turns": T}}
//     {"segment": [[3], [3]]}                                         (the one-segment skeleton)
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "model/model.h"

namespace implicitfit {

int ReadBSplineSurfaceNode(const nlohmann::json& node, const std::string& path,
                           const std::string& name, Model* model);
void WriteBSplineSurfaceNode(const Model& model, const ModelNode& node, nlohmann::json* out);

int ReadBSplineVolumeNode(const nlohmann::json& node, const std::string& path,
                          const std::string& name, Model* model);
void WriteBSplineVolumeNode(const Model& model, const ModelNode& node, nlohmann::json* out);

// The skeleton_offset whose "skeleton" is {"curve": curve} (where: the path of `curve`), with
// the tube's radius (> 0, checked by the caller) and Coleman features (empty: none).
int ReadCurveSkeletonOffset(const nlohmann::json& curve, const std::string& where, double radius,
                            const std::vector<double>& features, const std::string& name,
                            Model* model);
// {"curve": {...}} of a curve skeleton node.
nlohmann::json WriteCurveSkeleton(const Model& model, const ModelNode& node);

// coleman_features' "curve_features": [{"curve": [[3], ...] (1..4096 points), "width": W,
// "depth": D, "radius": R, "flare": phi}, ...] (model/primitives/coleman_curve_features.h; W, R > 0,
// D >= 0, phi in [0, 1]): each as [3 n vertices, W, D, R, phi].
std::vector<std::vector<double>> ReadCurveFeatures(const nlohmann::json& list,
                                                   const std::string& where);
nlohmann::json WriteCurveFeatures(const Model& model, const ModelNode& node);

}  // namespace implicitfit
