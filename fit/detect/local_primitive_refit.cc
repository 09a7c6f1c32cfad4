#include "fit/detect/local_primitive_refit.h"

#include <Eigen/Dense>
#include <cmath>

#include "fit/primitive/fittable_primitives.h"
#include "model/primitives/primitive_kinds.h"

namespace implicitfit {
namespace {

// Unit directions (the plane's normal with its offset, the axes), by field role.
void Normalise(NodeType kind, double* p) {
  const std::vector<ParameterField>& fields = ParameterFieldsOf(kind);
  int dir = 0, offset = -1;
  if (!FindFieldWithRole(fields, FieldRole::kDirection, &dir)) return;
  FindFieldWithRole(fields, FieldRole::kPlaneOffset, &offset);
  double* v = p + dir;
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (!(n > 0)) return;
  for (int k = 0; k < 3; ++k) v[k] /= n;
  if (offset >= 0) p[offset] /= n;
}

// Keeps positive lengths (radii) positive and angles (the cone's) inside (0, pi/2).
bool Admissible(NodeType kind, const double* p) {
  int k = 0;
  for (const ParameterField& f : ParameterFieldsOf(kind)) {
    for (int j = 0; j < f.size; ++j) {
      if (f.role == FieldRole::kPositiveLength && !(p[k + j] > 0)) return false;
      if (f.role == FieldRole::kAngle && !(p[k + j] > 1e-4 && p[k + j] < M_PI / 2 - 1e-4))
        return false;
    }
    k += f.size;
  }
  return true;
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
  if (indices.size() < 8 || !FindFittablePrimitive(kind)) return -1.0;
  return VisitFittablePrimitive(
      kind, [&](auto e) { return Refit<decltype(e)>(kind, points, indices, params, iterations); });
}

}  // namespace implicitfit
