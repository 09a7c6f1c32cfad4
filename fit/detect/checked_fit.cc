#include "fit/detect/checked_fit.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "fit/detect/detection_scales.h"
#include "fit/detect/primitive_detector.h"
#include "fit/metrology/primitive_tangent.h"
#include "fit/primitive/primitive_function.h"
#include "model/median.h"

namespace implicitfit {
namespace {

constexpr double kNormalShare = 0.8;     // inliers whose normals must agree within theta
constexpr double kConnectedShare = 0.5;  // share of the support its largest component holds
constexpr double kMaxNoiseSigmas = 2.0;  // robust residual scale <= this * s
constexpr double kSimplerFraction = 0.97;
constexpr double kSimplerCostRatio = 2.0;
constexpr size_t kMaxKindCheckPoints = 5000;  // points of the kind check (evenly spread)

// Degrees of freedom of a kind (the BIC penalty): plane 3 ... torus 7.
int DegreesOfFreedom(NodeType kind) { return FreeParameterCount(kind); }

std::vector<int> Spread(const std::vector<int>& v, size_t count) {
  if (v.size() <= count) return v;
  std::vector<int> out;
  const double step = static_cast<double>(v.size()) / count;
  for (size_t k = 0; k < count; ++k) out.push_back(v[static_cast<size_t>(k * step)]);
  return out;
}

std::string Format(const char* format, double a, double b = 0, double c = 0) {
  char text[256];
  std::snprintf(text, sizeof text, format, a, b, c);
  return text;
}

// The cloud recentred (precision far from the origin) with its scales.
struct Cloud {
  std::vector<Eigen::Vector3d> x;
  const std::vector<Eigen::Vector3d>& n;
  const NeighbourGraph& nb;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  DetectionScales scales;
  double cos_theta = 1.0;
};

struct Verdict {
  bool ok = false;
  std::string reason;
  int support = 0;
};

class Checker {
 public:
  Checker(const Cloud& c, const PrimitiveFitOptions& options) : c_(c), options_(options) {}

  Verdict Check(NodeType kind, const PrimitiveFitResult& r) const {
    Verdict v;
    const PrimitiveFunction f(kind, Recentred(kind, r.parameters));
    const size_t N = c_.x.size();
    std::vector<char> in_support(N, 0);
    size_t agree = 0;
    for (int i : r.inliers) {
      if (Agrees(f, i)) in_support[i] = 1, ++agree;
    }
    if (r.inliers.empty()) return Fail(&v, "no inliers");
    if (agree < kNormalShare * r.inliers.size())
      return Fail(&v, Format("only %.0f%% of its %.0f inliers have normals within %.0f deg of "
                             "grad f (a surface crossing others)",
                             100.0 * agree / r.inliers.size(),
                             static_cast<double>(r.inliers.size()), c_.scales.normal_angle_deg));
    const std::vector<int> C = LargeComponents(in_support);
    if (C.size() < kConnectedShare * agree)
      return Fail(&v, Format("its support is not connected: its connected parts of at least "
                             "%.0f points hold %.0f of its %.0f points",
                             static_cast<double>(MinComponent()), static_cast<double>(C.size()),
                             static_cast<double>(agree)));
    std::vector<double> abs_f;
    for (int i : C) abs_f.push_back(std::abs(f(c_.x[i])));
    const double scale = 1.4826 * Median(abs_f);
    if (scale > kMaxNoiseSigmas * c_.scales.likelihood_sigma)
      return Fail(&v, Format("its residuals spread over the band (1.4826 median |f| = %.4g > %g "
                             "x the cloud's noise scale %.4g)",
                             scale, kMaxNoiseSigmas, c_.scales.likelihood_sigma));
    const std::string simpler = SimplerKind(kind, Recentred(kind, r.parameters), C);
    if (!simpler.empty()) return Fail(&v, simpler);
    v.ok = true;
    v.reason = "passed";
    v.support = static_cast<int>(C.size());
    return v;
  }

 private:
  static Verdict Fail(Verdict* v, const std::string& reason) {
    v->ok = false;
    v->reason = reason;
    return *v;
  }

  std::vector<double> Recentred(NodeType kind, std::vector<double> p) const {
    TranslatePrimitive(kind, -c_.centroid, &p);
    return p;
  }

  bool Agrees(const PrimitiveFunction& f, int i) const {
    Eigen::Vector3d g;
    f(c_.x[i], &g);
    const double gn = g.norm();
    return gn > 0 && std::abs(g.dot(c_.n[i])) >= c_.cos_theta * gn;
  }
  bool Supports(const PrimitiveFunction& f, int i) const {
    return std::abs(f(c_.x[i])) < c_.scales.threshold && Agrees(f, i);
  }

  // The detector's smallest primitive: max(10, N / 500) points.
  size_t MinComponent() const { return std::max<size_t>(10, c_.x.size() / 500); }

