#include "fit/metrology/point_hypotheses.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "fit/metrology/primitive_tangent.h"

namespace implicitfit {
namespace {

using Vec3 = Eigen::Vector3d;

// Directions on the unit hemisphere z >= 0, evenly spread (Fibonacci lattice).
const std::vector<Vec3>& DirectionGrid() {
  static const std::vector<Vec3> grid = [] {
    constexpr int kCount = 600;
    std::vector<Vec3> g;
    const double golden = M_PI * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < kCount; ++i) {
      const double z = (i + 0.5) / kCount, r = std::sqrt(1.0 - z * z), phi = golden * i;
      g.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
    }
    return g;
  }();
  return grid;
}

double SumSquaredDistances(NodeType kind, const std::vector<double>& p, const Vec3* x, int n) {
  double s = 0;
  for (int i = 0; i < n; ++i) {
    const double d = PrimitiveSignedDistance(kind, p.data(), x[i].data(), nullptr);
    s += d * d;
  }
  return std::isfinite(s) ? s : INFINITY;
}

// Levenberg-Marquardt on the orthogonal distances of n points in local coordinates
// (fit/metrology/primitive_tangent.h). Returns the final sum of squares.
double RefineOnPoints(NodeType kind, const Vec3* x, int n, std::vector<double>* p) {
  const int P = static_cast<int>(p->size());
  double cost = SumSquaredDistances(kind, *p, x, n), lambda = 1e-3;
  std::vector<double> dp(P);
  for (int it = 0; it < 50 && cost > 0; ++it) {
    const Eigen::MatrixXd B = TangentBasis(kind, *p);
    Eigen::MatrixXd J(n, B.cols());
    Eigen::VectorXd r(n);
    for (int i = 0; i < n; ++i) {
      r[i] = PrimitiveSignedDistance(kind, p->data(), x[i].data(), dp.data());
      J.row(i) = Eigen::Map<const Eigen::RowVectorXd>(dp.data(), P) * B;
    }
    const Eigen::MatrixXd H = J.transpose() * J;
    const Eigen::VectorXd g = J.transpose() * r;
    bool improved = false;
    for (int tries = 0; tries < 10 && !improved; ++tries) {
      Eigen::MatrixXd A = H;
      A.diagonal() += lambda * (H.diagonal().array() + 1e-12).matrix();
      const Eigen::VectorXd delta = -A.ldlt().solve(g);
      std::vector<double> q = *p;
      Retract(kind, B, delta, &q);
      const double c = SumSquaredDistances(kind, q, x, n);
      if (c < cost) {
        const bool tiny = cost - c <= 1e-14 * cost;
        *p = std::move(q);
        cost = c;
        lambda = std::max(1e-9, lambda * 0.2);
        improved = true;
        if (tiny) return cost;
      } else {
        lambda *= 10;
      }
    }
    if (!improved) break;
  }
  return cost;
}

// Kind-specific construction for one axis direction u; the geometric residual over the sample
// (infinite when invalid).
double CylinderForDirection(const Vec3 p[5], const Vec3& u, std::vector<double>* params) {
  const Vec3 e1 = u.unitOrthogonal(), e2 = u.cross(e1);
  Eigen::Matrix<double, 5, 3> A;
  Eigen::Matrix<double, 5, 1> b;
  for (int i = 0; i < 5; ++i) {
    const double s = p[i].dot(e1), t = p[i].dot(e2);
    A.row(i) << 2 * s, 2 * t, 1.0;
    b[i] = s * s + t * t;
  }
  const Eigen::Vector3d z = A.colPivHouseholderQr().solve(b);
  const double r2 = z[2] + z[0] * z[0] + z[1] * z[1];
  if (!(r2 > 0) || !std::isfinite(r2)) return INFINITY;
  const Vec3 point = z[0] * e1 + z[1] * e2;
  *params = {point.x(), point.y(), point.z(), u.x(), u.y(), u.z(), std::sqrt(r2)};
  return SumSquaredDistances(NodeType::kCylinder, *params, p, 5);
}

double ConeForDirection(const Vec3 p[6], const Vec3& u_in, std::vector<double>* params) {
  // (x . u)^2 = c |x|^2 - 2 w . x + k with w = c a - (a . u) u: linear in (c, w, k) (the
  // (x . u) term of the expansion lies in the span of x, so s = a . u is recovered from w:
  // w . u = (c - 1) s, and a = w_perp / c + s u).
  Eigen::Matrix<double, 6, 5> A;
  Eigen::Matrix<double, 6, 1> b;
  for (int i = 0; i < 6; ++i) {
    const double h = p[i].dot(u_in);
    A.row(i) << p[i].squaredNorm(), -2 * p[i].x(), -2 * p[i].y(), -2 * p[i].z(), 1.0;
    b[i] = h * h;
  }
  const Eigen::Matrix<double, 5, 1> z = A.colPivHouseholderQr().solve(b);
  const double c = z[0];
  if (!(c > 1e-6 && c < 1 - 1e-6)) return INFINITY;
  const Vec3 w(z[1], z[2], z[3]);
  const double s = w.dot(u_in) / (c - 1);
  const Vec3 apex = (w - w.dot(u_in) * u_in) / c + s * u_in;
  Vec3 u = u_in;
  double side = 0;
  for (int i = 0; i < 6; ++i) side += (p[i] - apex).dot(u);
  if (side < 0) u = -u;
  const double alpha = std::acos(std::sqrt(c));
  *params = {apex.x(), apex.y(), apex.z(), u.x(), u.y(), u.z(), alpha};
  return SumSquaredDistances(NodeType::kCone, *params, p, 6);
}

// Torus for one axis direction u (see the header): the axis point a is the Kasa circle centre
// of the points projected on the plane orthogonal to u (the parallels of a torus project onto
// circles about the axis), or the projections' centroid when that fits better; then the profile
// in (rho, h) = (distance to the axis, height) is a circle, linear in (R, h0, K):
//   rho^2 + h^2 = 2 R rho + 2 h0 h + K,   r^2 = K + R^2 + h0^2.
double TorusForDirection(const Vec3* p, int n, const Vec3& u, std::vector<double>* params) {
  const Vec3 e1 = u.unitOrthogonal(), e2 = u.cross(e1);
  Eigen::MatrixXd A(n, 3);
  Eigen::VectorXd b(n);
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (int i = 0; i < n; ++i) {
    const double s = p[i].dot(e1), t = p[i].dot(e2);
    A.row(i) << 2 * s, 2 * t, 1.0;
    b[i] = s * s + t * t;
    mean += Eigen::Vector2d(s, t) / n;
  }
  const Eigen::Vector3d z = A.colPivHouseholderQr().solve(b);
  double best = INFINITY;
  for (const Eigen::Vector2d& a : {Eigen::Vector2d(z[0], z[1]), mean}) {
    Eigen::MatrixXd P(n, 3);
    Eigen::VectorXd q(n);
    for (int i = 0; i < n; ++i) {
      const double s = p[i].dot(e1) - a[0], t = p[i].dot(e2) - a[1], h = p[i].dot(u);
      const double rho = std::sqrt(s * s + t * t);
      P.row(i) << 2 * rho, 2 * h, 1.0;
      q[i] = rho * rho + h * h;
    }
    const Eigen::Vector3d w = P.colPivHouseholderQr().solve(q);
    const double R = w[0], h0 = w[1], r2 = w[2] + R * R + h0 * h0;
    if (!(R > 0) || !(r2 > 0) || !std::isfinite(r2) || std::sqrt(r2) >= R) continue;
    const Vec3 c = a[0] * e1 + a[1] * e2 + h0 * u;
    std::vector<double> h = {c.x(), c.y(), c.z(), u.x(), u.y(), u.z(), R, std::sqrt(r2)};
    const double cost = SumSquaredDistances(NodeType::kTorus, h, p, n);
    if (cost < best) {
      best = cost;
      *params = h;
    }
  }
  return best;
}

// The sample's best primitive over the direction grid: the kStarts best directions at least
// 10 degrees apart are each refined by Gauss-Newton on the K distances; the lowest wins (one
// start can land in another solution of the K-point problem).
template <typename Build>
bool FromDirectionGrid(NodeType kind, const Vec3* p, int K, Build build,
                       std::vector<double>* params) {
  constexpr int kStarts = 6;
  const std::vector<Vec3>& grid = DirectionGrid();
  std::vector<std::pair<double, int>> ranked;
  std::vector<std::vector<double>> built(grid.size());
  for (size_t g = 0; g < grid.size(); ++g) {
    const double s = build(p, grid[g], &built[g]);
    if (std::isfinite(s)) ranked.push_back({s, static_cast<int>(g)});
  }
  std::sort(ranked.begin(), ranked.end());
  std::vector<int> starts;
  for (const auto& [s, g] : ranked) {
    bool apart = true;
    for (int o : starts)
      apart = apart && std::abs(grid[g].dot(grid[o])) < std::cos(10 * M_PI / 180);
    if (apart) starts.push_back(g);
    if (static_cast<int>(starts.size()) == kStarts) break;
  }
  double best = INFINITY;
  for (int g : starts) {
    std::vector<double> h = built[g];
    const double s = RefineOnPoints(kind, p, K, &h);
    bool finite = std::isfinite(s);
    for (double v : h) finite = finite && std::isfinite(v);
    if (finite && s < best) {
      best = s;
      *params = h;
    }
  }
  return std::isfinite(best);
}

double Binomial(int n, int k) {
  double c = 1;
  for (int i = 0; i < k; ++i) c = c * (n - i) / (i + 1);
  return c;
}

// The next k-subset of {0..n-1} in lexicographic order; false after the last.
bool NextCombination(std::vector<int>* idx, int n) {
  const int k = static_cast<int>(idx->size());
  int i = k - 1;
  while (i >= 0 && (*idx)[i] == n - k + i) --i;
  if (i < 0) return false;
  ++(*idx)[i];
  for (int j = i + 1; j < k; ++j) (*idx)[j] = (*idx)[j - 1] + 1;
  return true;
}

}  // namespace

