// Jensen's constructive surface geometry (docs/maths.md JE-1): parametric patches f_i: D_i -> R^3
// over star-shaped polygonal domains, arranged in a tree whose links place a child patch on its
// parent and blend it in. A parametric surface, not an implicit node: it is evaluated as
// G(s, t) over the root's domain (and fitted by fit/splines/patch_tree_fit.h).
// Patch kinds (the textbook's parametric forms and the B-spline patch):
//   plane      o + u e_1 + v e_2                                     [o, e_1, e_2]
//   sphere     c + R (cos 2 pi u sin pi v, sin 2 pi u sin pi v, cos pi v)        [c, R]
//   cylinder   c + (R cos 2 pi u, R sin 2 pi u, h v)                              [c, R, h]
//   dome       the sphere of radius R about c in azimuthal coordinates: rho = |(u, v)| / R,
//              c + (S u, S v, R cos(pi rho / 2)), S = sin(pi rho / 2) / rho (S -> pi / 2 at the
//              pole, by its series: smooth); |(u, v)| = R is the equator (u, v, 0) + c, so a
//              domain inside the disk of radius R is a cap of the upper hemisphere   [c, R]
//   bspline    S(u, v) of model/splines/bspline_evaluation.h                [control points]
// Link (parent i, child j), placement (a, b, c, d, theta), band sigma_b, filter half-width eps:
//   gamma(s, t) = R(-theta) ((s, t) - (a, b)) + (c, d)   (the paper's row-vector form
//                 ((s, t) - (a, b)) R(theta) + (c, d)): gamma(a, b) = (c, d);
//   Gamma(y) = f_i(a, b) + [t_1' t_2' n] y, n the unit normal f_s x f_t / |.| of f_i at (a, b),
//              t_1 = f_s / |f_s|, t_2 = n x t_1, (t_1', t_2') = (t_1, t_2) turned by theta about n:
//              a rigid placement of the child's own coordinates (its origin onto f_i(a, b), its z
//              axis onto n); the paper prints the matrix with n as its third *row*, not a rotation;
//   theta_j = h(min(1, sigma_j / sigma_b)) on D_j (model/splines/star_ratio.h), phi = 1 - theta_j o gamma;
//   f_i <- phi f_i + (theta_j o gamma) Gamma(G_j o gamma), children folded in the order of the
//   links, G_j the child's own blended surface (its links first: leaves up). The frame at (a, b)
//   is f_i's own (the paper uses the parent as blended so far; the two agree unless an earlier
//   sibling's band reaches (a, b)). phi f_i + theta Gamma is computed as written, so G = f_i
//   exactly where theta = 0 and G = Gamma(G_j o gamma) exactly where theta = 1.
// Everything is templated on the scalar: the placements and (s, t) may be Jets.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "model/splines/bspline_evaluation.h"
#include "model/splines/star_ratio.h"
#include "model/vec3.h"

namespace implicitfit {

enum class PatchKind { kPlane, kSphere, kCylinder, kDome, kBSpline };

struct ParametricPatch {
  PatchKind kind = PatchKind::kPlane;
  StarDomain domain;
  std::vector<double> p;   // the kind's parameters (header)
  SplineStructure spline;  // kBSpline

  // out[0] = f(u, v), out[1] = f_u, out[2] = f_v.
  template <typename T>
  void Derivatives(const T& u, const T& v, T out[3][3]) const;
};

struct PatchLink {
  int parent = 0, child = 1;
  double band = 0.5;     // sigma_b in (0, 1]
  double filter = 0.05;  // eps > 0, in the child's domain units
};

class PatchTree {
 public:
  static constexpr int kPerLink = 5;  // a, b, c, d, theta
  std::vector<ParametricPatch> patches;
  std::vector<PatchLink> links;
  std::vector<double> placements;  // kPerLink per link
  int root = 0;

  // "" when every link names existing patches, every patch but the root has one parent, the
  // links form a tree under the root, the domains are star-shaped, and the numbers are in range.
  std::string Problem() const;

