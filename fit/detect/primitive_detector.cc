#include "fit/detect/primitive_detector.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <limits>
#include <numeric>
#include <random>
#include <stdexcept>
#include <thread>
#include <unordered_map>

#include "fit/detect/detection_scales.h"
#include "fit/detect/local_primitive_refit.h"
#include "fit/primitive/minimal_samples.h"
#include "fit/detect/patch_hypotheses.h"
#include "fit/primitive/primitive_fitter.h"
#include "fit/primitive/primitive_function.h"
#include "fit/detect/restricted_normals.h"
#include "fit/detect/surface_merging.h"
#include "fit/common/thread_count.h"
#include "model/median.h"
#include "model/worker_threads.h"

namespace implicitfit {
namespace {

using Eigen::Vector3d;

constexpr int kMaxRefitPoints = 2000;  // points of a growth refit (evenly spread subset)
constexpr int kMaxCostPoints = 4000;   // points of the kind-selection cost
constexpr size_t kMaxRefinePoints = 100000;  // points of the final ML refinement (subset above)
constexpr int kGrowthRounds = 8;       // refit-and-regrow rounds of one candidate
// Each kind's growth from a seed stops at this many points (breadth-first from the seed's patch:
// a local region is enough for the refit, which uses kMaxRefitPoints of them, and for the kind
// choice); the winning kind's support is grown without limit once, when the candidate is accepted
// (over the points still free then: a conflicting candidate is never completed). Above every
// benchmark cloud's size (31 374 points), so it only changes large clouds, where each kind's
// every refit round regrew the whole support (10^6 points: growth took about 55% of the time).
constexpr size_t kMaxGrowthPoints = 50000;
constexpr double kKeepFraction = 0.8;       // a candidate is accepted if this much is still free
constexpr double kSimplerFraction = 0.97;   // a simpler kind explaining this much wins
constexpr double kMaxRmsSigmas = 2.0;       // a candidate's RMS must stay under this * sigma
constexpr double kFarFactor = 10.0;         // shapes beyond this many cloud diagonals: degenerate
constexpr int kFallbackSteps = 3;           // crease points join a primitive this close
constexpr double kMergeFraction = 0.8;  // pieces merge when each explains this much of the other
constexpr int kMaxSplitPieces = 3;      // primitives of the split test's alternative
// A simpler curved kind replaces the winner only if its penalised cost is at most this times
// the winner's (a sphere through a short cylindrical band explains its points within the band but
// leaves the band's sagitta in its residuals: 26 times the cylinder's cost on Fit4CAD PC155).
constexpr double kSimplerCostRatio = 2.0;
constexpr double kRetryBand = 0.5;         // band (x tau) of the retried growth of a candidate
constexpr int kMinFreeSeedNeighbours = 3;  // leftover pass: free neighbours a seed is checked on

// Degrees of freedom of a kind (the BIC penalty).
int DegreesOfFreedom(NodeType kind) {
  switch (kind) {
    case NodeType::kPlane:
      return 3;
    case NodeType::kSphere:
      return 4;
    case NodeType::kCylinder:
      return 5;
    case NodeType::kCone:
      return 6;
    default:
      return 7;
  }
}

// Minimal sample size of a kind (fit/primitive/minimal_samples.h).
int SampleSize(NodeType kind) {
  switch (kind) {
    case NodeType::kPlane:
      return 1;
    case NodeType::kSphere:
    case NodeType::kCylinder:
      return 2;
    case NodeType::kCone:
      return 3;
    default:
      return 7;
  }
}

// Shifts a primitive's parameters by +shift (the detector works on recentred points).
void Translate(NodeType kind, std::vector<double>* p, const Vector3d& shift) {
  if (kind == NodeType::kPlane) {
    const Vector3d n((*p)[0], (*p)[1], (*p)[2]);
    (*p)[3] += n.dot(shift) / n.norm();
    return;
  }
  for (int k = 0; k < 3; ++k) (*p)[k] += shift[k];
}

// At most `count` entries of v, evenly spread (deterministic).
std::vector<int> Spread(const std::vector<int>& v, size_t count) {
  if (v.size() <= count) return v;
  std::vector<int> out;
  out.reserve(count);
  const double step = static_cast<double>(v.size()) / count;
  for (size_t k = 0; k < count; ++k) out.push_back(v[static_cast<size_t>(k * step)]);
  return out;
}

// Runs body(i, worker) for i in [0, count) on `threads` threads; worker in [0, threads).
template <typename Body>
void ParallelFor(int count, int threads, Body body) {
  // At most 256 (more cannot be faster on any machine this runs on; huge requests would spend
  // their time starting threads); RunWorkers copes with the ones the system refuses.
  threads = std::max(1, std::min({threads, count, 256}));
  if (threads == 1) {
    for (int i = 0; i < count; ++i) body(i, 0);
    return;
  }
  RunWorkers(threads, [&](int t) {
    for (int i = t; i < count; i += threads) body(i, t);
  });
}

struct Scales {
  double tau, cos_theta, sigma;
};

class Detector {
 public:
  Detector(const std::vector<Vector3d>& x, const std::vector<Vector3d>& n,
           const NeighbourGraph& nb, const Scales& scales, int min_points,
           const DetectionOptions& options)
      : x_(x),
        input_n_(n),
        n_(&n),
        nb_(nb),
        tau_(scales.tau),
        cos_(scales.cos_theta),
        sigma_(scales.sigma),
        min_points_(min_points),
        options_(options),
        labels_(x.size(), -1) {}

  // Progress line (options_.progress), and a figure for the seed rounds.
  void Tell(const std::string& message) const {
    if (options_.progress) options_.progress(message);
  }
  std::string Assigned() const {
    size_t assigned = 0;
    for (int l : labels_) assigned += l >= 0;
    char line[120];
    std::snprintf(line, sizeof line, "%zu primitives, %zu of %zu points assigned",
                  primitives_.size(), assigned, labels_.size());
    return line;
  }

  // The truncated-Gaussian cost of a residual r (the kind selection's likelihood).
  double Cost(double r) const {
    return std::min(r * r / (sigma_ * sigma_), (tau_ / sigma_) * (tau_ / sigma_));
  }

  bool Supports(const PrimitiveFunction& f, int i) const { return Supports(f, i, tau_); }
  bool Supports(const PrimitiveFunction& f, int i, double band) const {
    Vector3d g;
    const double r = f(x_[i], &g);
    if (!(std::abs(r) < band)) return false;
    const double gn = g.norm();
    return gn > 0 && std::abs(g.dot((*n_)[i])) >= cos_ * gn;
  }

  struct Workspace {
    std::vector<unsigned> stamp;
    unsigned current = 0;
    // Growth restricted to a region (the split test): points whose region stamp differs are
    // treated as taken.
    std::vector<unsigned> region;
    unsigned region_id = 0;
    bool restricted = false;
    void Restrict(const std::vector<int>& points, size_t n) {
      if (region.size() != n) region.assign(n, 0), region_id = 0;
      if (++region_id == 0) {
        std::fill(region.begin(), region.end(), 0);
        region_id = 1;
      }
      for (int i : points) region[i] = region_id;
      restricted = true;
    }
    bool Blocked(int i) const { return restricted && region[i] != region_id; }
    void Next(size_t n) {
      if (stamp.size() != n) stamp.assign(n, 0), current = 0;
      if (++current == 0) {
        std::fill(stamp.begin(), stamp.end(), 0);
        current = 1;
      }
    }
  };