bool PlaneFromPoints(const Vec3 p[3], std::vector<double>* params) {
  const Vec3 n = (p[1] - p[0]).cross(p[2] - p[0]);
  const double scale = (p[1] - p[0]).norm() * (p[2] - p[0]).norm();
  if (!(n.norm() > 1e-9 * scale)) return false;
  const Vec3 u = n.normalized();
  *params = {u.x(), u.y(), u.z(), u.dot(p[0])};
  return true;
}

bool SphereFromPoints(const Vec3 p[4], std::vector<double>* params) {
  Eigen::Matrix4d A;
  Eigen::Vector4d b;
  for (int i = 0; i < 4; ++i) {
    A.row(i) << 2 * p[i].x(), 2 * p[i].y(), 2 * p[i].z(), 1.0;
    b[i] = p[i].squaredNorm();
  }
  Eigen::FullPivLU<Eigen::Matrix4d> lu(A);
  lu.setThreshold(1e-10);
  if (lu.rank() < 4) return false;
  const Eigen::Vector4d z = lu.solve(b);
  const double r2 = z[3] + z.head<3>().squaredNorm();
  if (!(r2 > 0) || !std::isfinite(r2)) return false;
  *params = {z[0], z[1], z[2], std::sqrt(r2)};
  return true;
}

