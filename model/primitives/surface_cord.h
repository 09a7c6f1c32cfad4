// Coleman's surface cords (docs/maths.md CO-2, App. B of the paper): a polyline on the zero set
// of a model that follows a guide polyline g_0..g_n drawn near the surface, from the surface
// point nearest g_0 to the one nearest g_n, for curve features
// (model/primitives/coleman_curve_features.h).
//   p_0 = the projection of g_0 onto f = 0 (Newton along the gradient: x <- x - f grad f / |grad f|^2);
//   while the current target is g_k (k = 1 first): d = the direction from p_i to g_k within the
//   tangent plane at p_i (the component of g_k - p_i orthogonal to grad f), p_{i+1} = the
//   projection of p_i + h d / |d| onto f = 0 (an inelastic, non-stiff cord: each step of length
//   about h bends to the surface);
//   a target is passed when (g_k - p_{i+1}) . (p_{i+1} - p_i) < 0 (the step went beyond the foot of
//   g_k on it): for an inner target the cord goes on toward g_{k+1}; at the last one growth stops
//   and the cord ends at the foot of g_n on that step taken on the surface: the point
//   x(s) = proj(p_i + s d/|d|), 0 <= s <= h, where g_n - x(s) is normal to the cord's direction
//   in the tangent plane (bisection on s). The paper's chord foot p_i + ((g_n - p_i) . e) e,
//   e = (p_{i+1} - p_i)/|p_{i+1} - p_i|, lies behind p_i when g_n is well off the surface (the
//   chord turns toward the surface), so the cord would fold back; the surface foot does not, and
//   on a sphere it is the projection of g_n itself.
// The paper's termination test reads (g_n - p_i) . (p_{i+1} - p_i) < 0; with the foot formula that
// follows it, the test on p_{i+1} is the one under which the partial segment lies on the step.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "model/model.h"

namespace implicitfit {

struct SurfaceCordOptions {
  double step = 0.0;     // h; <= 0: 1/100 of the guide's length
  int max_steps = 100000;
};

struct SurfaceCord {
  std::vector<Eigen::Vector3d> points;  // on f = 0 (|f| < 1e-10 (1 + |x|) unless projection failed)
  bool reached = false;                 // the last target was passed (not max_steps)
};

// Throws std::invalid_argument for fewer than 2 guide points or non-finite input.
SurfaceCord GrowSurfaceCord(const Model& model, const std::vector<Eigen::Vector3d>& guide,
                            const SurfaceCordOptions& options = {});

}  // namespace implicitfit
