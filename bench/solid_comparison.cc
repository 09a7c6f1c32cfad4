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
#include <pcl/PolygonMesh.h>
#include <pcl/conversions.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_types.h>
#include <pcl/surface/poisson.h>

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

// Closest point on triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5).
Vec ClosestOnTriangle(const Vec& p, const Vec& a, const Vec& b, const Vec& c) {
  const Vec ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Vec cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

struct Figures {
  double chamfer = 0, hausdorff = 0, normal_consistency = 0, seconds = 0;
  long bad_edges = 0;
  size_t triangles = 0;
};

Figures Judge(const TriangleMesh& mesh, const implicitfit::Model& truth,
              const std::vector<Vec>& truth_points, unsigned seed) {
  Figures fig;
  fig.triangles = mesh.triangles.size();
  std::map<std::pair<int, int>, int> uses;
  for (const Eigen::Vector3i& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      ++uses[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
  for (const auto& [e, n] : uses) fig.bad_edges += n != 2;
  // mesh -> truth at area-uniform mesh points.
  std::vector<double> cumulative;
  double area = 0;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    area += 0.5 * (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                      .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]])
                      .norm();
    cumulative.push_back(area);
  }
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  double sum_mt = 0, max_mt = 0, normals = 0;
  const int samples = 50000;
  for (int s = 0; s < samples; ++s) {
    const size_t i = std::min(
        cumulative.size() - 1,
        static_cast<size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), u(rng) * area) -
                            cumulative.begin()));
    const Eigen::Vector3i& t = mesh.triangles[i];
    const double r1 = std::sqrt(u(rng)), r2 = u(rng);
    const Vec x = (1 - r1) * mesh.vertices[t[0]] + r1 * (1 - r2) * mesh.vertices[t[1]] +
                  r1 * r2 * mesh.vertices[t[2]];
    double f;
    const Vec g = truth.Gradient(x, &f);
    const double d = std::abs(f) / g.norm();
    sum_mt += d;
    max_mt = std::max(max_mt, d);
    const Vec n = (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                      .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]])
                      .normalized();
    normals += n.dot(g.normalized());
  }
  // truth -> mesh: exact distance to the nearest of the 16 triangles with the nearest centroids.
  pcl::PointCloud<pcl::PointXYZ>::Ptr centroids(new pcl::PointCloud<pcl::PointXYZ>);
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Vec c = (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3;
    centroids->push_back(pcl::PointXYZ(c.x(), c.y(), c.z()));
  }
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud(centroids);
  std::vector<int> idx;
  std::vector<float> d2;
  double sum_tm = 0, max_tm = 0;
  for (const Vec& p : truth_points) {
    tree.nearestKSearch(pcl::PointXYZ(p.x(), p.y(), p.z()), 16, idx, d2);
    double best = 1e300;
    for (int i : idx) {
      const Eigen::Vector3i& t = mesh.triangles[i];
      best = std::min(best, (p - ClosestOnTriangle(p, mesh.vertices[t[0]], mesh.vertices[t[1]],
                                                   mesh.vertices[t[2]]))
                                .norm());
    }
    sum_tm += best;
    max_tm = std::max(max_tm, best);
  }
  fig.chamfer = 0.5 * (sum_mt / samples + sum_tm / truth_points.size());
  fig.hausdorff = std::max(max_mt, max_tm);
  fig.normal_consistency = normals / samples;
  return fig;
}

TriangleMesh FromPcl(const pcl::PolygonMesh& poly) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  pcl::fromPCLPointCloud2(poly.cloud, cloud);
  TriangleMesh mesh;
  for (const auto& p : cloud) mesh.vertices.emplace_back(p.x, p.y, p.z);
  mesh.normals.assign(mesh.vertices.size(), Vec::UnitZ());
  for (const auto& v : poly.polygons)
    for (size_t k = 1; k + 1 < v.vertices.size(); ++k)
      mesh.triangles.emplace_back(v.vertices[0], v.vertices[k], v.vertices[k + 1]);
  return mesh;
}

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

    pcl::PointCloud<pcl::PointNormal>::Ptr pc(new pcl::PointCloud<pcl::PointNormal>);
    for (size_t i = 0; i < cloud.cloud.size(); ++i) {
      pcl::PointNormal p;
      p.x = cloud.cloud.points[i].x(), p.y = cloud.cloud.points[i].y(),
      p.z = cloud.cloud.points[i].z();
      p.normal_x = cloud.cloud.normals[i].x(), p.normal_y = cloud.cloud.normals[i].y(),
      p.normal_z = cloud.cloud.normals[i].z();
      pc->push_back(p);
    }
    for (int depth : {7, 8}) {
      t0 = std::chrono::steady_clock::now();
      pcl::Poisson<pcl::PointNormal> poisson;
      poisson.setDepth(depth);
      poisson.setInputCloud(pc);
      pcl::PolygonMesh poly;
      poisson.reconstruct(poly);
      const double seconds = Seconds(t0);
      Figures p = Judge(FromPcl(poly), solid.truth, truth_points, seed);
      p.seconds = seconds;
      const std::string name = "PCL Poisson depth " + std::to_string(depth);
      Row(solid.name.c_str(), name.c_str(), p, size);
    }
  }
  return 0;
}