bool CylinderFromPoints(const Vec3 p[5], std::vector<double>* params) {
  return FromDirectionGrid(NodeType::kCylinder, p, 5, CylinderForDirection, params);
}

bool ConeFromPoints(const Vec3 p[6], std::vector<double>* params) {
  return FromDirectionGrid(NodeType::kCone, p, 6, ConeForDirection, params);
}

bool TorusFromPoints(const Vec3* p, int n, std::vector<double>* params) {
  if (n < 7) return false;
  return FromDirectionGrid(
      NodeType::kTorus, p, n,
      [n](const Vec3* q, const Vec3& u, std::vector<double>* h) {
        return TorusForDirection(q, n, u, h);
      },
      params);
}

int PointSampleSize(NodeType kind, int points) {
  const int k = FreeParameterCount(kind);
  return kind == NodeType::kTorus ? std::min(points, k + 3) : k;
}

std::string PointSetDegeneracy(NodeType kind, const std::vector<Vec3>& points) {
  const int k = FreeParameterCount(kind);
  const std::string name = NodeTypeName(kind);
  if (static_cast<int>(points.size()) < k + 1)
    return "too few points: a " + name + " has " + std::to_string(k) +
           " free parameters, so at least " + std::to_string(k + 1) +
           " points are needed; the cloud has " + std::to_string(points.size());
  Vec3 mean = Vec3::Zero();
  for (const Vec3& x : points) mean += x;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Vec3& x : points) cov += (x - mean) * (x - mean).transpose();
  const Eigen::Vector3d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvalues();
  const double spread = std::sqrt(std::max(0.0, ev[2]));
  // Relative thickness below 1e-9: collinear / coplanar to rounding (noise-free data).
  if (std::sqrt(std::max(0.0, ev[1])) <= 1e-9 * spread)
    return "degenerate points: they are collinear, so no unique " + name + " passes through them";
  if (kind != NodeType::kPlane && std::sqrt(std::max(0.0, ev[0])) <= 1e-9 * spread)
    return "degenerate points: they are coplanar, so a " + name + " through them is not determined";
  return "";
}

