// implicitfit detect vs CGAL 5.5 Efficient RANSAC on the same clouds, in one run:
//   the eight Fit4CAD clouds (../shared/data/fit4cad, GPL-3: read in place) with normals
//   estimated as a user's run would (PCA + MST orientation) and with normals from the ground-
//   truth surfaces (gradients of the implicit equations; tori: grad of the torus fitted to their
//   labelled points), CGAL's labelled icosahedron, and generated scenes
//   (datasets/generators/scene_generator.h: six primitives, noise 0.005, 10% outliers), CGAL's ten
//   spheres and PCL's sphere cap (labels from reference spheres, normals estimated).
// Per cloud and method: recall, precision, mean IoU, kind accuracy, coverage
// (fit/detect/segmentation_metrics.h, primitives with >= 1% of the points), parameter error (RMS of the
// detected f over each recovered ground-truth primitive's points, over the bbox diagonal;
// implicitfit only: the CGAL wrapper does not export shapes) and time (detection only: both get
// the same points and normals). CGAL runs with its defaults and with the best (recall, then
// precision) of a 2 x 2 grid over epsilon (0.3%, 1% of the diagonal) and cluster_epsilon (1%, 3%),
// min_points 0.5% of the points, each grid run stopped after 10 s (CGAL's defaults run to the end).
// --scale: instead, one generated scene of about 10^6 points (ground 500 000, five objects of
// 80 000, 10% outliers), implicitfit only: neighbourhoods + detection time.
// --scale-scene DIR: writes that scene as DIR/scene_1e6.ply (double x y z, normals) and its
// truth DIR/scene_1e6.truth (datasets/io/truth_labels.h) for bench/detect_scale.sh, which runs
// `implicitfit detect` and `detect_comparison --cgal` on it under /usr/bin/time -v.
// --cgal CLOUD TRUTH: CGAL's Efficient RANSAC (defaults) on a cloud file with normals, scored
// against a truth file: one table row (its peak memory is the process's).
// Usage: detect_comparison [--quick] [--no-cgal] [--scale] > table.md
#include <Eigen/Dense>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "bench/cgal_shape_detection.h"
#include "datasets/clouds/cloud_file.h"
#include "datasets/clouds/cloud_file_info.h"
#include "datasets/generators/ground_truth.h"
#include "datasets/normals/neighbourhoods.h"
#include "datasets/normals/normal_estimation.h"
#include "datasets/generators/scene_generator.h"
#include "datasets/clouds/ply_writer.h"
#include "datasets/io/truth_labels.h"
#include "fit/detect/primitive_detector.h"
#include "fit/primitive/primitive_fitter.h"
#include "fit/detect/segmentation_metrics.h"

using namespace implicitfit;

