// Closest points on spline surfaces and curves (the feet that the signed distance of a
// bspline_surface node and the distance to a curve skeleton are taken at), in double precision.
//
// Surface: minimise D(u, v) = |S(u, v) - x|^2 / 2 over the parameter rectangle by projected
// Newton: gradient g = (S_u . r, S_v . r), r = S - x; Hessian H = [S_a . S_b + S_ab . r]
// (Gauss-Newton [S_a . S_b] where H is not positive definite); a variable at its bound whose
// gradient points outward is held there (active set); every step is clamped to the rectangle
// and halved until D decreases. Robust start: the Greville abscissae of the three control
// points nearest to x (the control net lies close to the surface: convex-hull property), and the
// best of the three Newton runs is kept. The foot is where the gradient vanishes in the free
// variables (interior foot: r is normal to the surface) or on the rectangle's edge.
// Curve: the same in one variable t over [t_0, t_1] (an ellipse is periodic: t wraps). Starts:
// B-spline, the Greville abscissae of the three nearest control points and both ends; ellipse and
// helix, the three best of 16 samples per turn (at most 4096 samples).
#pragma once

#include "model/splines/spline_structure.h"

namespace implicitfit {

struct SurfaceFoot {
  double u = 0.0, v = 0.0;
  bool u_at_bound = false, v_at_bound = false;  // the foot lies on an edge of the rectangle
  double distance2 = 0.0;                       // |S(u, v) - x|^2
};
// start: an optional extra start (u, v) (a previous foot: the fits' parameter correction).
SurfaceFoot ClosestSurfacePoint(const SplineStructure& s, const double* points, const double* x,
                                const double* start = nullptr);

// The local search alone: projected Newton from (u, v) (the fits' parameter correction, where
// the previous foot is a good start).
SurfaceFoot SurfaceFootFrom(const SplineStructure& s, const double* points, const double* x,
                            double u, double v);

struct CurveFoot {
  double t = 0.0;
  bool at_end = false;  // the foot is an end of an open curve
  double distance2 = 0.0;
};
CurveFoot ClosestCurvePoint(const SplineStructure& s, const double* points, const double* x);

}  // namespace implicitfit