PointHypothesisSearch BestPointHypothesis(
    NodeType kind, const std::vector<Vec3>& points, double tau, int budget, std::mt19937& rng,
    const std::function<void(std::vector<double>*)>& constrain) {
  PointHypothesisSearch search;
  constexpr int kMinValid = 4;
  const int n = static_cast<int>(points.size());
  if (n < FreeParameterCount(kind)) return search;
  const int k = PointSampleSize(kind, n);
  search.enumerated = Binomial(n, k) <= budget;
  std::vector<int> idx(k);
  std::iota(idx.begin(), idx.end(), 0);
  std::uniform_int_distribution<int> pick(0, n - 1);
  double best_cost = INFINITY;
  std::vector<double> h;
  std::vector<Vec3> sample(k);
  for (int t = 0; t < budget; ++t) {
    if (search.enumerated) {
      if (t > 0 && !NextCombination(&idx, n)) break;
    } else {
      for (int j = 0; j < k; ++j) {
        do idx[j] = pick(rng);
        while (std::find(idx.begin(), idx.begin() + j, idx[j]) != idx.begin() + j);
      }
    }
    ++search.tried;
    for (int j = 0; j < k; ++j) sample[j] = points[idx[j]];
    bool ok = false;
    switch (kind) {
      case NodeType::kPlane:
        ok = PlaneFromPoints(sample.data(), &h);
        break;
      case NodeType::kSphere:
        ok = SphereFromPoints(sample.data(), &h);
        break;
      case NodeType::kCylinder:
        ok = CylinderFromPoints(sample.data(), &h);
        break;
      case NodeType::kCone:
        ok = ConeFromPoints(sample.data(), &h);
        break;
      case NodeType::kTorus:
        ok = TorusFromPoints(sample.data(), k, &h);
        break;
      default:
        break;
    }
    if (!ok) continue;
    if (constrain) constrain(&h);
    ++search.valid;
    int support = 0;
    double cost = 0;
    for (const Vec3& x : points) {
      const double d = std::abs(PrimitiveSignedDistance(kind, h.data(), x.data(), nullptr));
      support += d < tau;
      cost += std::min(d * d, tau * tau);
    }
    if (!std::isfinite(cost)) continue;
    if (support > search.support || (support == search.support && cost < best_cost)) {
      search.support = support;
      search.parameters = h;
      best_cost = cost;
    }
    // Early stop: when every point supports the best hypothesis no subset can find more
    // support; kMinValid hypotheses still compete on the truncated cost.
    if (search.support == n && search.valid >= kMinValid) {
      search.stopped_early = true;
      break;
    }
  }
  return search;
}

}  // namespace implicitfit
