// The bspline_surface node (docs/maths.md TB-3): f(x) is the signed distance from x to the patch
// S([u_p, u_n] x [v_q, v_m]), positive on the side of S_u x S_v:
//   f(x) = sign((x - S*) . N*) |x - S*|,   S* = S(u*, v*) the closest point
// (model/splines/closest_point.h), N* = S_u x S_v there. At a foot inside the rectangle x - S* is
// normal to the surface, and f is evaluated as (x - S*) . N* / |N*| (the same number, smooth
// through the surface itself); at a foot on an edge (x beyond the patch's boundary) as the signed
// length. Beyond the boundary the sign flips where (x - S*) . N* does, with |f| > 0: f is
// discontinuous there but zero only on the patch, so the zero set is the patch exactly (the
// mesher drops the jump: datasets/meshing/model_mesher.h).
// Derivatives (Jets, Dual3): the foot (u*, v*) is found in double precision and held fixed; by
// the envelope theorem (dD/du = dD/dv = 0 at an interior foot, an edge foot stays on its edge)
// the first derivatives of f in x and in the control points are exact.
#pragma once

#include <type_traits>
#include <vector>

#include "model/splines/bspline_evaluation.h"
#include "model/splines/closest_point.h"
#include "model/vec3.h"

namespace implicitfit {

template <typename T>
T BSplineSurfaceSignedDistance(const SplineStructure& s, const T* p, const T* x) {
  const int n = 3 * s.count[0] * s.count[1];
  const double xd[3] = {ValueOf(x[0]), ValueOf(x[1]), ValueOf(x[2])};
  SurfaceFoot foot;
  if constexpr (std::is_same<T, double>::value) {
    foot = ClosestSurfacePoint(s, p, xd);
  } else {
    thread_local std::vector<double> values;
    values.resize(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) values[i] = ValueOf(p[i]);
    foot = ClosestSurfacePoint(s, values.data(), xd);
  }
  T d[kMaxSplineDerivative + 1][kMaxSplineDerivative + 1][3];
  SurfaceDerivatives(s, p, T(foot.u), T(foot.v), 1, d);
  T r[3], normal[3];
  for (int k = 0; k < 3; ++k) r[k] = x[k] - d[0][0][k];
  Cross3(d[1][0], d[0][1], normal);
  const T nn = Dot3(normal, normal);
  const T along = Dot3(r, normal);
  const double side = ValueOf(along) < 0.0 ? -1.0 : 1.0;
  using std::sqrt;
  const T r2 = Dot3(r, r);
  const bool edge = foot.u_at_bound || foot.v_at_bound;
  // An edge foot, or a degenerate normal (a collapsed edge): the signed length, unless x is on
  // the surface (a Jet's sqrt has no derivative at 0).
  if ((edge || !(ValueOf(nn) > 0.0)) && ValueOf(r2) > 1e-300) return side * sqrt(r2);
  if (!(ValueOf(nn) > 0.0)) return T(0.0);
  return along / sqrt(nn);
}

}  // namespace implicitfit
