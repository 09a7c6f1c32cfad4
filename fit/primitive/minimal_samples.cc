#include "fit/primitive/minimal_samples.h"

#include <Eigen/Dense>
#include <cmath>

namespace implicitfit {

bool PlaneFromSample(const Vec3& p, const Vec3& n, std::vector<double>* params) {
  if (!(n.norm() > 0)) return false;
  const Vec3 u = n.normalized();
  *params = {u.x(), u.y(), u.z(), u.dot(p)};
  return true;
}

bool SphereFromSample(const Vec3 p[2], const Vec3 n[2], std::vector<double>* params) {
  // Closest points of lines p0 + s n0 and p1 + t n1.
  const Vec3 w = p[0] - p[1];
  const double a = n[0].dot(n[0]), b = n[0].dot(n[1]), c = n[1].dot(n[1]);
  const double d = n[0].dot(w), e = n[1].dot(w);
  const double den = a * c - b * b;
  if (den < 1e-6 * a * c) return false;  // parallel normal lines
  const double s = (b * e - c * d) / den, t = (a * e - b * d) / den;
  const Vec3 center = 0.5 * ((p[0] + s * n[0]) + (p[1] + t * n[1]));
  const double r = 0.5 * ((p[0] - center).norm() + (p[1] - center).norm());
  if (!(r > 0) || !std::isfinite(r)) return false;
  *params = {center.x(), center.y(), center.z(), r};
  return true;
}

bool CylinderFromSample(const Vec3 p[2], const Vec3 n[2], std::vector<double>* params) {
  Vec3 axis = n[0].cross(n[1]);
  if (axis.norm() < 1e-3) return false;
  axis.normalize();
  // Project into the plane orthogonal to the axis and intersect the two normal lines there.
  const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - axis * axis.transpose();
  const Vec3 q0 = P * p[0], q1 = P * p[1], m0 = (P * n[0]).normalized(),
             m1 = (P * n[1]).normalized();
  const Vec3 w = q0 - q1;
  const double b = m0.dot(m1), d = m0.dot(w), e = m1.dot(w);
  const double den = 1.0 - b * b;
  if (den < 1e-6) return false;
  const double s = (b * e - d) / den;
  const Vec3 point = q0 + s * m0;
  const double r = 0.5 * ((q0 - point).norm() + (q1 - point).norm());
  if (!(r > 0) || !std::isfinite(r)) return false;
  *params = {point.x(), point.y(), point.z(), axis.x(), axis.y(), axis.z(), r};
  return true;
}

bool ConeFromSample(const Vec3 p[3], const Vec3 n[3], std::vector<double>* params) {
  Eigen::Matrix3d A;
  Eigen::Vector3d rhs;
  for (int i = 0; i < 3; ++i) {
    A.row(i) = n[i].transpose();
    rhs[i] = n[i].dot(p[i]);
  }
  Eigen::FullPivLU<Eigen::Matrix3d> lu(A);
  if (lu.rank() < 3) return false;
  const Vec3 apex = lu.solve(rhs);
  // Normals may be inward or outward: use them up to sign, consistently with the first.
  Vec3 m[3];
  for (int i = 0; i < 3; ++i) m[i] = n[i].normalized();
  Vec3 axis = (m[0] - m[1]).cross(m[0] - m[2]);
  if (axis.norm() < 1e-6) return false;
  axis.normalize();
  double side = 0.0;
  for (int i = 0; i < 3; ++i) side += (p[i] - apex).dot(axis);
  if (side < 0) axis = -axis;
  const double sin_alpha = std::abs(m[0].dot(axis));
  const double alpha = std::asin(std::min(1.0, sin_alpha));
  if (!(alpha > 1e-3 && alpha < M_PI / 2 - 1e-3)) return false;
  *params = {apex.x(), apex.y(), apex.z(), axis.x(), axis.y(), axis.z(), alpha};
  return true;
}

bool TorusFromSample(const std::vector<Vec3>& p, const std::vector<Vec3>& n,
                     std::vector<double>* params) {
  const int k = static_cast<int>(p.size());
  if (k < 5) return false;
  Eigen::MatrixXd M(k, 6);
  for (int i = 0; i < k; ++i) {
    const Vec3 u = n[i].normalized();
    M.block<1, 3>(i, 0) = p[i].cross(u).transpose();  // multiplies d
    M.block<1, 3>(i, 3) = u.transpose();              // multiplies m
  }
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(M, Eigen::ComputeFullV);
  const Eigen::Matrix<double, 6, 1> v = svd.matrixV().col(5);
  Vec3 d = v.head<3>(), m = v.tail<3>();
  const double dn = d.norm();
  if (dn < 1e-9) return false;
  d /= dn;
  m /= dn;
  const Vec3 q = d.cross(m);  // closest point of the axis line to the origin
  // Meridian coordinates and the linear fit of (R, h0, r).
  Eigen::MatrixXd A(2 * k, 3);
  Eigen::VectorXd b(2 * k);
  for (int i = 0; i < k; ++i) {
    const Vec3 rel = p[i] - q;
    const double h = rel.dot(d);
    Vec3 radial = rel - h * d;
    const double rho = radial.norm();
    if (rho < 1e-12) return false;
    radial /= rho;
    const Vec3 u = n[i].normalized();
    A.row(2 * i) << 1.0, 0.0, u.dot(radial);
    b[2 * i] = rho;
    A.row(2 * i + 1) << 0.0, 1.0, u.dot(d);
    b[2 * i + 1] = h;
  }
  const Eigen::Vector3d x = A.colPivHouseholderQr().solve(b);
  const double R = x[0], h0 = x[1], r = std::abs(x[2]);  // |r|: inward normals give r < 0
  if (!(R > 0 && r > 0) || !std::isfinite(R + r)) return false;
  const Vec3 c = q + h0 * d;
  *params = {c.x(), c.y(), c.z(), d.x(), d.y(), d.z(), R, r};
  return true;
}

}  // namespace implicitfit
