#include "model/bernstein/bernstein_patch.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace implicitfit {

std::vector<std::array<int, 4>> BernsteinMultiIndices(int k) {
  std::vector<std::array<int, 4>> out;
  out.reserve(static_cast<size_t>(NumBernsteinControlPoints(k)));
  for (int l1 = k; l1 >= 0; --l1)
    for (int l2 = k - l1; l2 >= 0; --l2)
      for (int l3 = k - l1 - l2; l3 >= 0; --l3) out.push_back({l1, l2, l3, k - l1 - l2 - l3});
  return out;
}

Tetrahedron::Tetrahedron() : v_{1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0} { Init(); }

Tetrahedron::Tetrahedron(const Eigen::Vector3d& x1, const Eigen::Vector3d& x2,
                         const Eigen::Vector3d& x3, const Eigen::Vector3d& x4) {
  const Eigen::Vector3d* x[4] = {&x1, &x2, &x3, &x4};
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 3; ++c) v_[3 * i + c] = (*x[i])[c];
  Init();
}

Tetrahedron Tetrahedron::FromArray(const double* v) {
  return Tetrahedron(Eigen::Vector3d(v[0], v[1], v[2]), Eigen::Vector3d(v[3], v[4], v[5]),
                     Eigen::Vector3d(v[6], v[7], v[8]), Eigen::Vector3d(v[9], v[10], v[11]));
}

Eigen::Matrix3d Tetrahedron::EdgeMatrix() const {
  Eigen::Matrix3d e;
  for (int i = 0; i < 3; ++i) e.col(i) = vertex(i) - vertex(3);
  return e;
}

Eigen::Matrix<double, 4, 3> Tetrahedron::BarycentricJacobian() const {
  Eigen::Matrix<double, 4, 3> d;
  for (int i = 0; i < 3; ++i)
    for (int c = 0; c < 3; ++c) d(i, c) = inv_[3 * i + c];
  d.row(3) = -(d.row(0) + d.row(1) + d.row(2));
  return d;
}

void Tetrahedron::Init() {
  for (double c : v_)
    if (!std::isfinite(c))
      throw std::invalid_argument("tetrahedron: vertex coordinates must be finite");
  double longest = 0.0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) longest = std::max(longest, (vertex(i) - vertex(j)).norm());
  const Eigen::Matrix3d e = EdgeMatrix();
  const double det = e.determinant();
  relative_volume_ = longest > 0.0 ? std::abs(det) / (longest * longest * longest) : 0.0;
  if (!(relative_volume_ > kFlatTolerance)) {
    std::ostringstream s;
    s << "tetrahedron is degenerate (flat): relative volume 6V/L^3 = " << relative_volume_
      << " must exceed " << kFlatTolerance << " (a regular tetrahedron has 0.707)";
    throw std::invalid_argument(s.str());
  }
  const Eigen::Matrix3d inv = e.inverse();
  for (int i = 0; i < 3; ++i)
    for (int c = 0; c < 3; ++c) inv_[3 * i + c] = inv(i, c);
}

}  // namespace implicitfit
