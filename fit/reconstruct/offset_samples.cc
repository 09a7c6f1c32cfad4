#include "fit/reconstruct/offset_samples.h"

#include <cmath>
#include <cstdint>

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

std::uint64_t SignVector(const std::vector<Model>& literals, const Vec& x) {
  std::uint64_t signs = 0;
  for (size_t j = 0; j < literals.size(); ++j)
    if (literals[j].Value(x) < 0) signs |= 1ULL << j;
  return signs;
}

}  // namespace

OffsetSamplePair OffsetSamples(const Vec& p, const Vec& n, int k,
                               const std::vector<Model>& literals, double t, bool adaptive) {
  OffsetSamplePair out;
  out.inside = p - t * n;
  out.outside = p + t * n;
  if (!adaptive || k < 0 || k >= static_cast<int>(literals.size()) || literals.size() > 64)
    return out;
  double f;
  const Vec g = literals[k].Gradient(p, &f);
  const double g2 = g.squaredNorm();
  if (!(g2 > 0) || !std::isfinite(f)) return out;
  const Vec foot = p - (f / g2) * g;
  const Vec d = (g.dot(n) >= 0 ? 1.0 : -1.0) * g / std::sqrt(g2);
  const double first = t / 64;
  const int steps = 16;
  for (const double side : {-1.0, 1.0}) {
    auto at = [&](double u) { return Vec(foot + side * u * d); };
    const std::uint64_t reference = SignVector(literals, at(first));
    double agree = first, differ = -1;
    for (int m = 1; m <= steps; ++m) {
      const double u = t * m / steps;
      if (u <= first) continue;
      if (SignVector(literals, at(u)) != reference) {
        differ = u;
        break;
      }
      agree = u;
    }
    if (differ < 0) continue;  // no other surface within t: the fixed sample
    for (int b = 0; b < 20; ++b) {
      const double mid = 0.5 * (agree + differ);
      (SignVector(literals, at(mid)) == reference ? agree : differ) = mid;
    }
    const Vec sample = at(0.5 * (first + agree));
    if (side < 0) {
      out.inside = sample;
      out.inside_adapted = true;
    } else {
      out.outside = sample;
      out.outside_adapted = true;
    }
  }
  return out;
}

}  // namespace implicitfit
