#include "model/bernstein/bernstein_conversion.h"

#include <Eigen/LU>
#include <stdexcept>

namespace implicitfit {
namespace {

Eigen::Matrix4d HomogeneousVertices(const Tetrahedron& tet) {
  Eigen::Matrix4d x;
  for (int i = 0; i < 4; ++i) x.col(i) << tet.vertex(i), 1.0;
  return x;
}

}  // namespace

std::vector<double> QuadricToBernstein(const CartesianQuadric& q, const Tetrahedron& tet, int k) {
  if (k < 2) throw std::invalid_argument("QuadricToBernstein: degree must be >= 2");
  Eigen::Matrix4d g;
  g << q.A, q.b, q.b.transpose(), q.c;
  const Eigen::Matrix4d x = HomogeneousVertices(tet);
  const Eigen::Matrix4d bm = x.transpose() * g * x;
  std::vector<double> cp;
  for (const auto& l : BernsteinMultiIndices(2)) {
    int ij[2], n = 0;
    for (int i = 0; i < 4; ++i)
      for (int m = 0; m < l[i]; ++m) ij[n++] = i;
    cp.push_back(bm(ij[0], ij[1]));
  }
  for (int d = 2; d < k; ++d) cp = ElevateDegree(d, cp);
  return cp;
}

CartesianQuadric BernsteinToQuadric(const double* control_points, const Tetrahedron& tet) {
  Eigen::Matrix4d bm;
  const auto indices = BernsteinMultiIndices(2);
  for (size_t n = 0; n < indices.size(); ++n) {
    int ij[2], m = 0;
    for (int i = 0; i < 4; ++i)
      for (int r = 0; r < indices[n][i]; ++r) ij[m++] = i;
    bm(ij[0], ij[1]) = bm(ij[1], ij[0]) = control_points[n];
  }
  const Eigen::Matrix4d xinv = HomogeneousVertices(tet).inverse();
  const Eigen::Matrix4d g = xinv.transpose() * bm * xinv;
  CartesianQuadric q;
  q.A = 0.5 * (g.topLeftCorner<3, 3>() + g.topLeftCorner<3, 3>().transpose());
  q.b = 0.5 * (g.topRightCorner<3, 1>() + g.bottomLeftCorner<1, 3>().transpose());
  q.c = g(3, 3);
  return q;
}

std::vector<double> ElevateDegree(int k, const std::vector<double>& control_points) {
  if (k < 0 || static_cast<long long>(control_points.size()) != NumBernsteinControlPoints(k))
    throw std::invalid_argument("ElevateDegree: wrong number of control points for the degree");
  std::vector<double> out;
  for (const auto& l : BernsteinMultiIndices(k + 1)) {
    double s = 0.0;
    for (int i = 0; i < 4; ++i) {
      if (l[i] == 0) continue;
      int m[4] = {l[0], l[1], l[2], l[3]};
      --m[i];
      s += l[i] * control_points[BernsteinIndex(m[1], m[2], m[3])];
    }
    out.push_back(s / (k + 1));
  }
  return out;
}

Eigen::MatrixXd ReexpressionMatrix(int k, const Eigen::Matrix4d& a) {
  if (k < 0) throw std::invalid_argument("ReexpressionMatrix: degree must be >= 0");
  const long long n = NumBernsteinControlPoints(k);
  const auto multi = BernsteinMultiIndices(k);
  Eigen::MatrixXd m(n, n);
  // w: rows = control points of the current degree r, columns = the original n control points.
  Eigen::MatrixXd w(n, n);
  for (long long row = 0; row < n; ++row) {
    const auto& lambda = multi[static_cast<size_t>(row)];
    w.setIdentity();
    int r = k;
    for (int vertex = 0; vertex < 4; ++vertex)
      for (int rep = 0; rep < lambda[vertex]; ++rep, --r) {
        const double t[4] = {a(vertex, 0), a(vertex, 1), a(vertex, 2), a(vertex, 3)};
        // One de Casteljau step from degree r to r - 1 at t (ascending index, in place).
        for (int s1 = 0; s1 <= r - 1; ++s1)
          for (int s2 = 0; s2 <= s1; ++s2)
            for (int l4 = 0; l4 <= s2; ++l4) {
              const int l3 = s2 - l4, l2 = s1 - s2;
              const int j = BernsteinIndex(l2, l3, l4);
              w.row(j) = t[0] * w.row(j) + t[1] * w.row(BernsteinIndex(l2 + 1, l3, l4)) +
                         t[2] * w.row(BernsteinIndex(l2, l3 + 1, l4)) +
                         t[3] * w.row(BernsteinIndex(l2, l3, l4 + 1));
            }
      }
    m.row(row) = w.row(0);
  }
  return m;
}

}  // namespace implicitfit
