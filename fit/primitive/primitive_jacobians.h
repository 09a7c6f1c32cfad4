// Closed-form value, parameter gradient and point gradient of the five primitive distances
// (model/primitives/plane.h ... model/primitives/torus.h), for the fitter's hot loops: the compressed residual blocks
// (fit/primitive/compressed_distance_cost.h) and the inlier classification (grad_x f against the normals).
//
// Maths. Notation: d = x - c (c the apex/centre/axis point), a the axis parameter (any length),
// u = a / |a|, h = u . d (axial), radial vector w = d - h u = (u x d) x u, rho = |w| = |u x d|,
// e = w / rho. The derivative of any g(u) with respect to a goes through the normalisation:
// dg/da = (I - u u^T) dg/du / |a|; with dh/du = d and drho/du = -h d / rho (up to a multiple of
// u, which the projection removes), (I - u u^T) d = w, so
//   dh/da = w / |a|,   drho/da = -h e / |a|,   dh/dd = u,   drho/dd = e.
//   plane    f = (n . x - dd) / L, L = |n|, m = n / L
//            df/dn = (x - f m) / L,  df/d(dd) = -1 / L,  df/dx = m
//   sphere   f = |d| - r                      df/dc = -d/|d|, df/dr = -1, df/dx = d/|d|
//   cylinder f = rho - r                      df/dq = -e, df/da = -h e / |a|, df/dr = -1,
//                                             df/dx = e
//   cone     nappe branch (rho sin(al) + h cos(al) >= 0): f = rho cos(al) - h sin(al)
//              df/dx = cos(al) e - sin(al) u = -df/dc,
//              df/da = -(h cos(al) + rho sin(al)) e / |a|,  df/d(al) = -(rho sin(al) + h cos(al))
//            apex branch: f = sqrt(rho^2 + h^2) = |d|
//              df/dx = d / |d| = -df/dc,  df/da = 0,  df/d(al) = 0
//   torus    q = rho - R, g = sqrt(q^2 + h^2), f = g - r
//              df/dx = (q e + h u) / g = -df/dc,  df/da = h R e / (g |a|),
//              df/dR = -q / g,  df/dr = -1
// Degenerate points (on an axis: rho = 0; at a centre: |d| = 0; g = 0) take a zero for the
// undefined direction instead of a NaN.
// The parameter-only quantities (u, 1/|a|, sin and cos of the cone angle, ...) are computed once
// by the constructor, so one object serves a whole batch of points.
//
// API: PrimitiveDistance<Evaluator> for Plane/Sphere/Cylinder/Cone/TorusEvaluator;
// PrimitiveDistance<E>::kAvailable is false for any other evaluator: the primitive fitter needs
// it (CompressedDistanceCost static_asserts it; a new fittable kind brings its closed form).
//   PrimitiveDistance<E> f(params);           // flat layout of the evaluator
//   double v = f(x, dp, dx);                  // dp: kNumParameters values or nullptr,
//                                             // dx: 3 values or nullptr
#pragma once

#include <cmath>

#include "model/primitives/cone.h"
#include "model/primitives/cylinder.h"
#include "model/primitives/plane.h"
#include "model/primitives/sphere.h"
#include "model/primitives/torus.h"
#include "model/vec3.h"

