// implicitfit reconstruct + mesh vs PCL's Poisson surface reconstruction on the same clouds
// (issue 14). Generated solids (datasets/generated_solids.h) sampled with noise 0.2% of their
// size (--outliers adds uniform outliers); implicitfit starts from a scene of ground-truth
// labels (primitives fitted to their labelled points, as detect would give). Both meshes are
// judged against the truth model: Chamfer distance (mean of the two directed mean distances,
// mesh -> truth by the truth's first-order distance |f| / |grad f| at area-uniform mesh points,
// truth -> mesh by exact point-triangle distance from noise-free truth points), Hausdorff
// distance (largest of both), normal consistency (mean of n_mesh . grad f / |grad f|, signed:
// 1 is perfect, orientation included), watertightness (edges not in exactly two triangles) and
// time (reconstruction + meshing; Poisson: its reconstruction).
//   build/bench/solid_comparison [--points 20000] [--outliers 0] [--seed 1]
#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "bench/mesh_judging.h"
#include "datasets/generated_solids.h"
#include "datasets/model_mesher.h"
#include "datasets/model_sampler.h"
#include "fit/solid_reconstruction.h"

namespace {

using implicitfit::TriangleMesh;
using Vec = Eigen::Vector3d;

double Seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

using bench::Figures;
using bench::Judge;

void Row(const char* solid, const char* method, const Figures& f, double size) {
  std::printf("| %s | %s | %.5f (%.2e) | %.5f (%.2e) | %.4f | %s (%ld) | %zu | %.2f |\n", solid,
              method, f.chamfer, f.chamfer / size, f.hausdorff, f.hausdorff / size,
              f.normal_consistency, f.bad_edges ? "no" : "yes", f.bad_edges, f.triangles,
              f.seconds);
}

}  // namespace

int main(int argc, char** argv) {
  int points = 20000;
  double outliers = 0.0;
  unsigned seed = 1;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--points"))
      points = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--outliers"))
      outliers = std::atof(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--seed"))
      seed = static_cast<unsigned>(std::atoi(argv[i + 1]));
  }
  std::printf(
      "| solid | method | Chamfer (/ size) | Hausdorff (/ size) | normal consistency | watertight "
      "(bad edges) | triangles | seconds |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (const implicitfit::GeneratedSolid& solid : implicitfit::AllGeneratedSolids()) {
    const double size = (solid.box_max - solid.box_min).maxCoeff();
    implicitfit::SampleOptions so;
    so.count = points;
    so.noise = 0.002 * size;
    so.outlier_fraction = outliers;
    so.seed = seed;
    so.has_box = true;
    so.box_min = solid.box_min;
    so.box_max = solid.box_max;
    const implicitfit::SampledCloud cloud = implicitfit::SampleModel(solid.truth, so);
    implicitfit::SampleOptions clean = so;
    clean.noise = 0;
    clean.outlier_fraction = 0;
    clean.seed = seed + 1000;
    const std::vector<Vec> truth_points = implicitfit::SampleModel(solid.truth, clean).cloud.points;

    // implicitfit: scene from ground-truth labels, reconstruct, mesh (128 cells on the longest
    // side).
    const std::vector<int> labels =
        implicitfit::GroundTruthLabels(solid, cloud.cloud, 4 * so.noise);
    std::vector<implicitfit::NodeType> kinds;
    for (const implicitfit::Model& p : solid.primitives) kinds.push_back(p.nodes()[0].type);
    auto t0 = std::chrono::steady_clock::now();
    const auto scene = implicitfit::FitLabelledPrimitives(cloud.cloud.points, cloud.cloud.normals,
                                                          labels, kinds, seed);
    const implicitfit::SolidReconstruction r =
        implicitfit::ReconstructSolid(cloud.cloud.points, cloud.cloud.normals, scene);
    implicitfit::MeshOptions mo;
    mo.has_box = true;
    mo.box_min = solid.box_min;
    mo.box_max = solid.box_max;
    mo.cell = size / 128;
    const TriangleMesh ours = implicitfit::MeshModel(r.model, mo).mesh;
    const double ours_seconds = Seconds(t0);
    Figures f = Judge(ours, solid.truth, truth_points, seed);
    f.seconds = ours_seconds;
    Row(solid.name.c_str(),
        r.success ? "implicitfit reconstruct + mesh" : "implicitfit (reconstruct failed)", f, size);

    for (int depth : {7, 8}) {
      t0 = std::chrono::steady_clock::now();
      const TriangleMesh poisson =
          bench::PoissonMesh(cloud.cloud.points, cloud.cloud.normals, depth);
      const double seconds = Seconds(t0);
      Figures p = Judge(poisson, solid.truth, truth_points, seed);
      p.seconds = seconds;
      const std::string name = "PCL Poisson depth " + std::to_string(depth);
      Row(solid.name.c_str(), name.c_str(), p, size);
    }
  }
  return 0;
}
