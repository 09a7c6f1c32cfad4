#include "bench/mesh_judging.h"

#include <pcl/conversions.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>
#include <pcl/surface/marching_cubes_hoppe.h>
#include <pcl/surface/poisson.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <random>

namespace bench {
namespace {

using implicitfit::TriangleMesh;

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

pcl::PointCloud<pcl::PointNormal>::Ptr ToPcl(const std::vector<Vec>& points,
                                             const std::vector<Vec>& normals) {
  pcl::PointCloud<pcl::PointNormal>::Ptr pc(new pcl::PointCloud<pcl::PointNormal>);
  for (size_t i = 0; i < points.size(); ++i) {
    pcl::PointNormal p;
    p.x = points[i].x(), p.y = points[i].y(), p.z = points[i].z();
    p.normal_x = normals[i].x(), p.normal_y = normals[i].y(), p.normal_z = normals[i].z();
    pc->push_back(p);
  }
  return pc;
}

// PCL's marching cubes emits three vertices per triangle: merge positions equal to 1e-6 of the
// mesh size so that edges
// are shared (the watertightness count needs shared vertices).
TriangleMesh Welded(const TriangleMesh& soup) {
  Vec lo = soup.vertices.empty() ? Vec::Zero() : soup.vertices[0], hi = lo;
  for (const Vec& v : soup.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  const double eps = 1e-6 * std::max((hi - lo).maxCoeff(), 1e-300);  // float rounding of PCL
  std::map<std::array<long long, 3>, int> index;
  std::vector<int> remap(soup.vertices.size());
  TriangleMesh mesh;
  for (size_t i = 0; i < soup.vertices.size(); ++i) {
    const Vec& v = soup.vertices[i];
    const auto [it, added] =
        index.emplace(std::array<long long, 3>{std::llround(v.x() / eps), std::llround(v.y() / eps),
                                               std::llround(v.z() / eps)},
                      static_cast<int>(mesh.vertices.size()));
    if (added) {
      mesh.vertices.push_back(v);
      mesh.normals.push_back(soup.normals[i]);
    }
    remap[i] = it->second;
  }
  for (const Eigen::Vector3i& t : soup.triangles) {
    const Eigen::Vector3i w(remap[t[0]], remap[t[1]], remap[t[2]]);
    if (w[0] != w[1] && w[1] != w[2] && w[0] != w[2]) mesh.triangles.push_back(w);
  }
  return mesh;
}

}  // namespace

TruthSurface ModelTruth(const implicitfit::Model& truth, std::vector<Vec> truth_points) {
  TruthSurface t;
  t.points = std::move(truth_points);
  t.distance = [truth](const Vec& x, Vec* normal) {
    double f;
    const Vec g = truth.Gradient(x, &f);
    *normal = g.normalized();
    return std::abs(f) / g.norm();
  };
  return t;
}

TruthSurface CloudTruth(const std::vector<Vec>& points, const std::vector<Vec>& normals) {
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (const Vec& p : points) cloud->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
  auto tree = std::make_shared<pcl::KdTreeFLANN<pcl::PointXYZ>>();
  tree->setInputCloud(cloud);
  TruthSurface t;
  t.points = points;
  t.distance = [tree, points, normals](const Vec& x, Vec* normal) {
    std::vector<int> idx;
    std::vector<float> d2;
    tree->nearestKSearch(pcl::PointXYZ(x.x(), x.y(), x.z()), 1, idx, d2);
    *normal = normals[idx[0]].normalized();
    return (points[idx[0]] - x).norm();
  };
  return t;
}

Figures JudgeMesh(const TriangleMesh& mesh, const TruthSurface& truth, unsigned seed) {
  Figures fig;
  fig.triangles = mesh.triangles.size();
  if (mesh.triangles.empty()) {
    fig.chamfer = fig.hausdorff = std::numeric_limits<double>::infinity();
    return fig;
  }
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
    Vec truth_normal;
    const double d = truth.distance(x, &truth_normal);
    sum_mt += d;
    max_mt = std::max(max_mt, d);
    const Vec n = (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                      .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]])
                      .normalized();
    if (n.allFinite()) normals += n.dot(truth_normal);
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
  for (const Vec& p : truth.points) {
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
  fig.mesh_to_truth = sum_mt / samples;
  fig.truth_to_mesh = sum_tm / truth.points.size();
  fig.chamfer = 0.5 * (fig.mesh_to_truth + fig.truth_to_mesh);
  fig.hausdorff = std::max(max_mt, max_tm);
  fig.normal_consistency = normals / samples;
  return fig;
}

Figures Judge(const TriangleMesh& mesh, const implicitfit::Model& truth,
              const std::vector<Vec>& truth_points, unsigned seed) {
  return JudgeMesh(mesh, ModelTruth(truth, truth_points), seed);
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

TriangleMesh PoissonMesh(const std::vector<Vec>& points, const std::vector<Vec>& normals,
                         int depth) {
  pcl::Poisson<pcl::PointNormal> poisson;
  poisson.setDepth(depth);
  poisson.setInputCloud(ToPcl(points, normals));
  pcl::PolygonMesh poly;
  poisson.reconstruct(poly);
  return FromPcl(poly);
}

TriangleMesh HoppeMesh(const std::vector<Vec>& points, const std::vector<Vec>& normals,
                       int resolution, float extend) {
  const auto cloud = ToPcl(points, normals);
  pcl::search::KdTree<pcl::PointNormal>::Ptr tree(new pcl::search::KdTree<pcl::PointNormal>);
  tree->setInputCloud(cloud);
  pcl::MarchingCubesHoppe<pcl::PointNormal> mc;
  mc.setGridResolution(resolution, resolution, resolution);
  mc.setPercentageExtendGrid(extend);
  mc.setIsoLevel(0.0f);
  mc.setSearchMethod(tree);
  mc.setInputCloud(cloud);
  pcl::PolygonMesh poly;
  mc.reconstruct(poly);
  return Welded(FromPcl(poly));
}

}  // namespace bench
