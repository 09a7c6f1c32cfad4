#include "fit/detect/patch_hypotheses.h"

#include <Eigen/Dense>
#include <cmath>

namespace implicitfit {

using Eigen::Matrix3d;
using Eigen::Vector3d;

bool PlaneFromPatch(const std::vector<Vector3d>& p, const std::vector<Vector3d>&,
                    std::vector<double>* params) {
  if (p.size() < 3) return false;
  Vector3d mean = Vector3d::Zero();
  for (const auto& x : p) mean += x;
  mean /= static_cast<double>(p.size());
  Matrix3d c = Matrix3d::Zero();
  for (const auto& x : p) c += (x - mean) * (x - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Matrix3d> eig(c);
  if (eig.info() != Eigen::Success || !(eig.eigenvalues()[1] > 0)) return false;
  const Vector3d normal = eig.eigenvectors().col(0);
  *params = {normal[0], normal[1], normal[2], normal.dot(mean)};
  return true;
}

bool SphereFromPatch(const std::vector<Vector3d>& p, const std::vector<Vector3d>& n,
                     std::vector<double>* params) {
  if (p.size() < 3 || n.size() != p.size()) return false;
  Matrix3d a = Matrix3d::Zero();
  Vector3d b = Vector3d::Zero();
  for (size_t i = 0; i < p.size(); ++i) {
    const Matrix3d proj = Matrix3d::Identity() - n[i] * n[i].transpose();
    a += proj;
    b += proj * p[i];
  }
  const Eigen::SelfAdjointEigenSolver<Matrix3d> eig(a);
  // Normals nearly parallel: the smallest eigenvalue of sum (I - n n^T) vanishes.
  if (eig.info() != Eigen::Success || !(eig.eigenvalues()[0] > 1e-6 * eig.eigenvalues()[2]))
    return false;
  const Vector3d c = a.ldlt().solve(b);
  double r = 0;
  for (const auto& x : p) r += (x - c).norm();
  r /= static_cast<double>(p.size());
  if (!c.allFinite() || !(r > 0)) return false;
  *params = {c[0], c[1], c[2], r};
  return true;
}

bool CylinderFromPatch(const std::vector<Vector3d>& p, const std::vector<Vector3d>& n,
                       std::vector<double>* params) {
  if (p.size() < 4 || n.size() != p.size()) return false;
  Matrix3d m = Matrix3d::Zero();
  for (const auto& v : n) m += v * v.transpose();
  const Eigen::SelfAdjointEigenSolver<Matrix3d> eig(m);
  // The normals must span a plane (second eigenvalue clearly above the smallest).
  if (eig.info() != Eigen::Success || !(eig.eigenvalues()[1] > 1e-4 * eig.eigenvalues()[2]))
    return false;
  const Vector3d a = eig.eigenvectors().col(0), e1 = eig.eigenvectors().col(1),
                 e2 = eig.eigenvectors().col(2);
  Vector3d mean = Vector3d::Zero();
  for (const auto& x : p) mean += x;
  mean /= static_cast<double>(p.size());
  Eigen::MatrixXd lhs(p.size(), 3);
  Eigen::VectorXd rhs(p.size());
  for (size_t i = 0; i < p.size(); ++i) {
    const double u = e1.dot(p[i] - mean), v = e2.dot(p[i] - mean);
    lhs.row(i) << u, v, 1.0;
    rhs[i] = -(u * u + v * v);
  }
  const Vector3d def = lhs.colPivHouseholderQr().solve(rhs);
  const double cu = -def[0] / 2, cv = -def[1] / 2, r2 = cu * cu + cv * cv - def[2];
  if (!def.allFinite() || !(r2 > 0)) return false;
  const Vector3d q = mean + cu * e1 + cv * e2;
  *params = {q[0], q[1], q[2], a[0], a[1], a[2], std::sqrt(r2)};
  return true;
}

}  // namespace implicitfit
