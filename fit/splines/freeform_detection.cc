#include "fit/splines/freeform_detection.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <stdexcept>

#include "fit/common/thread_count.h"
#include "fit/splines/bspline_surface_fitter.h"
#include "fit/splines/local_scales.h"
#include "fit/splines/parameter_frame.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

// Union-find over the members of one subset.
struct Components {
  std::vector<int> parent;
  int Find(int a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  }
};

// The connected parts of `subset` over the neighbour graph, through pairs that pass `joined`,
// largest first; member[] is scratch (size N, -1 outside any call).
template <typename Joined>
std::vector<std::vector<int>> ConnectedParts(const std::vector<int>& subset,
                                             const NeighbourGraph& neighbours,
                                             const Joined& joined, std::vector<int>* member) {
  Components uf;
  uf.parent.resize(subset.size());
  std::iota(uf.parent.begin(), uf.parent.end(), 0);
  for (size_t a = 0; a < subset.size(); ++a) (*member)[subset[a]] = static_cast<int>(a);
  for (size_t a = 0; a < subset.size(); ++a)
    for (int j : neighbours[subset[a]]) {
      const int b = (*member)[j];
      if (b < 0 || !joined(subset[a], j)) continue;
      const int ra = uf.Find(static_cast<int>(a)), rb = uf.Find(b);
      if (ra != rb) uf.parent[ra] = rb;
    }
  std::vector<std::vector<int>> parts;
  std::vector<int> slot(subset.size(), -1);
  for (size_t a = 0; a < subset.size(); ++a) {
    const int r = uf.Find(static_cast<int>(a));
    if (slot[r] < 0) {
      slot[r] = static_cast<int>(parts.size());
      parts.emplace_back();
    }
    parts[slot[r]].push_back(subset[a]);
  }
  for (int i : subset) (*member)[i] = -1;
  std::sort(parts.begin(), parts.end(),
            [](const std::vector<int>& x, const std::vector<int>& y) { return x.size() > y.size(); });
  return parts;
}

struct Candidate {
  bool ok = false;
  SurfaceFitResult fit;
  double cost = 0.0;
};

class FreeformStage {
 public:
  FreeformStage(const std::vector<Vec>& points, const std::vector<Vec>& normals,
                const NeighbourGraph& neighbours, const FreeformOptions& o)
      : points_(points),
        normals_(normals),
        neighbours_(neighbours),
        o_(o),
        member_(points.size(), -1),
        figures_(ComputeLocalScaleFigures(points, normals, neighbours, o.normal_angle_deg)) {
    threads_ = ThreadCountOrDefault(o.num_threads);
  }

