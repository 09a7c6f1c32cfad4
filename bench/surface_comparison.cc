// fit --model patch-mesh + mesh vs PCL's Poisson (depth 7, 8) and PCL's marching cubes (Hoppe's
// signed distance, 100^3 grid) on the same oriented clouds, in one run (issue 11):
//   scans: ../shared/data/cgal kitten and oni (skipped when absent), the bundled sphere
//          (datasets/data/cgal_sphere_single.xyz); judged against the input points;
//   generated closed surfaces: ellipsoid (radii 1, 0.7, 0.5), torus (R 1, r 0.35), smooth union
//          of two spheres (r 0.6 at x = -+0.4, delta 0.1); 20 000 points with noise 0.2% of
//          their size, judged against the generating model and 20 000 noise-free points on it.
// Figures (bench/mesh_judging.h): Chamfer distance and its two directed means, Hausdorff
// distance, normal consistency, watertightness, triangles; patch count (implicitfit), seconds
// (fit + mesh; PCL: its reconstruction; wall and CPU time: the machine may be shared), peak
// resident memory of the method
// (each method runs in its own forked process: VmHWM of that process after the reconstruction, the
// parent's few MB included). Patch-mesh rows use the fitter's defaults
// (fit/bernstein/bernstein_mesh_fitter.h) and mesh the zero set on the fit's grid box with the
// mesher's default cell (datasets/meshing/default_mesh_cell.h, what `mesh` does; --mesh-cells n:
// longest box side / n); on the non-convex scans further rows fit at degrees 4 and 5 (--scan-degree), on
// convex inputs a second row fits with --convex and reports the certificate.
//   build/bench/surface_comparison [--points 20000] [--seed 1] [--cells n] [--degree k]
//                                [--scan-degree k2,k3,... (default 4,5; 0: no further scan row)]
//                                [--scan-cells n2 (the further scan rows' cubes; default: --cells)]
//                                [--far-field-ramp r] [--far-field-ramp-power p] [--only NAME-PART]
//                                [--far-field-relaxation r] [--far-field-floor f]
//                                [--sign-guard-samples s] [--normal-weight w] (MeshFitOptions, step 2)
//                                [--sharp-normal f (crease leaves' normal rows x f, estimated
//                                normals only: the cases whose normals the bench estimated)]
//                                [--progress 1 (the fit's stages and rounds on stderr)]
//                                [--continuity 0|1] [--soft-c1 w (continuity 0)]
//                                [--smoothing-weight w] [--mesh-cells n] [--mesh-feature-angle deg]
//                                [--adaptive 1] [--max-levels L] [--sharp 0|1] [--feature-angle deg]
//                                [--refine-factor r] [--refine-spacing-floor s]
//                                [--min-leaf-spacings m] [--max-unknowns n] [--soft-c1-sharp f]
//                                (adaptive refinement, MeshFitOptions)
//                                [--tangent-plane-signs 1] [--true-normals 1]
//                                [--save-meshes DIR (every method's mesh as
//                                DIR/<cloud>-<method>.ply with each vertex's distance to the
//                                truth in .ply.dist, the cloud and the truth's points as
//                                DIR/<cloud>-cloud.xyz and -truth.xyz)]
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "bench/mesh_judging.h"
#include "datasets/clouds/cloud_file.h"
#include "datasets/generators/cad_solids.h"
#include "datasets/generators/generated_solids.h"
#include "datasets/normals/normal_estimation.h"
#include "datasets/meshing/model_mesher.h"
#include "datasets/generators/model_sampler.h"
#include "fit/bernstein/bernstein_mesh_fitter.h"
#ifdef IMPLICITFIT_HAVE_CGAL_POISSON
#include "bench/cgal_poisson.h"
#endif

