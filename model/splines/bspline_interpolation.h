// Cubic B-spline interpolation through points (docs/maths.md TB-3, the textbook's T10): given
// Q_0..Q_m and parameters t_0 < ... < t_m (chord length by default), the cubic with clamped knots
// [t_0 x4, t_1, ..., t_(m-1), t_m x4] has m + 3 control points; C(t_j) = Q_j gives m + 1
// equations and the two end conditions the other two:
//   derivative: C'(t_0) = D_0, C'(t_m) = D_m (the textbook's form; "clamped" ends);
//   natural:    C''(t_0) = C''(t_m) = 0.
// The (m + 3) x (m + 3) system is banded (each row touches at most 4 neighbouring control
// points) and solved by sparse LU (Eigen). A cubic polynomial curve sampled at any parameters
// with its own end derivatives is reproduced exactly (it lies in the spline space).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "model/splines/spline_structure.h"

namespace implicitfit {

enum class EndCondition { kDerivative, kNatural };

struct InterpolationEnds {
  EndCondition kind = EndCondition::kNatural;
  Eigen::Vector3d start = Eigen::Vector3d::Zero(), end = Eigen::Vector3d::Zero();  // kDerivative
};

struct InterpolatedCurve {
  SplineStructure structure;            // degree 3, clamped knots at the parameters
  std::vector<double> control_points;   // 3 (m + 3) numbers
  std::vector<double> parameters;       // t_0..t_m
};

// Throws std::invalid_argument for fewer than 2 points, non-finite input, coincident
// consecutive points (chord length) or parameters that do not increase strictly, or more points
// than SplineLimits::kMaxControlPointsPerAxis - 2.
InterpolatedCurve InterpolateCubicBSpline(const std::vector<Eigen::Vector3d>& points,
                                          const InterpolationEnds& ends = {},
                                          std::vector<double> parameters = {});

}  // namespace implicitfit