  // The free points connected to `sources` through points that support f.
  // Breadth-first: with a `limit`, the first `limit` of them (the nearest along the graph).
  std::vector<int> Grow(const PrimitiveFunction& f, const std::vector<int>& sources, Workspace& w,
                        double band, size_t limit = SIZE_MAX) const {
    w.Next(x_.size());
    std::vector<int> out;
    for (int s : sources) {
      if (labels_[s] >= 0 || w.Blocked(s) || w.stamp[s] == w.current) continue;
      w.stamp[s] = w.current;
      if (Supports(f, s, band)) out.push_back(s);
    }
    for (size_t h = 0; h < out.size() && out.size() < limit; ++h)
      for (int j : nb_[out[h]]) {
        if (labels_[j] >= 0 || w.Blocked(j) || w.stamp[j] == w.current) continue;
        w.stamp[j] = w.current;
        if (Supports(f, j, band)) out.push_back(j);
      }
    return out;
  }

  // The first `size` free points reached from the seed over the neighbour graph.
  std::vector<int> Patch(int seed, Workspace& w) const {
    w.Next(x_.size());
    std::vector<int> out = {seed};
    w.stamp[seed] = w.current;
    for (size_t h = 0; h < out.size() && static_cast<int>(out.size()) < options_.patch_size; ++h)
      for (int j : nb_[out[h]]) {
        if (labels_[j] >= 0 || w.Blocked(j) || w.stamp[j] == w.current) continue;
        w.stamp[j] = w.current;
        out.push_back(j);
        if (static_cast<int>(out.size()) >= options_.patch_size) break;
      }
    return out;
  }

  bool Hypothesis(NodeType kind, const std::vector<int>& patch, std::mt19937& rng,
                  std::vector<double>* h) const {
    std::uniform_int_distribution<size_t> pick(0, patch.size() - 1);
    const int m = SampleSize(kind);
    std::vector<Vec3> p, q;
    for (int s = 0; s < m; ++s) {
      const int i = patch[pick(rng)];
      p.push_back(x_[i]);
      q.push_back((*n_)[i]);
    }
    switch (kind) {
      case NodeType::kPlane:
        return PlaneFromSample(p[0], q[0], h);
      case NodeType::kSphere:
        return SphereFromSample(p.data(), q.data(), h);
      case NodeType::kCylinder:
        return CylinderFromSample(p.data(), q.data(), h);
      case NodeType::kCone:
        return ConeFromSample(p.data(), q.data(), h);
      case NodeType::kTorus:
        return TorusFromSample(p, q, h);
      default:
        return false;
    }
  }

  // Centres, apices and radii within kFarFactor cloud diagonals of the (recentred) cloud.
  bool Reasonable(NodeType kind, const std::vector<double>& p) const {
    const double limit = kFarFactor * diagonal_;
    if (kind == NodeType::kPlane) return true;
    Vector3d c(p[0], p[1], p[2]);
    if (kind == NodeType::kCylinder) {  // any point of the axis: its distance to the origin
      const Vector3d a = Vector3d(p[3], p[4], p[5]).normalized();
      c -= c.dot(a) * a;
    }
    if (c.norm() > limit) return false;
    if (kind == NodeType::kSphere) return p[3] < limit;
    if (kind == NodeType::kCylinder) return p[6] < limit;
    if (kind == NodeType::kTorus) return p[6] < limit && p[7] < limit;
    return true;
  }

  bool Finite(const std::vector<double>& p) const {
    for (double v : p)
      if (!std::isfinite(v)) return false;
    return true;
  }

  // A sphere and a cylinder that coincide along a great circle (the sphere's centre on the axis
  // and the radii equal, within tau): on a narrow band around that circle (its height 2h with
  // sagitta h^2 / 2R below tau) they are the same surface within the band, and only the BIC
  // penalty (sphere 4, cylinder 5 degrees of freedom) separates them.
  bool SphereZoneOfCylinder(const std::vector<double>& sphere,
                            const std::vector<double>& cylinder) const {
    const Vector3d a = Vector3d(cylinder[3], cylinder[4], cylinder[5]).normalized();
    const Vector3d d =
        Vector3d(sphere[0] - cylinder[0], sphere[1] - cylinder[1], sphere[2] - cylinder[2]);
    return (d - d.dot(a) * a).norm() < tau_ && std::abs(sphere[3] - cylinder[6]) < tau_;
  }

  bool CylinderKindAllowed() const {
    return std::find(options_.kinds.begin(), options_.kinds.end(), NodeType::kCylinder) !=
           options_.kinds.end();
  }

  // A sphere's support that is only a narrow band around a circle (a cylinder ring one or two
  // rows high) does not tell a sphere from a cylinder: the sphere's curvature across the band is
  // below the distance band, and only the BIC penalty (sphere 4, cylinder 5 degrees of freedom)
  // picked the sphere. Parts have such cylindrical bands between two faces; a sphere is
  // identified by a support curved in every direction. The band's cylinder: axis along the
  // support's direction of least spread (the normal of the circle's plane) through the sphere's
  // centre, radius the mean distance to it, least-squares refitted; the support is a band when
  // that cylinder's RMS stays within kMaxRmsSigmas sigma (a candidate's own acceptance rule).
  // A spherical cap or zone of measurable curvature across leaves an RMS of its sagitta.
  bool BandCylinder(const std::vector<int>& support, std::vector<double>* cylinder) const {
    if (support.size() < 8) return false;
    const std::vector<int> s = Spread(support, kMaxRefitPoints);
    Vector3d mean = Vector3d::Zero();
    for (int i : s) mean += x_[i];
    mean /= static_cast<double>(s.size());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (int i : s) cov += (x_[i] - mean) * (x_[i] - mean).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
    const Vector3d a = eig.eigenvectors().col(0);
    double radius = 0;
    for (int i : s) {
      const Vector3d d = x_[i] - mean;
      radius += (d - d.dot(a) * a).norm();
    }
    radius /= static_cast<double>(s.size());
    std::vector<double> q = {mean.x(), mean.y(), mean.z(), a.x(), a.y(), a.z(), radius};
    const double rms = RefitPrimitiveLocally(NodeType::kCylinder, x_, s, &q, 30);
    if (!(rms >= 0 && rms <= kMaxRmsSigmas * sigma_) || !Finite(q) ||
        !Reasonable(NodeType::kCylinder, q))
      return false;
    *cylinder = std::move(q);
    return true;
  }

  struct Grown {
    std::vector<double> params;
    std::vector<int> support;
    bool capped = false;       // support stopped at kMaxGrowthPoints
    std::vector<int> sources;  // then: where to grow it from again,
    double band = 0.0;         // and in which band
  };

