// detect --freeform on real scans, from the user's path (the raw file: normals estimated and
// oriented as `detect` does, no labels; jobs/detect_job.cc's DetectCloudFile, the command's own
// code): the PCL table-top stereo scan and the Stanford bunny's bun000 range scan
// (../shared/data, read in place; skipped when absent).
// Per scan: the primitives and what they leave unassigned, the smooth regions the freeform stage
// found in that remainder (fit/splines/freeform_detection.h step 1), the B-spline surfaces it
// accepted and the points they hold, their pooled RMS distance (the signed distance of each point
// to its patch), the worst patch's RMS, and the noise measured independently of any fit:
//   sigma_plane: for each point, the least-squares plane through it and its k = 12 nearest
//   neighbours (k + 1 = 13 points); r = the point's distance to that plane. For points on a plane
//   with independent noise sigma along the normal, E[r^2] = sigma^2 (1 - 3/13) (the point's own
//   leverage in a 3-parameter fit, averaged: 3/13), so sigma_plane = sqrt(mean r^2 * 13/10).
//   Curvature adds kappa^2 rho^4 / 4-order terms (rho the neighbourhood radius, ~2 spacings),
//   which the figure keeps (it can only overstate the noise on curved parts; the column over
//   the whole cloud shows it on the edges and the clutter).
//   sigma_plane is given over the freeform points and, as the median-based value
//   (median r^2 / 0.4549, the median of chi^2_1), over every point of the cloud.
// Usage: build/bench/freeform_scans [--only table|bunny] > table.md   (progress on stderr)
#include <sys/stat.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "datasets/normals/neighbourhoods.h"
#include "implicitfit/detect.h"

using namespace implicitfit;