  // Steps 2-5 of the header on one region.
  void Process(const std::vector<int>& region, int depth, const char* origin = "small_region") {
    if (static_cast<int>(region.size()) < o_.min_points) {
      ++result_.small_parts;
      result_.small_part_points += static_cast<int>(region.size());
      result_.lost_points[origin] += static_cast<int>(region.size());
      return;
    }
    std::vector<Vec> p, n;
    Gather(region, &p, &n);
    const PartScales scales =
        ScalesOfPart(figures_, region, {o_.noise, o_.threshold, o_.normal_angle_deg, o_.spacing});
    if (scales.volume) {  // points filling a volume, not sampling a surface: no patch
      ++result_.volume;
      result_.lost_points["volume"] += static_cast<int>(region.size());
      return;
    }
    ParameterFrame frame;
    try {
      frame = FitParameterFrame(p, n);
    } catch (const std::invalid_argument&) {
      result_.lost_points["no_frame"] += static_cast<int>(region.size());
      return;
    }
    int folded = 0;
    for (const Vec& x : n) folded += x.dot(frame.normal) < std::cos(80.0 * M_PI / 180.0);
    if (folded > 0.02 * n.size()) ++result_.folded;  // counted; fitted as any region (step 2)
    const Candidate best = BestGrid(p, n, frame, scales);
    if (!best.ok) {
      ++result_.no_grid;
      Split(region, p, depth, "no_grid");
      return;
    }
    // Support, refit on it, support again (step 4).
    std::vector<int> support = Support(region, best.fit.ToModel(), scales);
    if (static_cast<int>(support.size()) < o_.min_points) {
      ++result_.small_support;
      Split(region, p, depth, "small_support");
      return;
    }
    const SurfaceFitOptions fo = FitOptions(best.fit.count_u, best.fit.count_v, true);
    const SurfaceFitResult refit = Refit(support, fo);
    SurfaceFitResult final_fit = refit.success ? refit : best.fit;
    Assessment a = Assess(region, final_fit.ToModel(), scales);
    const double bound = 2.0 * scales.likelihood_sigma;
    if (static_cast<int>(a.support.size()) < o_.min_points || a.rms > bound) {
      const bool over = a.rms > bound;
      ++(over ? result_.rms_over : result_.small_support);
      Split(region, p, depth, over ? "rms_over" : "small_support");
      return;
    }
    // Fringes (step 5): the pieces under min_points that the support leaves of the region lie
    // mostly just beyond the patch's rectangle (each refit's domain is its support's); one refit
    // on the support and them, kept when its support is larger and within the RMS bound.
    std::vector<int> grown = a.support;
    for (const std::vector<int>& part : SmoothParts(Outside(region, a.support)))
      if (static_cast<int>(part.size()) < o_.min_points)
        grown.insert(grown.end(), part.begin(), part.end());
    if (grown.size() > a.support.size()) {
      const SurfaceFitResult wider = Refit(grown, fo);
      if (wider.success) {
        Assessment b = Assess(region, wider.ToModel(), scales);
        if (b.support.size() > a.support.size() && b.rms <= bound) {
          ++result_.grown;
          a = std::move(b);
          final_fit = wider;
        }
      }
    }
    FreeformSurface surface;
    surface.model = final_fit.ToModel();
    surface.points = a.support;
    std::sort(surface.points.begin(), surface.points.end());
    surface.rms_distance = a.rms;
    surface.count_u = final_fit.count_u;
    surface.count_v = final_fit.count_v;
    const double m = static_cast<double>(a.support.size());
    surface.normal_side = a.agree >= 0.9 * m   ? "outward"
                          : a.agree <= 0.1 * m ? "inward"
                                               : "unknown";
    for (size_t k = 0; k < a.support.size(); ++k) assigned_[a.support[k]] = a.residuals[k];
    result_.surfaces.push_back(std::move(surface));
    TellProgress(false);
    // What the patch left of the region may hold another surface.
    std::vector<int> rest;
    for (int i : region)
      if (!assigned_.count(i)) rest.push_back(i);
    if (depth < o_.max_depth)
      for (const std::vector<int>& part : SmoothParts(rest))
        Process(part, depth + 1, "beside_patch");
    else
      result_.lost_points["rest_at_depth_limit"] += static_cast<int>(rest.size());
  }

  std::vector<std::vector<int>> SmoothParts(const std::vector<int>& subset) {
    const std::vector<double>& band = figures_.cos_band;
    return ConnectedParts(
        subset, neighbours_,
        [&](int i, int j) { return normals_[i].dot(normals_[j]) >= std::min(band[i], band[j]); },
        &member_);
  }

  // The progress line (options' progress): at most every 5 s unless `now`.
  void TellProgress(bool now) {
    if (!o_.progress) return;
    const auto t = std::chrono::steady_clock::now();
    if (!now && std::chrono::duration<double>(t - last_told_).count() < 5.0) return;
    last_told_ = t;
    char line[200];
    std::snprintf(
        line, sizeof line,
        "freeform: %zu surfaces, %zu of %d smooth-region points assigned, region %d of %d",
        result_.surfaces.size(), assigned_.size(), total_points_, regions_done_, total_regions_);
    o_.progress(line);
  }
  void StartRegions(int regions, int points) {
    total_regions_ = regions;
    total_points_ = points;
    last_told_ = std::chrono::steady_clock::now();
  }
  void RegionDone() {
    ++regions_done_;
    TellProgress(false);
  }

  FreeformResult& result() { return result_; }
  const std::map<int, double>& assigned() const { return assigned_; }

 private:
  // A patch on a part of the region: its support, each support point's signed distance, the
  // RMS of those and how many of the point normals agree with S_u x S_v.
  struct Assessment {
    std::vector<int> support;
    std::vector<double> residuals;
    double rms = INFINITY;
    int agree = 0;
  };

  Assessment Assess(const std::vector<int>& region, const Model& model, const PartScales& scales) {
    Assessment a;
    a.support = Support(region, model, scales);
    a.residuals.resize(a.support.size());
    double sum = 0.0;
    for (size_t k = 0; k < a.support.size(); ++k) {
      double f;
      const Vec g = model.Gradient(points_[a.support[k]], &f);
      a.residuals[k] = f;
      sum += f * f;
      a.agree += g.dot(normals_[a.support[k]]) > 0;
    }
    if (!a.support.empty()) a.rms = std::sqrt(sum / a.support.size());
    return a;
  }