  // The points of the connected parts (over the neighbour graph) of at least MinComponent()
  // points: a primitive seen in several pieces (coaxial bores, a face behind an occluder) keeps
  // them; a surface crossing others leaves scattered bits.
  std::vector<int> LargeComponents(const std::vector<char>& in) const {
    std::vector<int> component(in.size(), -1), out;
    for (size_t s = 0; s < in.size(); ++s) {
      if (!in[s] || component[s] >= 0) continue;
      std::vector<int> q = {static_cast<int>(s)};
      component[s] = static_cast<int>(s);
      for (size_t h = 0; h < q.size(); ++h)
        for (int j : c_.nb[q[h]])
          if (in[j] && component[j] < 0) component[j] = static_cast<int>(s), q.push_back(j);
      if (q.size() >= MinComponent()) out.insert(out.end(), q.begin(), q.end());
    }
    std::sort(out.begin(), out.end());
    return out;
  }

  double Cost(const PrimitiveFunction& f, const std::vector<int>& s, int dof) const {
    const double sigma = c_.scales.likelihood_sigma, tau = c_.scales.threshold;
    const double cap = (tau / sigma) * (tau / sigma);
    double cost = 0;
    for (int i : s) {
      const double r = f(c_.x[i]);
      cost += std::min(r * r / (sigma * sigma), cap);
    }
    return cost + dof * std::log(static_cast<double>(std::max<size_t>(2, s.size())));
  }

  // Empty when no simpler kind explains the points; else why the kind is wrong.
  std::string SimplerKind(NodeType kind, const std::vector<double>& params,
                          const std::vector<int>& C) const {
    const std::vector<int> s = Spread(C, kMaxKindCheckPoints);
    const PrimitiveFunction own(kind, params);
    int own_supported = 0;
    for (int i : s) own_supported += Supports(own, i);
    const double own_cost = Cost(own, s, DegreesOfFreedom(kind));
    std::vector<Eigen::Vector3d> px, pn;
    for (int i : s) px.push_back(c_.x[i]), pn.push_back(c_.n[i]);
    for (NodeType k : {NodeType::kPlane, NodeType::kSphere, NodeType::kCylinder, NodeType::kCone}) {
      if (DegreesOfFreedom(k) >= DegreesOfFreedom(kind)) continue;
      PrimitiveFitOptions o;
      o.kind = k;
      o.seed = options_.seed;
      o.start_band = c_.scales.threshold;
      o.compute_covariance = false;
      o.num_threads = 1;
      const PrimitiveFitResult q = FitPrimitive(px, pn, o);
      if (!q.success) continue;
      const PrimitiveFunction g(k, q.parameters);  // px are recentred: so is q
      if (kind == NodeType::kCylinder && k == NodeType::kSphere) {
        // A sphere along a cylinder's great circle: the same surface on a narrow band.
        const Eigen::Vector3d a = Eigen::Vector3d(params[3], params[4], params[5]).normalized();
        const Eigen::Vector3d d(q.parameters[0] - params[0], q.parameters[1] - params[1],
                                q.parameters[2] - params[2]);
        if ((d - d.dot(a) * a).norm() < c_.scales.threshold &&
            std::abs(q.parameters[3] - params[6]) < c_.scales.threshold)
          continue;
      }
      int supported = 0;
      for (int i : s) supported += Supports(g, i);
      if (supported >= kSimplerFraction * own_supported &&
          (k == NodeType::kPlane || Cost(g, s, DegreesOfFreedom(k)) <= kSimplerCostRatio * own_cost))
        return std::string("its points are a ") + NodeTypeName(k) + " (a " + NodeTypeName(k) +
               " explains " + std::to_string(supported) + " of the " + std::to_string(s.size()) +
               " points checked, the " + NodeTypeName(kind) + " " +
               std::to_string(own_supported) + ")";
    }
    return "";
  }

