// implicitfit reconstruct + mesh vs Poisson surface reconstruction (PCL's pcl::Poisson and
// CGAL 5.5's poisson_surface_reconstruction_delaunay) on the same clouds, in one run (issue 14).
// Clouds:
//   generated solids (datasets/generators/generated_solids.h) sampled with noise 0.2% of their size
//     (--outliers adds uniform outliers); truth: the model (first-order distance |f| / |grad f|,
//     normal grad f / |grad f|); truth samples: noise-free samples of it;
//   the Fit4CAD parts (../shared/data/fit4cad, GPL-3, read only; no normals: estimated and
//     oriented by datasets/normals/normal_estimation.h); truth: each labelled point's ground-truth
//     surface (planes and quadrics: the implicit equation; tori: the exact torus distance, the
//     torus read from the parametric file by datasets/generators/fit4cad_torus.h);
//   CGAL's box-on-ground scan (exact outward normals, no labels); truth: the tangent plane of
//     each point (its faces are planar).
//   For the real clouds, the distance of x to the truth is the least, over its 16 nearest truth
//   points p, of: e, the first-order distance of x to p's surface (equation or tangent plane),
//   when x projects onto that surface within twice the local sampling radius of p
//   (sqrt(|x - p|^2 - e^2) <= 2 r_p, r_p the distance from p to its 8th nearest truth point:
//   random samples leave holes that large, e.g. 0.58 on Fit4CAD PC33's top face; a face wrongly
//   extended by less than that is still caught from the other side, truth -> mesh, by the
//   neighbouring face), else |x - p| (x is beyond the sampled part of p's surface). Truth
//   samples: the points.
// implicitfit starts from primitives fitted to ground-truth labels (generated solids, Fit4CAD;
// as detect would give) or from `detect` (the box, unlabelled), then reconstruct and mesh (256
// cells on the longest side of the cloud's box enlarged by 10%, --cells: the finest grid of
// PCL's Poisson at depth 8). When reconstruct closed an open scan, a second row judges the mesh
// without its faces on closure planes (fit/reconstruct/solid_bounding.h: not measured). Figures: Chamfer
// distance (mean of the two directed mean distances: mesh -> truth at 50 000 area-uniform mesh
// points, truth -> mesh by exact point-triangle distance from the truth samples), Hausdorff
// distance (largest of both), normal consistency (mean of n_face . n_truth, signed: 1 is perfect,
// orientation included), watertightness (edges not in exactly two triangles), time (reconstruction
// + meshing; Poisson: its reconstruction). The last columns give implicitfit / the best Poisson
// figure.
//   build/bench/solid_comparison [--points 20000] [--outliers 0] [--seed 1] [--only NAME]
//                                [--cells 256] [--fit-iterations n] [--no-poisson 1]
//                                [--fixed-offset 1]
// stderr: each implicitfit expression and where its Hausdorff distance is reached.
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
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "apps/reconstruct_job.h"
#ifdef IMPLICITFIT_HAVE_CGAL_POISSON
#include "bench/cgal_poisson.h"
#endif
#include "datasets/clouds/cloud_file.h"
#include "datasets/generators/fit4cad_torus.h"
#include "datasets/generators/generated_solids.h"
#include "datasets/generators/ground_truth.h"
#include "datasets/meshing/model_mesher.h"
#include "datasets/generators/model_sampler.h"
#include "datasets/normals/normal_estimation.h"
#include "fit/reconstruct/solid_reconstruction.h"

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

// The true surface: distance of a point to it and its outward unit normal there.
using TruthDistance = std::function<double(const Vec& x, Vec* normal)>;

struct Case {
  std::string name;
  std::vector<Vec> points, normals;                     // the oriented cloud
  std::vector<implicitfit::SolidPrimitive> primitives;  // empty: detect (apps/detect_job.h)
  std::string cloud_path;                               // for detect
  TruthDistance truth;
  std::vector<Vec> truth_points;
  Vec box_min, box_max;  // the meshing box
  double size = 1.0;     // longest side of the cloud's bounding box
};

