// An independent, deliberately naive Bernstein–Bézier implementation, used only as a test
// oracle. It shares no code with model/: multi-indices are enumerated here from docs/design.md's
// wording (lambda1 from k down to 0, then lambda2, then lambda3, lambda4 the rest) and looked up
// in a std::map; barycentric coordinates solve the 4x4 system [x_i; 1] tau = [x; 1] by
// Eigen's FullPivLU; f is the explicit multinomial sum k!/prod(lambda_i!) prod tau_i^lambda_i;
// the A^mu matrices are written out entry by entry from docs/design.md's formula.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace oracle {

using MultiIndex = std::array<int, 4>;

inline std::vector<MultiIndex> DesignOrder(int k) {
  std::vector<MultiIndex> out;
  for (int a = k; a >= 0; --a)
    for (int b = k - a; b >= 0; --b)
      for (int c = k - a - b; c >= 0; --c) out.push_back({a, b, c, k - a - b - c});
  return out;
}

// Control points as a map multi-index -> value.
inline std::map<MultiIndex, double> ByIndex(int k, const std::vector<double>& b) {
  std::map<MultiIndex, double> m;
  const std::vector<MultiIndex> order = DesignOrder(k);
  for (size_t i = 0; i < order.size(); ++i) m[order[i]] = b.at(i);
  return m;
}

inline Eigen::Vector4d Barycentric(const std::array<Eigen::Vector3d, 4>& v,
                                   const Eigen::Vector3d& x) {
  Eigen::Matrix4d m;
  for (int i = 0; i < 4; ++i) m.col(i) << v[i], 1.0;
  Eigen::Vector4d rhs;
  rhs << x, 1.0;
  return m.fullPivLu().solve(rhs);
}

inline double Factorial(int n) { return n <= 1 ? 1.0 : n * Factorial(n - 1); }

inline double Bernstein(const MultiIndex& l, const Eigen::Vector4d& tau) {
  const int k = l[0] + l[1] + l[2] + l[3];
  double v = Factorial(k);
  for (int i = 0; i < 4; ++i) v *= std::pow(tau[i], l[i]) / Factorial(l[i]);
  return v;
}

// f(x); with magnitude != nullptr also sum |b_lambda B_lambda(tau)|, the scale of the rounding
// error of any evaluation of the sum (it grows like |tau|^k far outside the tetrahedron).
inline double Patch(int k, const std::vector<double>& b, const std::array<Eigen::Vector3d, 4>& v,
                    const Eigen::Vector3d& x, double* magnitude = nullptr) {
  const Eigen::Vector4d tau = Barycentric(v, x);
  const std::vector<MultiIndex> order = DesignOrder(k);
  double f = 0.0, m = 0.0;
  for (size_t i = 0; i < order.size(); ++i) {
    f += b[i] * Bernstein(order[i], tau);
    m += std::abs(b[i] * Bernstein(order[i], tau));
  }
  if (magnitude) *magnitude = m;
  return f;
}

// All A^mu, |mu| = k - 2, built longhand.
inline std::vector<Eigen::Matrix3d> GuoMatrices(int k, const std::vector<double>& b) {
  const std::map<MultiIndex, double> c = ByIndex(k, b);
  std::vector<Eigen::Matrix3d> out;
  for (const MultiIndex& mu : DesignOrder(k - 2)) {
    auto at = [&](int i, int j) {
      MultiIndex l = mu;
      ++l[i];
      ++l[j];
      return c.at(l);
    };
    Eigen::Matrix3d a;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) a(i, j) = at(i, j) + at(3, 3) - at(i, 3) - at(j, 3);
    out.push_back(a);
  }
  return out;
}

// Smallest eigenvalue over all A^mu by Eigen's iterative solver, and the largest Frobenius norm.
struct Certificate {
  bool convex = true;
  double min_eigenvalue = INFINITY;
  double scale = 0.0;
};
inline Certificate Certify(int k, const std::vector<double>& b, double tolerance = 1e-12) {
  Certificate c;
  for (const Eigen::Matrix3d& a : GuoMatrices(k, b)) {
    const double lmin = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(a).eigenvalues()(0);
    c.min_eigenvalue = std::min(c.min_eigenvalue, lmin);
    c.scale = std::max(c.scale, a.norm());
    if (!(lmin > tolerance * a.norm())) c.convex = false;
  }
  return c;
}

}  // namespace oracle
