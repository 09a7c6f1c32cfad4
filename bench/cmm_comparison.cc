// implicitfit vs PCL on coordinate-measuring-machine sets (tests/support/cmm_reference.h: 10 mm
// parts ~100 mm from the origin, 6-40 points on partial arcs, 1 um lobed form error, 0.1 um
// noise, no normals), in one run. For each set: the independent long double least-squares
// reference; implicitfit `--estimator least-squares` (and minimum-zone, timed); PCL's sample
// consensus with its coefficient refinement (SACSegmentation + setOptimizeCoefficients: float
// points and coefficients, as a user would call it; cylinder and cone need normals, estimated by
// pcl::NormalEstimation from the 8 nearest points). Prints a Markdown table: median time per
// fit, the median and largest geometric difference to the reference (mm; angles times the
// part size), failures (least squares, minimum zone not certified, PCL nothing found or > 1 mm
// off).
// --zone-reference adds, per minimum-zone set, the independent GLOBAL reference of
// tests/support/minimum_zone_reference.h (exchange over enumerations of levelled zones in long
// double: the narrowest levelled zone of a subset that holds every point is the set's minimum
// zone); its column counts the sets it decided and, of those, the ones where implicitfit's
// certified width equals it within 1e-12 mm, is narrower (a zone with fewer than k + 1
// contacts, which no levelled zone represents) or wider (a failure: a narrower zone exists). --test-sets uses the 16 sets per kind of
// tests/fit/metrology/metrology_test.cc (k + 2, 12, 25, 40 points, seeds 31 n + 1..4) instead
// of --sizes/--seeds. The torus has no PCL model (its PCL columns are n/a).
//
// Usage: cmm_comparison [--sizes 6,10,20,40] [--seeds 20]
//                       [--kinds plane,sphere,cylinder,cone,torus] [--zone-reference] [--test-sets]
#include <pcl/ModelCoefficients.h>
#include <pcl/features/normal_3d.h>
#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/sac_segmentation.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "fit/primitive/primitive_fitter.h"
#include "fit/metrology/primitive_tangent.h"
#include "support/cmm_reference.h"
#include "support/minimum_zone_reference.h"