namespace {

struct Case {
  std::string name;
  PointCloud cloud;
  std::vector<int> labels;
  std::vector<NodeType> kinds;
};

struct Row {
  SegmentationMetrics m;
  double seconds = 0.0, param_error = NAN;
};

// Normals from the Fit4CAD equations: plane (a b c d): (a, b, c); quadric
// (a11 a22 a33 a12 a13 a23 b1 b2 b3 c): A x + b; torus: grad of a torus fitted to its points.
std::vector<Eigen::Vector3d> TruthNormals(const PointCloud& cloud, const std::vector<int>& labels,
                                          const std::vector<NodeType>& kinds,
                                          const std::vector<std::vector<double>>& coefficients,
                                          const std::vector<Eigen::Vector3d>& estimated) {
  std::vector<Eigen::Vector3d> n = estimated;
  for (size_t g = 0; g < kinds.size(); ++g) {
    std::vector<int> idx;
    for (size_t i = 0; i < labels.size(); ++i)
      if (labels[i] == static_cast<int>(g)) idx.push_back(static_cast<int>(i));
    const std::vector<double>& c = coefficients[g];
    if (kinds[g] == NodeType::kPlane && c.size() == 4) {
      for (int i : idx) n[i] = Eigen::Vector3d(c[0], c[1], c[2]).normalized();
    } else if (kinds[g] != NodeType::kTorus && c.size() == 10) {
      Eigen::Matrix3d A;
      A << c[0], c[3], c[4], c[3], c[1], c[5], c[4], c[5], c[2];
      const Eigen::Vector3d b(c[6], c[7], c[8]);
      for (int i : idx) n[i] = (A * cloud.points[i] + b).normalized();
    } else {
      std::vector<Eigen::Vector3d> px, pn;
      for (int i : idx) px.push_back(cloud.points[i]), pn.push_back(estimated[i]);
      PrimitiveFitOptions o;
      o.kind = kinds[g];
      const PrimitiveFitResult r = FitPrimitive(px, pn, o);
      if (!r.parameters.empty()) {
        const Model m = r.ToModel(kinds[g]);
        for (int i : idx) n[i] = m.Gradient(cloud.points[i]).normalized();
      }
    }
  }
  // Orient consistently (the equations' signs are arbitrary), as for any file's normals.
  return n;
}

double Diagonal(const PointCloud& c) {
  Eigen::Vector3d lo = c.points[0], hi = c.points[0];
  for (const auto& p : c.points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  return (hi - lo).norm();
}

Row RunImplicitfit(const Case& c) {
  Row row;
  const auto start = std::chrono::steady_clock::now();
  const Neighbourhoods nb = FindNeighbourhoods(c.cloud.points);
  const DetectionResult r =
      DetectPrimitives(c.cloud.points, c.cloud.normals, nb.indices, nb.spacing);
  row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::vector<NodeType> kinds;
  for (const auto& p : r.primitives) kinds.push_back(p.kind);
  row.m = CompareSegmentations(c.labels, c.kinds, r.labels, kinds);
  double ss = 0;
  long n = 0;
  for (size_t g = 0; g < c.kinds.size(); ++g) {
    const int d = row.m.match[g];
    if (d < 0 || row.m.iou[g] < 0.5 || kinds[d] != c.kinds[g]) continue;
    Model m;
    m.AddPrimitive(kinds[d], r.primitives[d].parameters);
    for (size_t i = 0; i < c.labels.size(); ++i)
      if (c.labels[i] == static_cast<int>(g)) ss += std::pow(m.Value(c.cloud.points[i]), 2), ++n;
  }
  if (n > 0) row.param_error = std::sqrt(ss / n) / Diagonal(c.cloud);
  return row;
}

Row RunCgal(const Case& c, const implicitfit_bench::CgalParameters& p) {
  Row row;
  const implicitfit_bench::CgalDetection d =
      implicitfit_bench::CgalEfficientRansac(c.cloud.points, c.cloud.normals, p);
  row.seconds = d.seconds;
  row.m = CompareSegmentations(c.labels, c.kinds, d.labels, d.kinds);
  return row;
}

void Print(const std::string& cloud, size_t points, const std::string& method, const Row& r) {
  char err[32] = "-";
  if (std::isfinite(r.param_error)) std::snprintf(err, sizeof err, "%.1e", r.param_error);
  std::printf("| %s | %zu | %s | %d/%d | %d/%d | %.2f | %.2f | %.2f | %s | %.2f |\n", cloud.c_str(),
              points, method.c_str(), r.m.recovered, r.m.truth_counted, r.m.precise,
              r.m.detected_counted, r.m.mean_iou, r.m.kind_accuracy, r.m.coverage, err, r.seconds);
  std::fflush(stdout);
}

}  // namespace

GeneratedScene ScaleScene() {
  GeneratedSceneOptions o;
  o.ground_points = 500000;
  o.object_points = 80000;
  return GenerateScene(o);
}

namespace {

// --scale: detection on the 10^6-point scene, one implicitfit row.
void RunScale() {
  const GeneratedScene g = ScaleScene();
  Case c{"generated scene, 10^6 points", g.cloud, g.labels, g.kinds};
  const Row r = RunImplicitfit(c);
  Print(c.name, c.cloud.size(), "implicitfit", r);
}

// --scale-scene DIR: the 10^6-point scene and its truth, written for bench/detect_scale.sh.
void WriteScaleScene(const std::string& dir) {
  const GeneratedScene g = ScaleScene();
  WritePlyFile(g.cloud, dir + "/scene_1e6.ply");
  WriteTruthFile(g.labels, g.kinds, dir + "/scene_1e6.truth");
  std::printf("%s/scene_1e6.ply: %zu points\n", dir.c_str(), g.cloud.size());
}

// --cgal CLOUD TRUTH: CGAL's defaults on a cloud file, scored against a truth file.
void RunCgalOnFile(const char* cloud, const char* truth) {
  Case c;
  c.name = cloud;
  c.cloud = ReadCloudFile(cloud);
  const TruthLabels t = ReadTruthFile(truth, static_cast<long>(c.cloud.size()));
  c.labels = t.labels;
  c.kinds = t.kinds;
  Print(c.name, c.cloud.size(), "CGAL defaults", RunCgal(c, {}));
}

// The Fit4CAD clouds with estimated normals and (unless quick) with the truth's normals.
void AddFit4Cad(const std::string& data, bool quick, std::vector<Case>* cases) {
  for (const std::string name : {"test_PC33", "test_PC34", "test_PC35", "test_PC21", "train_PC124",
                                 "train_PC131", "train_PC145", "train_PC155"}) {
    const std::string base = data + "/fit4cad/fit4cad_" + name;
    if (!std::ifstream(base + ".xyzl")) continue;
    Case c;
    CloudFileInfo info;
    c.cloud = ReadCloudFile(base + ".xyzl", &info);
    c.labels = info.labels;
    for (int& l : c.labels) l -= 1;
    c.kinds = ReadFit4CadKinds(base + "/" + name + "_implicit.txt");
    EnsureOrientedNormals(&c.cloud);
    c.name = name + " (est. normals)";
    cases->push_back(c);
    Case t = c;
    t.name = name + " (truth normals)";
    t.cloud.normals =
        TruthNormals(c.cloud, c.labels, c.kinds,
                     ReadFit4CadCoefficients(base + "/" + name + "_implicit.txt"), c.cloud.normals);
    EnsureOrientedNormals(&t.cloud);
    if (!quick) cases->push_back(t);
  }
}

// CGAL's labelled icosahedron (20 planes, normals estimated), when present.
void AddIcosahedron(const std::string& data, std::vector<Case>* cases) {
  const std::string path = data + "/cgal/cgal_ball_icosahedron_20planes_labeled.ply";
  if (!std::ifstream(path)) return;
  Case c;
  c.name = "CGAL icosahedron";
  c.cloud = ReadCloudFile(path);
  EnsureOrientedNormals(&c.cloud);
  c.labels = ReadPlyIntProperty(path, "segment_index");
  c.kinds.assign(20, NodeType::kPlane);
  cases->push_back(c);
}

// The spheres (x, y, z, r) of reference_spheres.txt listed for files whose name contains `stem`.
std::vector<Eigen::Vector4d> ReferenceSpheres(std::ifstream& ref, const std::string& stem) {
  std::vector<Eigen::Vector4d> spheres;
  for (std::string line; std::getline(ref, line);) {
    char f[256];
    double cx, cy, cz, r;
    if (line.empty() || line[0] == '#' ||
        std::sscanf(line.c_str(), "%255s %lf %lf %lf %lf", f, &cx, &cy, &cz, &r) != 5)
      continue;
    const std::string fs = f;
    if (fs.find(stem) != std::string::npos) spheres.emplace_back(cx, cy, cz, r);
  }
  return spheres;
}

// CGAL's ten spheres and PCL's sphere cap, labelled by reference spheres, normals estimated.
void AddSphereClouds(const std::string& data, std::vector<Case>* cases) {
  // Labels from the reference spheres fitted to them (cgal/reference_spheres.txt: algebraic fits,
  // RMS <= 3e-7; a point belongs to the sphere it lies on within 1e-4 of the cloud's diagonal, -1
  // otherwise).
  for (const auto& [file, name] :
       {std::pair<std::string, std::string>{"cgal/cgal_spheres_10.ply", "CGAL 10 spheres"},
        {"pcl/pcl_cturtle_sphere_cap_r2.ply", "PCL sphere cap (cturtle)"}}) {
    const std::string path = data + "/" + file;
    std::ifstream ref(data + "/cgal/reference_spheres.txt");
    if (!std::ifstream(path) || !ref) continue;
    const std::string stem = file.substr(file.find('/') + 1, file.rfind('.') - file.find('/') - 1);
    const std::vector<Eigen::Vector4d> spheres = ReferenceSpheres(ref, stem);
    if (spheres.empty()) continue;
    Case c;
    c.name = name;
    c.cloud = ReadCloudFile(path);
    c.cloud.normals.clear();
    EnsureOrientedNormals(&c.cloud);
    const double tol = 1e-4 * Diagonal(c.cloud);
    c.labels.assign(c.cloud.size(), -1);
    for (size_t i = 0; i < c.cloud.size(); ++i)
      for (size_t k = 0; k < spheres.size(); ++k)
        if (std::abs((c.cloud.points[i] - spheres[k].head<3>()).norm() - spheres[k][3]) < tol)
          c.labels[i] = static_cast<int>(k);
    c.kinds.assign(spheres.size(), NodeType::kSphere);
    cases->push_back(c);
  }
}

// Every cloud of the table, in its order (quick: no truth-normal Fit4CAD rows, one scene).
std::vector<Case> MakeCases(bool quick) {
  const std::string data = IMPLICITFIT_SHARED_DATA;
  std::vector<Case> cases;
  AddFit4Cad(data, quick, &cases);
  AddIcosahedron(data, &cases);
  AddSphereClouds(data, &cases);
  for (unsigned seed = 1; seed <= (quick ? 1u : 3u); ++seed) {
    GeneratedSceneOptions o;
    o.seed = seed;
    GeneratedScene g = GenerateScene(o);
    cases.push_back({"generated scene " + std::to_string(seed), g.cloud, g.labels, g.kinds});
  }
  return cases;
}

// CGAL's best (recall, then precision) over the 2 x 2 grid of epsilon and cluster_epsilon.
Row CgalBestOfGrid(const Case& c) {
  Row best;
  bool first = true;
  for (double eps : {0.003, 0.01})
    for (double cluster : {0.01, 0.03})
      for (double min_points : {0.005}) {
        implicitfit_bench::CgalParameters p;
        p.defaults = false;
        p.max_seconds = 10.0;
        p.epsilon_fraction = eps;
        p.cluster_epsilon_fraction = cluster;
        p.min_points_fraction = min_points;
        const Row r = RunCgal(c, p);
        if (first || r.m.recovered > best.m.recovered ||
            (r.m.recovered == best.m.recovered &&
             r.m.precise * best.m.detected_counted > best.m.precise * r.m.detected_counted))
          best = r, first = false;
      }
  return best;
}

// The summary's sums over the clouds.
struct Totals {
  double seconds_ours = 0, seconds_cgal = 0;
  int rec_ours = 0, rec_cgal = 0, rec_grid = 0, truth = 0;
};

// A cloud's rows: implicitfit, then (with cgal) CGAL's defaults and its best of the grid.
void RunCase(const Case& c, bool cgal, Totals* totals) {
  const Row ours = RunImplicitfit(c);
  Print(c.name, c.cloud.size(), "implicitfit", ours);
  totals->seconds_ours += ours.seconds;
  totals->rec_ours += ours.m.recovered;
  totals->truth += ours.m.truth_counted;
  if (!cgal) return;
  implicitfit_bench::CgalParameters defaults;
  const Row d = RunCgal(c, defaults);
  Print(c.name, c.cloud.size(), "CGAL defaults", d);
  totals->seconds_cgal += d.seconds;
  totals->rec_cgal += d.m.recovered;
  const Row best = CgalBestOfGrid(c);
  Print(c.name, c.cloud.size(), "CGAL best of grid", best);
  totals->rec_grid += best.m.recovered;
}

// The lines under the table: recovered primitives and detection time per method.
void PrintSummary(const Totals& t, bool cgal) {
  std::printf("\nrecovered ground-truth primitives: implicitfit %d/%d", t.rec_ours, t.truth);
  if (cgal)
    std::printf(", CGAL defaults %d/%d, CGAL best of grid %d/%d", t.rec_cgal, t.truth, t.rec_grid,
                t.truth);
  std::printf("\ntotal detection time: implicitfit %.2f s", t.seconds_ours);
  if (cgal) std::printf(", CGAL defaults %.2f s", t.seconds_cgal);
  std::printf("\n");
}

}  // namespace

// The single-run modes (--scale, --scale-scene, --cgal) when asked, else the table and summary.
int main(int argc, char** argv) {
  bool quick = false, cgal = true;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--scale")) {
      RunScale();
      return 0;
    }
    if (!std::strcmp(argv[i], "--scale-scene") && i + 1 < argc) {
      WriteScaleScene(argv[i + 1]);
      return 0;
    }
    if (!std::strcmp(argv[i], "--cgal") && i + 2 < argc) {
      RunCgalOnFile(argv[i + 1], argv[i + 2]);
      return 0;
    }
    if (!std::strcmp(argv[i], "--quick")) quick = true;
    if (!std::strcmp(argv[i], "--no-cgal")) cgal = false;
  }
  const std::vector<Case> cases = MakeCases(quick);
  std::printf(
      "| cloud | points | method | recall | precision | mean IoU | kind acc. | coverage | param. "
      "err. | time (s) |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  Totals totals;
  for (const Case& c : cases) RunCase(c, cgal, &totals);
  PrintSummary(totals, cgal);
  return 0;
}
