// Scalar helpers shared by every evaluator. The evaluators are templated on the scalar T so that
// double, Ceres Jets and the model's own Dual3 flow through the same code. model/ must not
// include Ceres, so the value part of a dual number is read through its member `a` (both Jet
// and Dual3 name it so) by overload resolution, without naming either type.
#pragma once

#include <type_traits>
#include <utility>

namespace implicitfit {

inline double ValueOf(double x) { return x; }

// Ceres Jet, Dual3: value in member `a`.
template <typename T>
auto ValueOf(const T& x) -> decltype(ValueOf(x.a)) {
  return ValueOf(x.a);
}

}  // namespace implicitfit