namespace {

using namespace implicitfit;
using testsupport::CmmKind;
using testsupport::CmmSet;

NodeType KindOf(CmmKind k) {
  switch (k) {
    case CmmKind::kPlane:
      return NodeType::kPlane;
    case CmmKind::kSphere:
      return NodeType::kSphere;
    case CmmKind::kCylinder:
      return NodeType::kCylinder;
    case CmmKind::kTorus:
      return NodeType::kTorus;
    default:
      return NodeType::kCone;
  }
}

double Seconds(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// PCL's fit in implicitfit's layout; empty when it found nothing.
std::vector<double> RunPcl(const CmmSet& s) {
  pcl::PointCloud<pcl::PointXYZ>::Ptr xyz(new pcl::PointCloud<pcl::PointXYZ>);
  for (const auto& p : s.points) xyz->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
  pcl::ModelCoefficients c;
  pcl::PointIndices inliers;
  const double threshold = 0.005;  // 5 um: the form error and noise with margin
  if (s.kind == CmmKind::kPlane || s.kind == CmmKind::kSphere) {
    pcl::SACSegmentation<pcl::PointXYZ> seg;
    seg.setOptimizeCoefficients(true);
    seg.setMethodType(pcl::SAC_RANSAC);
    seg.setMaxIterations(1000);
    seg.setDistanceThreshold(threshold);
    seg.setModelType(s.kind == CmmKind::kPlane ? pcl::SACMODEL_PLANE : pcl::SACMODEL_SPHERE);
    if (s.kind == CmmKind::kSphere) seg.setRadiusLimits(0, 100);
    seg.setInputCloud(xyz);
    seg.segment(inliers, c);
  } else {
    pcl::PointCloud<pcl::Normal>::Ptr normals(new pcl::PointCloud<pcl::Normal>);
    pcl::NormalEstimation<pcl::PointXYZ, pcl::Normal> ne;
    ne.setInputCloud(xyz);
    ne.setSearchMethod(
        pcl::search::KdTree<pcl::PointXYZ>::Ptr(new pcl::search::KdTree<pcl::PointXYZ>));
    ne.setKSearch(std::min<int>(8, static_cast<int>(s.points.size()) - 1));
    ne.compute(*normals);
    pcl::SACSegmentationFromNormals<pcl::PointXYZ, pcl::Normal> seg;
    seg.setOptimizeCoefficients(true);
    seg.setMethodType(pcl::SAC_RANSAC);
    seg.setMaxIterations(1000);
    seg.setDistanceThreshold(threshold);
    seg.setNormalDistanceWeight(0.1);
    seg.setRadiusLimits(0, 100);
    seg.setModelType(s.kind == CmmKind::kCylinder ? pcl::SACMODEL_CYLINDER : pcl::SACMODEL_CONE);
    if (s.kind == CmmKind::kCone) seg.setMinMaxOpeningAngle(0.05, 1.5);
    seg.setInputCloud(xyz);
    seg.setInputNormals(normals);
    seg.segment(inliers, c);
  }
  if (c.values.empty()) return {};
  const std::vector<float>& v = c.values;
  if (s.kind == CmmKind::kPlane) return {v[0], v[1], v[2], -v[3]};
  return std::vector<double>(v.begin(), v.end());
}

double Largest(const std::vector<std::pair<std::string, double>>& d) {
  double m = 0;
  for (const auto& e : d) m = std::max(m, std::isfinite(e.second) ? e.second : INFINITY);
  return m;
}

double Median(std::vector<double> v) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

double Max(const std::vector<double>& v) {
  return v.empty() ? NAN : *std::max_element(v.begin(), v.end());
}

std::string Fixed(double v, const char* format = "%.2f") {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, format, v);
  return buffer;
}

std::vector<std::string> Split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(item);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> sizes = {"6", "10", "20", "40"},
                           kinds = {"plane", "sphere", "cylinder", "cone"};
  int seeds = 20;
  bool zone_reference = false, test_sets = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--zone-reference")) {
      zone_reference = true;
      continue;
    }
    if (!std::strcmp(argv[i], "--test-sets")) {
      test_sets = true;
      continue;
    }
    if (i + 1 >= argc) {
      std::fprintf(stderr, "%s: %s needs a value\n", argv[0], argv[i]);
      return 2;
    }
    if (!std::strcmp(argv[i], "--sizes"))
      sizes = Split(argv[++i]);
    else if (!std::strcmp(argv[i], "--kinds"))
      kinds = Split(argv[++i]);
    else if (!std::strcmp(argv[i], "--seeds"))
      seeds = std::atoi(argv[++i]);
    else {
      std::fprintf(stderr,
                   "usage: %s [--sizes N,N] [--seeds S] [--kinds plane,sphere,cylinder,cone,torus] "
                   "[--zone-reference] [--test-sets]\n",
                   argv[0]);
      return 2;
    }
  }
  std::printf(
      "| kind | points | implicitfit LS ms | implicitfit MZ ms | PCL ms | implicitfit LS "
      "difference median / max (mm) "
      "| PCL difference median / max (mm) | failures LS / MZ / PCL | MZ width / LS form error "
      "median |%s\n|---|---|---|---|---|---|---|---|---|%s\n",
      zone_reference ? " MZ vs global reference: decided / equal / narrower / wider |" : "",
      zone_reference ? "---|" : "");
  for (const std::string& name : kinds) {
    const CmmKind kind = name == "plane"      ? CmmKind::kPlane
                         : name == "sphere"   ? CmmKind::kSphere
                         : name == "cylinder" ? CmmKind::kCylinder
                         : name == "torus"    ? CmmKind::kTorus
                                              : CmmKind::kCone;
    const NodeType nk = KindOf(kind);
    const int k = FreeParameterCount(nk);
    std::vector<std::string> kind_sizes = sizes;
    if (test_sets) kind_sizes = {std::to_string(k + 2), "12", "25", "40"};
    for (const std::string& size : kind_sizes) {
      const int n = std::max(std::atoi(size.c_str()), kind == CmmKind::kCone    ? 7
                                                      : kind == CmmKind::kTorus ? 8
                                                                                : 6);
      std::vector<double> t_ls, t_mz, t_pcl, d_ours, d_pcl, mz_ratio;
      int fail_ours = 0, fail_mz = 0, fail_pcl = 0, decided = 0, equal = 0, narrower = 0, wider = 0;
      const int set_count = test_sets ? 4 : seeds;
      for (int seed = 1; seed <= set_count; ++seed) {
        const CmmSet s =
            testsupport::MakeCmmSet(kind, n, test_sets ? 31 * n + seed : 1000 * n + seed);
        const auto ref = testsupport::CmmReference(s).Solve();
        PrimitiveFitOptions o;
        o.kind = nk;
        o.num_threads = 1;
        o.compute_covariance = false;
        o.estimator = Estimator::kLeastSquares;
        auto start = std::chrono::steady_clock::now();
        const PrimitiveFitResult ls = FitPrimitive(s.points, {}, o);
        t_ls.push_back(1e3 * Seconds(start));
        o.estimator = Estimator::kMinimumZone;
        start = std::chrono::steady_clock::now();
        const PrimitiveFitResult mz = FitPrimitive(s.points, {}, o);
        t_mz.push_back(1e3 * Seconds(start));
        start = std::chrono::steady_clock::now();
        const std::vector<double> pcl = kind == CmmKind::kTorus ? std::vector<double>() : RunPcl(s);
        t_pcl.push_back(1e3 * Seconds(start));
        if (!mz.success) ++fail_mz;
        if (zone_reference && mz.success && n >= k + 2) {
          const auto g = testsupport::MinimumZoneBySubsetExchange(s);
          if (g.decided) {
            ++decided;
            const double diff = mz.zone.zone_width - static_cast<double>(g.width);
            equal += std::abs(diff) <= 1e-12;
            narrower += diff < -1e-12;
            wider += diff > 1e-12;
            if (std::abs(diff) > 1e-12)
              std::fprintf(stderr,
                           "%s n=%d seed=%d: implicitfit %.17g (%zu contacts), reference %.17g\n",
                           name.c_str(), n, seed, mz.zone.zone_width, mz.zone.contacts.size(),
                           static_cast<double>(g.width));
          } else {
            std::fprintf(stderr, "%s n=%d seed=%d: reference undecided (subset of %d)\n",
                         name.c_str(), n, seed, g.subset_size);
          }
        }
        if (mz.success && ls.success) mz_ratio.push_back(mz.zone.zone_width / ls.form.form_error);
        if (ls.success)
          d_ours.push_back(Largest(testsupport::ParameterDifferences(s, ls.parameters, ref)));
        else
          ++fail_ours;
        const double dp =
            pcl.empty() ? INFINITY : Largest(testsupport::ParameterDifferences(s, pcl, ref));
        if (std::isfinite(dp) && dp < 1.0)
          d_pcl.push_back(dp);
        else
          ++fail_pcl;  // nothing found, or more than 1 mm off
      }
      // Minimum zone needs k + 2 points: below that its column says n/a.
      const bool mz_applies = n >= k + 2;
      const bool no_pcl = kind == CmmKind::kTorus;
      std::printf(
          "| %s | %d | %.2f | %s | %s | %.2g / %.2g | %s | %d / %s / %s | %s |",
          name.c_str(), n, Median(t_ls), mz_applies ? Fixed(Median(t_mz)).c_str() : "n/a",
          no_pcl ? "n/a" : Fixed(Median(t_pcl)).c_str(), Median(d_ours), Max(d_ours),
          no_pcl ? "n/a" : (Fixed(Median(d_pcl), "%.2g") + " / " + Fixed(Max(d_pcl), "%.2g")).c_str(),
          fail_ours, mz_applies ? std::to_string(fail_mz).c_str() : "n/a",
          no_pcl ? "n/a" : std::to_string(fail_pcl).c_str(),
          mz_applies ? Fixed(Median(mz_ratio), "%.3f").c_str() : "n/a");
      if (zone_reference)
        std::printf(" %s |", mz_applies ? (std::to_string(decided) + " / " + std::to_string(equal) +
                                           " / " + std::to_string(narrower) + " / " +
                                           std::to_string(wider)).c_str()
                                        : "n/a");
      std::printf("\n");
      std::fflush(stdout);
    }
  }
  return 0;
}