  SurfaceFitResult Refit(const std::vector<int>& ids, const SurfaceFitOptions& fo) {
    std::vector<Vec> p, n;
    Gather(ids, &p, &n);
    ++result_.fits;
    return FitBSplineSurface(p, n, fo);
  }

  // The region's points outside `inside` (both ascending or not: a lookup set).
  static std::vector<int> Outside(const std::vector<int>& region, const std::vector<int>& inside) {
    std::vector<int> sorted = inside, out;
    std::sort(sorted.begin(), sorted.end());
    for (int i : region)
      if (!std::binary_search(sorted.begin(), sorted.end(), i)) out.push_back(i);
    return out;
  }

  void Gather(const std::vector<int>& ids, std::vector<Vec>* p, std::vector<Vec>* n) const {
    for (int i : ids) {
      p->push_back(points_[i]);
      n->push_back(normals_[i]);
    }
  }

  SurfaceFitOptions FitOptions(int nu, int nv, bool refine) const {
    SurfaceFitOptions fo;
    fo.degree = o_.degree;
    fo.count_u = nu;
    fo.count_v = nv;
    fo.refine_rounds = refine ? 2 : 0;
    fo.correction_rounds = refine ? 8 : 4;
    fo.num_threads = o_.num_threads;
    return fo;
  }

  // Step 3: the grid of least penalised cost, if it beats leaving the points unassigned.
  Candidate BestGrid(const std::vector<Vec>& p, const std::vector<Vec>& n,
                     const ParameterFrame& frame, const PartScales& scales) {
    const double n_points = static_cast<double>(p.size());
    const double s = scales.likelihood_sigma;
    const double cap = scales.threshold * scales.threshold / (s * s);
    Candidate best;
    best.cost = n_points * cap;  // every point unassigned
    const double aspect = std::min(frame.length_v / frame.length_u, 1.0);
    int worse = 0;
    for (int nu : {4, 6, 8, 12, 16, 24, 32, 48, 64}) {
      nu = std::max(nu, o_.degree + 1);
      const int nv = std::max(o_.degree + 1, static_cast<int>(std::lround(nu * aspect)));
      if (n_points < 5.0 * nu * nv) break;
      const SurfaceFitResult fit = FitBSplineSurface(p, n, FitOptions(nu, nv, false));
      ++result_.fits;
      if (!fit.success) continue;
      double cost = 3.0 * nu * nv * std::log(n_points);
      for (double r : fit.residuals) cost += std::min(r * r / (s * s), cap);
      if (cost < best.cost) {
        best.ok = true;
        best.cost = cost;
        best.fit = fit;
        worse = 0;
      } else if (++worse >= 2) {
        break;
      }
    }
    return best;
  }

  // The region's points within both bands of the patch, their largest connected part.
  std::vector<int> Support(const std::vector<int>& region, const Model& model,
                           const PartScales& scales) {
    std::vector<char> in(region.size(), 0);
    ParallelFor(region.size(), threads_, [&](size_t begin, size_t end) {
      for (size_t k = begin; k < end; ++k) {
        double f;
        const Vec g = model.Gradient(points_[region[k]], &f);
        const double gn = g.norm();
        const bool near = std::abs(f) < scales.threshold && gn > 0;
        in[k] = !near                                                                  ? 0
                : std::abs(g.dot(normals_[region[k]])) >= scales.cos_normal_angle * gn ? 1
                                                                                       : 2;
      }
    });
    // A point within the distance band whose own normal strays (in == 2: an estimated normal's
    // error is the point's, the surface's is its neighbours') joins when most of its neighbours
    // in the region pass both bands.
    for (size_t k = 0; k < region.size(); ++k) member_[region[k]] = static_cast<int>(k);
    std::vector<char> filled(region.size(), 0);
    for (size_t k = 0; k < region.size(); ++k) {
      if (in[k] != 2) continue;
      int inside = 0, pass = 0;
      for (int j : neighbours_[region[k]])
        if (member_[j] >= 0) {
          ++inside;
          pass += in[member_[j]] == 1;
        }
      filled[k] = 2 * pass > inside;
    }
    for (int i : region) member_[i] = -1;
    for (size_t k = 0; k < region.size(); ++k) in[k] = in[k] == 1 || filled[k];
    std::vector<int> close;
    for (size_t k = 0; k < region.size(); ++k)
      if (in[k]) close.push_back(region[k]);
    const std::vector<std::vector<int>> parts =
        ConnectedParts(close, neighbours_, [](int, int) { return true; }, &member_);
    return parts.empty() ? std::vector<int>{} : parts[0];
  }

