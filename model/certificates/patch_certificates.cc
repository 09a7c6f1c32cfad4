#include "model/certificates/patch_certificates.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "model/bernstein/bernstein_conversion.h"
#include "model/certificates/convexity_certificate.h"
#include "model/certificates/symmetric_eigen3.h"

namespace implicitfit {
namespace {

// lgamma-free multinomial k!/(l1! l2! l3! l4!) as a double (exact for the degrees used here).
double Multinomial(const std::array<int, 4>& l) {
  double r = 1.0;
  int n = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 1; j <= l[i]; ++j) r = r * double(++n) / double(j);
  return r;
}

// Smallest eigenvalue over the A^mu of a degree-k patch (+inf for none), via the existing
// certificate's matrices.
template <typename F>
void ForEachGuoMatrix(int k, const double* b, F f) {
  const int m = k - 2;
  for (int s1 = 0; s1 <= m; ++s1)
    for (int s2 = 0; s2 <= s1; ++s2)
      for (int m4 = 0; m4 <= s2; ++m4) {
        double a[6];
        GuoMatrix(k, b, s1 - s2, s2 - m4, m4, a);
        f(a);
      }
}

double MaxAbs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

}  // namespace

CartesianMargin CartesianConvexityMargin(int k, const Tetrahedron& tet, const double* b) {
  CartesianMargin r;
  if (k < 2) return r;
  const Eigen::Matrix3d einv = tet.EdgeMatrix().inverse();
  double lmin = std::numeric_limits<double>::infinity();
  ForEachGuoMatrix(k, b, [&](const double a[6]) {
    Eigen::Matrix3d A;
    A << a[0], a[3], a[4], a[3], a[1], a[5], a[4], a[5], a[2];
    const Eigen::Matrix3d c = einv.transpose() * A * einv;
    const double s[6] = {c(0, 0),
                         c(1, 1),
                         c(2, 2),
                         0.5 * (c(0, 1) + c(1, 0)),
                         0.5 * (c(0, 2) + c(2, 0)),
                         0.5 * (c(1, 2) + c(2, 1))};
    const double l = SymmetricMinEigenvalue3(s);
    if (std::isnan(l) || l < lmin) lmin = l;
  });
  r.min_eigenvalue_cartesian = lmin;
  r.hessian_lower_bound = double(k) * (k - 1) * lmin;
  return r;
}

std::vector<double> BernsteinSquare(int k, const double* b) {
  const std::vector<std::array<int, 4>> lk = BernsteinMultiIndices(k);
  std::vector<double> out(static_cast<size_t>(NumBernsteinControlPoints(2 * k)), 0.0);
  std::vector<double> weight(lk.size());
  for (size_t i = 0; i < lk.size(); ++i) weight[i] = Multinomial(lk[i]) * b[i];
  for (size_t i = 0; i < lk.size(); ++i)
    for (size_t j = 0; j < lk.size(); ++j) {
      std::array<int, 4> nu;
      for (int a = 0; a < 4; ++a) nu[a] = lk[i][a] + lk[j][a];
      out[BernsteinIndex(nu[1], nu[2], nu[3])] += weight[i] * weight[j];
    }
  const std::vector<std::array<int, 4>> l2k = BernsteinMultiIndices(2 * k);
  for (size_t i = 0; i < l2k.size(); ++i) out[i] /= Multinomial(l2k[i]);
  return out;
}