  // G(s, t) of the root, or of any patch's subtree.
  template <typename T>
  void Evaluate(const T* placement, const T& s, const T& t, T out[3]) const {
    EvaluatePatch(root, placement, s, t, out);
  }
  template <typename T>
  void EvaluatePatch(int patch, const T* placement, const T& s, const T& t, T out[3]) const;
  // gamma of link l.
  template <typename T>
  void Gamma(int l, const T* placement, const T& s, const T& t, T* u, T* v) const;
  // theta_j at the child's (u, v), and phi at the parent's (s, t) (= 1 - theta_j o gamma).
  template <typename T>
  T Theta(int l, const T& u, const T& v) const {
    const PatchLink& k = links[l];
    return BlendWeight(patches[k.child].domain, u, v, k.filter, k.band);
  }
  template <typename T>
  T Phi(int l, const T* placement, const T& s, const T& t) const {
    T u, v;
    Gamma(l, placement, s, t, &u, &v);
    return 1.0 - Theta(l, u, v);
  }
};

// ----------------------------------------------------------------------------------------------

template <typename T>
void ParametricPatch::Derivatives(const T& u, const T& v, T out[3][3]) const {
  using std::cos;
  using std::sin;
  using std::sqrt;
  switch (kind) {
    case PatchKind::kPlane:
      for (int k = 0; k < 3; ++k) {
        out[0][k] = p[k] + u * p[3 + k] + v * p[6 + k];
        out[1][k] = T(p[3 + k]);
        out[2][k] = T(p[6 + k]);
      }
      return;
    case PatchKind::kSphere: {
      const double R = p[3], w = 2.0 * M_PI;
      const T cu = cos(w * u), su = sin(w * u), cv = cos(M_PI * v), sv = sin(M_PI * v);
      const T r[3] = {cu * sv, su * sv, cv};
      const T ru[3] = {-w * su * sv, w * cu * sv, T(0.0)};
      const T rv[3] = {M_PI * cu * cv, M_PI * su * cv, -M_PI * sv};
      for (int k = 0; k < 3; ++k) {
        out[0][k] = p[k] + R * r[k];
        out[1][k] = R * ru[k];
        out[2][k] = R * rv[k];
      }
      return;
    }
    case PatchKind::kCylinder: {
      const double R = p[3], h = p[4], w = 2.0 * M_PI;
      const T cu = cos(w * u), su = sin(w * u);
      out[0][0] = p[0] + R * cu;
      out[0][1] = p[1] + R * su;
      out[0][2] = p[2] + h * v;
      out[1][0] = -R * w * su;
      out[1][1] = R * w * cu;
      out[1][2] = T(0.0);
      out[2][0] = T(0.0);
      out[2][1] = T(0.0);
      out[2][2] = T(h);
      return;
    }
    case PatchKind::kDome: {
      // x = (pi/2)^2 rho^2; S = sin(sqrt x) / sqrt x * pi/2, C = cos(sqrt x), and their
      // derivatives in x, by series near the pole (no sqrt of 0 for Jets).
      const double R = p[3], q = 0.25 * M_PI * M_PI / (R * R);
      const T x = q * (u * u + v * v);
      T s, c, ds, dc;  // sin(r)/r, cos(r) and d/dx of both, r = sqrt(x)
      if (ValueOf(x) < 1e-4) {
        s = 1.0 - x / 6.0 + x * x / 120.0 - x * x * x / 5040.0;
        ds = -1.0 / 6.0 + x / 60.0 - x * x / 1680.0;
        c = 1.0 - x / 2.0 + x * x / 24.0 - x * x * x / 720.0;
        dc = -0.5 + x / 12.0 - x * x / 240.0;
      } else {
        const T r = sqrt(x);
        s = sin(r) / r;
        c = cos(r);
        ds = (cos(r) - s) / (2.0 * x);
        dc = -sin(r) / (2.0 * r);
      }
      const double half_pi = 0.5 * M_PI;
      const T xu = 2.0 * q * u, xv = 2.0 * q * v;  // dx/du, dx/dv
      out[0][0] = p[0] + half_pi * s * u;
      out[0][1] = p[1] + half_pi * s * v;
      out[0][2] = p[2] + R * c;
      out[1][0] = half_pi * (s + ds * xu * u);
      out[1][1] = half_pi * ds * xu * v;
      out[1][2] = R * dc * xu;
      out[2][0] = half_pi * ds * xv * u;
      out[2][1] = half_pi * (s + ds * xv * v);
      out[2][2] = R * dc * xv;
      return;
    }
    case PatchKind::kBSpline: {
      thread_local std::vector<T> control;
      control.resize(p.size());
      for (size_t i = 0; i < p.size(); ++i) control[i] = T(p[i]);
      T d[kMaxSplineDerivative + 1][kMaxSplineDerivative + 1][3];
      SurfaceDerivatives(spline, control.data(), u, v, 1, d);
      for (int k = 0; k < 3; ++k) {
        out[0][k] = d[0][0][k];
        out[1][k] = d[1][0][k];
        out[2][k] = d[0][1][k];
      }
      return;
    }
  }
}

template <typename T>
void PatchTree::Gamma(int l, const T* placement, const T& s, const T& t, T* u, T* v) const {
  using std::cos;
  using std::sin;
  const T* q = placement + kPerLink * l;
  const T ds = s - q[0], dt = t - q[1];
  const T c = cos(q[4]), sn = sin(q[4]);
  *u = c * ds + sn * dt + q[2];
  *v = c * dt - sn * ds + q[3];
}

template <typename T>
void PatchTree::EvaluatePatch(int patch, const T* placement, const T& s, const T& t,
                              T out[3]) const {
  using std::cos;
  using std::sin;
  using std::sqrt;
  T d[3][3];
  patches[patch].Derivatives(s, t, d);
  for (int k = 0; k < 3; ++k) out[k] = d[0][k];
  for (size_t l = 0; l < links.size(); ++l) {
    if (links[l].parent != patch) continue;
    T u, v;
    Gamma(static_cast<int>(l), placement, s, t, &u, &v);
    const T w = Theta(static_cast<int>(l), u, v);
    if (!(ValueOf(w) > 0.0)) continue;  // phi = 1: f_i exactly
    T y[3];
    EvaluatePatch(links[l].child, placement, u, v, y);
    const T* q = placement + kPerLink * l;
    T f[3][3];
    patches[patch].Derivatives(q[0], q[1], f);
    T n[3], t1[3], t2[3];
    Cross3(f[1], f[2], n);
    const T nn = sqrt(Dot3(n, n)), ns = sqrt(Dot3(f[1], f[1]));
    for (int k = 0; k < 3; ++k) {
      n[k] /= nn;
      t1[k] = f[1][k] / ns;
    }
    Cross3(n, t1, t2);
    const T c = cos(q[4]), sn = sin(q[4]);
    const T phi = 1.0 - w;
    for (int k = 0; k < 3; ++k) {
      const T e1 = c * t1[k] + sn * t2[k], e2 = c * t2[k] - sn * t1[k];
      const T placed = f[0][k] + e1 * y[0] + e2 * y[1] + n[k] * y[2];
      out[k] = phi * out[k] + w * placed;
    }
  }
}

}  // namespace implicitfit