namespace {

using implicitfit::TriangleMesh;
using Vec = Eigen::Vector3d;

struct Case {
  std::string name;
  std::vector<Vec> points, normals;
  bench::TruthSurface truth;
  double size = 1;
  bool convex = false;
  bool scan = false;
  bool estimated_normals = false;  // PCA normals (datasets/normals), not the file's or model's
};

// What a method's child process sends back.
struct Outcome {
  bench::Figures figures;
  double peak_rss_mb = 0;
  double cpu_seconds = 0;  // user + system time of the method
  long long patches = 0;
  int certified = -1;  // -1: not asked; 0/1: the convexity certificate
  double fit_rms = 0, initial_rms = 0;
  long long box_sign_errors = -1;  // MeshFitResult::box_sign_errors
  bool ok = false;
};

double CpuSeconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double PeakRssMb() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::atof(line.c_str() + 6) / 1024.0;
  return 0;
}

// Runs `method` (which fills the mesh and the implicitfit fields) in a forked child, timing it
// and reading its peak memory before judging the mesh.
Outcome RunIsolated(const Case& c, unsigned seed,
                    const std::function<TriangleMesh(Outcome*)>& method,
                    const std::string& save_path = "") {
  int fd[2];
  if (pipe(fd) != 0) return {};
  std::fflush(stdout);
  const pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    Outcome o;
    const auto t0 = std::chrono::steady_clock::now();
    const double cpu0 = CpuSeconds();
    const TriangleMesh mesh = method(&o);
    o.cpu_seconds = CpuSeconds() - cpu0;
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    o.peak_rss_mb = PeakRssMb();
    if (!save_path.empty() && !mesh.triangles.empty()) {
      implicitfit::WriteMeshPlyFile(mesh, save_path);
      // Each vertex's distance to the truth, one a line (where is the mesh off?).
      if (FILE* f = std::fopen((save_path + ".dist").c_str(), "w")) {
        Vec unused;
        for (const Vec& v : mesh.vertices) std::fprintf(f, "%.6g\n", c.truth.distance(v, &unused));
        std::fclose(f);
      }
    }
    o.figures = bench::JudgeMesh(mesh, c.truth, seed);
    o.figures.seconds = seconds;
    o.ok = true;
    const ssize_t written = write(fd[1], &o, sizeof o);
    _exit(written == static_cast<ssize_t>(sizeof o) ? 0 : 1);
  }
  close(fd[1]);
  Outcome o;
  if (read(fd[0], &o, sizeof o) != static_cast<ssize_t>(sizeof o)) o.ok = false;
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  return o;
}

void Row(const Case& c, const std::string& method, const Outcome& o) {
  if (!o.ok) {
    std::printf("| %s | %s | failed | | | | | | | | | |\n", c.name.c_str(), method.c_str());
    return;
  }
  const bench::Figures& f = o.figures;
  std::string patches = o.patches ? std::to_string(o.patches) : "-";
  if (o.certified >= 0) patches += o.certified ? ", certified convex" : ", not certified";
  std::printf(
      "| %s | %s | %.5f (%.2e) | %.5f / %.5f | %.5f (%.2e) | %.4f | %s (%ld) | %zu | %s | %.2f | "
      "%.2f | %.0f |\n",
      c.name.c_str(), method.c_str(), f.chamfer, f.chamfer / c.size, f.mesh_to_truth,
      f.truth_to_mesh, f.hausdorff, f.hausdorff / c.size, f.normal_consistency,
      f.bad_edges ? "no" : "yes", f.bad_edges, f.triangles, patches.c_str(), f.seconds,
      o.cpu_seconds, o.peak_rss_mb);
  std::fflush(stdout);
}

