// Blobs (Blinn; textbook 22.2 "blobs", docs/maths.md TB-2): m centres c_i with signed weights a_i,
// kernel widths w_i and a threshold T, in the project sign (f < 0 inside)
//   f(x) = T - sum_i a_i k_i(|x - c_i|).
// Kernels (w_i > 0):
//   gaussian  k(R) = exp(-w R^2)                                  (Blinn; w = b_i, 1/length^2)
//   wyvill    k(R) = 1 - 4/9 s^6 + 17/9 s^4 - 22/9 s^2,  s = R/w  (Wyvill soft objects, R < w;
//                                                                   0 beyond: support radius w)
//   h_n       k(R) = 1 - H_n(2 R / w - 1)                         (Li & Phillips' step of order
//                                                                   n, model/blends/unit_step.h: 1 at the
//                                                                   centre, 0 for R >= w, C^(n-1))
// One Gaussian blob is the sphere R = sqrt(ln(a / T) / b); one compact blob with a = 2T is the
// sphere R = w / 2 (H_n(0) = 1/2). f is no distance; the fitter's residual f / |grad f| is one
// to first order. Where no kernel reaches (compact kernels), f = T and grad f = 0.
// Parameters: [c_1 .. c_m (3 m), a_1 .. a_m (m), w_1 .. w_m (m), T (1)].
#pragma once

#include <cmath>

#include "model/scalar.h"
#include "model/blends/unit_step.h"
#include "model/vec3.h"

namespace implicitfit {

enum class BlobKernel { kGaussian = 0, kWyvill = 1, kUnitStep = 2 };

struct BlobsEvaluator {
  static int NumParameters(int count) { return 5 * count + 1; }

  template <typename T>
  static T Evaluate(BlobKernel kernel, int order, int count, const T* p, const T* x) {
    using std::exp;
    using std::sqrt;
    const T* centers = p;
    const T* weights = p + 3 * count;
    const T* widths = p + 4 * count;
    T sum = T(0.0);
    for (int i = 0; i < count; ++i) {
      T d[3];
      Sub3(x, centers + 3 * i, d);
      const T r2 = Dot3(d, d);
      const T& w = widths[i];
      if (kernel == BlobKernel::kGaussian) {
        sum += weights[i] * exp(-w * r2);
        continue;
      }
      if (ValueOf(r2) >= ValueOf(w) * ValueOf(w)) continue;  // outside the support
      if (kernel == BlobKernel::kWyvill) {
        const T s2 = r2 / (w * w);
        sum += weights[i] * (1.0 + s2 * (-22.0 / 9.0 + s2 * (17.0 / 9.0 - 4.0 / 9.0 * s2)));
      } else {
        // R = sqrt(r2 + tiny): finite Jet derivatives at the centre (where d r2 = 0).
        const T r = sqrt(r2 + 1e-300);
        sum += weights[i] * (1.0 - UnitStep::OfOrder(order)(2.0 * r / w - 1.0));
      }
    }
    return p[5 * count] - sum;
  }
};

}  // namespace implicitfit
