#include "model/splines/bspline_basis.h"

#include <algorithm>
#include <cmath>

namespace implicitfit {

int FindSpan(int degree, int count, const double* knots, double t) {
  const int p = degree, n = count;
  if (!(t < knots[n])) {  // right end (or beyond, or NaN): the last non-empty span
    int s = n - 1;
    while (s > p && !(knots[s] < knots[s + 1])) --s;
    return s;
  }
  if (t <= knots[p]) {  // left end (or before): the first non-empty span
    int s = p;
    while (s < n - 1 && !(knots[s] < knots[s + 1])) ++s;
    return s;
  }
  // knots[p] < t < knots[n]: the last s with knots[s] <= t (binary search).
  const double* it = std::upper_bound(knots + p, knots + n + 1, t);
  return static_cast<int>(it - knots) - 1;
}

namespace {

double Ratio(double numerator, double denominator, double zero_over_zero) {
  if (denominator == 0.0) return numerator == 0.0 ? zero_over_zero : 0.0;
  return numerator / denominator;
}

double CoxDeBoorRecursive(int i, int q, double t, const std::vector<double>& u, int last_span,
                          double zz) {
  if (q == 0) {
    if (u[i] <= t && t < u[i + 1]) return 1.0;
    return i == last_span && t == u[i + 1] ? 1.0 : 0.0;  // the closed right end
  }
  double value = 0.0;
  const double a = CoxDeBoorRecursive(i, q - 1, t, u, last_span, zz);
  const double b = CoxDeBoorRecursive(i + 1, q - 1, t, u, last_span, zz);
  // A zero denominator comes with a zero-length support, so the multiplied basis function is
  // 0 there: either convention gives the same value (the factor is multiplied by 0).
  value += Ratio(t - u[i], u[i + q] - u[i], zz) * a;
  value += Ratio(u[i + q + 1] - t, u[i + q + 1] - u[i + 1], zz) * b;
  return value;
}

}  // namespace

double CoxDeBoor(int i, int degree, double t, const std::vector<double>& knots, int count,
                 double zero_over_zero) {
  const int last = FindSpan(degree, count, knots.data(), knots[count]);
  return CoxDeBoorRecursive(i, degree, t, knots, last, zero_over_zero);
}

std::vector<double> ClampedUniformKnots(int degree, int count, double a, double b) {
  std::vector<double> knots(static_cast<size_t>(count + degree + 1));
  const int interior = count - degree - 1;
  for (int i = 0; i <= degree; ++i) {
    knots[i] = a;
    knots[count + i] = b;
  }
  for (int j = 1; j <= interior; ++j)
    knots[degree + j] = a + (b - a) * static_cast<double>(j) / (interior + 1);
  return knots;
}

std::string KnotVectorProblem(const std::vector<double>& knots, int degree, int count) {
  const size_t need = static_cast<size_t>(count) + degree + 1;
  if (knots.size() != need)
    return "must hold " + std::to_string(need) + " knots (control points + degree + 1), not " +
           std::to_string(knots.size());
  for (size_t i = 0; i < knots.size(); ++i) {
    if (!std::isfinite(knots[i])) return "knot " + std::to_string(i) + " is not finite";
    if (i > 0 && knots[i] < knots[i - 1])
      return "knots must not decrease (knot " + std::to_string(i) + ")";
  }
  if (!(knots[degree] < knots[count]))
    return "the parameter range [u_p, u_n] is empty (all the inner knots are equal)";
  size_t run = 1;
  for (size_t i = 1; i <= knots.size(); ++i) {
    if (i < knots.size() && knots[i] == knots[i - 1]) {
      ++run;
      continue;
    }
    const bool end = i - run == 0 || i == knots.size();
    if (run > static_cast<size_t>(end ? degree + 1 : std::max(degree, 1)))
      return "a knot is repeated " + std::to_string(run) + " times (at most degree" +
             std::string(end ? " + 1 at an end" : " inside") + ")";
    run = 1;
  }
  return "";
}

std::vector<double> GrevilleAbscissae(const std::vector<double>& knots, int degree, int count) {
  std::vector<double> g(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i) {
    if (degree == 0) {
      g[i] = 0.5 * (knots[i] + knots[i + 1]);
      continue;
    }
    double s = 0.0;
    for (int j = 1; j <= degree; ++j) s += knots[i + j];
    g[i] = s / degree;
  }
  return g;
}

}  // namespace implicitfit