double BoxSize(const std::vector<Vec>& points) {
  Vec lo = points[0], hi = points[0];
  for (const Vec& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  return (hi - lo).maxCoeff();
}

bool AddScan(const std::string& path, const std::string& name, bool convex,
             std::vector<Case>* cases) {
  if (!std::ifstream(path).good()) {
    std::printf("(skipped %s: %s is absent)\n", name.c_str(), path.c_str());
    return false;
  }
  implicitfit::PointCloud cloud = implicitfit::ReadCloudFile(path);
  const bool estimate = !cloud.has_normals();
  if (estimate) implicitfit::EnsureOrientedNormals(&cloud);  // the user's path
  Case c;
  c.estimated_normals = estimate;
  c.name = name;
  c.points = cloud.points;
  c.normals = cloud.normals;
  c.truth = bench::CloudTruth(c.points, c.normals);
  c.size = BoxSize(c.points);
  c.convex = convex;
  c.scan = true;
  cases->push_back(std::move(c));
  return true;
}

void AddGenerated(const std::string& name, const implicitfit::Model& truth, bool convex, int points,
                  unsigned seed, std::vector<Case>* cases) {
  implicitfit::SampleOptions so;
  so.count = points;
  so.seed = seed;
  const implicitfit::SampledCloud clean = implicitfit::SampleModel(truth, so);
  const double size = (clean.box_max - clean.box_min).maxCoeff() / 1.1;
  so.noise = 0.002 * size;
  so.seed = seed + 1000;
  const implicitfit::SampledCloud noisy = implicitfit::SampleModel(truth, so);
  Case c;
  c.name = name;
  c.points = noisy.cloud.points;
  c.normals = noisy.cloud.normals;
  c.truth = bench::ModelTruth(truth, clean.cloud.points);
  c.size = BoxSize(clean.cloud.points);
  c.convex = convex;
  cases->push_back(std::move(c));
}

// A generated CAD-like solid (datasets/generators/cad_solids.h, generated_solids.h): `points`
// with noise 0.1% of the size along the normal, normals estimated from the points (PCA + MST,
// datasets/normals/normal_estimation.h: what a user has) unless true_normals; judged against the
// model and 20 000 noise-free points.
void AddSolid(const std::string& name, const implicitfit::Model& truth, const Vec& box_min,
              const Vec& box_max, int points, unsigned seed, bool true_normals,
              std::vector<Case>* cases) {
  implicitfit::SampleOptions so;
  so.count = points;
  so.seed = seed;
  so.has_box = true;
  so.box_min = box_min;
  so.box_max = box_max;
  implicitfit::SampleOptions clean = so;
  clean.count = 20000;
  clean.seed = seed + 1000;
  const implicitfit::SampledCloud truth_cloud = implicitfit::SampleModel(truth, clean);
  const double size = BoxSize(truth_cloud.cloud.points);
  so.noise = 0.001 * size;
  implicitfit::PointCloud cloud = implicitfit::SampleModel(truth, so).cloud;
  if (!true_normals) {
    cloud.normals.clear();
    implicitfit::EnsureOrientedNormals(&cloud);
  }
  Case c;
  c.estimated_normals = !true_normals;
  c.name = name + (true_normals ? " (true normals)" : "");
  c.points = cloud.points;
  c.normals = cloud.normals;
  c.truth = bench::ModelTruth(truth, truth_cloud.cloud.points);
  c.size = size;
  cases->push_back(std::move(c));
}

// A Fit4CAD part (../shared/data/fit4cad, GPL-3, read in place): noise-free points without
// normals (estimated and oriented as for a user), judged against its points.
void AddFit4Cad(const std::string& part, std::vector<Case>* cases) {
  const std::string path =
      std::string(IMPLICITFIT_SHARED_DATA) + "/fit4cad/fit4cad_" + part + ".xyzl";
  if (!std::ifstream(path).good()) {
    std::printf("(skipped Fit4CAD %s: %s is absent)\n", part.c_str(), path.c_str());
    return;
  }
  implicitfit::PointCloud cloud = implicitfit::ReadCloudFile(path);
  implicitfit::EnsureOrientedNormals(&cloud);
  Case c;
  c.estimated_normals = true;
  c.name = "Fit4CAD " + part;
  c.points = cloud.points;
  c.normals = cloud.normals;
  c.truth = bench::CloudTruth(c.points, c.normals);
  c.size = BoxSize(c.points);
  cases->push_back(std::move(c));
}

// The command line (top comment); the MeshFitOptions ones in `fit`, the rest beside it.
struct Options {
  int points = 20000, cells = 0, degree = 3, scan_cells = -1;
  std::vector<int> scan_degrees = {4, 5};
  implicitfit::MeshFitOptions fit;  // far field, sign guard, adaptive refinement (step 2)
  std::string only;                 // run only the clouds whose name contains this
  std::string save_dir;             // write the meshes here when given
  unsigned seed = 1;
  bool true_normals = false;  // generated CAD-like solids: the sampler's normals, not estimated
  int mesh_cells = 0;         // mesher: box / mesh_cells; 0: the mesher's default cell
  double mesh_feature_angle = 30.0;  // mesher: MeshOptions::feature_angle_deg
  bool progress = false;             // the fit's stages and rounds on stderr, with seconds
};

// --scan-degree's comma-separated list of degrees (0: none).
std::vector<int> ParseDegrees(const char* list) {
  std::vector<int> degrees;
  for (const char* p = list; *p;) {
    char* end = nullptr;
    const long k = std::strtol(p, &end, 10);
    if (end == p) break;
    if (k > 0) degrees.push_back(static_cast<int>(k));
    p = *end == ',' ? end + 1 : end;
  }
  return degrees;
}

// Reads the "--name value" pairs; an unknown name or a name without a value is an error (exit 2,
// before any work), and the --save-meshes folder is made when it is missing.
Options ParseOptions(int argc, char** argv) {
  Options o;
  implicitfit::MeshFitOptions& f = o.fit;
  const auto refuse = [](const std::string& why) {
    std::fprintf(stderr, "surface_comparison: %s (options: the comment at the top of "
                         "bench/surface_comparison.cc)\n", why.c_str());
    std::exit(2);
  };
  if (argc % 2 == 0) refuse(std::string(argv[argc - 1]) + " has no value");
  for (int i = 1; i + 1 < argc; i += 2) {
    const char* name = argv[i];
    const char* value = argv[i + 1];
    if (!std::strcmp(name, "--points"))
      o.points = std::atoi(value);
    else if (!std::strcmp(name, "--seed"))
      o.seed = static_cast<unsigned>(std::atoi(value));
    else if (!std::strcmp(name, "--cells"))
      o.cells = std::atoi(value);
    else if (!std::strcmp(name, "--degree"))
      o.degree = std::atoi(value);
    else if (!std::strcmp(name, "--scan-degree"))
      o.scan_degrees = ParseDegrees(value);
    else if (!std::strcmp(name, "--scan-cells"))
      o.scan_cells = std::atoi(value);
    else if (!std::strcmp(name, "--far-field-ramp"))
      f.far_field_ramp = std::atof(value);
    else if (!std::strcmp(name, "--far-field-ramp-power"))
      f.far_field_ramp_power = std::atof(value);
    else if (!std::strcmp(name, "--far-field-relaxation"))
      f.far_field_relaxation = std::atof(value);
    else if (!std::strcmp(name, "--far-field-floor"))
      f.far_field_floor = std::atof(value);
    else if (!std::strcmp(name, "--sign-guard-samples"))
      f.sign_guard_samples = std::atoi(value);
    else if (!std::strcmp(name, "--only"))
      o.only = value;
    else if (!std::strcmp(name, "--progress"))
      o.progress = std::atoi(value) != 0;
    else if (!std::strcmp(name, "--save-meshes"))
      o.save_dir = value;
    else if (!std::strcmp(name, "--tangent-plane-signs"))
      f.far_field_winding = std::atoi(value) == 0;
    else if (!std::strcmp(name, "--true-normals"))
      o.true_normals = std::atoi(value) != 0;
    else if (!std::strcmp(name, "--adaptive"))
      f.adaptive = std::atoi(value) != 0;
    else if (!std::strcmp(name, "--max-levels"))
      f.max_levels = std::atoi(value);
    else if (!std::strcmp(name, "--sharp"))
      f.sharp_features = std::atoi(value) != 0;
    else if (!std::strcmp(name, "--feature-angle"))
      f.feature_angle_deg = std::atof(value);
    else if (!std::strcmp(name, "--refine-factor"))
      f.refine_factor = std::atof(value);
    else if (!std::strcmp(name, "--refine-spacing-floor"))
      f.refine_spacing_floor = std::atof(value);
    else if (!std::strcmp(name, "--min-leaf-spacings"))
      f.min_leaf_spacings = std::atof(value);
    else if (!std::strcmp(name, "--max-unknowns"))
      f.max_unknowns = std::atoll(value);
    else if (!std::strcmp(name, "--normal-weight"))
      f.normal_weight = std::atof(value);
    else if (!std::strcmp(name, "--continuity"))
      f.continuity = std::atoi(value);
    else if (!std::strcmp(name, "--smoothing-weight"))
      f.smoothing_weight = std::atof(value);
    else if (!std::strcmp(name, "--soft-c1"))
      f.soft_c1_weight = std::atof(value);
    else if (!std::strcmp(name, "--sharp-normal"))
      f.sharp_normal_factor = std::atof(value);
    else if (!std::strcmp(name, "--soft-c1-sharp"))
      f.soft_c1_sharp_factor = std::atof(value);
    else if (!std::strcmp(name, "--mesh-cells"))
      o.mesh_cells = std::atoi(value);
    else if (!std::strcmp(name, "--mesh-feature-angle"))
      o.mesh_feature_angle = std::atof(value);
    else
      refuse(std::string("unknown option ") + name);
  }
  if (!o.save_dir.empty()) {
    std::error_code error;
    std::filesystem::create_directories(o.save_dir, error);
    if (error || !std::filesystem::is_directory(o.save_dir))
      refuse("--save-meshes " + o.save_dir + ": cannot make the folder (" + error.message() + ")");
  }
  return o;
}

// DIR/<first word of the cloud>-<method tag>.ply, or "" when not asked.
std::string SavePath(const Options& o, const Case& c, const std::string& tag) {
  return o.save_dir.empty()
             ? std::string()
             : o.save_dir + "/" + c.name.substr(0, c.name.find(' ')) + "-" + tag + ".ply";
}

// With --save-meshes: the input cloud (x y z nx ny nz) and the truth's points (x y z) beside the
// meshes, DIR/<first word>-cloud.xyz and -truth.xyz, for looking at where a mesh is off.
void SaveInputs(const Options& o, const Case& c) {
  if (o.save_dir.empty()) return;
  const std::string stem = o.save_dir + "/" + c.name.substr(0, c.name.find(' '));
  if (FILE* f = std::fopen((stem + "-cloud.xyz").c_str(), "w")) {
    for (size_t i = 0; i < c.points.size(); ++i)
      std::fprintf(f, "%.9g %.9g %.9g %.9g %.9g %.9g\n", c.points[i].x(), c.points[i].y(),
                   c.points[i].z(), c.normals[i].x(), c.normals[i].y(), c.normals[i].z());
    std::fclose(f);
  }
  if (FILE* f = std::fopen((stem + "-truth.xyz").c_str(), "w")) {
    for (const Vec& p : c.truth.points) std::fprintf(f, "%.9g %.9g %.9g\n", p.x(), p.y(), p.z());
    std::fclose(f);
  }
}

// The clouds whose name contains --only (the others are not even made: sampling, normals).
std::vector<Case> MakeCases(const Options& o) {
  std::vector<Case> cases;
  const auto wanted = [&](const std::string& name) {
    return name.find(o.only) != std::string::npos;
  };
  const std::string shared = IMPLICITFIT_SHARED_DATA, bundled = IMPLICITFIT_BUNDLED_DATA;
  if (wanted("kitten")) AddScan(shared + "/cgal/cgal_kitten.xyz", "kitten (scan)", false, &cases);
  if (wanted("oni")) AddScan(shared + "/cgal/cgal_oni.pwn", "oni (scan)", false, &cases);
  if (wanted("sphere (scan)"))
    AddScan(bundled + "/cgal_sphere_single.xyz", "sphere (scan)", true, &cases);
  if (wanted("ellipsoid")) {
    implicitfit::Model m;
    m.AddPrimitive(implicitfit::NodeType::kEllipsoid, {0, 0, 0, 1.0, 0.7, 0.5, 1, 0, 0, 0, 1, 0});
    AddGenerated("ellipsoid", m, true, o.points, o.seed, &cases);
  }
  if (wanted("torus")) {
    implicitfit::Model m;
    m.AddPrimitive(implicitfit::NodeType::kTorus, {0, 0, 0, 0, 0, 1, 1.0, 0.35});
    AddGenerated("torus", m, false, o.points, o.seed, &cases);
  }
  if (wanted("union of two spheres")) {
    implicitfit::Model m;
    const int a = m.AddPrimitive(implicitfit::NodeType::kSphere, {-0.4, 0, 0, 0.6});
    const int b = m.AddPrimitive(implicitfit::NodeType::kSphere, {0.4, 0, 0, 0.6});
    m.AddOperator(implicitfit::NodeType::kUnion, {a, b}, 0.1, 0.1, 3);
    AddGenerated("union of two spheres", m, false, o.points, o.seed, &cases);
  }
  if (wanted("Stanford bunny"))
    AddScan(shared + "/stanford/stanford_bunny_bun000_rangescan.ply",
            "Stanford bunny bun000 (range scan)", false, &cases);
  for (const implicitfit::CadSolid& s : implicitfit::AllCadSolids())
    if (wanted(s.name))
      AddSolid(s.name, s.truth, s.box_min, s.box_max, o.points, o.seed, o.true_normals, &cases);
  for (const implicitfit::GeneratedSolid& s : implicitfit::AllGeneratedSolids())
    if (wanted(s.name))
      AddSolid(s.name, s.truth, s.box_min, s.box_max, o.points, o.seed, o.true_normals, &cases);
  if (const implicitfit::CadSolid s = implicitfit::HeldOutPartSolid(); wanted(s.name))
    AddSolid(s.name, s.truth, s.box_min, s.box_max, o.points, o.seed, o.true_normals, &cases);
  for (const char* part : {"test_PC21", "test_PC33", "test_PC34", "test_PC35", "train_PC124",
                           "train_PC131", "train_PC145", "train_PC155"})
    if (wanted(std::string("Fit4CAD ") + part)) AddFit4Cad(part, &cases);
  return cases;
}

// One patch-mesh row's fit settings.
struct PatchRow {
  int degree, cells;
  bool convex;
};

// A cloud's patch-mesh rows: --degree; non-convex scans also --scan-degree; convex ones --convex.
std::vector<PatchRow> PatchRows(const Options& o, const Case& c) {
  std::vector<PatchRow> rows = {{o.degree, o.cells, false}};
  // Issue 11: the degree is the lever that lowers the fit's RMS most at a given grid.
  if (c.scan && !c.convex)
    for (int k : o.scan_degrees) {
      const int n = o.scan_cells >= 0 ? o.scan_cells : o.cells;
      if (k != o.degree || n != o.cells) rows.push_back({k, n, false});
    }
  if (c.convex) rows.push_back({o.degree, o.cells, true});
  return rows;
}

// The row's patch-mesh fit and the mesh of its zero set on the fit's grid box (in the child).
TriangleMesh FitAndMesh(const Options& o, const Case& c, const PatchRow& row, Outcome* out) {
  implicitfit::MeshFitOptions fo = o.fit;
  fo.degree = row.degree;
  fo.cells = row.cells;
  fo.convex = row.convex;
  fo.normals_estimated = c.estimated_normals;
  if (o.progress)
    fo.progress = [name = c.name](const implicitfit::ProgressEvent& e) {
      std::fprintf(stderr, "%s: %s %s %s (%.2f s)\n", name.c_str(), e.stage.c_str(),
                   e.kind == implicitfit::ProgressEvent::Kind::kBegin  ? "begins:"
                   : e.kind == implicitfit::ProgressEvent::Kind::kEnd ? "ends:"
                                                                       : "-",
                   e.detail.c_str(), e.seconds);
    };
  if (row.convex) {  // certified fits are C1 on a uniform grid
    fo.adaptive = false;
    fo.continuity = 1;
  }
  const implicitfit::MeshFitResult r = implicitfit::FitBernsteinMesh(c.points, c.normals, fo);
  out->patches = r.tetrahedra;
  out->fit_rms = r.rms;
  out->initial_rms = r.initial_rms;
  out->box_sign_errors = r.box_sign_errors;
  if (row.convex) out->certified = r.success && r.certified_convex;
  if (!r.success) {  // the row then reads inf: say why
    std::fprintf(stderr, "%s: patch mesh (degree %d, cells %d) failed: %s\n", c.name.c_str(),
                 row.degree, row.cells, r.message.c_str());
    return TriangleMesh();
  }
  implicitfit::MeshOptions mo;
  mo.has_box = true;
  mo.box_min = r.grid.BoxMin();
  mo.box_max = r.grid.BoxMax();
  if (o.mesh_cells > 0) mo.cell = (mo.box_max - mo.box_min).maxCoeff() / o.mesh_cells;
  mo.feature_angle_deg = o.mesh_feature_angle;
  std::fprintf(stderr,
               "%s: noise %.3g spacing %.3g threshold %.3g rounds %d (%d rejected) levels %d "
               "leaves %lld unknowns %lld sharp faces %lld rms %.3g\n",
               c.name.c_str(), r.noise, r.spacing, r.residual_threshold, r.rounds,
               r.rejected_rounds, r.levels, r.leaves, r.unknowns, r.sharp_faces, r.rms);
  mo.num_threads = 2;
  return implicitfit::MeshModel(r.ToModel(), mo).mesh;
}

// The implicitfit rows of a cloud, each fitted and meshed in its own process.
void RunPatchMeshRows(const Options& o, const Case& c) {
  for (const PatchRow& row : PatchRows(o, c)) {
    const Outcome out = RunIsolated(
        c, o.seed, [&](Outcome* result) { return FitAndMesh(o, c, row, result); },
        SavePath(o, c,
                 std::string(row.convex ? "convex-" : "") + "degree" + std::to_string(row.degree)));
    std::string row_label;
    if (row.degree != 3) row_label += " --degree " + std::to_string(row.degree);
    if (row.cells > 0) row_label += " --cells " + std::to_string(row.cells);
    char method[240];
    std::snprintf(method, sizeof method,
                  "implicitfit patch-mesh%s%s (rms %.2e, start %.2e; f <= 0 at %lld box-face "
                  "samples)",
                  row.convex ? " --convex" : "", row_label.c_str(), out.fit_rms, out.initial_rms,
                  out.box_sign_errors);
    Row(c, method, out);
  }
}

// A cloud's peer rows: PCL Poisson depth 7 and 8, CGAL Poisson (when built), PCL marching cubes.
void RunPeerRows(const Options& o, const Case& c) {
  for (int depth : {7, 8}) {
    const Outcome out = RunIsolated(
        c, o.seed, [&](Outcome*) { return bench::PoissonMesh(c.points, c.normals, depth); },
        SavePath(o, c, "poisson" + std::to_string(depth)));
    Row(c, "PCL Poisson depth " + std::to_string(depth), out);
  }
#ifdef IMPLICITFIT_HAVE_CGAL_POISSON
  {
    const Outcome out = RunIsolated(
        c, o.seed,
        [&](Outcome*) { return implicitfit_bench::CgalPoisson(c.points, c.normals).mesh; },
        SavePath(o, c, "cgal-poisson"));
    Row(c, "CGAL Poisson", out);
  }
#endif
  const Outcome out = RunIsolated(
      c, o.seed, [&](Outcome*) { return bench::HoppeMesh(c.points, c.normals, 100); },
      SavePath(o, c, "hoppe"));
  Row(c, "PCL marching cubes (Hoppe) 100^3", out);
}

}  // namespace

// The clouds, then the table: per cloud the patch-mesh rows, then the peers' rows.
int main(int argc, char** argv) {
  const Options options = ParseOptions(argc, argv);
  const std::vector<Case> cases = MakeCases(options);
  std::printf("parent resident memory before the methods: %.0f MB\n\n", PeakRssMb());
  std::printf(
      "| cloud | method | Chamfer (/ size) | mesh->truth / truth->mesh | Hausdorff (/ size) | "
      "normal "
      "consistency | watertight (bad edges) | triangles | patches | wall s | CPU s | peak MB |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Case& c : cases) {
    if (c.name.find(options.only) == std::string::npos) continue;
    SaveInputs(options, c);
    RunPatchMeshRows(options, c);
    RunPeerRows(options, c);
  }
  return 0;
}
