#include "fit/minimum_zone.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "fit/primitive_tangent.h"

namespace implicitfit {
namespace {

struct Linearisation {
  Eigen::MatrixXd basis;  // P x k
  Eigen::VectorXd d;      // signed distances of every point
  Eigen::MatrixXd g;      // N x k local gradients
};

Linearisation Linearise(NodeType kind, const std::vector<double>& p,
                        const std::vector<Eigen::Vector3d>& x) {
  const int n = static_cast<int>(x.size()), P = static_cast<int>(p.size());
  Linearisation l;
  l.basis = TangentBasis(kind, p);
  l.d.resize(n);
  l.g.resize(n, l.basis.cols());
  std::vector<double> dp(P);
  for (int i = 0; i < n; ++i) {
    l.d[i] = PrimitiveSignedDistance(kind, p.data(), x[i].data(), dp.data());
    l.g.row(i) = Eigen::Map<const Eigen::RowVectorXd>(dp.data(), P) * l.basis;
  }
  return l;
}

// A_S: columns [sigma_i g_i; 1] of the reference.
Eigen::MatrixXd ReferenceMatrix(const Linearisation& l, const std::vector<int>& S,
                                const std::vector<int>& sigma) {
  const int k = static_cast<int>(l.g.cols()), m = static_cast<int>(S.size());
  Eigen::MatrixXd A(k + 1, m);
  for (int c = 0; c < m; ++c) {
    A.block(0, c, k, 1) = sigma[c] * l.g.row(S[c]).transpose();
    A(k, c) = 1.0;
  }
  return A;
}

Eigen::VectorXd UnitLast(int size) {
  Eigen::VectorXd e = Eigen::VectorXd::Zero(size);
  e[size - 1] = 1.0;
  return e;
}

}  // namespace

MinimumZoneResult MinimumZoneFit(NodeType kind, const std::vector<Eigen::Vector3d>& points,
                                 const std::vector<double>& start) {
  MinimumZoneResult result;
  if (!(kind == NodeType::kPlane || kind == NodeType::kSphere || kind == NodeType::kCylinder ||
        kind == NodeType::kCone)) {
    result.message =
        std::string("minimum zone is available for plane, sphere, cylinder and cone, not ") +
        NodeTypeName(kind);
    return result;
  }
  const int k = FreeParameterCount(kind), m = k + 1, n = static_cast<int>(points.size());
  if (n < m + 1) {
    result.message = "minimum zone of a " + std::string(NodeTypeName(kind)) + " needs at least " +
                     std::to_string(m + 1) + " points";
    return result;
  }
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto& p : points) centroid += p;
  centroid /= static_cast<double>(n);
  std::vector<Eigen::Vector3d> x(n);
  double size = 0;
  for (int i = 0; i < n; ++i) {
    x[i] = points[i] - centroid;
    size = std::max(size, x[i].norm());
  }
  std::vector<double> theta = start;
  TranslatePrimitive(kind, -centroid, &theta);