  const Cloud& c_;
  const PrimitiveFitOptions& options_;
};

std::string DescribeFit(NodeType kind, const PrimitiveFitResult& r) {
  std::string d = std::string("the best ") + NodeTypeName(kind);
  const int k = kind == NodeType::kSphere ? 3 : kind == NodeType::kCylinder ? 6 : -1;
  if (k >= 0 && static_cast<int>(r.parameters.size()) > k)
    d += Format(" (radius %.6g", r.parameters[k]) + ", " +
         std::to_string(r.inliers.size()) + " inliers)";
  else
    d += " (" + std::to_string(r.inliers.size()) + " inliers)";
  return d;
}

}  // namespace

nlohmann::json CheckedFit::ToJson() const {
  return {{"checked", checked}, {"source", source},   {"first_check", first_check},
          {"noise", noise},     {"band", band},       {"normal_angle_deg", normal_angle_deg},
          {"support", support}};
}

bool FillsAVolume(const std::vector<Eigen::Vector3d>& points,
                  const std::vector<Eigen::Vector3d>& normals, const NeighbourGraph& neighbours,
                  double spacing, std::string* why) {
  if (points.size() < kMinCheckedPoints || normals.size() != points.size() ||
      neighbours.size() != points.size() || !(spacing > 0))
    return false;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto& p : points) centroid += p;
  centroid /= static_cast<double>(points.size());
  std::vector<Eigen::Vector3d> x;
  x.reserve(points.size());
  for (const auto& p : points) x.push_back(p - centroid);
  const DetectionScales scales = EstimateDetectionScales(x, normals, neighbours, spacing);
  if (!scales.volume) return false;
  if (why) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "the points fill a volume at their sampling scale (spacing %.3g: no tangent "
                  "plane through their neighbourhoods, neighbouring normals far apart), as "
                  "detect finds too",
                  spacing);
    *why = text;
  }
  return true;
}

CheckedFit FitCheckedPrimitive(const std::vector<Eigen::Vector3d>& points,
                               const std::vector<Eigen::Vector3d>& normals,
                               const NeighbourGraph& neighbours, double spacing,
                               const PrimitiveFitOptions& options) {
  CheckedFit out;
  out.source = "fit";
  const bool checkable = !normals.empty() && normals.size() == points.size() &&
                         neighbours.size() == points.size() &&
                         points.size() >= kMinCheckedPoints &&
                         options.estimator == Estimator::kRobust && options.initial.empty();
  if (!checkable) {
    out.result = FitPrimitive(points, normals, options);
    return out;
  }
  Cloud c{{}, normals, neighbours, Eigen::Vector3d::Zero(), {}, 1.0};
  for (const auto& p : points) c.centroid += p;
  c.centroid /= static_cast<double>(points.size());
  c.x.reserve(points.size());
  for (const auto& p : points) c.x.push_back(p - c.centroid);
  c.scales = EstimateDetectionScales(c.x, normals, neighbours, spacing);
  c.cos_theta = std::cos(c.scales.normal_angle_deg * M_PI / 180.0);
  out.checked = true;
  out.noise = c.scales.noise;
  out.band = c.scales.threshold;
  out.normal_angle_deg = c.scales.normal_angle_deg;
  if (!(c.scales.threshold > 0)) {  // every point at one place: nothing to check against
    out.checked = false;
    out.result = FitPrimitive(points, normals, options);
    return out;
  }

  PrimitiveFitOptions first = options;
  if (first.threshold <= 0 && first.start_band <= 0) first.start_band = c.scales.threshold;
  out.result = FitPrimitive(points, normals, first);
  const Checker checker(c, options);
  const NodeType kind = options.kind;
  std::string why;
  if (out.result.success) {
    const Verdict v = checker.Check(kind, out.result);
    out.first_check = v.reason;
    if (v.ok) {
      out.support = v.support;
      return out;
    }
    why = DescribeFit(kind, out.result) + " is refused: " + v.reason;
  } else {
    out.first_check = "the fit failed: " + out.result.message;
    why = "the fit failed: " + out.result.message;
  }

  // The detector's primitives of the kind, largest first, each refined with a fixed band.
  DetectionOptions d;
  d.seed = options.seed;
  d.num_threads = options.num_threads;
  const DetectionResult detected = DetectPrimitives(points, normals, neighbours, spacing, d);
  std::map<std::string, int> found;
  int tried = 0;
  for (const DetectedPrimitive& p : detected.primitives) {
    ++found[NodeTypeName(p.kind)];
    if (p.kind != kind) continue;
    ++tried;
    PrimitiveFitOptions o = options;
    o.initial = p.parameters;
    o.threshold = options.threshold > 0 ? options.threshold : c.scales.threshold;
    o.start_band = 0;
    PrimitiveFitResult r = FitPrimitive(points, normals, o);
    if (!r.success) continue;
    const Verdict v = checker.Check(kind, r);
    if (!v.ok) continue;
    out.result = std::move(r);
    out.source = "detection";
    out.support = v.support;
    return out;
  }
  std::string census;
  for (const auto& [name, count] : found)
    census += (census.empty() ? "" : ", ") + std::to_string(count) + " " + name +
              (count > 1 ? "s" : "");
  PrimitiveFitResult refused = out.result;
  refused.success = false;
  refused.termination = FitTermination::kFailure;
  refused.message = std::string("no ") + NodeTypeName(kind) + " explains the cloud: " + why +
                    "; the detector finds " + (census.empty() ? "nothing" : census) +
                    (tried ? " (none of the " + std::to_string(tried) + " " + NodeTypeName(kind) +
                                 (tried > 1 ? "s" : "") + " passes the checks)"
                           : "");
  out.result = std::move(refused);
  return out;
}

}  // namespace implicitfit