struct Figures {
  double chamfer = 0, hausdorff = 0, normal_consistency = 0, seconds = 0;
  long bad_edges = 0;
  size_t triangles = 0;
  bool ok = false;
  Vec worst = Vec::Zero();     // where the Hausdorff distance is reached
  bool worst_on_mesh = false;  // ... at a mesh point (mesh -> truth) or a truth point
};

Figures Judge(const TriangleMesh& mesh, const TruthDistance& truth,
              const std::vector<Vec>& truth_points, unsigned seed) {
  Figures fig;
  fig.triangles = mesh.triangles.size();
  if (mesh.triangles.empty()) return fig;
  fig.ok = true;
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
    Vec n_truth;
    const double d = truth(x, &n_truth);
    sum_mt += d;
    if (d > max_mt) {
      max_mt = d;
      fig.worst = x;
      fig.worst_on_mesh = true;
    }
    const Vec n = (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                      .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]])
                      .normalized();
    if (n.allFinite()) normals += n.dot(n_truth);
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
    if (best > max_tm) {
      max_tm = best;
      if (max_tm > max_mt) {
        fig.worst = p;
        fig.worst_on_mesh = false;
      }
    }
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

void Row(const std::string& cloud, const std::string& method, const Figures& f, double size,
         const Figures* best_poisson = nullptr) {
  if (!f.ok) {
    std::printf("| %s | %s | failed | | | | | %.2f | |\n", cloud.c_str(), method.c_str(),
                f.seconds);
    return;
  }
  std::string ratio;
  if (best_poisson && best_poisson->ok) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.2f / %.2f", f.chamfer / best_poisson->chamfer,
                  f.hausdorff / best_poisson->hausdorff);
    ratio = buffer;
  }
  std::printf("| %s | %s | %.5f (%.2e) | %.5f (%.2e) | %.4f | %s (%ld) | %zu | %.2f | %s |\n",
              cloud.c_str(), method.c_str(), f.chamfer, f.chamfer / size, f.hausdorff,
              f.hausdorff / size, f.normal_consistency, f.bad_edges ? "no" : "yes", f.bad_edges,
              f.triangles, f.seconds, ratio.c_str());
  std::fflush(stdout);
}

void BoundingBox(const std::vector<Vec>& points, Vec* lo, Vec* hi) {
  *lo = *hi = points[0];
  for (const Vec& p : points) {
    *lo = lo->cwiseMin(p);
    *hi = hi->cwiseMax(p);
  }
}

// Truth of a real cloud (header): nearest truth point, its surface (equation or tangent plane).
struct PointTruth {
  std::vector<Vec> points, normals;                              // oriented truth points
  std::vector<std::function<double(const Vec&, Vec*)>> surface;  // per point: signed e, grad
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;

  std::vector<double> radius;  // per point: distance to its 8th nearest neighbour

  void Build() {
    pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
    for (const Vec& p : points) cloud->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
    tree.setInputCloud(cloud);
    std::vector<int> idx;
    std::vector<float> d2;
    for (const Vec& p : points) {
      tree.nearestKSearch(pcl::PointXYZ(p.x(), p.y(), p.z()), 9, idx, d2);
      radius.push_back(std::sqrt(d2.back()));
    }
  }
  double Distance(const Vec& x, Vec* normal) const {
    std::vector<int> idx;
    std::vector<float> d2;
    tree.nearestKSearch(pcl::PointXYZ(x.x(), x.y(), x.z()), 16, idx, d2);
    double best = std::numeric_limits<double>::infinity();
    for (int i : idx) {  // the nearest point alone misreads points near a crease
      const double to_point = (x - points[i]).norm();
      Vec g;
      const double e = std::abs(surface[i](x, &g));
      const double tangential = std::sqrt(std::max(0.0, to_point * to_point - e * e));
      const double d = tangential <= 2 * radius[i] ? e : to_point;
      if (d < best) {
        best = d;
        *normal = g.dot(normals[i]) < 0 ? Vec(-g) : g;
      }
    }
    return best;
  }
};