  // Initial reference: by decreasing |d_i| of the start, k points whose gradients g_i are
  // independent, then the first further point whose null vector (step 1 below) has no zero
  // entry: a non-degenerate reference (invertible levelled equations).
  Linearisation lin = Linearise(kind, theta, x);
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return std::abs(lin.d[a]) > std::abs(lin.d[b]); });
  std::vector<int> S, sigma(m);
  {
    auto smallest_singular = [](const Eigen::MatrixXd& M, Eigen::VectorXd* null) {
      Eigen::JacobiSVD<Eigen::MatrixXd> svd(M, Eigen::ComputeFullV);
      if (null) *null = svd.matrixV().col(M.cols() - 1);
      const Eigen::VectorXd sv = svd.singularValues();
      return std::make_pair(sv[sv.size() - 1], sv[0]);
    };
    Eigen::MatrixXd G(k, 0);
    for (int i : order) {
      if (static_cast<int>(S.size()) == m) break;
      Eigen::MatrixXd trial = G;
      trial.conservativeResize(k, G.cols() + 1);
      trial.col(G.cols()) = lin.g.row(i).transpose();
      if (static_cast<int>(S.size()) < k) {
        const auto [lo, hi] = smallest_singular(trial, nullptr);
        if (lo > 1e-8 * hi) {
          G = trial;
          S.push_back(i);
        }
      } else {
        Eigen::VectorXd c;
        smallest_singular(trial, &c);
        if (c.cwiseAbs().minCoeff() > 1e-6 * c.cwiseAbs().maxCoeff()) S.push_back(i);
      }
    }
    if (static_cast<int>(S.size()) < m) {
      result.message =
          "minimum zone: the points do not determine the " + std::string(NodeTypeName(kind));
      return result;
    }
  }
  double h = 0;
  const double eps = 1e-15 * std::max(size, 1e-300);
  bool done = false;
  for (int iteration = 0; iteration < 200 && !done; ++iteration) {
    // 1. Alternation signs from the null vector of [g_i], i in S.
    {
      Eigen::MatrixXd G(k, m);
      for (int c = 0; c < m; ++c) G.col(c) = lin.g.row(S[c]).transpose();
      Eigen::JacobiSVD<Eigen::MatrixXd> svd(G, Eigen::ComputeFullV);
      const Eigen::VectorXd c = svd.matrixV().col(m - 1);
      for (int i = 0; i < m; ++i)
        sigma[i] = c[i] > 0 ? 1 : c[i] < 0 ? -1 : (lin.d[S[i]] >= 0 ? 1 : -1);
    }
    // 2. Newton on d_i(theta) = sigma_i h.
    h = 0;
    for (int i = 0; i < m; ++i) h += sigma[i] * lin.d[S[i]] / m;
    for (int newton = 0; newton < 40; ++newton) {
      Eigen::MatrixXd M(m, m);
      Eigen::VectorXd F(m);
      for (int i = 0; i < m; ++i) {
        M.block(i, 0, 1, k) = lin.g.row(S[i]);
        M(i, k) = -sigma[i];
        F[i] = lin.d[S[i]] - sigma[i] * h;
      }
      Eigen::FullPivLU<Eigen::MatrixXd> lu(M);
      if (lu.rank() < m) {
        result.message = "minimum zone: degenerate reference (the points do not determine the " +
                         std::string(NodeTypeName(kind)) + ")";
        return result;
      }
      const Eigen::VectorXd step = -lu.solve(F);
      Retract(kind, lin.basis, step.head(k), &theta);
      h += step[k];
      lin = Linearise(kind, theta, x);
      if ((lin.basis * step.head(k)).norm() <= eps && std::abs(step[k]) <= eps) break;
    }
    if (h < 0) {
      h = -h;
      for (int& s : sigma) s = -s;
    }
    // 3. The worst point; exchange or stop.
    int worst = 0;
    for (int i = 1; i < n; ++i)
      if (std::abs(lin.d[i]) > std::abs(lin.d[worst])) worst = i;
    const Eigen::MatrixXd A = ReferenceMatrix(lin, S, sigma);
    Eigen::FullPivLU<Eigen::MatrixXd> lu(A);
    const Eigen::VectorXd lambda = lu.solve(UnitLast(m));
    if (std::abs(lin.d[worst]) <= h * (1 + 1e-9) + eps) {
      result.multipliers.assign(lambda.data(), lambda.data() + m);
      // A multiplier that turned negative after the Newton move: recompute the signs there.
      if (lambda.minCoeff() >= -1e-9 || iteration >= 190) {
        done = true;
        break;
      }
      continue;
    }
    const int sw = lin.d[worst] >= 0 ? 1 : -1;
    Eigen::VectorXd a(m);
    a.head(k) = sw * lin.g.row(worst).transpose();
    a[k] = 1.0;
    const Eigen::VectorXd mu = lu.solve(a);
    // Ratio test; pivots below 1e-9 of the largest are refused (a near-singular reference), ties
    // go to the first (Bland's rule against cycling).
    int leave = -1;
    double best = INFINITY;
    const double pivot = 1e-9 * mu.cwiseAbs().maxCoeff();
    for (int i = 0; i < m; ++i)
      if (mu[i] > pivot && lambda[i] / mu[i] < best * (1 - 1e-12)) {
        best = lambda[i] / mu[i];
        leave = i;
      }
    if (leave < 0) {
      result.message = "minimum zone: the exchange found no point to leave the reference";
      return result;
    }
    S[leave] = worst;
    sigma[leave] = sw;
    ++result.exchanges;
  }
  if (!done) {
    result.message = "minimum zone: the exchange did not settle in 200 iterations";
    return result;
  }
  result.contacts = S;
  result.sides = sigma;
  bool positive = true;
  for (int i = 0; i < m; ++i) {
    positive = positive && result.multipliers[i] >= -1e-9;
    (sigma[i] > 0 ? result.outer_contacts : result.inner_contacts) += 1;
  }
  double worst = 0;
  for (int i = 0; i < n; ++i) worst = std::max(worst, std::abs(lin.d[i]));
  result.optimality_verified = positive && worst <= h * (1 + 1e-9) + eps &&
                               result.outer_contacts > 0 && result.inner_contacts > 0;
  if (kind == NodeType::kCylinder) {  // axis point closest to the centroid
    Eigen::Map<Eigen::Vector3d> q(theta.data()), u(theta.data() + 3);
    u.normalize();
    q -= u * u.dot(q);
  }
  TranslatePrimitive(kind, centroid, &theta);
  result.parameters = theta;
  result.zone_width = 2 * h;
  result.figures = ComputeFormFigures(kind, theta, points);
  result.success = result.optimality_verified;
  result.message =
      result.success ? "minimum zone: optimality conditions hold"
                     : "minimum zone: the optimality conditions do not hold at the last reference";
  return result;
}

}  // namespace implicitfit