  // Step 2's split at the median of the longest principal axis; each half's smooth parts.
  // `why`: the test that refused the region, for the points lost at max_depth.
  void Split(const std::vector<int>& region, const std::vector<Vec>& p, int depth,
             const char* why) {
    if (depth >= o_.max_depth) {
      ++result_.depth_limit;
      result_.lost_points[std::string("depth_limit/") + why] += static_cast<int>(region.size());
      return;
    }
    ++result_.splits;
    Vec c = Vec::Zero();
    for (const Vec& x : p) c += x;
    c /= static_cast<double>(p.size());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (const Vec& x : p) cov += (x - c) * (x - c).transpose();
    const Vec axis = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvectors().col(2);
    std::vector<double> along(p.size());
    for (size_t k = 0; k < p.size(); ++k) along[k] = (p[k] - c).dot(axis);
    std::vector<double> sorted = along;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    const double median = sorted[sorted.size() / 2];
    std::vector<int> halves[2];
    for (size_t k = 0; k < p.size(); ++k) halves[along[k] < median ? 0 : 1].push_back(region[k]);
    for (const std::vector<int>& half : halves)
      for (const std::vector<int>& part : SmoothParts(half))
        Process(part, depth + 1, "split_piece");
  }

  const std::vector<Vec>& points_;
  const std::vector<Vec>& normals_;
  const NeighbourGraph& neighbours_;
  FreeformOptions o_;
  std::vector<int> member_;
  LocalScaleFigures figures_;
  int threads_ = 1;
  FreeformResult result_;
  std::chrono::steady_clock::time_point last_told_;
  int total_regions_ = 0, total_points_ = 0, regions_done_ = 0;
  std::map<int, double> assigned_;  // point -> residual, every accepted patch's support
};

}  // namespace

bool FreeformOptions::IsValid(std::string* error) const {
  if (!(noise > 0) || !(threshold > 0) || !(normal_angle_deg > 0 && normal_angle_deg < 90) ||
      min_points < 1 || degree < 1 || degree > SplineLimits::kMaxDegree || max_depth < 0 ||
      !(spacing >= 0)) {
    *error = "freeform: noise, threshold and normal band must be positive, min_points >= 1";
    return false;
  }
  return true;
}

FreeformResult DetectFreeformSurfaces(const std::vector<Vec>& points, const std::vector<Vec>& normals,
                                      const NeighbourGraph& neighbours,
                                      const FreeformOptions& options, int first_label,
                                      std::vector<int>* labels, std::vector<double>* residuals) {
  const auto t0 = std::chrono::steady_clock::now();
  std::string error;
  if (!options.IsValid(&error)) throw std::invalid_argument(error);
  if (normals.size() != points.size() || neighbours.size() != points.size() ||
      labels->size() != points.size())
    throw std::invalid_argument("freeform: points, normals, neighbours and labels differ in size");
  residuals->resize(points.size(), 0.0);
  FreeformStage stage(points, normals, neighbours, options);
  std::vector<int> free;
  for (size_t i = 0; i < points.size(); ++i)
    if ((*labels)[i] < 0) free.push_back(static_cast<int>(i));
  const std::vector<std::vector<int>> regions = stage.SmoothParts(free);
  int large = 0, large_points = 0;
  for (const std::vector<int>& region : regions)  // largest first
    if (static_cast<int>(region.size()) >= options.min_points) {
      ++large;
      large_points += static_cast<int>(region.size());
    }
  if (options.progress)
    options.progress("freeform: " + std::to_string(free.size()) + " unassigned points, " +
                     std::to_string(large) + " smooth regions of at least " +
                     std::to_string(options.min_points) + " points (" +
                     std::to_string(large_points) + " points)");
  stage.StartRegions(large, large_points);
  for (int k = 0; k < large; ++k) {
    ++stage.result().regions;
    stage.result().region_points += static_cast<int>(regions[k].size());
    stage.Process(regions[k], 0);
    stage.RegionDone();
  }
  FreeformResult result = std::move(stage.result());
  for (size_t s = 0; s < result.surfaces.size(); ++s)
    for (int i : result.surfaces[s].points) {
      (*labels)[i] = first_label + static_cast<int>(s);
      (*residuals)[i] = stage.assigned().at(i);
    }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (options.progress) {
    int assigned = 0;
    for (const FreeformSurface& s : result.surfaces) assigned += static_cast<int>(s.points.size());
    char line[160];
    std::snprintf(line, sizeof line, "freeform: %zu surfaces, %d points assigned in %.1f s",
                  result.surfaces.size(), assigned, result.seconds);
    options.progress(line);
  }
  return result;
}

}  // namespace implicitfit