std::function<double(const Vec&, Vec*)> TangentPlane(const Vec& p, const Vec& n) {
  return [p, n](const Vec& x, Vec* g) {
    *g = n;
    return n.dot(x - p);
  };
}

// Fit4CAD equations (datasets/generators/ground_truth.h): plane [a b c d], quadric of 10 numbers.
std::function<double(const Vec&, Vec*)> Fit4CadSurface(const std::vector<double>& q) {
  if (q.size() == 4)
    return [q](const Vec& x, Vec* g) {
      const Vec n(q[0], q[1], q[2]);
      *g = n.normalized();
      return (n.dot(x) + q[3]) / n.norm();
    };
  return [q](const Vec& x, Vec* g) {
    Eigen::Matrix3d a;
    a << q[0], q[3], q[4], q[3], q[1], q[5], q[4], q[5], q[2];
    const Vec b(q[6], q[7], q[8]);
    const Vec grad = 2 * (a * x + b);
    *g = grad.normalized();
    return (x.dot(a * x) + 2 * b.dot(x) + q[9]) / grad.norm();
  };
}

std::vector<Case> GeneratedCases(int points, double outliers, unsigned seed) {
  std::vector<Case> cases;
  for (const implicitfit::GeneratedSolid& solid : implicitfit::AllGeneratedSolids()) {
    Case c;
    c.name = solid.name;
    c.size = (solid.box_max - solid.box_min).maxCoeff();
    implicitfit::SampleOptions so;
    so.count = points;
    so.noise = 0.002 * c.size;
    so.outlier_fraction = outliers;
    so.seed = seed;
    so.has_box = true;
    so.box_min = solid.box_min;
    so.box_max = solid.box_max;
    const implicitfit::SampledCloud cloud = implicitfit::SampleModel(solid.truth, so);
    c.points = cloud.cloud.points;
    c.normals = cloud.cloud.normals;
    implicitfit::SampleOptions clean = so;
    clean.noise = 0;
    clean.outlier_fraction = 0;
    clean.seed = seed + 1000;
    c.truth_points = implicitfit::SampleModel(solid.truth, clean).cloud.points;
    const implicitfit::Model truth = solid.truth;
    c.truth = [truth](const Vec& x, Vec* normal) {
      double f;
      const Vec g = truth.Gradient(x, &f);
      *normal = g.normalized();
      return std::abs(f) / g.norm();
    };
    const std::vector<int> labels =
        implicitfit::GroundTruthLabels(solid, cloud.cloud, 4 * so.noise);
    std::vector<implicitfit::NodeType> kinds;
    for (const implicitfit::Model& p : solid.primitives) kinds.push_back(p.nodes()[0].type);
    c.primitives = implicitfit::FitLabelledPrimitives(c.points, c.normals, labels, kinds, seed);
    c.box_min = solid.box_min;
    c.box_max = solid.box_max;
    cases.push_back(std::move(c));
  }
  return cases;
}

void MeshBoxOfCloud(Case* c) {
  Vec lo, hi;
  BoundingBox(c->points, &lo, &hi);
  c->size = (hi - lo).maxCoeff();
  c->box_min = lo - 0.1 * (hi - lo);
  c->box_max = hi + 0.1 * (hi - lo);
}

