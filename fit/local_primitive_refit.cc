#include "fit/local_primitive_refit.h"

#include <Eigen/Dense>
#include <cmath>

#include "fit/primitive_jacobians.h"

namespace implicitfit {
namespace {

// Unit directions: the plane's normal (with its offset), the axis of the others.
void Normalise(NodeType kind, double* p) {
  if (kind == NodeType::kSphere) return;
  double* v = kind == NodeType::kPlane ? p : p + 3;
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (!(n > 0)) return;
  for (int k = 0; k < 3; ++k) v[k] /= n;
  if (kind == NodeType::kPlane) p[3] /= n;
}

// Keeps radii positive and the cone angle inside (0, pi/2).
bool Admissible(NodeType kind, const double* p) {
  switch (kind) {
    case NodeType::kSphere:
      return p[3] > 0;
    case NodeType::kCylinder:
      return p[6] > 0;
    case NodeType::kCone:
      return p[6] > 1e-4 && p[6] < M_PI / 2 - 1e-4;
    case NodeType::kTorus:
      return p[6] > 0 && p[7] > 0;
    default:
      return true;
  }
}

template <typename E>
double Refit(NodeType kind, const std::vector<Eigen::Vector3d>& points,
             const std::vector<int>& indices, std::vector<double>* params, int iterations) {
  constexpr int P = PrimitiveDistance<E>::kNumParameters;
  using Mat = Eigen::Matrix<double, P, P>;
  using Vec = Eigen::Matrix<double, P, 1>;
  Vec p = Eigen::Map<const Vec>(params->data());
  auto cost = [&](const Vec& q, Mat* jtj, Vec* jtr) {
    const PrimitiveDistance<E> f(q.data());
    double ss = 0;
    if (jtj) jtj->setZero(), jtr->setZero();
    Vec g;
    for (int i : indices) {
      const double r = f(points[i].data(), jtj ? g.data() : nullptr, nullptr);
      ss += r * r;
      if (jtj) {
        jtj->template selfadjointView<Eigen::Lower>().rankUpdate(g);
        *jtr += r * g;
      }
    }
    if (jtj) *jtj = jtj->template selfadjointView<Eigen::Lower>();
    return ss;
  };
  Mat jtj;
  Vec jtr;
  double ss = cost(p, &jtj, &jtr);
  if (!std::isfinite(ss)) return -1.0;
  double lambda = 1e-3;
  for (int it = 0; it < iterations; ++it) {
    bool improved = false;
    for (int tries = 0; tries < 6 && !improved; ++tries) {
      Mat a = jtj;
      for (int k = 0; k < P; ++k) a(k, k) += lambda * std::max(jtj(k, k), 1e-12);
      const Vec delta = a.ldlt().solve(-jtr);
      if (!delta.allFinite()) return -1.0;
      Vec q = p + delta;
      Normalise(kind, q.data());
      if (!Admissible(kind, q.data())) {
        lambda *= 10;
        continue;
      }
      const double s = cost(q, nullptr, nullptr);
      if (std::isfinite(s) && s <= ss) {
        const double gain = ss - s;
        p = q;
        ss = cost(p, &jtj, &jtr);
        lambda = std::max(lambda / 10, 1e-9);
        improved = true;
        if (gain <= 1e-10 * ss) it = iterations;  // converged
      } else {
        lambda *= 10;
      }
    }
    if (!improved) break;
  }
  if (kind == NodeType::kCylinder) {  // the axis point nearest the origin (it drifts along)
    const Eigen::Vector3d a = p.template segment<3>(3).normalized();
    const Eigen::Vector3d c = p.template head<3>();
    p.template head<3>() = c - c.dot(a) * a;
  }
  Eigen::Map<Vec>(params->data()) = p;
  return std::sqrt(ss / indices.size());
}

}  // namespace

double RefitPrimitiveLocally(NodeType kind, const std::vector<Eigen::Vector3d>& points,
                             const std::vector<int>& indices, std::vector<double>* params,
                             int iterations) {
  if (indices.size() < 8) return -1.0;
  switch (kind) {
    case NodeType::kPlane:
      return Refit<PlaneEvaluator>(kind, points, indices, params, iterations);
    case NodeType::kSphere:
      return Refit<SphereEvaluator>(kind, points, indices, params, iterations);
    case NodeType::kCylinder:
      return Refit<CylinderEvaluator>(kind, points, indices, params, iterations);
    case NodeType::kCone:
      return Refit<ConeEvaluator>(kind, points, indices, params, iterations);
    case NodeType::kTorus:
      return Refit<TorusEvaluator>(kind, points, indices, params, iterations);
    default:
      return -1.0;
  }
}

}  // namespace implicitfit