  // Best hypothesis of `kind` on the patch, refitted and grown.
  Grown GrowKind(NodeType kind, const std::vector<int>& patch, std::mt19937& rng,
                 Workspace& w) const {
    Grown best;
    std::vector<double> h;
    int best_score = 0;
    double best_residual = INFINITY;
    std::vector<double> params;
    const int tries =
        kind == NodeType::kPlane ? std::max(4, options_.hypotheses / 3) : options_.hypotheses;
    // Try 0: the fit to the whole patch (fit/detect/patch_hypotheses.h), then minimal samples.
    std::vector<Vector3d> px, pn;
    for (int i : patch) px.push_back(x_[i]), pn.push_back((*n_)[i]);
    for (int t = -1; t < tries; ++t) {
      if (t < 0) {
        const bool ok = kind == NodeType::kPlane      ? PlaneFromPatch(px, pn, &h)
                        : kind == NodeType::kSphere   ? SphereFromPatch(px, pn, &h)
                        : kind == NodeType::kCylinder ? CylinderFromPatch(px, pn, &h)
                                                      : false;
        if (!ok || !Finite(h)) continue;
      } else if (!Hypothesis(kind, patch, rng, &h) || !Finite(h)) {
        continue;
      }
      // Score: supported patch points; ties (every hypothesis through a small patch may hold
      // all of it) go to the smallest sum of squared residuals over them (the most accurate).
      const PrimitiveFunction f(kind, h);
      int score = 0;
      double residual = 0;
      for (int i : patch)
        if (Supports(f, i)) {
          ++score;
          const double r = f(x_[i]);
          residual += r * r;
        }
      if (score > best_score || (score == best_score && residual < best_residual))
        best_score = score, best_residual = residual, params = h;
    }
    if (best_score < std::min<int>(8, patch.size() / 2)) return best;
    // Growth within a distance band; a growth whose RMS shows it crossed a tangent joint (the
    // surface leaves the model slowly, so the band is crossed gradually) is retried once in half
    // the band, which stops it nearer the joint.
    const std::vector<double> start = params;
    for (double band : {tau_, kRetryBand * tau_}) {
      params = start;
      best = Grown();
      auto patch_support = [&](const std::vector<double>& p) {
        const PrimitiveFunction f(kind, p);
        std::vector<int> s;
        for (int i : patch)
          if (Supports(f, i, band)) s.push_back(i);
        return s;
      };
      {  // Refit on the patch support first.
        std::vector<double> refit = params;
        std::vector<int> s = patch_support(params);
        if (RefitPrimitiveLocally(kind, x_, s, &refit) >= 0 && Finite(refit) &&
            patch_support(refit).size() >= s.size())
          params = refit;
      }
      std::vector<int> sources = patch_support(params);
      best.params = params;
      best.support = Grow(PrimitiveFunction(kind, params), sources, w, band, kMaxGrowthPoints);
      for (int round = 0; round < kGrowthRounds; ++round) {
        std::vector<double> refit = best.params;
        if (RefitPrimitiveLocally(kind, x_, Spread(best.support, kMaxRefitPoints), &refit) < 0 ||
            !Finite(refit))
          break;
        std::vector<int> s = patch_support(refit);
        if (s.empty()) break;
        std::vector<int> grown = Grow(PrimitiveFunction(kind, refit), s, w, band, kMaxGrowthPoints);
        if (grown.size() <= best.support.size()) break;
        const bool small_gain = grown.size() < 1.02 * best.support.size();
        best.params = std::move(refit);
        best.support = std::move(grown);
        if (small_gain) break;
      }
      // The least-squares fit to the final support (the kind selection compares fitted models).
      std::vector<double> refit = best.params;
      const std::vector<int> spread = Spread(best.support, kMaxRefitPoints);
      const double rms = RefitPrimitiveLocally(kind, x_, spread, &refit, 30);
      if (rms >= 0 && Finite(refit)) best.params = std::move(refit);
      // A growth stopped at kMaxGrowthPoints is completed when its candidate is accepted.
      best.band = band;
      best.capped = best.support.size() >= kMaxGrowthPoints;
      if (best.capped) best.sources = patch_support(best.params);
      // A right model leaves the noise (RMS ~ sigma); a wrong one that happens to cross the band
      // (a cone through the faces at a vertex) spreads its residuals over it (RMS ~ tau / sqrt 3).
      // Far-off (degenerate) shapes, e.g. a torus of radius 1e13 imitating a cone, are dropped.
      if (rms <= kMaxRmsSigmas * sigma_ && Reasonable(kind, best.params)) return best;
    }
    best.support.clear();
    return best;
  }

  struct Candidate {
    NodeType kind = NodeType::kPlane;
    std::vector<double> params;
    std::vector<int> support;
    // A support stopped at kMaxGrowthPoints: completed (grown without limit from `sources` in
    // `band`) only when the candidate is accepted, over the points still free then.
    bool capped = false;
    std::vector<int> sources;
    double band = 0.0;
    std::vector<int> patch;
  };

  // The whole support of a capped candidate over the points free now, refitted and regrown
  // while it grows by 2% or more (the refit of a growth stopped at kMaxGrowthPoints saw only
  // the region around its seed: a plane's small tilt there leaves the band far away and would
  // cut a large face in two). Sorted.
  std::vector<int> CompleteSupport(Candidate* c, Workspace& w) const {
    std::vector<int> support = Grow(PrimitiveFunction(c->kind, c->params), c->sources, w, c->band);
    for (int round = 0; round < kGrowthRounds; ++round) {
      std::vector<double> refit = c->params;
      if (RefitPrimitiveLocally(c->kind, x_, Spread(support, kMaxRefitPoints), &refit, 30) < 0 ||
          !Finite(refit) || !Reasonable(c->kind, refit))
        break;
      std::vector<int> grown = Grow(PrimitiveFunction(c->kind, refit), c->sources, w, c->band);
      if (grown.size() < 1.02 * support.size()) break;
      c->params = std::move(refit);
      support = std::move(grown);
    }
    std::sort(support.begin(), support.end());
    return support;
  }

  // Seedable: the point's normal agrees (within theta) with those of its first 8 neighbours; in
  // the leftover pass, with those of them that are free (at least kMinFreeSeedNeighbours).
  bool Seedable(int i) const {
    if (nb_[i].empty()) return false;
    int compared = 0;
    for (size_t k = 0; k < std::min<size_t>(8, nb_[i].size()); ++k) {
      const int j = nb_[i][k];
      if (leftover_pass_ && labels_[j] >= 0) continue;
      if (std::abs((*n_)[i].dot((*n_)[j])) < cos_) return false;
      ++compared;
    }
    return !leftover_pass_ || compared >= kMinFreeSeedNeighbours;
  }

  // The split test of a curved winner W grown on U = `all` (u: its evenly spread subset, each
  // standing for `scale` points). Alternatives: each of the seed's candidates of a simpler kind
  // (fewer degrees of freedom than W) as piece 1, then up to kMaxSplitPieces - 1 primitives of
  // simpler kinds grown (the largest support, ties to the simpler kind) from a seed on what the
  // previous pieces leave of U, growth restricted to it. W and the alternatives are scored by
  // the penalised truncated-Gaussian likelihood of the kind selection, each point costing its
  // smallest residual over the pieces:
  //   C_W     = sum_{i in u} min(r_iW^2 / s^2, cap) scale + p_W ln |U|,
  //   C_split = sum_{i in u} min_j min(r_ij^2 / s^2, cap) scale + sum_j p_j ln |U|.
  // A surface that really is W leaves simpler pieces that cover only part of it, at residuals
  // above the noise (capped cost for the rest), so W wins; a torus spanning a cylinder and a
  // tangent plane, or a flat cone over the faces at a polyhedron's vertex, leaves exact pieces.
  // Returns the piece 1 (index in `grown`) of the cheapest alternative cheaper than W, else -1.
  int SplitTest(size_t winner, const std::vector<Grown>& grown, const std::vector<NodeType>& kinds,
                const std::vector<int>& all, const std::vector<int>& u, double scale,
                std::mt19937& rng, Workspace& w) const {
    auto allowed = [&](NodeType k) {
      return DegreesOfFreedom(k) < DegreesOfFreedom(kinds[winner]);
    };
    const double ln_u = std::log(static_cast<double>(all.size()));
    auto cost_of = [&](const std::vector<PrimitiveFunction>& pieces, int dof) {
      double cost = 0;
      for (int i : u) {
        double c = Cost(INFINITY);  // the cap
        for (const auto& f : pieces) c = std::min(c, Cost(f(x_[i])));
        cost += c;
      }
      return cost * scale + dof * ln_u;
    };
    const double cost_w = cost_of({PrimitiveFunction(kinds[winner], grown[winner].params)},
                                  DegreesOfFreedom(kinds[winner]));
    double best_cost = cost_w;
    int best_first = -1;
    for (size_t first = 0; first < grown.size(); ++first) {
      if (first == winner || !allowed(kinds[first])) continue;
      std::vector<PrimitiveFunction> pieces = {
          PrimitiveFunction(kinds[first], grown[first].params)};
      int dof = DegreesOfFreedom(kinds[first]);
      std::vector<int> rest;
      {
        std::vector<int> taken = grown[first].support;
        std::sort(taken.begin(), taken.end());
        std::set_difference(all.begin(), all.end(), taken.begin(), taken.end(),
                            std::back_inserter(rest));
      }
      for (int piece = 1; piece < kMaxSplitPieces; ++piece) {
        if (static_cast<int>(rest.size()) < std::max(min_points_, 8)) break;
        int seed = -1;
        std::uniform_int_distribution<size_t> pick(0, rest.size() - 1);
        for (int t = 0; t < 10 && seed < 0; ++t) {
          const int i = rest[pick(rng)];
          if (Seedable(i)) seed = i;
        }
        if (seed < 0) break;
        w.Restrict(rest, x_.size());
        const std::vector<int> patch = Patch(seed, w);
        Grown g;
        NodeType kind = NodeType::kPlane;
        if (static_cast<int>(patch.size()) >= std::min(options_.patch_size, 8))
          for (NodeType k : options_.kinds) {
            if (!allowed(k)) continue;
            Grown h = GrowKind(k, patch, rng, w);
            if (h.support.size() > g.support.size() * (1.0 / kSimplerFraction))
              g = std::move(h), kind = k;
          }
        w.restricted = false;
        if (g.support.empty()) break;
        pieces.emplace_back(kind, g.params);
        dof += DegreesOfFreedom(kind);
        std::sort(g.support.begin(), g.support.end());
        std::vector<int> left;
        std::set_difference(rest.begin(), rest.end(), g.support.begin(), g.support.end(),
                            std::back_inserter(left));
        rest = std::move(left);
      }
      const double cost = cost_of(pieces, dof);
      if (cost < best_cost) best_cost = cost, best_first = static_cast<int>(first);
    }
    return best_first;
  }

