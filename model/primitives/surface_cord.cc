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
      const Vec e = (next - p).normalized();
      cord.points.push_back(Project(model, p + (guide[target] - p).dot(e) * e));
      cord.reached = true;
      break;
    }
    cord.points.push_back(next);
  }
  return cord;
}

}  // namespace implicitfit