// A Fit4CAD part; false (and a message) when its files are absent or unusable.
bool Fit4CadCase(const std::string& data, const std::string& part, unsigned seed, Case* c,
                 std::string* why) {
  const std::string cloud_path = data + "/fit4cad/fit4cad_" + part + ".xyzl";
  const std::string implicit_path =
      data + "/fit4cad/fit4cad_" + part + "/" + part + "_implicit.txt";
  if (!std::ifstream(cloud_path) || !std::ifstream(implicit_path)) {
    *why = "absent";
    return false;
  }
  implicitfit::CloudFileInfo info;
  implicitfit::PointCloud cloud = implicitfit::ReadCloudFile(cloud_path, &info);
  implicitfit::EnsureOrientedNormals(&cloud);
  const std::vector<implicitfit::NodeType> kinds = implicitfit::ReadFit4CadKinds(implicit_path);
  const std::vector<std::vector<double>> coefficients =
      implicitfit::ReadFit4CadCoefficients(implicit_path);
  // Tori: the exact distance to the torus of the parametric file (its implicit coefficients are
  // in an undocumented order).
  const std::string parametric_path =
      data + "/fit4cad/fit4cad_" + part + "/" + part + "_parametric.txt";
  std::vector<std::function<double(const Vec&, Vec*)>> torus_surface(kinds.size());
  for (size_t k = 0; k < kinds.size(); ++k) {
    if (kinds[k] != implicitfit::NodeType::kTorus) continue;
    const implicitfit::Model torus = implicitfit::Fit4CadTorusFromParametric(
        implicitfit::ReadFit4CadCoefficients(parametric_path).at(k));
    torus_surface[k] = [torus](const Vec& x, Vec* g) {
      double f;
      *g = torus.Gradient(x, &f).normalized();
      return f;
    };
  }
  c->name = "Fit4CAD " + part;
  c->points = cloud.points;
  c->normals = cloud.normals;
  std::vector<int> labels(cloud.size(), -1);
  PointTruth* truth = new PointTruth;  // lives for the run (the lambda below keeps it)
  for (size_t i = 0; i < cloud.size(); ++i) {
    const int k = info.labels[i] - 1;
    if (k < 0 || k >= static_cast<int>(kinds.size())) continue;
    labels[i] = k;
    truth->points.push_back(cloud.points[i]);
    truth->normals.push_back(cloud.normals[i]);
    truth->surface.push_back(coefficients[k].size() == 4 || coefficients[k].size() == 10
                                 ? Fit4CadSurface(coefficients[k])
                             : torus_surface[k] ? torus_surface[k]
                                                : TangentPlane(cloud.points[i], cloud.normals[i]));
  }
  truth->Build();
  c->truth = [truth](const Vec& x, Vec* n) { return truth->Distance(x, n); };
  c->truth_points = truth->points;
  try {
    c->primitives = implicitfit::FitLabelledPrimitives(c->points, c->normals, labels, kinds, seed);
  } catch (const std::exception& e) {
    *why = e.what();
    return false;
  }
  MeshBoxOfCloud(c);
  return true;
}

bool CgalBoxCase(const std::string& data, Case* c, std::string* why) {
  c->cloud_path = data + "/cgal/cgal_point_set_3_box_on_ground.xyz";
  if (!std::ifstream(c->cloud_path)) {
    *why = "absent";
    return false;
  }
  const implicitfit::PointCloud cloud = implicitfit::ReadCloudFile(c->cloud_path);
  c->name = "CGAL box on ground";
  c->points = cloud.points;
  c->normals = cloud.normals;
  PointTruth* truth = new PointTruth;
  truth->points = cloud.points;
  truth->normals = cloud.normals;
  for (size_t i = 0; i < cloud.size(); ++i)
    truth->surface.push_back(TangentPlane(cloud.points[i], cloud.normals[i]));
  truth->Build();
  c->truth = [truth](const Vec& x, Vec* n) { return truth->Distance(x, n); };
  c->truth_points = truth->points;
  MeshBoxOfCloud(c);
  return true;
}

int g_cells = 256;         // cells of implicitfit's mesh on the longest side (--cells)
int g_fit_iterations = 0;  // --fit-iterations: the tree fitter's iterations per pass (0: default)
bool g_poisson = true;     // --no-poisson: implicitfit's row only
bool g_adaptive = true;    // --fixed-offset 1: the inside/outside samples at the fixed offset

