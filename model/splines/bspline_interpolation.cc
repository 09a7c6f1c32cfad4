#include "model/splines/bspline_interpolation.h"

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <cmath>
#include <stdexcept>

namespace implicitfit {

InterpolatedCurve InterpolateCubicBSpline(const std::vector<Eigen::Vector3d>& points,
                                          const InterpolationEnds& ends,
                                          std::vector<double> parameters) {
  const int m = static_cast<int>(points.size()) - 1;
  if (m < 1) throw std::invalid_argument("interpolation: at least 2 points are needed");
  if (m + 3 > SplineLimits::kMaxControlPointsPerAxis)
    throw std::invalid_argument("interpolation: too many points");
  for (const Eigen::Vector3d& q : points)
    if (!q.allFinite()) throw std::invalid_argument("interpolation: a point is not finite");
  if (parameters.empty()) {  // chord length
    parameters.push_back(0.0);
    for (int j = 1; j <= m; ++j)
      parameters.push_back(parameters.back() + (points[j] - points[j - 1]).norm());
  }
  if (static_cast<int>(parameters.size()) != m + 1)
    throw std::invalid_argument("interpolation: one parameter per point");
  for (int j = 1; j <= m; ++j)
    if (!(parameters[j] > parameters[j - 1]) || !std::isfinite(parameters[j]))
      throw std::invalid_argument(
          "interpolation: parameters must increase strictly (two consecutive points coincide?)");
  const Eigen::Vector3d d[2] = {ends.start, ends.end};
  if (ends.kind == EndCondition::kDerivative && !(d[0].allFinite() && d[1].allFinite()))
    throw std::invalid_argument("interpolation: end derivatives must be finite");

  InterpolatedCurve out;
  SplineStructure& s = out.structure;
  const int p = 3, n = m + 3;
  s.degree[0] = p;
  s.count[0] = n;
  s.knots[0].assign(p + 1, parameters.front());
  for (int j = 1; j < m; ++j) s.knots[0].push_back(parameters[j]);
  s.knots[0].insert(s.knots[0].end(), p + 1, parameters.back());

  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, 3);
  // Rows: C(t_0) = Q_0, the start condition, C(t_j) = Q_j (j = 1..m-1), the end condition,
  // C(t_m) = Q_m: the banded order of the unknowns.
  auto add_row = [&](int row, double t, int order, const Eigen::Vector3d& value) {
    const int span = FindSpan(p, n, s.knots[0].data(), t);
    double ders[3 * (kMaxSplineDegree + 1)];
    BasisDerivatives(span, t, p, 2, s.knots[0].data(), ders);
    for (int j = 0; j <= p; ++j)
      if (ders[order * (p + 1) + j] != 0.0)
        entries.emplace_back(row, span - p + j, ders[order * (p + 1) + j]);
    rhs.row(row) = value.transpose();
  };
  const int end_order = ends.kind == EndCondition::kDerivative ? 1 : 2;
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  add_row(0, parameters[0], 0, points[0]);
  add_row(1, parameters[0], end_order, end_order == 1 ? d[0] : zero);
  for (int j = 1; j < m; ++j) add_row(j + 1, parameters[j], 0, points[j]);
  add_row(m + 1, parameters[m], end_order, end_order == 1 ? d[1] : zero);
  add_row(m + 2, parameters[m], 0, points[m]);
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  lu.compute(a);
  if (lu.info() != Eigen::Success)
    throw std::invalid_argument("interpolation: the system is singular");
  const Eigen::MatrixXd c = lu.solve(rhs);
  out.control_points.resize(3 * static_cast<size_t>(n));
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) out.control_points[3 * i + k] = c(i, k);
  out.parameters = parameters;
  return out;
}

}  // namespace implicitfit
