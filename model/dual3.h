// Forward-mode dual number with a 3-vector of derivatives: x = a + v . (dx, dy, dz). Used by
// Model::Gradient to get grad f in one evaluation of the templated evaluators.
// Why not Eigen::AutoDiffScalar: its expression-template derivatives do not survive the
// evaluators' "T result = expression" pattern (compile errors deep in Eigen); why not
// ceres::Jet: model/ must not depend on Ceres. The member is named `a` like a Jet so
// ValueOf() (model/scalar.h) reads it the same way.
#pragma once

#include <Eigen/Core>
#include <cmath>

namespace implicitfit {

struct Dual3 {
  double a = 0.0;
  Eigen::Vector3d v = Eigen::Vector3d::Zero();

  Dual3() = default;
  Dual3(double value) : a(value) {}  // NOLINT: implicit from constants, like ceres::Jet
  Dual3(double value, const Eigen::Vector3d& derivative) : a(value), v(derivative) {}

  Dual3& operator+=(const Dual3& o) {
    a += o.a;
    v += o.v;
    return *this;
  }
  Dual3& operator-=(const Dual3& o) {
    a -= o.a;
    v -= o.v;
    return *this;
  }
  Dual3& operator*=(const Dual3& o) {
    v = v * o.a + a * o.v;
    a *= o.a;
    return *this;
  }
  Dual3& operator/=(const Dual3& o) {
    *this = Dual3(a / o.a, (v - a / o.a * o.v) / o.a);
    return *this;
  }
};

inline Dual3 operator-(const Dual3& x) { return Dual3(-x.a, -x.v); }
inline Dual3 operator+(Dual3 x, const Dual3& y) { return x += y; }
inline Dual3 operator-(Dual3 x, const Dual3& y) { return x -= y; }
inline Dual3 operator*(Dual3 x, const Dual3& y) { return x *= y; }
inline Dual3 operator/(Dual3 x, const Dual3& y) { return x /= y; }
inline Dual3 operator+(Dual3 x, double y) {
  x.a += y;
  return x;
}
inline Dual3 operator+(double y, Dual3 x) {
  x.a += y;
  return x;
}
inline Dual3 operator-(Dual3 x, double y) {
  x.a -= y;
  return x;
}
inline Dual3 operator-(double y, const Dual3& x) { return Dual3(y - x.a, -x.v); }
inline Dual3 operator*(const Dual3& x, double y) { return Dual3(x.a * y, x.v * y); }
inline Dual3 operator*(double y, const Dual3& x) { return Dual3(x.a * y, x.v * y); }
inline Dual3 operator/(const Dual3& x, double y) { return Dual3(x.a / y, x.v / y); }
inline Dual3 operator/(double y, const Dual3& x) { return Dual3(y / x.a, -y / (x.a * x.a) * x.v); }

inline bool operator<(const Dual3& x, const Dual3& y) { return x.a < y.a; }
inline bool operator>(const Dual3& x, const Dual3& y) { return x.a > y.a; }
inline bool operator<=(const Dual3& x, const Dual3& y) { return x.a <= y.a; }
inline bool operator>=(const Dual3& x, const Dual3& y) { return x.a >= y.a; }

inline Dual3 sqrt(const Dual3& x) {
  const double s = std::sqrt(x.a);
  return Dual3(s, x.v / (2.0 * s));
}
inline Dual3 sin(const Dual3& x) { return Dual3(std::sin(x.a), std::cos(x.a) * x.v); }
inline Dual3 cos(const Dual3& x) { return Dual3(std::cos(x.a), -std::sin(x.a) * x.v); }
inline Dual3 abs(const Dual3& x) { return x.a < 0.0 ? -x : x; }
inline Dual3 exp(const Dual3& x) {
  const double e = std::exp(x.a);
  return Dual3(e, e * x.v);
}

}  // namespace implicitfit