namespace {

using Vec = Eigen::Vector3d;

// r_i: the distance of point i to the plane through it and its k nearest neighbours.
std::vector<double> LocalPlaneResiduals(const std::vector<Vec>& points, int k) {
  NeighbourhoodOptions o;
  o.min_k = o.max_k = k;
  o.radius_factor = 0.0;
  const Neighbourhoods nb = FindNeighbourhoods(points, o);
  std::vector<double> r(points.size(), 0.0);
  for (size_t i = 0; i < points.size(); ++i) {
    Vec c = points[i];
    for (int j : nb.indices[i]) c += points[j];
    c /= static_cast<double>(nb.indices[i].size() + 1);
    Eigen::Matrix3d cov = (points[i] - c) * (points[i] - c).transpose();
    for (int j : nb.indices[i]) cov += (points[j] - c) * (points[j] - c).transpose();
    const Vec n = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvectors().col(0);
    r[i] = std::abs((points[i] - c).dot(n));
  }
  return r;
}

struct Row {
  std::string name;
  size_t points = 0;
  int primitives = 0, remainder = 0, region_points = 0, surfaces = 0, assigned = 0;
  int false_assigned = 0;  // assigned with |residual| > 3 sigma_plane of its patch
  double worst_ratio = 0;  // the largest patch RMS / sigma_plane over the patch's points
  double rms = 0, worst_rms = 0, sigma_detector = 0, sigma_plane_free = 0, sigma_plane_all = 0;
  double seconds_detect = 0, seconds_freeform = 0;
};

Row RunScan(const std::string& name, const std::string& path) {
  Row row;
  row.name = name;
  const auto t0 = std::chrono::steady_clock::now();
  const CloudDetection d = DetectCloudFile(path, DetectionOptions{}, true);
  row.seconds_detect = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  row.points = d.cloud.size();
  const nlohmann::json& ff = d.report.at("freeform");
  row.region_points = ff.at("region_points");
  row.seconds_freeform = ff.at("seconds");
  row.sigma_detector = d.result.noise;
  const int k = 12;
  const std::vector<double> r = LocalPlaneResiduals(d.cloud.points, k);
  const double leverage = (k + 1.0) / (k + 1.0 - 3.0);
  double sum2 = 0, s2 = 0;
  for (size_t s = 0; s < d.scene.primitives.size(); ++s) {
    const ScenePrimitive& p = d.scene.primitives[s];
    if (p.model.nodes()[0].type != NodeType::kBSplineSurface) {
      ++row.primitives;
      continue;
    }
    ++row.surfaces;
    row.worst_rms = std::max(row.worst_rms, p.rms_distance);
    std::vector<int> members;
    double patch_plane2 = 0;
    for (size_t i = 0; i < d.cloud.size(); ++i)
      if (d.result.labels[i] == static_cast<int>(s)) {
        members.push_back(static_cast<int>(i));
        sum2 += d.result.residuals[i] * d.result.residuals[i];
        patch_plane2 += r[i] * r[i];
      }
    if (members.empty()) continue;
    row.assigned += static_cast<int>(members.size());
    s2 += patch_plane2;
    // The patch's own noise: the local-plane figure over its points.
    const double sigma_patch = std::sqrt(patch_plane2 / members.size() * leverage);
    if (sigma_patch > 0) row.worst_ratio = std::max(row.worst_ratio, p.rms_distance / sigma_patch);
    for (int i : members) row.false_assigned += std::abs(d.result.residuals[i]) > 3.0 * sigma_patch;
  }
  row.remainder = d.scene.unassigned + row.assigned;
  row.rms = row.assigned ? std::sqrt(sum2 / row.assigned) : 0.0;
  std::fprintf(stderr,
               "%s: detection %.1f s; assigned with |residual| > 3 sigma_plane of its "
               "patch: %d; lost points by reason: %s; rejections: %s\n",
               name.c_str(), row.seconds_detect, row.false_assigned,
               ff.at("lost_points").dump().c_str(), ff.at("rejected").dump().c_str());
  std::vector<double> all2;
  for (double x : r) all2.push_back(x * x);
  row.sigma_plane_free = row.assigned ? std::sqrt(s2 / row.assigned * leverage) : 0.0;
  std::nth_element(all2.begin(), all2.begin() + all2.size() / 2, all2.end());
  row.sigma_plane_all = std::sqrt(all2[all2.size() / 2] / 0.4549 * leverage);
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  std::string only;
  for (int i = 1; i + 1 < argc; ++i)
    if (!std::strcmp(argv[i], "--only")) only = argv[i + 1];
  const std::string data = IMPLICITFIT_SHARED_DATA;
  const std::vector<std::pair<std::string, std::string>> scans = {
      {"table", data + "/pcl/pcl_table_scene_mug_stereo_textured_finite.ply"},
      {"bunny", data + "/stanford/stanford_bunny_bun000_rangescan.ply"}};
  std::printf(
      "| scan | points | primitives | left unassigned | in smooth regions | B-spline "
      "surfaces | points assigned | share of smooth regions | share of all left unassigned "
      "| pooled RMS | worst patch RMS | sigma_plane (freeform pts) | RMS / sigma_plane | "
      "worst patch RMS / its sigma_plane | sigma_plane (all, median) | detector sigma | "
      "detect + freeform s | freeform s |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const auto& [name, path] : scans) {
    if (!only.empty() && only != name) continue;
    struct stat st;
    if (stat(path.c_str(), &st) != 0) {
      std::fprintf(stderr, "%s: %s absent, skipped\n", name.c_str(), path.c_str());
      continue;
    }
    const Row r = RunScan(name, path);
    std::printf(
        "| %s | %zu | %d | %d | %d | %d | %d | %.1f%% | %.1f%% | %.3g | %.3g | %.3g | %.2f "
        "| %.2f | %.3g | %.3g | %.1f | %.1f |\n",
        r.name.c_str(), r.points, r.primitives, r.remainder, r.region_points, r.surfaces,
        r.assigned, r.region_points ? 100.0 * r.assigned / r.region_points : 0.0,
        r.remainder ? 100.0 * r.assigned / r.remainder : 0.0, r.rms, r.worst_rms,
        r.sigma_plane_free, r.sigma_plane_free > 0 ? r.rms / r.sigma_plane_free : 0.0,
        r.worst_ratio, r.sigma_plane_all, r.sigma_detector, r.seconds_detect, r.seconds_freeform);
    std::fflush(stdout);
  }
  return 0;
}
