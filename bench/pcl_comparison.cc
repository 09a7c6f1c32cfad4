// implicitfit vs PCL SACSegmentationFromNormals (RANSAC + optimizeModelCoefficients), in one
// run, on the same generated clouds: partial views, 1% noise (of the primitive's size) along
// the normal, 20% uniform outliers, 10^4 / 10^5 / 10^6 points. Prints a Markdown table of the
// median time of each tool, the mean parameter errors over the seeds, and the ratios
// implicitfit / PCL (< 1: implicitfit better).
//
// PCL is given what it needs and implicitfit is not: the true noise (distance threshold 3
// sigma), radius limits and, for the cone, opening-angle limits. implicitfit runs with its
// defaults (it estimates the scale itself).
//
// Usage: pcl_comparison [--sizes 10000,100000,1000000] [--seeds 3] [--kinds
// sphere,cylinder,cone,plane]
#include <pcl/ModelCoefficients.h>
#include <pcl/point_types.h>
#include <pcl/segmentation/sac_segmentation.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "datasets/generators/model_sampler.h"
#include "fit/primitive/primitive_fitter.h"

namespace {

using namespace implicitfit;
using Vec = Eigen::Vector3d;

struct Truth {
  NodeType kind;
  std::vector<double> params;
  double size;
  Vec view;
  double view_angle;
};

Truth TruthOf(const std::string& kind) {
  if (kind == "sphere") return {NodeType::kSphere, {1.0, -2.0, 0.5, 1.0}, 1.0, Vec(1, 1, 1), 70};
  if (kind == "cylinder") {
    const Vec a = Vec(0.0, 0.6, 0.8);
    return {NodeType::kCylinder, {0.5, 0.2, -1.0, a.x(), a.y(), a.z(), 0.5}, 0.5, Vec(1, 0, 0), 80};
  }
  if (kind == "cone") {
    const Vec a = Vec(-0.3, 0.4, 1.0).normalized();
    return {NodeType::kCone, {0.1, 0.2, 0.3, a.x(), a.y(), a.z(), 0.5}, 1.0, Vec(1, 0, 0), 85};
  }
  const Vec n = Vec(0.2, -0.3, 0.9).normalized();
  return {NodeType::kPlane, {n.x(), n.y(), n.z(), 0.4}, 1.0, Vec::Zero(), 180};
}

double Angle(Vec a, Vec b) {
  a.normalize();
  b.normalize();
  return std::acos(std::min(1.0, std::abs(a.dot(b))));
}

// Named errors of a fitted parameter vector (model layout) against the truth.
std::map<std::string, double> Errors(NodeType kind, const std::vector<double>& t,
                                     const std::vector<double>& p) {
  std::map<std::string, double> e;
  if (p.empty()) return e;
  switch (kind) {
    case NodeType::kSphere:
      e["center"] = (Vec(p[0], p[1], p[2]) - Vec(t[0], t[1], t[2])).norm();
      e["radius"] = std::abs(p[3] - t[3]);
      break;
    case NodeType::kCylinder: {
      const Vec a = Vec(p[3], p[4], p[5]).normalized(), q(p[0], p[1], p[2]), t0(t[0], t[1], t[2]);
      e["axis_angle"] = Angle(a, Vec(t[3], t[4], t[5]));
      e["axis_offset"] = ((t0 - q) - a * a.dot(t0 - q)).norm();
      e["radius"] = std::abs(p[6] - t[6]);
      break;
    }
    case NodeType::kCone:
      e["apex"] = (Vec(p[0], p[1], p[2]) - Vec(t[0], t[1], t[2])).norm();
      e["axis_angle"] = Angle(Vec(p[3], p[4], p[5]), Vec(t[3], t[4], t[5]));
      e["half_angle"] = std::abs(p[6] - t[6]);
      break;
    default: {
      Vec n(p[0], p[1], p[2]);
      double d = p[3] / n.norm();
      n.normalize();
      if (n.dot(Vec(t[0], t[1], t[2])) < 0) n = -n, d = -d;
      e["normal_angle"] = Angle(n, Vec(t[0], t[1], t[2]));
      e["offset"] = std::abs(d - t[3]);
      break;
    }
  }
  return e;
}

// PCL's coefficients in the model layout.
std::vector<double> FromPcl(NodeType kind, const std::vector<float>& c) {
  if (kind == NodeType::kPlane) return {c[0], c[1], c[2], -c[3]};  // ax + by + cz + d = 0
  return std::vector<double>(c.begin(), c.end());                  // sphere 4, cylinder 7, cone 7
}

std::vector<double> RunPcl(const Truth& truth, const PointCloud& cloud, double sigma) {
  pcl::PointCloud<pcl::PointXYZ>::Ptr xyz(new pcl::PointCloud<pcl::PointXYZ>);
  pcl::PointCloud<pcl::Normal>::Ptr normals(new pcl::PointCloud<pcl::Normal>);
  xyz->resize(cloud.size());
  normals->resize(cloud.size());
  for (size_t i = 0; i < cloud.size(); ++i) {
    (*xyz)[i] = pcl::PointXYZ(cloud.points[i].x(), cloud.points[i].y(), cloud.points[i].z());
    (*normals)[i] = pcl::Normal(cloud.normals[i].x(), cloud.normals[i].y(), cloud.normals[i].z());
  }
  pcl::SACSegmentationFromNormals<pcl::PointXYZ, pcl::Normal> seg;
  seg.setOptimizeCoefficients(true);
  seg.setMethodType(pcl::SAC_RANSAC);
  seg.setMaxIterations(1000);
  seg.setDistanceThreshold(3.0 * sigma);
  seg.setNormalDistanceWeight(0.1);
  seg.setRadiusLimits(0.0, 10.0 * truth.size);
  switch (truth.kind) {
    case NodeType::kSphere:
      seg.setModelType(pcl::SACMODEL_SPHERE);
      break;
    case NodeType::kCylinder:
      seg.setModelType(pcl::SACMODEL_CYLINDER);
      break;
    case NodeType::kCone:
      seg.setModelType(pcl::SACMODEL_CONE);
      seg.setMinMaxOpeningAngle(0.05, 1.5);
      break;
    default:
      seg.setModelType(pcl::SACMODEL_NORMAL_PLANE);
      break;
  }
  seg.setInputCloud(xyz);
  seg.setInputNormals(normals);
  pcl::PointIndices inliers;
  pcl::ModelCoefficients coefficients;
  seg.segment(inliers, coefficients);
  if (coefficients.values.empty()) return {};
  return FromPcl(truth.kind, coefficients.values);
}

double Seconds(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::vector<std::string> Split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(item);
  return out;
}

double Median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> sizes = {"10000", "100000", "1000000"},
                           kinds = {"sphere", "cylinder", "cone", "plane"};
  int seeds = 3;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--sizes"))
      sizes = Split(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--kinds"))
      kinds = Split(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--seeds"))
      seeds = std::atoi(argv[i + 1]);
    else {
      std::fprintf(stderr,
                   "usage: %s [--sizes N,N] [--seeds S] [--kinds sphere,cylinder,cone,plane]\n",
                   argv[0]);
      return 2;
    }
  }
  std::printf(
      "| kind | points | implicitfit ms | PCL ms | time ratio | parameter | implicitfit error | "
      "PCL error | error ratio |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (const std::string& kind : kinds) {
    const Truth truth = TruthOf(kind);
    for (const std::string& size : sizes) {
      const int n = std::atoi(size.c_str());
      std::vector<double> t_ours, t_pcl;
      std::map<std::string, double> err_ours, err_pcl;
      int fail_ours = 0, fail_pcl = 0;
      for (int seed = 1; seed <= seeds; ++seed) {
        Model model;
        model.AddPrimitive(truth.kind, truth.params);
        SampleOptions so;
        so.count = n;
        so.noise = 0.01 * truth.size;
        so.outlier_fraction = 0.2;
        so.seed = seed;
        so.view_dir = truth.view;
        so.view_angle_deg = truth.view_angle;
        const SampledCloud sampled = SampleModel(model, so);

        PrimitiveFitOptions fo;
        fo.kind = truth.kind;
        fo.seed = seed;
        fo.compute_covariance = false;
        auto start = std::chrono::steady_clock::now();
        const PrimitiveFitResult ours =
            FitPrimitive(sampled.cloud.points, sampled.cloud.normals, fo);
        t_ours.push_back(Seconds(start));
        start = std::chrono::steady_clock::now();
        const std::vector<double> pcl = RunPcl(truth, sampled.cloud, so.noise);
        t_pcl.push_back(Seconds(start));
        if (!ours.success) ++fail_ours;
        if (pcl.empty()) ++fail_pcl;
        for (auto& [k, v] : Errors(truth.kind, truth.params,
                                   ours.success ? ours.parameters : std::vector<double>{}))
          err_ours[k] += v / seeds;
        for (auto& [k, v] : Errors(truth.kind, truth.params, pcl)) err_pcl[k] += v / seeds;
      }
      const double mo = 1e3 * Median(t_ours), mp = 1e3 * Median(t_pcl);
      bool first = true;
      for (auto& [name, e] : err_ours) {
        const double ep = err_pcl.count(name) ? err_pcl[name] : NAN;
        if (first)
          std::printf("| %s | %d | %.1f | %.1f | %.2f | %s | %.3g | %.3g | %.3f |\n", kind.c_str(),
                      n, mo, mp, mo / mp, name.c_str(), e, ep, e / ep);
        else
          std::printf("| | | | | | %s | %.3g | %.3g | %.3f |\n", name.c_str(), e, ep, e / ep);
        first = false;
      }
      if (fail_ours || fail_pcl)
        std::printf("| | | failures: implicitfit %d, PCL %d of %d | | | | | | |\n", fail_ours,
                    fail_pcl, seeds);
      std::fflush(stdout);
    }
  }
  return 0;
}