void RunCase(const Case& c, unsigned seed) {
  // implicitfit: reconstruct (from the labelled scene, or detect), mesh at g_cells cells.
  auto t0 = std::chrono::steady_clock::now();
  Figures f, measured;  // measured: without the faces on closure planes (not seen in the data)
  bool closed = false;
  std::string method = "implicitfit reconstruct + mesh";
  try {
    implicitfit::SolidReconstruction r;
    size_t primitives = c.primitives.size();
    if (c.primitives.empty()) {  // apps/reconstruct_job.h: detect, then reconstruct
      const implicitfit::CloudReconstruction job =
          implicitfit::ReconstructCloudFile(c.cloud_path, "", seed);
      r = job.result;
      primitives = job.primitives.size();
      method = "implicitfit detect + reconstruct + mesh";
    } else {
      implicitfit::SolidReconstructionOptions ro;
      ro.seed = seed;
      if (g_fit_iterations > 0) ro.tree.max_iterations = g_fit_iterations;
      ro.adaptive_offset = g_adaptive;
      r = implicitfit::ReconstructSolid(c.points, c.normals, c.primitives, ro);
    }
    if (r.success) {
      implicitfit::MeshOptions mo;
      mo.has_box = true;
      mo.box_min = c.box_min;
      mo.box_max = c.box_max;
      mo.cell = (c.box_max - c.box_min).maxCoeff() / g_cells;
      const TriangleMesh ours = implicitfit::MeshModel(r.model, mo).mesh;
      const double seconds = Seconds(t0);
      f = Judge(ours, c.truth, c.truth_points, seed);
      f.seconds = seconds;
      if (!r.closures.empty()) {
        // The measured part: triangles with a vertex off every closure plane.
        closed = true;
        TriangleMesh seen = ours;
        seen.triangles.clear();
        const double tolerance = 1e-7 * c.size;
        for (const Eigen::Vector3i& t : ours.triangles) {
          bool on_closure = false;
          for (const implicitfit::AddedPlane& q : r.closures) {
            bool all = true;
            for (int k = 0; k < 3; ++k)
              all = all && std::abs(q.normal.dot(ours.vertices[t[k]]) - q.offset) < tolerance;
            on_closure = on_closure || all;
          }
          if (!on_closure) seen.triangles.push_back(t);
        }
        measured = Judge(seen, c.truth, c.truth_points, seed);
        measured.seconds = seconds;
      }
    } else {
      method += " (" + r.message + ")";
      f.seconds = Seconds(t0);
    }
    std::fprintf(stderr,
                 "%s: %s, %zu primitives, %zu blends, %.1f s (tree fit %.1f s, %d iterations)\n",
                 c.name.c_str(), r.expression.c_str(), primitives, r.blends.size(), r.seconds,
                 r.fit_seconds, r.fit_iterations);
    std::string sides;  // per primitive: s(olid), h(ole), u(nused)
    for (const std::string& side : r.sides) sides += side.empty() ? '?' : side[0];
    std::fprintf(stderr, "%s: sides %s, normal agreement %.4f of %d inliers (sigma %.3g), %s\n",
                 c.name.c_str(), sides.c_str(), r.normal_agreement, r.inliers, r.sigma,
                 r.message.c_str());
    if (f.ok)  // where implicitfit's largest deviation is (stderr, for the analysis)
      std::fprintf(
          stderr, "%s: Hausdorff distance at (%.6g, %.6g, %.6g), %s\n", c.name.c_str(), f.worst.x(),
          f.worst.y(), f.worst.z(),
          f.worst_on_mesh ? "a mesh point far from the truth" : "a truth point far from the mesh");
  } catch (const std::exception& e) {
    method += std::string(" (") + e.what() + ")";
    f.seconds = Seconds(t0);
  }

  std::vector<std::pair<std::string, Figures>> poisson;
  if (!g_poisson) {
    Figures none;
    Row(c.name, method, f, c.size, &none);
    return;
  }
  pcl::PointCloud<pcl::PointNormal>::Ptr pc(new pcl::PointCloud<pcl::PointNormal>);
  for (size_t i = 0; i < c.points.size(); ++i) {
    pcl::PointNormal p;
    p.x = c.points[i].x(), p.y = c.points[i].y(), p.z = c.points[i].z();
    p.normal_x = c.normals[i].x(), p.normal_y = c.normals[i].y(), p.normal_z = c.normals[i].z();
    pc->push_back(p);
  }
  for (int depth : {7, 8}) {
    t0 = std::chrono::steady_clock::now();
    pcl::Poisson<pcl::PointNormal> pcl_poisson;
    pcl_poisson.setDepth(depth);
    pcl_poisson.setInputCloud(pc);
    pcl::PolygonMesh poly;
    pcl_poisson.reconstruct(poly);
    const double seconds = Seconds(t0);
    Figures p = Judge(FromPcl(poly), c.truth, c.truth_points, seed);
    p.seconds = seconds;
    poisson.emplace_back("PCL Poisson depth " + std::to_string(depth), p);
  }
#ifdef IMPLICITFIT_HAVE_CGAL_POISSON
  const implicitfit_bench::CgalPoissonResult cgal =
      implicitfit_bench::CgalPoisson(c.points, c.normals);
  Figures p = cgal.success ? Judge(cgal.mesh, c.truth, c.truth_points, seed) : Figures{};
  p.seconds = cgal.seconds;
  poisson.emplace_back("CGAL Poisson", p);
#endif
  Figures best;  // the best Poisson figure of each kind (the strictest comparison)
  best.chamfer = best.hausdorff = 1e300;
  for (const auto& [name, q] : poisson)
    if (q.ok) {
      best.ok = true;
      best.chamfer = std::min(best.chamfer, q.chamfer);
      best.hausdorff = std::min(best.hausdorff, q.hausdorff);
    }
  Row(c.name, method, f, c.size, &best);
  if (closed)
    Row(c.name, method + ", closure faces left out (not measured)", measured, c.size, &best);
  for (const auto& [name, q] : poisson) Row(c.name, name, q, c.size);
}

}  // namespace