  // The candidate of one seed: every kind grown, the kind chosen by the penalised likelihood.
  Candidate Propose(int seed, std::mt19937& rng, Workspace& w) const {
    Candidate c;
    c.patch = Patch(seed, w);
    if (static_cast<int>(c.patch.size()) < std::min(options_.patch_size, 8)) return c;
    std::vector<Grown> grown;
    std::vector<NodeType> kinds;
    for (NodeType kind : options_.kinds) {
      Grown g = GrowKind(kind, c.patch, rng, w);
      if (g.support.empty()) continue;
      grown.push_back(std::move(g));
      kinds.push_back(kind);
    }
    if (grown.empty()) return c;
    std::vector<int> all;
    for (const Grown& g : grown) all.insert(all.end(), g.support.begin(), g.support.end());
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    const std::vector<int> u = Spread(all, kMaxCostPoints);
    const double scale = all.size() / static_cast<double>(u.size());
    double best_cost = INFINITY;
    size_t best = 0;
    std::vector<double> costs(grown.size());
    for (size_t k = 0; k < grown.size(); ++k) {
      const PrimitiveFunction f(kinds[k], grown[k].params);
      double cost = 0;
      for (int i : u) cost += Cost(f(x_[i]));
      cost = cost * scale + DegreesOfFreedom(kinds[k]) * std::log(static_cast<double>(all.size()));
      costs[k] = cost;
      if (cost < best_cost) best_cost = cost, best = k;
    }
    // The simplest kind that explains (within the bands) at least kSimplerFraction as many
    // points of U as the winner replaces it: differences below the detection tolerance do not
    // buy parameters (a plane beats a huge-radius sphere on a slightly bulging face). A curved
    // simpler kind must also cost at most kSimplerCostRatio times the winner's cost.
    std::vector<int> explained(grown.size(), 0);
    for (size_t k = 0; k < grown.size(); ++k) {
      const PrimitiveFunction f(kinds[k], grown[k].params);
      for (int i : u) explained[k] += Supports(f, i);
    }
    const size_t winner = best;
    for (size_t k = 0; k < grown.size(); ++k)
      if (DegreesOfFreedom(kinds[k]) < DegreesOfFreedom(kinds[best]) &&
          explained[k] >= kSimplerFraction * explained[winner] &&
          (kinds[k] == NodeType::kPlane || costs[k] <= kSimplerCostRatio * costs[winner]))
        best = k;
    // A sphere winner whose support a cylinder fits as well (BandCylinder) becomes that cylinder
    // after the split test (see BandCylinder).
    // Split test: a curved winner that grew across a tangent joint is better explained by the
    // seed's other candidate plus primitives found on the rest of U.
    if (kinds[best] != NodeType::kPlane) {
      const int first = SplitTest(best, grown, kinds, all, u, scale, rng, w);
      if (first >= 0) best = first;
    }
    c.kind = kinds[best];
    c.params = std::move(grown[best].params);
    c.support = std::move(grown[best].support);
    c.capped = grown[best].capped;
    c.sources = std::move(grown[best].sources);
    c.band = grown[best].band;
    std::vector<double> band;
    if (c.kind == NodeType::kSphere && CylinderKindAllowed() && BandCylinder(c.support, &band))
      c.kind = NodeType::kCylinder, c.params = std::move(band);
    std::sort(c.support.begin(), c.support.end());
    return c;
  }

  // The first pass, then the leftover pass: the points the first pass left free get normals
  // re-estimated from their free neighbours only (fit/detect/restricted_normals.h), and seeds are drawn
  // among them (seedable against their free neighbours). A narrow surface between two faces (a
  // cylinder ring two rows high, Fit4CAD PC34) has no seedable point in the first pass: its
  // estimated normals are smeared by the faces beside it. Points the leftover pass does not
  // assign get their original normals back.
  void Run(DetectionResult* result) {
    const int N = static_cast<int>(x_.size());
    std::vector<int> pool;
    for (int i = 0; i < N; ++i)
      if (Seedable(i)) pool.push_back(i);
    Tell("first pass: seeds among " + std::to_string(pool.size()) + " points");
    Rounds(std::move(pool), 0, result);
    Tell("first pass done: " + Assigned());
    std::vector<char> free(N, 0);
    int free_points = 0;
    for (int i = 0; i < N; ++i) free_points += free[i] = labels_[i] < 0;
    if (free_points < min_points_) return;
    const std::vector<Vector3d> restricted = RestrictedNormals(x_, input_n_, nb_, free);
    n_ = &restricted;
    leftover_pass_ = true;
    pool.clear();
    for (int i = 0; i < N; ++i)
      if (free[i] && Seedable(i)) pool.push_back(i);
    Tell("leftover pass: seeds among " + std::to_string(pool.size()) + " free points");
    Rounds(std::move(pool), 1, result);
    Tell("leftover pass done: " + Assigned());
    leftover_pass_ = false;
    n_ = &input_n_;
    bool assigned = false;
    for (int i = 0; i < N && !assigned; ++i) assigned = free[i] && labels_[i] >= 0;
    if (assigned) {  // points the leftover pass assigned keep their re-estimated normals
      own_n_ = input_n_;
      for (int i = 0; i < N; ++i)
        if (free[i] && labels_[i] >= 0) own_n_[i] = restricted[i];
      n_ = &own_n_;
    }
  }

