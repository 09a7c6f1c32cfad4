#include "model/splines/closest_point.h"

#include <algorithm>
#include <cmath>

#include "model/splines/bspline_evaluation.h"
#include "model/splines/curve_skeleton.h"

namespace implicitfit {
namespace {

constexpr int kMaxNewtonIterations = 60;
constexpr int kStarts = 3;

double Dot(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// The Greville abscissa of basis function i (model/splines/bspline_basis.h).
double Greville(const SplineStructure& s, int d, int i) {
  const int p = s.degree[d];
  double sum = 0.0;
  for (int j = 1; j <= p; ++j) sum += s.knots[d][i + j];
  return p > 0 ? sum / p : 0.5 * (s.knots[d][i] + s.knots[d][i + 1]);
}

// The kStarts smallest of the offered distances, with their values (an index, a parameter).
struct BestStarts {
  double d[kStarts];
  double value[kStarts];
  int found = 0;
  void Offer(double e, double v) {
    int k = found < kStarts ? found++ : kStarts;
    if (k == kStarts) {
      if (!(e < d[kStarts - 1])) return;
      k = kStarts - 1;
    }
    while (k > 0 && e < d[k - 1]) {
      d[k] = d[k - 1];
      value[k] = value[k - 1];
      --k;
    }
    d[k] = e;
    value[k] = v;
  }
};

double Distance2(const double* a, const double* b) {
  return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
         (a[2] - b[2]) * (a[2] - b[2]);
}

// The indices of the (at most) kStarts control points nearest to x, nearest first.
int NearestControlPoints(const double* points, int count, const double* x, int* best) {
  BestStarts b;
  for (int i = 0; i < count; ++i) b.Offer(Distance2(points + 3 * i, x), i);
  for (int k = 0; k < b.found; ++k) best[k] = static_cast<int>(b.value[k]);
  return b.found;
}

// The same on an n_u x n_v net, in two levels when it is large (bounded work per evaluation):
// every step-th point (at most 32 x 32), then the windows of +- step around the three best.
int NearestNetPoints(const double* points, int nu, int nv, const double* x, int* best) {
  if (nu * nv <= 1024) return NearestControlPoints(points, nu * nv, x, best);
  const int su = (nu + 31) / 32, sv = (nv + 31) / 32;
  BestStarts coarse;
  for (int i = 0; i < nu; i += su)
    for (int j = 0; j < nv; j += sv) coarse.Offer(Distance2(points + 3 * (i * nv + j), x), i * nv + j);
  BestStarts fine;
  for (int k = 0; k < coarse.found; ++k) {
    const int ci = static_cast<int>(coarse.value[k]) / nv, cj = static_cast<int>(coarse.value[k]) % nv;
    for (int i = std::max(0, ci - su); i <= std::min(nu - 1, ci + su); ++i)
      for (int j = std::max(0, cj - sv); j <= std::min(nv - 1, cj + sv); ++j) {
        bool seen = false;
        for (int f = 0; f < fine.found; ++f) seen |= static_cast<int>(fine.value[f]) == i * nv + j;
        if (!seen) fine.Offer(Distance2(points + 3 * (i * nv + j), x), i * nv + j);
      }
  }
  for (int k = 0; k < fine.found; ++k) best[k] = static_cast<int>(fine.value[k]);
  return fine.found;
}

// A curve's control polygon, in two levels when it holds more than 256 points.
int NearestPolygonPoints(const double* points, int n, const double* x, int* best) {
  if (n <= 256) return NearestControlPoints(points, n, x, best);
  const int step = (n + 63) / 64;
  BestStarts coarse;
  for (int i = 0; i < n; i += step) coarse.Offer(Distance2(points + 3 * i, x), i);
  BestStarts fine;
  for (int k = 0; k < coarse.found; ++k) {
    const int c = static_cast<int>(coarse.value[k]);
    for (int i = std::max(0, c - step); i <= std::min(n - 1, c + step); ++i) {
      bool seen = false;
      for (int f = 0; f < fine.found; ++f) seen |= static_cast<int>(fine.value[f]) == i;
      if (!seen) fine.Offer(Distance2(points + 3 * i, x), i);
    }
  }
  for (int k = 0; k < fine.found; ++k) best[k] = static_cast<int>(fine.value[k]);
  return fine.found;
}

struct SurfaceState {
  double u, v, D;
  double S[kMaxSplineDerivative + 1][kMaxSplineDerivative + 1][3];
};

void EvaluateSurface(const SplineStructure& s, const double* points, const double* x,
                     SurfaceState* st, int order) {
  SurfaceDerivatives(s, points, st->u, st->v, order, st->S);
  double r[3];
  for (int k = 0; k < 3; ++k) r[k] = st->S[0][0][k] - x[k];
  st->D = 0.5 * Dot(r, r);
}

// Projected Newton from (u, v) (header).
SurfaceFoot SurfaceNewton(const SplineStructure& s, const double* points, const double* x,
                          double u, double v) {
  const double lo[2] = {s.Begin(0), s.Begin(1)}, hi[2] = {s.End(0), s.End(1)};
  SurfaceState st;
  st.u = u;
  st.v = v;
  EvaluateSurface(s, points, x, &st, 2);
  bool held[2] = {false, false};
  for (int it = 0; it < kMaxNewtonIterations; ++it) {
    double r[3];
    for (int k = 0; k < 3; ++k) r[k] = st.S[0][0][k] - x[k];
    const double* su = st.S[1][0];
    const double* sv = st.S[0][1];
    const double g[2] = {Dot(su, r), Dot(sv, r)};
    double h[2][2] = {{Dot(su, su), Dot(su, sv)}, {Dot(su, sv), Dot(sv, sv)}};
    const double gn[2][2] = {{h[0][0], h[0][1]}, {h[1][0], h[1][1]}};
    h[0][0] += Dot(st.S[2][0], r);
    h[0][1] += Dot(st.S[1][1], r);
    h[1][0] = h[0][1];
    h[1][1] += Dot(st.S[0][2], r);
    if (!(h[0][0] > 0.0 && h[1][1] > 0.0 && h[0][0] * h[1][1] - h[0][1] * h[0][1] > 0.0))
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b) h[a][b] = gn[a][b];
    const double damping = 1e-14 * (h[0][0] + h[1][1]) + 1e-300;
    h[0][0] += damping;
    h[1][1] += damping;
    const double at[2] = {st.u, st.v};
    for (int a = 0; a < 2; ++a)  // active set: at a bound with the gradient pointing outward
      held[a] = (at[a] <= lo[a] && g[a] > 0.0) || (at[a] >= hi[a] && g[a] < 0.0);
    double step[2] = {0.0, 0.0};
    if (!held[0] && !held[1]) {
      const double det = h[0][0] * h[1][1] - h[0][1] * h[1][0];
      step[0] = -(h[1][1] * g[0] - h[0][1] * g[1]) / det;
      step[1] = -(h[0][0] * g[1] - h[1][0] * g[0]) / det;
    } else {
      for (int a = 0; a < 2; ++a)
        if (!held[a]) step[a] = -g[a] / h[a][a];
    }
    if (!std::isfinite(step[0]) || !std::isfinite(step[1])) break;
    double alpha = 1.0;
    SurfaceState trial;
    bool improved = false;
    for (int half = 0; half < 40; ++half) {
      trial.u = std::clamp(st.u + alpha * step[0], lo[0], hi[0]);
      trial.v = std::clamp(st.v + alpha * step[1], lo[1], hi[1]);
      EvaluateSurface(s, points, x, &trial, 2);
      if (trial.D <= st.D) {
        improved = true;
        break;
      }
      alpha *= 0.5;
    }
    if (!improved) break;
    const double moved = std::max(std::abs(trial.u - st.u) / (hi[0] - lo[0]),
                                  std::abs(trial.v - st.v) / (hi[1] - lo[1]));
    st = trial;
    if (moved < 1e-15) break;
  }
  SurfaceFoot foot;
  foot.u = st.u;
  foot.v = st.v;
  foot.distance2 = 2.0 * st.D;
  foot.u_at_bound = st.u <= lo[0] || st.u >= hi[0];
  foot.v_at_bound = st.v <= lo[1] || st.v >= hi[1];
  return foot;
}

struct CurveState {
  double t, D;
  double C[kMaxSplineDerivative + 1][3];
};

// t's range; an ellipse is periodic.
void CurveRange(const SplineStructure& s, double* lo, double* hi) {
  if (s.curve == CurveKind::kBSpline) {
    *lo = s.Begin(0);
    *hi = s.End(0);
  } else {
    *lo = 0.0;
    *hi = s.curve == CurveKind::kHelix ? s.turns : 1.0;
  }
}

void EvaluateCurve(const SplineStructure& s, const double* points, const double* x,
                   CurveState* st) {
  CurveKindDerivatives(s, points, st->t, 2, st->C);
  double r[3];
  for (int k = 0; k < 3; ++k) r[k] = st->C[0][k] - x[k];
  st->D = 0.5 * Dot(r, r);
}

CurveFoot CurveNewton(const SplineStructure& s, const double* points, const double* x, double t) {
  double lo, hi;
  CurveRange(s, &lo, &hi);
  const bool periodic = s.curve == CurveKind::kEllipse;
  auto wrap = [&](double value) {
    if (periodic) return value - std::floor(value);
    return std::clamp(value, lo, hi);
  };
  CurveState st;
  st.t = wrap(t);
  EvaluateCurve(s, points, x, &st);
  for (int it = 0; it < kMaxNewtonIterations; ++it) {
    double r[3];
    for (int k = 0; k < 3; ++k) r[k] = st.C[0][k] - x[k];
    const double g = Dot(st.C[1], r);
    double h = Dot(st.C[1], st.C[1]) + Dot(st.C[2], r);
    if (!(h > 0.0)) h = Dot(st.C[1], st.C[1]);
    h += 1e-300;
    if (!periodic && ((st.t <= lo && g > 0.0) || (st.t >= hi && g < 0.0))) break;
    const double step = -g / h;
    if (!std::isfinite(step)) break;
    double alpha = 1.0;
    CurveState trial;
    bool improved = false;
    for (int half = 0; half < 40; ++half) {
      trial.t = wrap(st.t + alpha * step);
      EvaluateCurve(s, points, x, &trial);
      if (trial.D <= st.D) {
        improved = true;
        break;
      }
      alpha *= 0.5;
    }
    if (!improved) break;
    const double moved = std::abs(alpha * step) / (hi - lo);
    st = trial;
    if (moved < 1e-15) break;
  }
  CurveFoot foot;
  foot.t = st.t;
  foot.distance2 = 2.0 * st.D;
  foot.at_end = !periodic && (st.t <= lo || st.t >= hi);
  return foot;
}

// Starts for an ellipse or a helix: the three best of a sampling at 16 points per turn (at most
// 1024 samples: beyond 64 turns they thin out), which holds the global minimum's basin
// for any x (one local minimum per turn at most, for a point far from the axis).
constexpr int kMaxCurveSamples = 1024;

int PeriodicStarts(const SplineStructure& s, const double* p, const double* x, double* starts) {
  const double range = s.curve == CurveKind::kHelix ? s.turns : 1.0;
  const int samples =
      std::clamp(static_cast<int>(std::ceil(16.0 * range)), 16, kMaxCurveSamples);
  BestStarts best;
  for (int i = 0; i <= samples; ++i) {
    const double t = range * i / samples;
    double c[kMaxSplineDerivative + 1][3];
    CurveKindDerivatives(s, p, t, 0, c);
    best.Offer(Distance2(c[0], x), t);
  }
  for (int k = 0; k < best.found; ++k) starts[k] = best.value[k];
  return best.found;
}

}  // namespace

SurfaceFoot SurfaceFootFrom(const SplineStructure& s, const double* points, const double* x,
                            double u, double v) {
  return SurfaceNewton(s, points, x, u, v);
}

SurfaceFoot ClosestSurfacePoint(const SplineStructure& s, const double* points, const double* x,
                                const double* start) {
  int nearest[kStarts];
  const int nv = s.count[1];
  const int found = NearestNetPoints(points, s.count[0], nv, x, nearest);
  SurfaceFoot best;
  bool first = true;
  if (start) {
    best = SurfaceNewton(s, points, x, start[0], start[1]);
    first = false;
  }
  for (int k = 0; k < found; ++k) {
    const int i = nearest[k] / nv, j = nearest[k] % nv;
    const SurfaceFoot foot = SurfaceNewton(s, points, x, Greville(s, 0, i), Greville(s, 1, j));
    if (first || foot.distance2 < best.distance2) best = foot;
    first = false;
  }
  return best;
}

CurveFoot ClosestCurvePoint(const SplineStructure& s, const double* points, const double* x) {
  double starts[kStarts + 5];
  int n = 0;
  if (s.curve == CurveKind::kBSpline) {
    int nearest[kStarts];
    const int found = NearestPolygonPoints(points, s.count[0], x, nearest);
    for (int k = 0; k < found; ++k) starts[n++] = Greville(s, 0, nearest[k]);
    starts[n++] = s.Begin(0);
    starts[n++] = s.End(0);
  } else {
    n = PeriodicStarts(s, points, x, starts);
  }
  CurveFoot best;
  for (int k = 0; k < n; ++k) {
    const CurveFoot foot = CurveNewton(s, points, x, starts[k]);
    if (k == 0 || foot.distance2 < best.distance2) best = foot;
  }
  return best;
}

}  // namespace implicitfit
