#include "model/primitives/surface_cord.h"

#include <cmath>
#include <stdexcept>

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

// Newton along the gradient onto f = 0.
Vec Project(const Model& model, Vec x) {
  for (int it = 0; it < 50; ++it) {
    double f;
    const Vec g = model.Gradient(x, &f);
    if (std::abs(f) < 1e-12 * (1.0 + x.cwiseAbs().maxCoeff())) break;
    const double g2 = g.squaredNorm();
    if (!(g2 > 1e-30) || !std::isfinite(g2)) break;
    x -= f * g / g2;
  }
  return x;
}

// The foot of g on the last step, taken on the surface: x(s) = Project(p + s t), s in [0, h], where
// (g - x(s)) . T(x(s)) changes sign (T: t projected into the tangent plane at x(s)); bisection.
// At s = 0 the product is |d| > 0 (t is the tangent component of g - p); at s = h it is < 0 or the
// step's end is kept.
Vec EndOnStep(const Model& model, const Vec& p, const Vec& t, double h, const Vec& g) {
  const auto side = [&](double s, Vec* x) {
    *x = Project(model, p + s * t);
    const Vec n = model.Gradient(*x).normalized();
    Vec tx = t;
    if (n.allFinite()) tx -= tx.dot(n) * n;
    return (g - *x).dot(tx);
  };
  Vec x;
  double lo = 0.0, hi = h;
  if (side(hi, &x) >= 0.0) return x;
  for (int it = 0; it < 60 && hi - lo > 1e-15 * h; ++it) {
    const double mid = 0.5 * (lo + hi);
    (side(mid, &x) > 0.0 ? lo : hi) = mid;
  }
  side(0.5 * (lo + hi), &x);
  return x;
}

}  // namespace

SurfaceCord GrowSurfaceCord(const Model& model, const std::vector<Vec>& guide,
                            const SurfaceCordOptions& options) {
  if (guide.size() < 2) throw std::invalid_argument("a surface cord needs 2 guide points");
  double length = 0.0;
  for (size_t k = 0; k < guide.size(); ++k) {
    if (!guide[k].allFinite()) throw std::invalid_argument("a guide point is not finite");
    if (k > 0) length += (guide[k] - guide[k - 1]).norm();
  }
  const double h = options.step > 0 ? options.step : length / 100.0;
  if (!(h > 0) || !std::isfinite(h)) throw std::invalid_argument("the guide has no length");
  SurfaceCord cord;
  cord.points.push_back(Project(model, guide[0]));
  size_t target = 1;
  for (int i = 0; i < options.max_steps; ++i) {
    const Vec p = cord.points.back();
    const Vec n = model.Gradient(p).normalized();
    Vec d = guide[target] - p;
    if (n.allFinite()) d -= d.dot(n) * n;
    if (!(d.norm() > 1e-300)) {  // the target is straight above or below p: passed
      if (++target == guide.size()) {
        cord.reached = true;
        break;
      }
      continue;
    }
    const Vec next = Project(model, p + h * d.normalized());
    if ((guide[target] - next).dot(next - p) < 0.0) {  // the step passed the target's foot
      if (target + 1 < guide.size()) {
        ++target;
        cord.points.push_back(next);
        continue;
      }
      cord.points.push_back(EndOnStep(model, p, d.normalized(), h, guide[target]));
      cord.reached = true;
      break;
    }
    cord.points.push_back(next);
  }
  return cord;
}

}  // namespace implicitfit