  // Seed rounds from `pool` (seedable points) until the stop rule; `pass` enters the seeds' RNGs.
  void Rounds(std::vector<int> pool, unsigned pass, DetectionResult* result) {
    const int N = static_cast<int>(x_.size());
    const int threads = ThreadCountOrDefault(options_.num_threads);
    std::vector<Workspace> workspaces(threads);
    std::vector<char> tried(N, 0);
    std::mt19937 rng(options_.seed + pass);
    int free_points = 0, failures = 0;
    auto last_told = std::chrono::steady_clock::now();
    for (int i = 0; i < N; ++i) free_points += labels_[i] < 0;
    for (int round = 0; !pool.empty(); ++round) {
      // Seeds: uniform among the untried free seedable points (ineligible ones are dropped lazily).
      std::vector<int> seeds;
      while (static_cast<int>(seeds.size()) < options_.seeds_per_round && !pool.empty()) {
        std::uniform_int_distribution<size_t> pick(0, pool.size() - 1);
        const size_t k = pick(rng);
        const int i = pool[k];
        pool[k] = pool.back();
        pool.pop_back();
        if (labels_[i] < 0 && !tried[i]) seeds.push_back(i);
      }
      if (seeds.empty()) break;
      std::vector<Candidate> candidates(seeds.size());
      ParallelFor(static_cast<int>(seeds.size()), threads, [&](int b, int t) {
        // The first pass's sequence is unchanged by the leftover pass (same results before it).
        std::vector<unsigned> words = {options_.seed, static_cast<unsigned>(round),
                                       static_cast<unsigned>(b)};
        if (pass > 0) words.push_back(pass);
        std::seed_seq seq(words.begin(), words.end());
        std::mt19937 local(seq);
        candidates[b] = Propose(seeds[b], local, workspaces[t]);
      });
      result->seeds += static_cast<int>(seeds.size());
      std::vector<int> order(seeds.size());
      std::iota(order.begin(), order.end(), 0);
      std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        return candidates[a].support.size() > candidates[b].support.size();
      });
      for (int b : order) {
        Candidate& c = candidates[b];
        if (static_cast<int>(c.support.size()) < min_points_) {
          for (int i : c.patch) tried[i] = 1;
          tried[seeds[b]] = 1;
          ++failures;
          continue;
        }
        std::vector<int> free;
        for (int i : c.support)
          if (labels_[i] < 0) free.push_back(i);
        if (free.size() < kKeepFraction * c.support.size() ||
            static_cast<int>(free.size()) < min_points_) {
          pool.push_back(seeds[b]);  // conflicted: may be seeded again
          continue;
        }
        if (c.capped) free = CompleteSupport(&c, workspaces[0]);
        const int id = static_cast<int>(primitives_.size());
        for (int i : free) labels_[i] = id;
        free_points -= static_cast<int>(free.size());
        primitives_.push_back({c.kind, std::move(c.params), {}, std::move(free), 0.0, "unknown"});
        ++result->candidates_accepted;
        failures = 0;
      }
      if (options_.progress &&
          std::chrono::steady_clock::now() - last_told > std::chrono::seconds(3)) {
        last_told = std::chrono::steady_clock::now();
        Tell("  " + std::to_string(result->seeds) + " seeds: " + Assigned());
      }
      // Stop once a primitive of min_points points among the free ones would have been seeded
      // with 99% probability by the failed seeds in a row.
      if (free_points < min_points_) break;
      const double p = static_cast<double>(min_points_) / free_points;
      if (failures > 0 && failures >= std::log(0.01) / std::log1p(-p)) break;
    }
  }

