// Morph (textbook 22.2 morphing; docs/maths.md TB-4) and complement (textbook CSG, TB-1):
//   morph:       m(x) = t f_A(x) + (1 - t) f_B(x),   0 <= t <= 1  (t = 1: A, t = 0: B)
//   complement:  c(x) = -f_A(x)                        (inside and outside swap)
// Both are exact in the sense of the project sign (f < 0 inside): the complement of a signed
// distance is a signed distance; the morph of two is not in general (|grad m| <= 1).
// Morph parameters: [t] (1); the tree fitter keeps t in (0, 1) by t = 1 / (1 + exp(-b)).
// Complement parameters: none.
#pragma once

namespace implicitfit {

template <typename T>
T Morph(const T& t, const T& a, const T& b) {
  // Written as t a + (1 - t) b (not b + t (a - b)) so t = 1 and t = 0 give A and B exactly.
  return t * a + (1.0 - t) * b;
}

}  // namespace implicitfit
