// Fit4CAD's torus ground truth. The implicit file gives a torus as 35 quartic coefficients in an
// order the data set does not document; the parametric file (NAME_parametric.txt, the same
// "PrimitiveK:=[Torus, [...]]" lines, read by datasets/generators/ground_truth.h's
// ReadFit4CadCoefficients) gives 18 numbers, six vectors a, b, c, d, e, o, of the
// parameterisation
//   P(u, v) = o + a cos u + b sin u + cos v (c cos u + d sin u) + e sin v,
// with a = R e1, b = R e2, c = r e1, d = r e2, e = r e3 for an orthonormal frame (e1, e2, e3):
// centre o, axis e3 (a x b, direction only), major radius R = |a|, minor radius r = |e|.
// Read this way, the noise-free labelled points of PC145 (one torus, 1 500 points), PC124 and
// PC155 lie on the torus to rounding (tests/datasets/generators/fit4cad_torus_test.cc).
#pragma once

#include <string>
#include <vector>

#include "model/model.h"

namespace implicitfit {

// A one-node torus model (exact signed distance, model/primitives/torus.h) from the 18 parametric numbers.
// Throws std::invalid_argument when there are not 18 numbers or the vectors are not such a
// frame (|a| != |b|, |c| = |d| = |e|, a parallel to c, b to d, e orthogonal to a and b, to 1e-6
// relative).
Model Fit4CadTorusFromParametric(const std::vector<double>& numbers);

}  // namespace implicitfit