  // Same-kind adjacent pieces that explain each other's points are merged (union-find).
  int Merge() {
    const int K = static_cast<int>(primitives_.size());
    std::vector<std::pair<int, int>> pairs;
    for (size_t i = 0; i < x_.size(); ++i) {
      const int a = labels_[i];
      if (a < 0) continue;
      for (int j : nb_[i]) {
        const int b = labels_[j];
        if (b > a && primitives_[a].kind == primitives_[b].kind) pairs.emplace_back(a, b);
      }
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    std::vector<int> parent(K);
    std::iota(parent.begin(), parent.end(), 0);
    auto root = [&](int a) {
      while (parent[a] != a) a = parent[a] = parent[parent[a]];
      return a;
    };
    auto explains = [&](int a, int b) {
      const PrimitiveFunction f(primitives_[a].kind, primitives_[a].parameters);
      const std::vector<int> s = Spread(primitives_[b].points, 500);
      int ok = 0;
      for (int i : s) ok += Supports(f, i);
      return ok >= kMergeFraction * s.size();
    };
    int merges = 0;
    for (auto [a, b] : pairs) {
      if (root(a) == root(b)) continue;
      if (explains(a, b) && explains(b, a)) {
        parent[root(b)] = root(a);
        ++merges;
      }
    }
    if (merges == 0) return 0;
    std::vector<DetectedPrimitive> merged;
    std::vector<int> new_id(K, -1);
    for (int a = 0; a < K; ++a)
      if (root(a) == a)
        new_id[a] = static_cast<int>(merged.size()), merged.push_back(primitives_[a]);
    for (int a = 0; a < K; ++a)
      if (root(a) != a) {
        auto& into = merged[new_id[root(a)]].points;
        into.insert(into.end(), primitives_[a].points.begin(), primitives_[a].points.end());
      }
    for (auto& p : merged) {
      std::sort(p.points.begin(), p.points.end());
      std::vector<double> refit = p.parameters;
      if (RefitPrimitiveLocally(p.kind, x_, Spread(p.points, kMaxRefitPoints), &refit) >= 0 &&
          Finite(refit))
        p.parameters = refit;
    }
    for (auto& l : labels_)
      if (l >= 0) l = new_id[root(l)];
    primitives_ = std::move(merged);
    return merges;
  }

  // The best `kind` for the points s: hypotheses from the whole set (fit/detect/patch_hypotheses.h) and
  // from minimal samples, the one explaining most points refitted by least squares. Returns the
  // number of points of s it explains (-1: no hypothesis).
  int FitKindToSupport(NodeType kind, const std::vector<int>& s, std::mt19937& rng,
                       std::vector<double>* params) const {
    auto explained = [&](const std::vector<double>& q) {
      const PrimitiveFunction f(kind, q);
      int n = 0;
      for (int i : s) n += Supports(f, i);
      return n;
    };
    std::vector<Vector3d> px, pn;
    for (int i : s) px.push_back(x_[i]), pn.push_back((*n_)[i]);
    std::vector<std::vector<double>> hypotheses;
    std::vector<double> h;
    if ((kind == NodeType::kPlane && PlaneFromPatch(px, pn, &h)) ||
        (kind == NodeType::kSphere && SphereFromPatch(px, pn, &h)) ||
        (kind == NodeType::kCylinder && CylinderFromPatch(px, pn, &h)))
      hypotheses.push_back(h);
    for (int t = 0; t < options_.hypotheses; ++t)
      if (Hypothesis(kind, s, rng, &h) && Finite(h)) hypotheses.push_back(h);
    int best = -1;
    for (auto& q : hypotheses) {
      const int n = explained(q);
      if (n > best) best = n, *params = q;
    }
    if (best < 0) return -1;
    std::vector<double> refit = *params;
    if (RefitPrimitiveLocally(kind, x_, s, &refit, 30) >= 0 && Finite(refit) &&
        Reasonable(kind, refit)) {
      const int n = explained(refit);
      if (n >= best) best = n, *params = refit;
    }
    return best;
  }

  // The kind selection's cost on the points s: truncated Gaussian plus the BIC penalty.
  double PenalisedCost(NodeType kind, const std::vector<double>& params,
                       const std::vector<int>& s) const {
    const PrimitiveFunction f(kind, params);
    double cost = 0;
    for (int i : s) cost += Cost(f(x_[i]));
    return cost +
           DegreesOfFreedom(kind) * std::log(static_cast<double>(std::max<size_t>(2, s.size())));
  }

  // The simplest allowed kind that explains at least kSimplerFraction as many of a primitive's
  // points as its own model replaces it (a cylinder grown as a huge-radius torus, a sphere as a
  // torus of zero major radius), a curved one only if its penalised cost on them is within
  // kSimplerCostRatio of the own model's: FitKindToSupport on the whole support.
  int Simplify() {
    int changed = 0;
    const int threads = ThreadCountOrDefault(options_.num_threads);
    std::vector<char> flags(primitives_.size(), 0);
    ParallelFor(static_cast<int>(primitives_.size()), threads, [&](int k, int) {
      DetectedPrimitive& p = primitives_[k];
      const std::vector<int> s = Spread(p.points, kMaxRefitPoints);
      auto explained = [&](NodeType kind, const std::vector<double>& params) {
        const PrimitiveFunction f(kind, params);
        int n = 0;
        for (int i : s) n += Supports(f, i);
        return n;
      };
      const int own = explained(p.kind, p.parameters);
      const double own_cost = PenalisedCost(p.kind, p.parameters, s);
      std::vector<NodeType> simpler;
      for (NodeType kind : options_.kinds)
        if (DegreesOfFreedom(kind) < DegreesOfFreedom(p.kind)) simpler.push_back(kind);
      std::sort(simpler.begin(), simpler.end(),
                [](NodeType a, NodeType b) { return DegreesOfFreedom(a) < DegreesOfFreedom(b); });
      std::seed_seq seq{options_.seed, 0x5eedu, static_cast<unsigned>(k)};
      std::mt19937 rng(seq);
      for (NodeType kind : simpler) {
        std::vector<double> best_params;
        const int best = FitKindToSupport(kind, s, rng, &best_params);
        if (best < 0) continue;
        if (p.kind == NodeType::kCylinder && kind == NodeType::kSphere &&
            SphereZoneOfCylinder(best_params, p.parameters))
          continue;  // the same surface on the cylinder's band: no simpler explanation
        if (best >= kSimplerFraction * own &&
            (kind == NodeType::kPlane ||
             PenalisedCost(kind, best_params, s) <= kSimplerCostRatio * own_cost)) {
          p.kind = kind;
          p.parameters = best_params;
          flags[k] = 1;
          break;
        }
      }
    });
    for (char f : flags) changed += f;
    return changed;
  }

  // Kind check against the neighbours (after merging): a curved primitive P may owe its kind to
  // points of a neighbouring surface it crosses (a sphere over a short cylinder and its chamfer
  // explains more points than the cylinder, so it wins the seed's comparison). On P's support S
  // every other allowed kind Q is fitted (FitKindToSupport, then least squares on the points Q
  // supports), and each model M in {P, Q...} is scored with every point's best explanation among
  // M and the other primitives that support it (distance and normal bands):
  //   C_M = sum_{i in S} min(r_iM^2 / s^2, min_{O != P supports i} r_iO^2 / s^2, tau^2 / s^2)
  //         + p_M ln |S|;
  // the cheapest replaces P. A point another primitive explains costs the same whatever M, so
  // the comparison rests on the points only P can explain, with the BIC penalty against
  // needless parameters. Returns the number of primitives whose kind changed.
  int Rekind() {
    const int K = static_cast<int>(primitives_.size());
    const int threads = ThreadCountOrDefault(options_.num_threads);
    std::vector<PrimitiveFunction> fs;
    for (const auto& p : primitives_) fs.emplace_back(p.kind, p.parameters);
    std::vector<DetectedPrimitive> replaced(primitives_);
    std::vector<char> flags(K, 0);
    const double cap = (tau_ / sigma_) * (tau_ / sigma_);
    ParallelFor(K, threads, [&](int k, int) {
      const DetectedPrimitive& p = primitives_[k];
      if (p.kind == NodeType::kPlane) return;
      const std::vector<int> s = Spread(p.points, kMaxRefitPoints);
      std::vector<double> other(s.size(), cap);
      int own = 0;  // points of s that no other primitive supports
      for (size_t m = 0; m < s.size(); ++m) {
        for (int o = 0; o < K; ++o) {
          if (o == k || !Supports(fs[o], s[m])) continue;
          other[m] = std::min(other[m], Cost(fs[o](x_[s[m]])));
        }
        own += other[m] == cap;
      }
      if (own < std::max(min_points_, 8)) return;  // a duplicate: nothing to compare on
      const double penalty = std::log(static_cast<double>(std::max<size_t>(2, p.points.size())));
      auto cost = [&](NodeType kind, const std::vector<double>& q) {
        const PrimitiveFunction f(kind, q);
        double c = 0;
        for (size_t m = 0; m < s.size(); ++m) {
          c += std::min(other[m], Cost(f(x_[s[m]])));
        }
        return c * p.points.size() / s.size() + DegreesOfFreedom(kind) * penalty;
      };
      // Every model (P's own included) least-squares fitted to the points of S it supports.
      // Returns the number of points of S it supports (0: too few to fit).
      auto refit_on_supported = [&](NodeType kind, std::vector<double>* q) {
        const PrimitiveFunction f(kind, *q);
        std::vector<int> supported;
        for (int i : s)
          if (Supports(f, i)) supported.push_back(i);
        if (static_cast<int>(supported.size()) < std::max(min_points_, 8)) return 0;
        std::vector<double> refit = *q;
        if (RefitPrimitiveLocally(kind, x_, supported, &refit, 30) >= 0 && Finite(refit) &&
            Reasonable(kind, refit) && cost(kind, refit) < cost(kind, *q))
          *q = std::move(refit);
        const PrimitiveFunction g(kind, *q);
        int n = 0;
        for (int i : s) n += Supports(g, i);
        return n;
      };
      std::vector<double> own_params = p.parameters;
      const int own_supported = refit_on_supported(p.kind, &own_params);
      double best_cost = cost(p.kind, own_params);
      if (own_params != p.parameters) replaced[k].parameters = own_params;
      std::seed_seq seq{options_.seed, 0x4b1du, static_cast<unsigned>(k)};
      std::mt19937 rng(seq);
      for (NodeType kind : options_.kinds) {
        if (kind == p.kind) continue;
        std::vector<double> q;
        // Q only trades coverage for accuracy (P over-reaches into a neighbour: Q supports fewer
        // points of S); a Q that supports as many is a surface bent over the joint with P's
        // neighbour (a torus over a cylinder and the start of its fillet).
        if (FitKindToSupport(kind, s, rng, &q) < 0) continue;
        const int supported = refit_on_supported(kind, &q);
        if (supported == 0 || supported >= own_supported) continue;
        if (p.kind == NodeType::kCylinder && kind == NodeType::kSphere &&
            SphereZoneOfCylinder(q, own_params))
          continue;  // the same surface on P's band: the BIC alone would pick the sphere
        const double c = cost(kind, q);
        if (c < best_cost) {
          best_cost = c;
          replaced[k].kind = kind;
          replaced[k].parameters = q;
          flags[k] = 1;
        }
      }
    });
    primitives_ = std::move(replaced);
    int changed = 0;
    for (char f : flags) changed += f;
    return changed;
  }

  // A sphere's or cylinder's box in the re-assignment also holds the rest of its closed cross-
  // section beside the support: the whole ball, the whole circle over the support's axial range.
  // A narrow ring whose growth stopped part of the way round (its neighbour links run to the
  // faces beside it) gets the rest of its points back (Reassign keeps a curved primitive's
  // parts).
  void ExtendToCrossSection(const DetectedPrimitive& p, Eigen::AlignedBox3d* box) const {
    if (p.points.empty()) return;
    const std::vector<double>& q = p.parameters;
    if (p.kind == NodeType::kSphere) {
      const Vector3d c(q[0], q[1], q[2]);
      box->extend(c - Vector3d::Constant(std::abs(q[3])));
      box->extend(c + Vector3d::Constant(std::abs(q[3])));
    } else if (p.kind == NodeType::kCylinder) {
      const Vector3d o(q[0], q[1], q[2]), a = Vector3d(q[3], q[4], q[5]).normalized();
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (int i : p.points) {
        const double t = (x_[i] - o).dot(a);
        lo = std::min(lo, t), hi = std::max(hi, t);
      }
      // A circle of radius r about axis a spans r sqrt(1 - a_i^2) along axis i.
      const Vector3d half = std::abs(q[6]) * (1.0 - a.array().square()).max(0.0).sqrt().matrix();
      for (const double t : {lo, hi}) {
        box->extend(o + t * a - half);
        box->extend(o + t * a + half);
      }
    }
  }

  // Every point to the primitive explaining it best; supports cut to their largest component;
  // small primitives dropped; primitives ordered by size.
  void Reassign() {
    const int N = static_cast<int>(x_.size());
    const int K = static_cast<int>(primitives_.size());
    // Boxes of the supports, widened by tau and a few spacings (reassigned points lie next to
    // them).
    std::vector<Eigen::AlignedBox3d> boxes(K);
    std::vector<double> bands(K, tau_);  // a merged plane's own band (fit/detect/surface_merging.h)
    for (int k = 0; k < K; ++k) {
      if (k < static_cast<int>(band_.size())) bands[k] = std::max(tau_, band_[k]);
      for (int i : primitives_[k].points) boxes[k].extend(x_[i]);
      ExtendToCrossSection(primitives_[k], &boxes[k]);
      boxes[k].min().array() -= margin_ + bands[k];
      boxes[k].max().array() += margin_ + bands[k];
    }
    std::vector<PrimitiveFunction> fs;
    for (const auto& p : primitives_) fs.emplace_back(p.kind, p.parameters);
    std::vector<int> labels(N, -1);
    std::vector<int> fallback(N, -1);  // nearest within tau whatever the normal
    const int threads = ThreadCountOrDefault(options_.num_threads);
    const int chunks = 64;
    ParallelFor(chunks, threads, [&](int c, int) {
      for (int i = static_cast<int>(static_cast<long>(N) * c / chunks);
           i < static_cast<long>(N) * (c + 1) / chunks; ++i) {
        // Distance, then normal: a smaller |f| wins unless it is within sigma of the other (a
        // point on the joint of two surfaces: Fit4CAD PC34's cylinder ring and the plane below
        // it), then the normal closer to grad f wins. Among agreeing normals (labels), and among
        // all within tau (fallback).
        auto better = [&](double r, double cos, int current, double best_r, double best_cos) {
          return current < 0 || r < best_r - sigma_ || (r < best_r + sigma_ && cos > best_cos);
        };
        double best = tau_, best_cos = 0, best_any = tau_, best_any_cos = 0;
        for (int k = 0; k < K; ++k) {
          if (!boxes[k].contains(x_[i])) continue;
          Vector3d g;
          const double r = std::abs(fs[k](x_[i], &g));
          const double gn = g.norm();
          if (!(r < bands[k]) || !(gn > 0)) continue;
          const double cos = std::abs(g.dot((*n_)[i])) / gn;
          if (cos >= cos_ && better(r, cos, labels[i], best, best_cos))
            best = r, best_cos = cos, labels[i] = k;
          if (better(r, cos, fallback[i], best_any, best_any_cos))
            best_any = r, best_any_cos = cos, fallback[i] = k;
        }
      }
    });
    // Points with no agreeing normal join a neighbouring primitive that is within tau, at most
    // kFallbackSteps neighbour steps from the points with agreeing normals (the width over
    // which estimated normals are smeared at a crease; no creeping along a tangent surface).
    std::vector<int> queue, depth(N, 0);
    for (int i = 0; i < N; ++i)
      if (labels[i] >= 0) queue.push_back(i);
    for (size_t h = 0; h < queue.size(); ++h) {
      const int i = queue[h];
      if (depth[i] >= kFallbackSteps) continue;
      for (int j : nb_[i])
        if (labels[j] < 0 && fallback[j] == labels[i]) {
          labels[j] = fallback[j];
          depth[j] = depth[i] + 1;
          queue.push_back(j);
        }
    }
    // Largest connected component of each support.
    std::vector<int> component(N, -1);
    std::vector<int> best_component(K, -1), best_size(K, 0);
    int next = 0;
    for (int i = 0; i < N; ++i) {
      if (labels[i] < 0 || component[i] >= 0) continue;
      const int id = next++;
      std::vector<int> q = {i};
      component[i] = id;
      for (size_t h = 0; h < q.size(); ++h)
        for (int j : nb_[q[h]])
          if (labels[j] == labels[i] && component[j] < 0) component[j] = id, q.push_back(j);
      if (static_cast<int>(q.size()) > best_size[labels[i]])
        best_size[labels[i]] = static_cast<int>(q.size()), best_component[labels[i]] = id;
    }
    // Merged planes (several pieces of one wall) and curved primitives keep every part of the
    // smallest primitive's size; the other planes their largest. A sphere's or cylinder's parts
    // are one closed surface: a narrow ring whose neighbour links run to the faces beside it
    // falls into arcs over the graph (Fit4CAD PC33: a cylinder ring 0.4 high, 143 of 1 500
    // points, came out as two halves 1.2 apart at a spacing of 0.5, and the smaller was dropped).
    std::vector<int> component_size(next, 0);
    for (int i = 0; i < N; ++i)
      if (labels[i] >= 0) ++component_size[component[i]];
    for (int i = 0; i < N; ++i) {
      if (labels[i] < 0 || component[i] == best_component[labels[i]]) continue;
      const bool multi = (labels[i] < static_cast<int>(multi_part_.size()) && multi_part_[labels[i]]) ||
                         primitives_[labels[i]].kind != NodeType::kPlane;
      if (!(multi && component_size[component[i]] >= min_points_)) labels[i] = -1;
    }
    std::fill(best_size.begin(), best_size.end(), 0);  // now the kept size
    for (int i = 0; i < N; ++i)
      if (labels[i] >= 0) ++best_size[labels[i]];
    std::vector<int> order;
    for (int k = 0; k < K; ++k)
      if (best_size[k] >= min_points_) order.push_back(k);
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return best_size[a] > best_size[b]; });
    std::vector<int> new_id(K, -1);
    std::vector<DetectedPrimitive> kept;
    for (int k : order) new_id[k] = static_cast<int>(kept.size()), kept.push_back(primitives_[k]);
    for (auto& p : kept) p.points.clear();
    for (int i = 0; i < N; ++i) {
      labels[i] = labels[i] >= 0 ? new_id[labels[i]] : -1;
      if (labels[i] >= 0) kept[labels[i]].points.push_back(i);
    }
    primitives_ = std::move(kept);
    labels_ = std::move(labels);
  }

  // The final "one surface or two" (fit/detect/surface_merging.h): planes of two parallel sheets
  // split, pieces of one plane merged. Returns {splits, merges}.
  std::pair<int, int> SplitAndMergeSurfaces() {
    const SurfaceMergeContext c{x_, *n_, nb_, tau_, cos_, min_points_};
    const int splits = SplitParallelSheets(c, &primitives_, &labels_);
    const int merges = MergeSameSurfaces(c, &primitives_, &labels_, &band_, &multi_part_);
    return {splits, merges};
  }

  // Maximum-likelihood refinement of `fit` on each primitive's points, then its figures.
  void Refine() {
    const int K = static_cast<int>(primitives_.size());
    const int threads = ThreadCountOrDefault(options_.num_threads);
    ParallelFor(K, threads, [&](int k, int) {
      DetectedPrimitive& p = primitives_[k];
      if (options_.refine) {
        // Primitives above kMaxRefinePoints are refined on an evenly spread subset of their
        // points (memory: the fit copies its points), the standard deviations scaled by
        // sqrt(subset / points): the information grows with the number of points.
        const std::vector<int> s = Spread(p.points, kMaxRefinePoints);
        std::vector<Vector3d> px, pn;
        for (int i : s) px.push_back(x_[i]), pn.push_back((*n_)[i]);
        PrimitiveFitOptions fo;
        fo.kind = p.kind;
        fo.initial = p.parameters;
        fo.start_band = tau_;  // adaptive: the ML refinement re-estimates its band
        fo.normal_cos = cos_;
        fo.num_threads = 1;
        fo.min_inliers = 8;
        fo.min_inlier_fraction = 0.0;
        fo.seed = options_.seed;
        const PrimitiveFitResult r = FitPrimitive(px, pn, fo);
        if (r.success && Finite(r.parameters)) {
          p.parameters = r.parameters;
          p.standard_deviations = r.standard_deviations;
          const double scale = std::sqrt(static_cast<double>(s.size()) / p.points.size());
          for (double& sd : p.standard_deviations) sd *= scale;
        }
      }
      const PrimitiveFunction f(p.kind, p.parameters);
      double ss = 0;
      int along = 0;
      for (int i : p.points) {
        Vector3d g;
        const double r = f(x_[i], &g);
        ss += r * r;
        along += g.dot((*n_)[i]) > 0;
      }
      const int n = static_cast<int>(p.points.size());
      p.rms_distance = n > 0 ? std::sqrt(ss / n) : 0.0;
      if (p.kind == NodeType::kPlane && 2 * along < n) {  // orient the plane with the normals
        for (double& v : p.parameters) v = -v;
        along = n - along;
      }
      p.normal_side = along >= 0.9 * n ? "outward" : along <= 0.1 * n ? "inward" : "unknown";
    });
  }

  double margin_ = 0.0, diagonal_ = 0.0;
  // Per primitive after the surface merge: its band and whether it is made of several pieces.
  std::vector<double> band_;
  std::vector<char> multi_part_;
  std::vector<DetectedPrimitive> primitives_;
  const std::vector<int>& labels() const { return labels_; }

 private:
  const std::vector<Vector3d>& x_;
  // The normals in use: the input's, the leftover pass's re-estimated ones during that pass,
  // then (only when that pass assigned points) a copy of the input with those points' new
  // normals; no copy of the input otherwise (memory: 24 bytes a point each).
  const std::vector<Vector3d>& input_n_;
  const std::vector<Vector3d>* n_;
  std::vector<Vector3d> own_n_;
  const NeighbourGraph& nb_;
  double tau_, cos_, sigma_;
  int min_points_;
  const DetectionOptions& options_;
  std::vector<int> labels_;
  bool leftover_pass_ = false;
};

}  // namespace

