#include "fit/metrology/minimum_zone.h"

#include <Eigen/Dense>
#include <algorithm>
#include <utility>
#include <cmath>
#include <cstdio>

#include "fit/metrology/chebyshev_lp.h"
#include "fit/metrology/primitive_tangent.h"

namespace implicitfit {
namespace {


struct Linearisation {
  Eigen::MatrixXd basis;  // P x k
  Eigen::VectorXd d;      // signed distances of every point
  Eigen::MatrixXd g;      // N x k local gradients
  double worst = 0.0;     // max_i |d_i|
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
  l.worst = l.d.cwiseAbs().maxCoeff();
  return l;
}

// The LP in scaled unknowns: delta_j = t * y_j / c_j, c_j = max_i |g_ij|, rows divided by t, so
// that every coefficient is O(1) and y_j = 1 moves a distance by up to t.
struct ScaledLp {
  Eigen::VectorXd column_scale;
  ChebyshevLpSolution solution;
};

ScaledLp SolveScaled(const Linearisation& l, double radius) {
  ScaledLp s;
  const double t = l.worst;
  s.column_scale = l.g.cwiseAbs().colwise().maxCoeff().transpose();
  for (int j = 0; j < s.column_scale.size(); ++j)
    if (!(s.column_scale[j] > 0)) s.column_scale[j] = 1.0;
  const Eigen::MatrixXd g = l.g * s.column_scale.cwiseInverse().asDiagonal();
  s.solution = SolveChebyshevLp(l.d / t, g, radius);
  return s;
}

Eigen::VectorXd StepOf(const ScaledLp& s, double t) {
  return t * s.solution.step.cwiseQuotient(s.column_scale);
}

std::vector<int> ContactsOf(const ChebyshevLpSolution& s) {
  std::vector<int> c;
  for (int i = 0; i < s.lambda.size(); ++i)
    if (s.lambda[i] > 0) c.push_back(i);
  return c;
}

// Newton on d_i(theta) = sigma_i h, i in S (|S| = k + 1 equations, unknowns theta and h).
// Returns false when the system is singular.
bool PolishLevelled(NodeType kind, const std::vector<Eigen::Vector3d>& x, const std::vector<int>& S,
                    const std::vector<int>& sigma, double eps, std::vector<double>* theta) {
  const int m = static_cast<int>(S.size());
  Linearisation lin = Linearise(kind, *theta, x);
  const int k = static_cast<int>(lin.g.cols());
  if (m != k + 1) return false;
  double h = 0;
  for (int i = 0; i < m; ++i) h += sigma[i] * lin.d[S[i]] / m;
  for (int newton = 0; newton < 30; ++newton) {
    Eigen::MatrixXd M(m, m);
    Eigen::VectorXd F(m);
    for (int i = 0; i < m; ++i) {
      M.block(i, 0, 1, k) = lin.g.row(S[i]);
      M(i, k) = -sigma[i];
      F[i] = lin.d[S[i]] - sigma[i] * h;
    }
    Eigen::FullPivLU<Eigen::MatrixXd> lu(M);
    if (lu.rank() < m) return false;
    const Eigen::VectorXd step = -lu.solve(F);
    Retract(kind, lin.basis, step.head(k), theta);
    h += step[k];
    lin = Linearise(kind, *theta, x);
    if ((lin.basis * step.head(k)).norm() <= eps && std::abs(step[k]) <= eps) return true;
  }
  return true;
}

// Sequential LP with a trust region from *theta (see the header). Returns "" or the LP's error.
std::string RunSlp(NodeType kind, const std::vector<Eigen::Vector3d>& x, double eps,
                   std::vector<double>* theta, Linearisation* lin, MinimumZoneResult* result) {
  double radius = 1.0;
  std::vector<int> contacts;
  for (int iteration = 0; iteration < 1000 && lin->worst > eps; ++iteration) {
    ++result->iterations;
    const ScaledLp lp = SolveScaled(*lin, radius);
    if (!lp.solution.success) return lp.solution.message;
    const double predicted = 1.0 - lp.solution.t;  // relative to lin->worst
    if (predicted <= 1e-13) break;
    std::vector<double> trial = *theta;
    Retract(kind, lin->basis, StepOf(lp, lin->worst), &trial);
    Linearisation next = Linearise(kind, trial, x);
    const double ratio = (lin->worst - next.worst) / (lin->worst * predicted);
    const double step_size = lp.solution.step.cwiseAbs().maxCoeff();
    if (ratio > 0.01) {
      const std::vector<int> now = ContactsOf(lp.solution);
      if (!contacts.empty() && now != contacts) ++result->exchanges;
      contacts = now;
      *theta = trial;
      *lin = std::move(next);
      if (ratio > 0.75 && step_size >= 0.99 * radius) radius = std::min(2 * radius, 1e6);
    } else {
      radius = step_size / 4;
      if (radius < 1e-15) break;
    }
  }
  return "";
}

// Polish on the contact set when it has k + 1 points (the usual, Haar case).
void Polish(NodeType kind, const std::vector<Eigen::Vector3d>& x, double eps,
            std::vector<double>* theta, Linearisation* lin) {
  const int k = static_cast<int>(lin->g.cols());
  std::vector<int> S, sigma;
  for (int i = 0; i < lin->d.size(); ++i)
    if (std::abs(lin->d[i]) >= lin->worst * (1 - 1e-6)) {
      S.push_back(i);
      sigma.push_back(lin->d[i] >= 0 ? 1 : -1);
    }
  std::vector<double> polished = *theta;
  if (static_cast<int>(S.size()) == k + 1 && PolishLevelled(kind, x, S, sigma, eps, &polished)) {
    Linearisation p = Linearise(kind, polished, x);
    if (p.worst <= lin->worst) {
      *theta = polished;
      *lin = std::move(p);
    }
  }
}

struct Certificate {
  std::string error;
  double kkt_residual = INFINITY;
  std::vector<int> contacts, sides;
  std::vector<double> multipliers;
  Eigen::MatrixXd null_directions;  // k x (k + 1 - contacts), scaled units; empty if Haar
  Eigen::VectorXd column_scale;
};

// Kuhn-Tucker certificate (see the header): on the near-active set A (|d_i| >= t (1 - 1e-8)),
// levelled (d_i = sigma_i t), the LP with radius rho small enough that no row changes sign
// gives t_LP = t (1 - rho r), r = min over lambda >= 0, sum lambda = 1 of
// |sum lambda_i sigma_i g_i|_1 (scaled columns); its multipliers are the lambda_i.
Certificate Certify(const Linearisation& lin) {
  Certificate c;
  const int n = static_cast<int>(lin.d.size()), k = static_cast<int>(lin.g.cols());
  const double h = lin.worst;
  std::vector<int> A;
  for (int i = 0; i < n; ++i)
    if (std::abs(lin.d[i]) >= h * (1 - 1e-8)) A.push_back(i);
  c.column_scale = lin.g.cwiseAbs().colwise().maxCoeff().transpose();
  for (int j = 0; j < k; ++j)
    if (!(c.column_scale[j] > 0)) c.column_scale[j] = 1.0;
  Eigen::VectorXd dA(A.size());
  Eigen::MatrixXd gA(A.size(), k);
  for (size_t r = 0; r < A.size(); ++r) {
    dA[r] = lin.d[A[r]] >= 0 ? 1.0 : -1.0;
    gA.row(r) = lin.g.row(A[r]).cwiseQuotient(c.column_scale.transpose());
  }
  const double rho = 0.5 / std::max(1.0, gA.cwiseAbs().rowwise().sum().maxCoeff());
  const ChebyshevLpSolution lp = SolveChebyshevLp(dA, gA, rho);
  if (!lp.success) {
    c.error = lp.message;
    return c;
  }
  c.kkt_residual = (1.0 - lp.t) / rho;
  std::vector<int> rows;
  for (size_t r = 0; r < A.size(); ++r) {
    if (!(lp.lambda[r] > 0)) continue;
    rows.push_back(static_cast<int>(r));
    c.contacts.push_back(A[r]);
    c.sides.push_back(lp.side[r]);
    c.multipliers.push_back(lp.lambda[r]);
  }
  // Directions that keep every contact levelled to first order: null space of
  // [sigma_i g_i, -1] (the zone's half width changes by the last component).
  const int m = static_cast<int>(rows.size());
  if (m < k + 1 && m > 0) {
    Eigen::MatrixXd M(m, k + 1);
    for (int r = 0; r < m; ++r) {
      M.block(r, 0, 1, k) = c.sides[r] * gA.row(rows[r]);
      M(r, k) = -1.0;
    }
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(M, Eigen::ComputeFullV);
    c.null_directions = svd.matrixV().block(0, m, k, k + 1 - m);
  }
  return c;
}

// Curvature of the Lagrangian sum lambda_i sigma_i d_i along a null direction v (scaled
// units), by a central second difference: negative means the point is not a local minimum.
double LagrangianCurvature(NodeType kind, const std::vector<Eigen::Vector3d>& x,
                           const std::vector<double>& theta, const Linearisation& lin,
                           const Certificate& c, const Eigen::VectorXd& v) {
  auto lagrangian = [&](double s) {
    std::vector<double> q = theta;
    Retract(kind, lin.basis, s * lin.worst * v.cwiseQuotient(c.column_scale), &q);
    double L = 0;
    for (size_t r = 0; r < c.contacts.size(); ++r)
      L += c.multipliers[r] * c.sides[r] *
           PrimitiveSignedDistance(kind, q.data(), x[c.contacts[r]].data(), nullptr);
    return L;
  };
  const double e = 1e-3;
  return (lagrangian(e) + lagrangian(-e) - 2 * lagrangian(0)) / (e * e * lin.worst);
}

// SLP, polish, certificate; with fewer than k + 1 contacts, the second-order check and the
// restarts (see the header). Returns "" or the error.
std::string Descend(NodeType kind, const std::vector<Eigen::Vector3d>& x, double eps,
                    std::vector<double>* theta, Linearisation* lin, Certificate* cert,
                    MinimumZoneResult* result) {
  for (int escape = 0;; ++escape) {
    const std::string error = RunSlp(kind, x, eps, theta, lin, result);
    if (!error.empty()) return error;
    Polish(kind, x, eps, theta, lin);
    if (lin->worst <= eps) break;
    *cert = Certify(*lin);
    if (!cert->error.empty()) return cert->error;
    result->second_order_curvature = INFINITY;
    Eigen::VectorXd descent;
    for (int j = 0; j < cert->null_directions.cols(); ++j) {
      const Eigen::VectorXd v = cert->null_directions.col(j).normalized();
      const double curvature = LagrangianCurvature(kind, x, *theta, *lin, *cert, v);
      if (curvature < result->second_order_curvature) {
        result->second_order_curvature = curvature;
        descent = v;
      }
    }
    if (descent.size() == 0 || escape >= 5) break;
    std::vector<double> best_theta = *theta;
    Linearisation best = *lin;
    const int k = static_cast<int>(lin->g.cols());
    std::vector<Eigen::VectorXd> moves;
    for (double s : {0.3, 0.03, 0.003}) {
      moves.push_back(s * descent);
      moves.push_back(-s * descent);
    }
    for (int j = 0; j < k; ++j)  // and along every parameter, for a nearby narrower minimum
      for (double s : {1.0, -1.0, 0.1, -0.1}) moves.push_back(s * Eigen::VectorXd::Unit(k, j));
    for (const Eigen::VectorXd& move : moves) {
      std::vector<double> q = *theta;
      Retract(kind, lin->basis, lin->worst * move.cwiseQuotient(cert->column_scale), &q);
      Linearisation l = Linearise(kind, q, x);
      if (!RunSlp(kind, x, eps, &q, &l, result).empty()) continue;
      if (l.worst < best.worst) {
        best_theta = q;
        best = l;
      }
    }
    if (!(best.worst < lin->worst)) break;  // no narrower zone nearby: keep this point
    ++result->escapes;
    *theta = best_theta;
    *lin = std::move(best);
  }
  return "";
}

// One exchange of the contact set (see the header): for every contact i and every other point j
// on either face, Newton on the levelled equations of the set with j in place of i, from theta;
// a solution that holds every point within its zone and is narrower than the current one is
// the move. Returns false when there is none (or the contacts are not k + 1).
bool NarrowerByExchange(NodeType kind, const std::vector<Eigen::Vector3d>& x,
                        const Certificate& cert, double eps, std::vector<double>* theta,
                        Linearisation* lin) {
  const int n = static_cast<int>(x.size()), k = static_cast<int>(lin->g.cols());
  if (static_cast<int>(cert.contacts.size()) != k + 1) return false;
  double best = lin->worst * (1 - 1e-13);
  std::vector<double> best_theta;
  for (int j = 0; j < n; ++j) {
    if (std::find(cert.contacts.begin(), cert.contacts.end(), j) != cert.contacts.end()) continue;
    for (int i = 0; i <= k; ++i)
      for (int side : {1, -1}) {
        std::vector<int> S = cert.contacts, sigma = cert.sides;
        S[i] = j;
        sigma[i] = side;
        std::vector<double> q = *theta;
        if (!PolishLevelled(kind, x, S, sigma, eps, &q)) continue;
        const Linearisation l = Linearise(kind, q, x);
        double level = 0;
        for (int s : S) level = std::max(level, std::abs(l.d[s]));
        bool levelled = true;
        for (int s : S) levelled = levelled && std::abs(std::abs(l.d[s]) - level) <= 1e-9 * level;
        if (levelled && l.worst <= level * (1 + 1e-12) && l.worst < best) {
          best = l.worst;
          best_theta = q;
        }
      }
  }
  if (best_theta.empty()) return false;
  *theta = best_theta;
  *lin = Linearise(kind, *theta, x);
  return true;
}

// The minimum zone of every point of `points` (the method of the header).
MinimumZoneResult SolveAll(NodeType kind, const std::vector<Eigen::Vector3d>& points,
                           const std::vector<double>& start) {
  MinimumZoneResult result;
  if (!(kind == NodeType::kPlane || kind == NodeType::kSphere || kind == NodeType::kCylinder ||
        kind == NodeType::kCone || kind == NodeType::kTorus)) {
    result.message =
        std::string("minimum zone is available for plane, sphere, cylinder, cone and torus, not ") +
        NodeTypeName(kind);
    return result;
  }
  const int k = FreeParameterCount(kind), n = static_cast<int>(points.size());
  if (n < k + 2) {
    result.message = "minimum zone of a " + std::string(NodeTypeName(kind)) + " needs at least " +
                     std::to_string(k + 2) + " points";
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
  const double eps = 1e-15 * std::max(size, 1e-300);

  Linearisation lin = Linearise(kind, theta, x);
  {
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(lin.g);
    const Eigen::VectorXd sv = svd.singularValues();
    if (!(sv[sv.size() - 1] > 1e-10 * sv[0])) {
      result.message =
          "minimum zone: the points do not determine the " + std::string(NodeTypeName(kind));
      return result;
    }
  }
  const std::string failed = "minimum zone: ";
  // SLP, polish, certificate, second-order escapes (Descend); then the exchange search for a
  // narrower levelled zone one contact away, and again from there (see the header).
  Certificate cert;
  for (int round = 0;; ++round) {
    const std::string error = Descend(kind, x, eps, &theta, &lin, &cert, &result);
    if (!error.empty()) {
      result.message = failed + error;
      return result;
    }
    if (lin.worst <= eps || round >= 10) break;
    if (!NarrowerByExchange(kind, x, cert, eps, &theta, &lin)) break;
    ++result.contact_swaps;
  }
  const double h = lin.worst;
  result.kkt_residual = h <= eps ? 0.0 : cert.kkt_residual;
  result.contacts = cert.contacts;
  for (int c : cert.contacts) {
    result.contact_points.push_back(points[c]);
    result.contact_distances.push_back(lin.d[c]);
  }
  result.sides = cert.sides;
  result.multipliers = cert.multipliers;
  for (int side : cert.sides) (side > 0 ? result.outer_contacts : result.inner_contacts) += 1;
  result.optimality_verified =
      h <= eps || (result.kkt_residual <= kMinimumZoneKktTolerance && result.outer_contacts > 0 &&
                   result.inner_contacts > 0 && !(result.second_order_curvature < 0));
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
  char buffer[160];
  std::snprintf(buffer, sizeof buffer,
                "minimum zone: optimality conditions %s (Kuhn-Tucker residual %.2g, %d outer / %d "
                "inner contacts)",
                result.optimality_verified ? "hold" : "do not hold", result.kkt_residual,
                result.outer_contacts, result.inner_contacts);
  result.message = buffer;
  return result;
}

// The working set of the exchange: the points farthest out and farthest in at theta, and an
// even spread of the rest (so that the subset determines the primitive).
std::vector<int> InitialWorkingSet(NodeType kind, const std::vector<Eigen::Vector3d>& points,
                                   const std::vector<double>& theta, int extremes, int spread) {
  const int n = static_cast<int>(points.size());
  std::vector<std::pair<double, int>> d(n);
  for (int i = 0; i < n; ++i)
    d[i] = {PrimitiveSignedDistance(kind, theta.data(), points[i].data(), nullptr), i};
  std::sort(d.begin(), d.end());
  std::vector<char> in(n, 0);
  for (int r = 0; r < extremes && r < n; ++r) in[d[r].second] = in[d[n - 1 - r].second] = 1;
  for (int r = 0; r < spread; ++r) in[static_cast<int>(static_cast<long long>(r) * n / spread)] = 1;
  std::vector<int> set;
  for (int i = 0; i < n; ++i)
    if (in[i]) set.push_back(i);
  return set;
}

}  // namespace

// Exchange over working sets: the zone of a subset S is a lower bound of the zone of all
// points; when every point lies within the subset's zone, its Kuhn-Tucker point (certificate
// and second-order check, all on active points) is one of the whole problem, whose other
// points are inactive. Otherwise the points farthest outside join S and the solve restarts
// from the subset's solution. Each LP then has |S| rows instead of N: 20 000 noisy sphere
// points took over 100 s in one solve.
MinimumZoneResult MinimumZoneFit(NodeType kind, const std::vector<Eigen::Vector3d>& points,
                                 const std::vector<double>& start, int direct_limit) {
  constexpr int kExtremes = 250, kSpread = 500, kAdded = 250;
  const int n = static_cast<int>(points.size());
  if (n <= direct_limit || n < 4 * (kExtremes + kSpread) / 3) return SolveAll(kind, points, start);
  std::vector<int> set = InitialWorkingSet(kind, points, start, kExtremes, kSpread);
  std::vector<double> theta = start;
  int iterations = 0, exchanges = 0, escapes = 0, swaps = 0;
  for (int round = 0; round < 40 && static_cast<int>(set.size()) < n / 2; ++round) {
    std::vector<Eigen::Vector3d> subset;
    subset.reserve(set.size());
    for (int i : set) subset.push_back(points[i]);
    MinimumZoneResult r = SolveAll(kind, subset, theta);
    iterations += r.iterations;
    exchanges += r.exchanges;
    escapes += r.escapes;
    swaps += r.contact_swaps;
    if (r.parameters.empty()) return r;  // the subset does not determine it: an error message
    theta = r.parameters;
    const double t = 0.5 * r.zone_width;
    const double tolerance = 1e-12 * std::max(1.0, t) + 1e-9 * t;
    std::vector<char> in(n, 0);
    for (int i : set) in[i] = 1;
    std::vector<std::pair<double, int>> outside;
    for (int i = 0; i < n; ++i) {
      if (in[i]) continue;
      const double d = std::abs(PrimitiveSignedDistance(kind, theta.data(), points[i].data(), nullptr));
      if (d > t + tolerance) outside.emplace_back(-d, i);
    }
    if (outside.empty()) {  // every point inside the subset's zone: its optimum is the optimum
      for (int& c : r.contacts) c = set[c];
      r.figures = ComputeFormFigures(kind, theta, points);
      r.iterations = iterations;
      r.exchanges = exchanges;
      r.escapes = escapes;
      r.contact_swaps = swaps;
      return r;
    }
    std::sort(outside.begin(), outside.end());
    for (size_t k = 0; k < outside.size() && k < static_cast<size_t>(kAdded); ++k)
      set.push_back(outside[k].second);
    std::sort(set.begin(), set.end());
  }
  MinimumZoneResult r = SolveAll(kind, points, theta);  // the exchange did not settle
  r.iterations += iterations;
  return r;
}

}  // namespace implicitfit
