#include "fit/detect/surface_merging.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "fit/detect/local_primitive_refit.h"
#include "fit/primitive/primitive_function.h"
#include "model/median.h"

namespace implicitfit {
namespace {

using Eigen::Vector3d;

constexpr size_t kMaxSample = 4000;      // points of a residual distribution (evenly spread)
constexpr double kMinSheetShare = 0.2;   // each sheet of a split holds this much
constexpr double kModeSeparation = 2.0;  // mu_2 - mu_1 > this * (s_1 + s_2)
constexpr double kMergeAngleDeg = 2.0;
constexpr double kMaxInterleave = 0.25;
constexpr double kMaxBandWidening = 10.0;  // tau_M <= this * tau
constexpr int kEmIterations = 60;

std::vector<int> Spread(const std::vector<int>& v, size_t count) {
  if (v.size() <= count) return v;
  std::vector<int> out;
  const double step = static_cast<double>(v.size()) / count;
  for (size_t k = 0; k < count; ++k) out.push_back(v[static_cast<size_t>(k * step)]);
  return out;
}

// Unit normal and offset of a plane's flat parameters (n . x = d after normalising).
void PlaneOf(const std::vector<double>& p, Vector3d* normal, double* offset) {
  const Vector3d n(p[0], p[1], p[2]);
  *normal = n.normalized();
  *offset = p[3] / n.norm();
}

double LogGauss(double r, double mu, double s) {
  const double z = (r - mu) / s;
  return -0.5 * z * z - std::log(s) - 0.5 * std::log(2 * M_PI);
}

struct Mixture {
  double mu1, mu2, s1, s2, w1;
  double log_likelihood;
};

// Two-Gaussian EM on r (sorted copy: quartile start).
Mixture FitTwoGaussians(std::vector<double> r, double floor) {
  std::sort(r.begin(), r.end());
  const size_t n = r.size();
  Mixture m{r[n / 4], r[3 * n / 4], 0, 0, 0.5, -INFINITY};
  const double spread = std::max(floor, 0.5 * (r[3 * n / 4] - r[n / 4]));
  m.s1 = m.s2 = spread;
  std::vector<double> g(n);
  for (int it = 0; it < kEmIterations; ++it) {
    double sw = 0, s1 = 0, s2 = 0, q1 = 0, q2 = 0;
    for (size_t i = 0; i < n; ++i) {
      const double a = std::log(m.w1) + LogGauss(r[i], m.mu1, m.s1);
      const double b = std::log(1 - m.w1) + LogGauss(r[i], m.mu2, m.s2);
      g[i] = 1.0 / (1.0 + std::exp(b - a));
      sw += g[i];
      s1 += g[i] * r[i];
      s2 += (1 - g[i]) * r[i];
    }
    if (!(sw > 1) || !(n - sw > 1)) break;
    m.w1 = sw / n;
    m.mu1 = s1 / sw;
    m.mu2 = s2 / (n - sw);
    for (size_t i = 0; i < n; ++i) {
      q1 += g[i] * (r[i] - m.mu1) * (r[i] - m.mu1);
      q2 += (1 - g[i]) * (r[i] - m.mu2) * (r[i] - m.mu2);
    }
    m.s1 = std::max(floor, std::sqrt(q1 / sw));
    m.s2 = std::max(floor, std::sqrt(q2 / (n - sw)));
  }
  if (m.mu1 > m.mu2) std::swap(m.mu1, m.mu2), std::swap(m.s1, m.s2), m.w1 = 1 - m.w1;
  m.log_likelihood = 0;
  for (double v : r) {
    const double a = std::log(m.w1) + LogGauss(v, m.mu1, m.s1);
    const double b = std::log(1 - m.w1) + LogGauss(v, m.mu2, m.s2);
    m.log_likelihood += std::max(a, b) + std::log1p(std::exp(-std::abs(a - b)));
  }
  return m;
}

std::vector<double> Residuals(const SurfaceMergeContext& c, const std::vector<double>& params,
                              const std::vector<int>& s) {
  const PrimitiveFunction f(NodeType::kPlane, params);
  std::vector<double> r;
  r.reserve(s.size());
  for (int i : s) r.push_back(f(c.x[i]));
  return r;
}

// The plane moved by mu along its unit normal.
std::vector<double> Offset(const std::vector<double>& p, double mu) {
  std::vector<double> q = p;
  q[3] += mu * Vector3d(p[0], p[1], p[2]).norm();
  return q;
}

void Refit(const SurfaceMergeContext& c, DetectedPrimitive* p) {
  std::vector<double> q = p->parameters;
  if (RefitPrimitiveLocally(NodeType::kPlane, c.x, Spread(p->points, 2000), &q, 30) >= 0) {
    bool finite = true;
    for (double v : q) finite = finite && std::isfinite(v);
    if (finite) p->parameters = q;
  }
}

}  // namespace

int SplitParallelSheets(const SurfaceMergeContext& c, std::vector<DetectedPrimitive>* primitives,
                        std::vector<int>* labels) {
  int splits = 0;
  const size_t K = primitives->size();
  for (size_t k = 0; k < K; ++k) {
    DetectedPrimitive& p = (*primitives)[k];
    if (p.kind != NodeType::kPlane || static_cast<int>(p.points.size()) < 2 * c.min_points)
      continue;
    const std::vector<double> r = Residuals(c, p.parameters, Spread(p.points, kMaxSample));
    const double n = static_cast<double>(r.size());
    const double mean = std::accumulate(r.begin(), r.end(), 0.0) / n;
    double var = 0;
    for (double v : r) var += (v - mean) * (v - mean);
    const double floor = 1e-9 * std::max(1.0, c.tau);
    const double s = std::max(floor, std::sqrt(var / n));
    double ll1 = 0;
    for (double v : r) ll1 += LogGauss(v, mean, s);
    const Mixture m = FitTwoGaussians(r, floor);
    const bool wins = -2 * m.log_likelihood + 5 * std::log(n) < -2 * ll1 + 2 * std::log(n);
    if (!wins || !(m.mu2 - m.mu1 > kModeSeparation * (m.s1 + m.s2)) ||
        std::min(m.w1, 1 - m.w1) < kMinSheetShare)
      continue;
    DetectedPrimitive q = p;
    p.parameters = Offset(p.parameters, m.mu1);
    q.parameters = Offset(q.parameters, m.mu2);
    const PrimitiveFunction fa(NodeType::kPlane, p.parameters), fb(NodeType::kPlane, q.parameters);
    std::vector<int> a, b;
    for (int i : p.points) (std::abs(fa(c.x[i])) <= std::abs(fb(c.x[i])) ? a : b).push_back(i);
    if (static_cast<int>(a.size()) < c.min_points || static_cast<int>(b.size()) < c.min_points)
      continue;
    p.points = std::move(a);
    q.points = std::move(b);
    Refit(c, &p);
    Refit(c, &q);
    const int id = static_cast<int>(primitives->size());
    for (int i : q.points) (*labels)[i] = id;
    primitives->push_back(std::move(q));
    ++splits;
  }
  return splits;
}

int MergeSameSurfaces(const SurfaceMergeContext& c, std::vector<DetectedPrimitive>* primitives,
                      std::vector<int>* labels, std::vector<double>* band,
                      std::vector<char>* multi_part) {
  std::vector<DetectedPrimitive>& P = *primitives;
  const int K = static_cast<int>(P.size());
  band->assign(K, c.tau);
  multi_part->assign(K, 0);
  std::vector<char> alive(K, 1);
  const double max_tan = std::tan(kMergeAngleDeg * M_PI / 180.0);
  const double cos_merge = std::cos(kMergeAngleDeg * M_PI / 180.0);
  std::vector<unsigned> stamp(c.x.size(), 0);
  unsigned current = 0;
  auto centroid = [&](const std::vector<int>& s) {
    Vector3d m = Vector3d::Zero();
    for (int i : s) m += c.x[i];
    return Vector3d(m / static_cast<double>(std::max<size_t>(1, s.size())));
  };
  // a and b connected through their points and the free points near plane f (within band,
  // normals agreeing): breadth-first from a.
  auto connected = [&](int a, int b, const PrimitiveFunction& f, double width) {
    if (++current == 0) std::fill(stamp.begin(), stamp.end(), 0), current = 1;
    std::vector<int> q;
    for (int i : P[a].points) stamp[i] = current, q.push_back(i);
    for (size_t h = 0; h < q.size(); ++h)
      for (int j : c.nb[q[h]]) {
        if (stamp[j] == current) continue;
        stamp[j] = current;
        const int l = (*labels)[j];
        if (l == b) return true;
        if (l != -1) continue;
        Vector3d g;
        const double r = f(c.x[j], &g);
        if (std::abs(r) < width && std::abs(g.normalized().dot(c.n[j])) >= c.cos_theta)
          q.push_back(j);
      }
    return false;
  };
  auto interleaved = [&](int a, int b) {  // share of the smaller piece touching the other
    const int small = P[a].points.size() < P[b].points.size() ? a : b, other = a + b - small;
    const std::vector<int> s = Spread(P[small].points, 2000);
    int touching = 0;
    for (int i : s)
      for (size_t k = 0; k < std::min<size_t>(8, c.nb[i].size()); ++k)
        if ((*labels)[c.nb[i][k]] == other) {
          ++touching;
          break;
        }
    return touching > kMaxInterleave * s.size();
  };
  int merges = 0;
  for (bool changed = true; changed;) {
    changed = false;
    std::vector<std::pair<size_t, std::pair<int, int>>> pairs;
    for (int a = 0; a < K; ++a)
      for (int b = a + 1; b < K; ++b) {
        if (!alive[a] || !alive[b] || P[a].kind != NodeType::kPlane ||
            P[b].kind != NodeType::kPlane)
          continue;
        Vector3d na, nb;
        double da, db;
        PlaneOf(P[a].parameters, &na, &da);
        PlaneOf(P[b].parameters, &nb, &db);
        if (std::abs(na.dot(nb)) < cos_merge) continue;
        pairs.push_back({P[a].points.size() + P[b].points.size(), {a, b}});
      }
    std::stable_sort(pairs.begin(), pairs.end(),
                     [](const auto& u, const auto& v) { return u.first > v.first; });
    for (const auto& [size, ab] : pairs) {
      const auto [a, b] = ab;
      if (!alive[a] || !alive[b]) continue;
      std::vector<int> both = P[a].points;
      both.insert(both.end(), P[b].points.begin(), P[b].points.end());
      std::vector<double> m = P[a].points.size() >= P[b].points.size() ? P[a].parameters
                                                                        : P[b].parameters;
      if (RefitPrimitiveLocally(NodeType::kPlane, c.x, Spread(both, 2000), &m, 30) < 0) continue;
      Vector3d nm;
      double dm;
      PlaneOf(m, &nm, &dm);
      const double ra = Median(Residuals(c, m, Spread(P[a].points, 1000)));
      const double rb = Median(Residuals(c, m, Spread(P[b].points, 1000)));
      Vector3d d = centroid(P[a].points) - centroid(P[b].points);
      d -= d.dot(nm) * nm;
      if (std::abs(ra - rb) > std::max(2 * c.tau, max_tan * d.norm())) continue;
      if (interleaved(a, b)) continue;
      std::vector<double> all = Residuals(c, m, Spread(both, kMaxSample));
      const double med = Median(all);
      for (double& v : all) v = std::abs(v - med);
      const double width = std::min(kMaxBandWidening * c.tau,
                                    std::max(c.tau, 3 * 1.4826 * Median(all)));
      if (!connected(a, b, PrimitiveFunction(NodeType::kPlane, m), width)) continue;
      for (int i : P[b].points) (*labels)[i] = a;
      P[a].points = std::move(both);
      std::sort(P[a].points.begin(), P[a].points.end());
      P[a].parameters = m;
      P[b].points.clear();
      alive[b] = 0;
      (*band)[a] = std::max((*band)[a], width);
      (*multi_part)[a] = 1;
      ++merges;
      changed = true;
    }
  }
  // Compact: the merged-away primitives go.
  std::vector<int> new_id(K, -1);
  std::vector<DetectedPrimitive> kept;
  std::vector<double> kept_band;
  std::vector<char> kept_multi;
  for (int k = 0; k < K; ++k)
    if (alive[k]) {
      new_id[k] = static_cast<int>(kept.size());
      kept.push_back(std::move(P[k]));
      kept_band.push_back((*band)[k]);
      kept_multi.push_back((*multi_part)[k]);
    }
  for (int& l : *labels)
    if (l >= 0) l = new_id[l];
  P = std::move(kept);
  *band = std::move(kept_band);
  *multi_part = std::move(kept_multi);
  return merges;
}

}  // namespace implicitfit