bool DetectionOptions::IsValid(std::string* error) const {
  auto fail = [error](const std::string& e) {
    if (error) *error = e;
    return false;
  };
  if (kinds.empty()) return fail("no primitive kind to detect");
  for (NodeType k : kinds)
    if (!(k == NodeType::kPlane || k == NodeType::kSphere || k == NodeType::kCylinder ||
          k == NodeType::kCone || k == NodeType::kTorus))
      return fail(std::string("cannot detect a ") + NodeTypeName(k));
  if (!(threshold >= 0) || !std::isfinite(threshold))
    return fail("threshold must be >= 0 and finite");
  if (!(normal_angle_deg >= 0 && normal_angle_deg < 90))
    return fail("normal angle must be in [0, 90) degrees");
  if (min_points < 0) return fail("min_points must be >= 0");
  if (patch_size < 8) return fail("patch_size must be >= 8");
  if (hypotheses < 1 || seeds_per_round < 1)
    return fail("hypotheses and seeds_per_round must be >= 1");
  if (num_threads < 0) return fail("num_threads must be >= 0");
  return true;
}

DetectionResult DetectPrimitives(const std::vector<Vector3d>& points,
                                 const std::vector<Vector3d>& normals,
                                 const NeighbourGraph& neighbours, double spacing,
                                 const DetectionOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  std::string error;
  if (!options.IsValid(&error)) throw std::invalid_argument("DetectPrimitives: " + error);
  const size_t N = points.size();
  if (normals.size() != N || neighbours.size() != N)
    throw std::invalid_argument(
        "DetectPrimitives: points, normals and neighbourhoods differ in count");
  for (size_t i = 0; i < N; ++i)
    for (int j : neighbours[i])
      if (j < 0 || static_cast<size_t>(j) >= N)
        throw std::invalid_argument("DetectPrimitives: neighbour index out of range");
  DetectionResult result;
  result.labels.assign(N, -1);
  result.residuals.assign(N, 0.0);
  result.spacing = spacing;
  result.min_points =
      options.min_points > 0 ? options.min_points : std::max<int>(10, static_cast<int>(N / 500));
  if (N < 3) return result;

  // Recentred copy (precision far from the origin).
  Vector3d centroid = Vector3d::Zero();
  for (const auto& p : points) centroid += p;
  centroid /= static_cast<double>(N);
  std::vector<Vector3d> x(N);
  for (size_t i = 0; i < N; ++i) x[i] = points[i] - centroid;

  const DetectionScales ds = EstimateDetectionScales(x, normals, neighbours, spacing,
                                                     options.threshold, options.normal_angle_deg);
  result.noise = ds.noise;
  result.threshold = ds.threshold;
  result.normal_angle_deg = ds.normal_angle_deg;
  if (!(result.threshold > 0)) return result;  // all points coincide
  if (ds.volume) return result;                // no surface at the sampling scale
  const Scales scales{result.threshold, std::cos(result.normal_angle_deg * M_PI / 180.0),
                      ds.likelihood_sigma};

  Detector detector(x, normals, neighbours, scales, result.min_points, options);
  detector.margin_ = result.threshold + 3.0 * spacing;
  {
    Eigen::AlignedBox3d box;
    for (const auto& p : x) box.extend(p);
    detector.diagonal_ = box.diagonal().norm();
  }
  if (options.progress) {
    char line[200];
    std::snprintf(line, sizeof line,
                  "%zu points: spacing %.4g, noise %.4g, band %.4g, normal band %.0f deg, smallest "
                  "primitive %d points",
                  N, spacing, result.noise, result.threshold, result.normal_angle_deg,
                  result.min_points);
    options.progress(line);
  }
  detector.Run(&result);
  detector.Tell("final stage: kinds, merging, re-assignment, refinement");
  result.simplified = detector.Simplify();
  result.merges = detector.Merge();
  result.simplified += detector.Rekind();
  const auto [splits, surface_merges] = detector.SplitAndMergeSurfaces();
  result.splits = splits;
  result.merges += surface_merges;
  detector.Reassign();
  detector.Refine();

  result.labels = detector.labels();
  for (auto& p : detector.primitives_) {
    const PrimitiveFunction f(p.kind, p.parameters);
    const int id = static_cast<int>(&p - detector.primitives_.data());
    for (int i : p.points) result.residuals[i] = f(x[i]);
    (void)id;
    Translate(p.kind, &p.parameters, centroid);
    result.primitives.push_back(std::move(p));
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (options.progress) {
    char line[120];
    std::snprintf(line, sizeof line, "%zu primitives in %.2f s", result.primitives.size(),
                  result.seconds);
    options.progress(line);
  }
  return result;
}

}  // namespace implicitfit