int main(int argc, char** argv) {
  int points = 20000;
  double outliers = 0.0;
  unsigned seed = 1;
  std::string only;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--points"))
      points = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--outliers"))
      outliers = std::atof(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--seed"))
      seed = static_cast<unsigned>(std::atoi(argv[i + 1]));
    else if (!std::strcmp(argv[i], "--cells"))
      g_cells = std::max(8, std::atoi(argv[i + 1]));
    else if (!std::strcmp(argv[i], "--only"))
      only = argv[i + 1];
    else if (!std::strcmp(argv[i], "--fit-iterations"))
      g_fit_iterations = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--no-poisson") && !std::strcmp(argv[i + 1], "1"))
      g_poisson = false;
    else if (!std::strcmp(argv[i], "--fixed-offset") && !std::strcmp(argv[i + 1], "1"))
      g_adaptive = false;
  }
  std::printf(
      "| cloud | method | Chamfer (/ size) | Hausdorff (/ size) | normal consistency | watertight "
      "(bad edges) | triangles | seconds | Chamfer / Hausdorff vs best Poisson |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  auto wanted = [&](const std::string& name) {
    return only.empty() || name.find(only) != std::string::npos;
  };
  for (const Case& c : GeneratedCases(points, outliers, seed))
    if (wanted(c.name)) RunCase(c, seed);
  const std::string data = IMPLICITFIT_SHARED_DATA;
  for (const std::string part : {"test_PC33", "test_PC34", "test_PC35", "test_PC21", "train_PC124",
                                 "train_PC131", "train_PC145", "train_PC155"}) {
    if (!wanted("Fit4CAD " + part)) continue;
    Case c;
    std::string why;
    if (Fit4CadCase(data, part, seed, &c, &why))
      RunCase(c, seed);
    else
      std::printf("| Fit4CAD %s | skipped: %s | | | | | | | |\n", part.c_str(), why.c_str());
  }
  if (wanted("CGAL box on ground")) {
    Case c;
    std::string why;
    if (CgalBoxCase(data, &c, &why))
      RunCase(c, seed);
    else
      std::printf("| CGAL box on ground | skipped: %s | | | | | | | |\n", why.c_str());
  }
  return 0;
}
