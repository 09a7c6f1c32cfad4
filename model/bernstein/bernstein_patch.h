// Bernstein–Bézier implicit patch over a tetrahedron (Guo §2), any degree k >= 1.
//
// Maths. The tetrahedron has vertices x1, x2, x3, x4; a point x has barycentric coordinates
// tau = (tau1, tau2, tau3, tau4), sum tau_i = 1, x = sum tau_i x_i. With the edge matrix
// E = [x1 - x4, x2 - x4, x3 - x4]:  (tau1, tau2, tau3) = E^-1 (x - x4),  tau4 = 1 - tau1 - tau2 -
// tau3 (negative outside the tetrahedron; the polynomial is evaluated everywhere). The patch is
//   f(x) = sum_{|lambda| = k} b_lambda B^k_lambda(tau),  B^k_lambda = k!/(lambda1!..lambda4!)
//   tau^lambda.
// Control points b_lambda are listed in docs/design.md order (multi-indices lexicographically
// descending); the position of lambda in that list does not depend on k:
//   index(lambda) = C(s1 + 2, 3) + C(s2 + 1, 2) + s3,  s1 = l2+l3+l4, s2 = l3+l4, s3 = l4,
// so the degree-(k-1) list is a prefix of the degree-k list.
// Evaluation is de Casteljau: b^{r-1}_lambda = sum_i tau_i b^r_{lambda+e_i}, k times (in place,
// ascending index, because index(lambda+e_i) >= index(lambda)). Stopping after k-1 and k-2
// steps gives the derivatives in the barycentric variables (f as a homogeneous polynomial):
//   df/dtau_i = k b^1_{e_i},   d2f/dtau_i dtau_j = k (k-1) b^2_{e_i+e_j},
// and in Cartesian coordinates, with D = d tau / d x (rows: rows of E^-1, and minus their sum),
//   grad f = D^T (df/dtau),   Hess f = D^T (d2f/dtau2) D.
// A flat tetrahedron (relative volume 6V / L^3 <= kFlatTolerance, L the longest edge; a regular
// tetrahedron has 1/sqrt(2)) is refused with std::invalid_argument.
// Templated on the scalar T (double, Ceres Jet, Dual3); the tetrahedron itself is double.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

namespace implicitfit {

// Number of control points of a degree-k patch: (k+1)(k+2)(k+3)/6.
constexpr long long NumBernsteinControlPoints(long long k) {
  return (k + 1) * (k + 2) * (k + 3) / 6;
}

// Position of a multi-index in the docs/design.md control-point list (independent of the degree;
// lambda1 = k - l2 - l3 - l4 is implied).
constexpr int BernsteinIndex(int l2, int l3, int l4) {
  const int s1 = l2 + l3 + l4, s2 = l3 + l4;
  return s1 * (s1 + 1) * (s1 + 2) / 6 + s2 * (s2 + 1) / 2 + l4;
}

// All multi-indices of degree k in docs/design.md order.
std::vector<std::array<int, 4>> BernsteinMultiIndices(int k);

class Tetrahedron {
 public:
  static constexpr double kFlatTolerance = 1e-9;
  // The reference tetrahedron x1 = e1, x2 = e2, x3 = e3, x4 = 0 (tau_{1..3} = x).
  Tetrahedron();
  // Throws std::invalid_argument when flat (see kFlatTolerance) or not finite.
  Tetrahedron(const Eigen::Vector3d& x1, const Eigen::Vector3d& x2, const Eigen::Vector3d& x3,
              const Eigen::Vector3d& x4);
  // From 12 numbers x1 x2 x3 x4.
  static Tetrahedron FromArray(const double* v);

  Eigen::Vector3d vertex(int i) const {
    return Eigen::Vector3d(v_[3 * i], v_[3 * i + 1], v_[3 * i + 2]);
  }
  // 6V / L^3 (1/sqrt(2) for a regular tetrahedron).
  double relative_volume() const { return relative_volume_; }
  // Edge matrix E = [x1 - x4, x2 - x4, x3 - x4] and D = d tau / dx (4 x 3).
  Eigen::Matrix3d EdgeMatrix() const;
  Eigen::Matrix<double, 4, 3> BarycentricJacobian() const;

  template <typename T>
  void Barycentric(const T* x, T* tau) const {
    const T d[3] = {x[0] - v_[9], x[1] - v_[10], x[2] - v_[11]};
    for (int i = 0; i < 3; ++i)
      tau[i] = inv_[3 * i] * d[0] + inv_[3 * i + 1] * d[1] + inv_[3 * i + 2] * d[2];
    tau[3] = 1.0 - tau[0] - tau[1] - tau[2];
  }