namespace implicitfit {

template <typename Evaluator>
struct PrimitiveDistance {
  static constexpr bool kAvailable = false;
};

namespace primitive_distance_internal {

// Axis frame shared by the cylinder, cone and torus: u, 1/|a| from the parameters at offset 3.
struct Axis {
  double u[3];
  double inv_len;
  explicit Axis(const double* a) {
    inv_len = 1.0 / Norm3(a);
    for (int k = 0; k < 3; ++k) u[k] = a[k] * inv_len;
  }
  // d = x - c, h = u . d, rho = |u x d|, e = (u x d) x u / rho (0 when rho = 0).
  double Split(const double* x, const double* c, double* d, double* rho, double* e) const {
    Sub3(x, c, d);
    double cr[3];
    Cross3(u, d, cr);
    *rho = Norm3(cr);
    Cross3(cr, u, e);
    const double s = *rho > 0 ? 1.0 / *rho : 0.0;
    for (int k = 0; k < 3; ++k) e[k] *= s;
    return Dot3(u, d);
  }
};

}  // namespace primitive_distance_internal

template <>
struct PrimitiveDistance<PlaneEvaluator> {
  static constexpr bool kAvailable = true;
  static constexpr int kNumParameters = 4;
  double n[3], offset, inv_len, m[3];
  explicit PrimitiveDistance(const double* p) : n{p[0], p[1], p[2]}, offset(p[3]) {
    inv_len = 1.0 / Norm3(p);
    for (int k = 0; k < 3; ++k) m[k] = n[k] * inv_len;
  }
  double operator()(const double* x, double* dp, double* dx) const {
    const double f = (Dot3(n, x) - offset) * inv_len;
    if (dp) {
      for (int k = 0; k < 3; ++k) dp[k] = (x[k] - f * m[k]) * inv_len;
      dp[3] = -inv_len;
    }
    if (dx)
      for (int k = 0; k < 3; ++k) dx[k] = m[k];
    return f;
  }
};

template <>
struct PrimitiveDistance<SphereEvaluator> {
  static constexpr bool kAvailable = true;
  static constexpr int kNumParameters = 4;
  double c[3], r;
  explicit PrimitiveDistance(const double* p) : c{p[0], p[1], p[2]}, r(p[3]) {}
  double operator()(const double* x, double* dp, double* dx) const {
    double d[3];
    Sub3(x, c, d);
    const double len = Norm3(d);
    const double s = len > 0 ? 1.0 / len : 0.0;
    if (dp) {
      for (int k = 0; k < 3; ++k) dp[k] = -d[k] * s;
      dp[3] = -1.0;
    }
    if (dx)
      for (int k = 0; k < 3; ++k) dx[k] = d[k] * s;
    return len - r;
  }
};

template <>
struct PrimitiveDistance<CylinderEvaluator> {
  static constexpr bool kAvailable = true;
  static constexpr int kNumParameters = 7;
  double q[3], r;
  primitive_distance_internal::Axis axis;
  explicit PrimitiveDistance(const double* p) : q{p[0], p[1], p[2]}, r(p[6]), axis(p + 3) {}
  double operator()(const double* x, double* dp, double* dx) const {
    double d[3], e[3], rho;
    const double h = axis.Split(x, q, d, &rho, e);
    if (dp) {
      const double sa = -h * axis.inv_len;
      for (int k = 0; k < 3; ++k) {
        dp[k] = -e[k];
        dp[3 + k] = sa * e[k];
      }
      dp[6] = -1.0;
    }
    if (dx)
      for (int k = 0; k < 3; ++k) dx[k] = e[k];
    return rho - r;
  }
};

template <>
struct PrimitiveDistance<ConeEvaluator> {
  static constexpr bool kAvailable = true;
  static constexpr int kNumParameters = 7;
  double apex[3], sin_a, cos_a;
  primitive_distance_internal::Axis axis;
  explicit PrimitiveDistance(const double* p)
      : apex{p[0], p[1], p[2]}, sin_a(std::sin(p[6])), cos_a(std::cos(p[6])), axis(p + 3) {}
  double operator()(const double* x, double* dp, double* dx) const {
    double d[3], e[3], rho;
    const double h = axis.Split(x, apex, d, &rho, e);
    const double t = rho * sin_a + h * cos_a;
    if (t >= 0.0) {  // nearest point on the nappe
      double g[3];
      for (int k = 0; k < 3; ++k) g[k] = cos_a * e[k] - sin_a * axis.u[k];
      if (dp) {
        const double sa = -(h * cos_a + rho * sin_a) * axis.inv_len;
        for (int k = 0; k < 3; ++k) {
          dp[k] = -g[k];
          dp[3 + k] = sa * e[k];
        }
        dp[6] = -t;
      }
      if (dx)
        for (int k = 0; k < 3; ++k) dx[k] = g[k];
      return rho * cos_a - h * sin_a;
    }
    const double len = std::sqrt(rho * rho + h * h);  // nearest point: the apex
    const double s = len > 0 ? 1.0 / len : 0.0;
    if (dp) {
      for (int k = 0; k < 3; ++k) {
        dp[k] = -d[k] * s;
        dp[3 + k] = 0.0;
      }
      dp[6] = 0.0;
    }
    if (dx)
      for (int k = 0; k < 3; ++k) dx[k] = d[k] * s;
    return len;
  }
};

template <>
struct PrimitiveDistance<TorusEvaluator> {
  static constexpr bool kAvailable = true;
  static constexpr int kNumParameters = 8;
  double c[3], major, minor;
  primitive_distance_internal::Axis axis;
  explicit PrimitiveDistance(const double* p)
      : c{p[0], p[1], p[2]}, major(p[6]), minor(p[7]), axis(p + 3) {}
  double operator()(const double* x, double* dp, double* dx) const {
    double d[3], e[3], rho;
    const double h = axis.Split(x, c, d, &rho, e);
    const double q = rho - major;
    const double g = std::sqrt(q * q + h * h);
    const double s = g > 0 ? 1.0 / g : 0.0;
    double gx[3];
    for (int k = 0; k < 3; ++k) gx[k] = (q * e[k] + h * axis.u[k]) * s;
    if (dp) {
      const double sa = h * major * s * axis.inv_len;
      for (int k = 0; k < 3; ++k) {
        dp[k] = -gx[k];
        dp[3 + k] = sa * e[k];
      }
      dp[6] = -q * s;
      dp[7] = -1.0;
    }
    if (dx)
      for (int k = 0; k < 3; ++k) dx[k] = gx[k];
    return g - minor;
  }
};

}  // namespace implicitfit
