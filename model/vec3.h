// Tiny 3-vector helpers on raw T* / arrays, so that evaluators stay allocation-free and work for
// any scalar (double, Ceres Jet, Dual3 of model/dual3.h; not Eigen's AutoDiffScalar: see there).
#pragma once

#include <cmath>

namespace implicitfit {

template <typename T>
T Dot3(const T* a, const T* b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

template <typename T>
T Norm3(const T* a) {
  using std::sqrt;
  return sqrt(Dot3(a, a));
}

// out = a - b
template <typename T>
void Sub3(const T* a, const T* b, T* out) {
  out[0] = a[0] - b[0];
  out[1] = a[1] - b[1];
  out[2] = a[2] - b[2];
}

// out = a x b
template <typename T>
void Cross3(const T* a, const T* b, T* out) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

// Splits d into its component along the unit axis u (returned) and the length of the rest
// (radial), computed as |u x d| which stays accurate when d is nearly parallel to u.
template <typename T>
T AxialRadial(const T* u, const T* d, T* radial) {
  T c[3];
  Cross3(u, d, c);
  *radial = Norm3(c);
  return Dot3(u, d);
}

// Axial and radial coordinates of x about the line through `origin` along `axis` (any non-zero
// length): returns h = (x - origin) . u and sets *radial = |(x - origin) x u|, u = axis / |axis|.
template <typename T>
T AxialCoordinates(const T* origin, const T* axis, const T* x, T* radial) {
  const T inv = 1.0 / Norm3(axis);
  const T u[3] = {axis[0] * inv, axis[1] * inv, axis[2] * inv};
  T d[3];
  Sub3(x, origin, d);
  return AxialRadial(u, d, radial);
}

}  // namespace implicitfit