 private:
  void Init();
  std::array<double, 12> v_;   // x1 x2 x3 x4
  std::array<double, 9> inv_;  // E^-1, row-major
  double relative_volume_ = 0.0;
};

namespace bernstein_detail {

// In place: n(r) values of degree r -> n(r-1) values of degree r-1 (see the header comment).
template <typename T>
void DeCasteljauStep(int r, const T* tau, T* b) {
  for (int s1 = 0; s1 <= r - 1; ++s1)
    for (int s2 = 0; s2 <= s1; ++s2)
      for (int l4 = 0; l4 <= s2; ++l4) {
        const int l3 = s2 - l4, l2 = s1 - s2;
        const int j = BernsteinIndex(l2, l3, l4);
        b[j] = tau[0] * b[j] + tau[1] * b[BernsteinIndex(l2 + 1, l3, l4)] +
               tau[2] * b[BernsteinIndex(l2, l3 + 1, l4)] +
               tau[3] * b[BernsteinIndex(l2, l3, l4 + 1)];
      }
}

// Reduces the control points to degree `stop` at tau, in `work` (n(k) values; the first
// n(stop) hold the result).
template <typename T>
void ReduceTo(int k, int stop, const T* control_points, const T* tau, T* work) {
  const long long n = NumBernsteinControlPoints(k);
  for (long long i = 0; i < n; ++i) work[i] = control_points[i];
  for (int r = k; r > stop; --r) DeCasteljauStep(r, tau, work);
}

// Calls f(T* workspace of n(k) values): on the stack up to degree 4, else on the heap.
constexpr int kStackControlPoints = 35;
template <typename T, typename F>
auto WithWorkspace(int k, F f) {
  if (NumBernsteinControlPoints(k) <= kStackControlPoints) {
    std::array<T, kStackControlPoints> stack;
    return f(stack.data());
  }
  std::vector<T> heap(static_cast<size_t>(NumBernsteinControlPoints(k)));
  return f(heap.data());
}

}  // namespace bernstein_detail

class BernsteinPatch {
 public:
  // f(x). control_points: NumBernsteinControlPoints(k) values, docs/design.md order.
  template <typename T>
  static T Evaluate(int k, const Tetrahedron& tet, const T* control_points, const T* x) {
    T tau[4];
    tet.Barycentric(x, tau);
    return EvaluateBarycentric(k, control_points, tau);
  }

  template <typename T>
  static T EvaluateBarycentric(int k, const T* control_points, const T* tau) {
    return bernstein_detail::WithWorkspace<T>(k, [&](T* work) {
      bernstein_detail::ReduceTo(k, 0, control_points, tau, work);
      return work[0];
    });
  }

  // f, grad f (Cartesian) and, if hessian != nullptr, the Cartesian Hessian.
  template <typename T>
  static T Derivatives(int k, const Tetrahedron& tet, const T* control_points, const T* x,
                       Eigen::Matrix<T, 3, 1>* gradient,
                       Eigen::Matrix<T, 3, 3>* hessian = nullptr) {
    T tau[4];
    tet.Barycentric(x, tau);
    const Eigen::Matrix<double, 4, 3> D = tet.BarycentricJacobian();
    return bernstein_detail::WithWorkspace<T>(k, [&](T* work) {
      return DerivativesIn(k, D, control_points, tau, work, gradient, hessian);
    });
  }

 private:
  template <typename T>
  static T DerivativesIn(int k, const Eigen::Matrix<double, 4, 3>& D, const T* control_points,
                         const T* tau, T* w, Eigen::Matrix<T, 3, 1>* gradient,
                         Eigen::Matrix<T, 3, 3>* hessian) {
    if (hessian) {
      hessian->setZero();
      if (k >= 2) {
        bernstein_detail::ReduceTo(k, 2, control_points, tau, w);
        Eigen::Matrix<T, 4, 4> h;  // d2f/dtau_i dtau_j = k(k-1) b^2_{e_i+e_j}
        for (int i = 0; i < 4; ++i)
          for (int j = 0; j < 4; ++j) {
            int l[4] = {0, 0, 0, 0};
            ++l[i];
            ++l[j];
            h(i, j) = T(double(k) * (k - 1)) * w[BernsteinIndex(l[1], l[2], l[3])];
          }
        for (int a = 0; a < 3; ++a)
          for (int c = 0; c < 3; ++c) {
            T s = T(0.0);
            for (int i = 0; i < 4; ++i)
              for (int j = 0; j < 4; ++j) s += D(i, a) * h(i, j) * D(j, c);
            (*hessian)(a, c) = s;
          }
      }
    }
    bernstein_detail::ReduceTo(k, 1, control_points, tau, w);  // df/dtau_i = k b^1_{e_i}
    for (int a = 0; a < 3; ++a) {
      T s = T(0.0);
      for (int i = 0; i < 4; ++i) s += D(i, a) * (double(k) * w[i]);
      (*gradient)(a) = s;
    }
    bernstein_detail::DeCasteljauStep(1, tau, w);
    return w[0];
  }
};

}  // namespace implicitfit