FinslerCertificate CertifyFinsler(int k, const double* b, const FinslerOptions& options) {
  FinslerCertificate result;
  if (k < 2) {
    result.convex = k == 1;
    result.degree = k;
    return result;
  }
  const long long n = NumBernsteinControlPoints(k);
  std::vector<double> elevated(b, b + n);
  for (int d = k; d < 2 * k; ++d) elevated = ElevateDegree(d, elevated);
  const std::vector<double> square = BernsteinSquare(k, b);
  const double min_b = *std::min_element(b, b + n);
  const double largest = MaxAbs(std::vector<double>(b, b + n));
  if (largest == 0.0) return result;
  // Upper end of c: 1 + c min b > 0 keeps phi increasing on the range of f over T.
  const double c_max = min_b < 0.0 ? 0.999 / (-min_b) : 100.0 / largest;
  const int degree = 2 * k + options.extra_elevation;
  result.degree = degree;

  // Margin at c (normalised by max|b~|) and whether A^mu of f~ all pass the strict test.
  auto evaluate = [&](double c, bool* convex) {
    std::vector<double> ft(elevated.size());
    for (size_t i = 0; i < ft.size(); ++i) ft[i] = elevated[i] + 0.5 * c * square[i];
    for (int d = 2 * k; d < degree; ++d) ft = ElevateDegree(d, ft);
    const ConvexityCertificate cert = CertifyConvexity(degree, ft.data());
    *convex = cert.convex;
    const double scale = MaxAbs(ft);
    return scale > 0.0 ? cert.min_eigenvalue / scale : -std::numeric_limits<double>::infinity();
  };
  double best_c = 0.0;
  bool best_convex = false;
  double best = evaluate(0.0, &best_convex);
  auto consider = [&](double c) {
    bool convex = false;
    const double m = evaluate(c, &convex);
    if (convex && !best_convex) best = -std::numeric_limits<double>::infinity();
    if ((convex || !best_convex) && m > best) {
      best = m;
      best_c = c;
      best_convex = convex;
    }
    return m;
  };
  // Log grid over (c_max 1e-4, c_max], then golden section around the best grid point.
  int best_i = -1;
  double best_grid = -std::numeric_limits<double>::infinity();
  std::vector<double> grid;
  for (int i = 0; i < options.grid; ++i)
    grid.push_back(c_max * std::pow(1e-4, 1.0 - double(i) / std::max(1, options.grid - 1)));
  for (int i = 0; i < options.grid; ++i) {
    const double m = consider(grid[i]);
    if (m > best_grid) best_grid = m, best_i = i;
  }
  if (best_i >= 0) {
    double lo = best_i > 0 ? grid[best_i - 1] : 0.0;
    double hi = best_i + 1 < options.grid ? grid[best_i + 1] : c_max;
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    double f1 = consider(x1), f2 = consider(x2);
    for (int it = 0; it < options.golden_steps; ++it) {
      if (f1 < f2) {
        lo = x1, x1 = x2, f1 = f2;
        x2 = lo + g * (hi - lo);
        f2 = consider(x2);
      } else {
        hi = x2, x2 = x1, f2 = f1;
        x1 = hi - g * (hi - lo);
        f1 = consider(x1);
      }
    }
  }
  result.convex = best_convex;
  result.c = best_c;
  result.margin = best;
  return result;
}

std::vector<double> SubTetrahedronControlPoints(int k, const double* b, const double tau[4][4]) {
  const std::vector<std::array<int, 4>> l = BernsteinMultiIndices(k);
  const long long n = NumBernsteinControlPoints(k);
  std::vector<double> out(l.size()), work(static_cast<size_t>(n));
  for (size_t i = 0; i < l.size(); ++i) {
    std::copy(b, b + n, work.begin());
    int r = k;
    for (int v = 0; v < 4; ++v)
      for (int s = 0; s < l[i][v]; ++s) bernstein_detail::DeCasteljauStep(r--, tau[v], work.data());
    out[i] = work[0];
  }
  return out;
}

namespace {

bool LocallyConvex(int k, const std::vector<double>& b, const double tau[4][4], int depth,
                   int max_depth, LocalConvexity* r) {
  r->max_depth_reached = std::max(r->max_depth_reached, depth);
  const auto [lo, hi] = std::minmax_element(b.begin(), b.end());
  if (*lo > 0.0 || *hi < 0.0) {
    ++r->pieces_dropped;
    return true;
  }
  if (CertifyConvexity(k, b.data()).convex) {
    ++r->pieces_certified;
    return true;
  }
  if (depth >= max_depth) return false;
  // Bisect the longest edge (in barycentric coordinates of the patch's tetrahedron: the A^mu
  // test is affine invariant, only the shape of the pieces matters).
  int ei = 0, ej = 1;
  double longest = -1.0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      double d = 0.0;
      for (int a = 0; a < 4; ++a) d += (tau[i][a] - tau[j][a]) * (tau[i][a] - tau[j][a]);
      if (d > longest) longest = d, ei = i, ej = j;
    }
  double mid[4];
  for (int a = 0; a < 4; ++a) mid[a] = 0.5 * (tau[ei][a] + tau[ej][a]);
  for (int side = 0; side < 2; ++side) {
    double child[4][4];
    for (int v = 0; v < 4; ++v)
      for (int a = 0; a < 4; ++a) child[v][a] = tau[v][a];
    const int replaced = side == 0 ? ej : ei;
    for (int a = 0; a < 4; ++a) child[replaced][a] = mid[a];
    // Control points of the child from the parent's, with the child's vertices relative to
    // the parent: the unchanged vertices are unit vectors, the midpoint is (1/2, 1/2).
    double local[4][4] = {};
    for (int v = 0; v < 4; ++v) local[v][v] = 1.0;
    for (int a = 0; a < 4; ++a) local[replaced][a] = 0.0;
    local[replaced][ei] = local[replaced][ej] = 0.5;
    const std::vector<double> cb = SubTetrahedronControlPoints(k, b.data(), local);
    if (!LocallyConvex(k, cb, child, depth + 1, max_depth, r)) return false;
  }
  return true;
}

}  // namespace

LocalConvexity CertifyLocalConvexity(int k, const double* b, int max_depth) {
  LocalConvexity r;
  if (k < 2) {
    r.locally_convex = k == 1;
    return r;
  }
  const double tau[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
  r.locally_convex = LocallyConvex(k, std::vector<double>(b, b + NumBernsteinControlPoints(k)), tau,
                                   0, max_depth, &r);
  return r;
}

}  // namespace implicitfit
