#include "model/certificates/convexity_certificate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "model/bernstein/bernstein_patch.h"
#include "model/certificates/symmetric_eigen3.h"

namespace implicitfit {

void GuoMatrix(int k, const double* b, int m2, int m3, int m4, double a[6]) {
  (void)k;  // the index of a multi-index does not depend on the degree
  // b(mu + e_i + e_j) for i, j in 1..4 (0-based 0..3); e_1 only changes the implied first entry.
  auto at = [&](int i, int j) {
    int l[4] = {0, m2, m3, m4};
    ++l[i];
    ++l[j];
    return b[BernsteinIndex(l[1], l[2], l[3])];
  };
  const double b44 = at(3, 3);
  const double b4[3] = {at(0, 3), at(1, 3), at(2, 3)};
  auto entry = [&](int i, int j) { return at(i, j) + b44 - b4[i] - b4[j]; };
  a[0] = entry(0, 0);
  a[1] = entry(1, 1);
  a[2] = entry(2, 2);
  a[3] = entry(0, 1);
  a[4] = entry(0, 2);
  a[5] = entry(1, 2);
}

ConvexityCertificate CertifyConvexity(int k, const double* control_points) {
  ConvexityCertificate result;
  if (k < 2) {
    result.convex = k == 1;
    return result;
  }
  // Control points near the ends of the double range (A^mu sums four of them and could
  // overflow): certify 2^-e b, exactly scaled, and scale the margin back.
  const long long n = NumBernsteinControlPoints(k);
  double largest = 0.0;
  for (long long i = 0; i < n; ++i) largest = std::max(largest, std::abs(control_points[i]));
  if (largest > 1e150 || (largest > 0.0 && largest < 1e-150)) {
    const int e = std::ilogb(largest);
    std::vector<double> scaled(control_points, control_points + n);
    for (double& b : scaled) b = std::ldexp(b, -e);
    result = CertifyConvexity(k, scaled.data());
    result.min_eigenvalue = std::ldexp(result.min_eigenvalue, e);
    return result;
  }
  result.convex = true;
  result.min_eigenvalue = std::numeric_limits<double>::infinity();
  const int m = k - 2;
  for (int s1 = 0; s1 <= m; ++s1)
    for (int s2 = 0; s2 <= s1; ++s2)
      for (int m4 = 0; m4 <= s2; ++m4) {
        double a[6];
        GuoMatrix(k, control_points, s1 - s2, s2 - m4, m4, a);
        const double lmin = SymmetricMinEigenvalue3(a);
        const double frobenius = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2] +
                                           2.0 * (a[3] * a[3] + a[4] * a[4] + a[5] * a[5]));
        if (!(lmin > kConvexityTolerance * frobenius)) result.convex = false;
        if (std::isnan(lmin) || lmin < result.min_eigenvalue) result.min_eigenvalue = lmin;
        ++result.num_matrices;
      }
  return result;
}

}  // namespace implicitfit
