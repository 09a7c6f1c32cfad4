#include "bench/solid_cases.h"

#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_types.h>

#include <cmath>
#include <fstream>
#include <limits>

#include "datasets/clouds/cloud_file.h"
#include "datasets/generators/cad_solids.h"
#include "datasets/generators/fit4cad_torus.h"
#include "datasets/generators/generated_solids.h"
#include "datasets/generators/ground_truth.h"
#include "datasets/generators/model_sampler.h"
#include "datasets/normals/normal_estimation.h"

namespace bench {
namespace {

void MeshBoxOfCloud(SolidCloud* c) {
  Vec lo = c->points[0], hi = c->points[0];
  for (const Vec& p : c->points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  c->size = (hi - lo).maxCoeff();
  c->box_min = lo - 0.1 * (hi - lo);
  c->box_max = hi + 0.1 * (hi - lo);
}

// Truth of a real cloud (solid_comparison.cc's header): nearest truth point, its surface (equation or tangent plane).
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

// Truth points on internal faces (SolidCloud::truth_points_outside_internal_faces): at least a
// quarter of a point's 16 nearest truth points carry another label whose surface passes through
// the point (|e| below a tenth of the point's spacing) while the point lies on theirs. Two
// surfaces meeting at a crease share only a line of such points and tangent surfaces a band a
// spacing or two wide; a face held by two labels has them everywhere.
std::vector<bool> InternalFacePoints(const PointTruth& truth, const std::vector<int>& labels) {
  std::vector<bool> internal(truth.points.size(), false);
  std::vector<int> idx;
  std::vector<float> d2;
  for (size_t i = 0; i < truth.points.size(); ++i) {
    const Vec& p = truth.points[i];
    truth.tree.nearestKSearch(pcl::PointXYZ(p.x(), p.y(), p.z()), 16, idx, d2);
    const double tol = 0.1 * truth.radius[i];
    int shared = 0;
    for (int j : idx) {
      if (labels[j] == labels[i]) continue;
      Vec g;
      shared += std::abs(truth.surface[j](p, &g)) < tol &&
                std::abs(truth.surface[i](truth.points[j], &g)) < tol;
    }
    internal[i] = 4 * shared >= static_cast<int>(idx.size());
  }
  return internal;
}

// A cloud of a truth model: `points` samples with noise 0.2% of the size (and `outliers`),
// noise-free truth samples, the first-order distance as the truth.
SolidCloud ModelCloud(const std::string& name, const implicitfit::Model& truth, const Vec& box_min,
                      const Vec& box_max, int points, double outliers, unsigned seed,
                      implicitfit::SampledCloud* sampled, implicitfit::SampleOptions* options) {
  SolidCloud c;
  c.name = name;
  c.size = (box_max - box_min).maxCoeff();
  implicitfit::SampleOptions& so = *options;
  so.count = points;
  so.noise = 0.002 * c.size;
  so.outlier_fraction = outliers;
  so.seed = seed;
  so.has_box = true;
  so.box_min = box_min;
  so.box_max = box_max;
  *sampled = implicitfit::SampleModel(truth, so);
  implicitfit::SampleOptions clean = so;
  clean.noise = 0;
  clean.outlier_fraction = 0;
  clean.seed = seed + 1000;
  c.truth_points = implicitfit::SampleModel(truth, clean).cloud.points;
  c.truth = [truth](const Vec& x, Vec* normal) {
    double f;
    const Vec g = truth.Gradient(x, &f);
    *normal = g.normalized();
    return std::abs(f) / g.norm();
  };
  c.box_min = box_min;
  c.box_max = box_max;
  c.points = sampled->cloud.points;
  return c;
}

// Points only: normals estimated and oriented as for a raw scan, end to end.
void StripNormals(SolidCloud* c) {
  implicitfit::PointCloud raw;
  raw.points = c->points;
  c->normals = implicitfit::EnsureOrientedNormals(&raw).action;
  c->normals_of_points = raw.normals;
  c->end_to_end = true;
}

}  // namespace

std::vector<SolidCloud> HeldOutClouds(int points, unsigned seed) {
  std::vector<SolidCloud> clouds;
  for (const implicitfit::CadSolid& s : implicitfit::AllCadSolids()) {
    implicitfit::SampledCloud sampled;
    implicitfit::SampleOptions so;
    SolidCloud c = ModelCloud("held out: " + s.name, s.truth, s.box_min, s.box_max, points, 0.0,
                              seed, &sampled, &so);
    StripNormals(&c);
    clouds.push_back(std::move(c));
  }
  return clouds;
}

std::vector<SolidCloud> GeneratedClouds(int points, double outliers, unsigned seed,
                                        bool labelled_rows) {
  std::vector<implicitfit::GeneratedSolid> solids = implicitfit::AllGeneratedSolids();
  for (implicitfit::GeneratedSolid& s : implicitfit::GeneratedParts()) solids.push_back(s);
  std::vector<SolidCloud> clouds;
  for (const implicitfit::GeneratedSolid& solid : solids) {
    implicitfit::SampledCloud cloud;
    implicitfit::SampleOptions so;
    SolidCloud c = ModelCloud(solid.name, solid.truth, solid.box_min, solid.box_max, points,
                              outliers, seed, &cloud, &so);
    if (labelled_rows) {  // exact normals, primitives from ground-truth labels
      SolidCloud l = c;
      l.normals = "exact";
      l.normals_of_points = cloud.cloud.normals;
      const std::vector<int> labels =
          implicitfit::GroundTruthLabels(solid, cloud.cloud, 4 * so.noise);
      std::vector<implicitfit::NodeType> kinds;
      for (const implicitfit::Model& p : solid.primitives) kinds.push_back(p.nodes()[0].type);
      l.labelled =
          implicitfit::FitLabelledPrimitives(l.points, l.normals_of_points, labels, kinds, seed);
      clouds.push_back(std::move(l));
    }
    StripNormals(&c);
    clouds.push_back(std::move(c));
  }
  return clouds;
}

bool Fit4CadCloud(const std::string& data, const std::string& part, unsigned seed,
                  bool labelled_rows, SolidCloud* c, std::string* why) {
  const std::string cloud_path = data + "/fit4cad/fit4cad_" + part + ".xyzl";
  const std::string implicit_path =
      data + "/fit4cad/fit4cad_" + part + "/" + part + "_implicit.txt";
  if (!std::ifstream(cloud_path) || !std::ifstream(implicit_path)) {
    *why = "absent";
    return false;
  }
  implicitfit::CloudFileInfo info;
  implicitfit::PointCloud cloud = implicitfit::ReadCloudFile(cloud_path, &info);
  c->normals = implicitfit::EnsureOrientedNormals(&cloud).action;
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
  c->normals_of_points = cloud.normals;
  std::vector<int> labels(cloud.size(), -1), truth_labels;
  PointTruth* truth = new PointTruth;  // lives for the run (the lambda below keeps it)
  for (size_t i = 0; i < cloud.size(); ++i) {
    const int k = info.labels[i] - 1;
    if (k < 0 || k >= static_cast<int>(kinds.size())) continue;
    labels[i] = k;
    truth_labels.push_back(k);
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
  const std::vector<bool> internal = InternalFacePoints(*truth, truth_labels);
  for (size_t i = 0; i < internal.size(); ++i) {
    if (internal[i])
      ++c->internal_face_points;
    else
      c->truth_points_outside_internal_faces.push_back(truth->points[i]);
  }
  c->end_to_end = true;
  if (labelled_rows) {
    try {
      c->labelled =
          implicitfit::FitLabelledPrimitives(c->points, c->normals_of_points, labels, kinds, seed);
    } catch (const std::exception& e) {
      *why = e.what();
      return false;
    }
  }
  MeshBoxOfCloud(c);
  return true;
}

bool ScanCloud(const std::string& path, const std::string& name, bool points_only,
               SolidCloud* c, std::string* why) {
  if (!std::ifstream(path)) {
    *why = "absent";
    return false;
  }
  implicitfit::CloudFileInfo info;
  implicitfit::PointCloud cloud = implicitfit::ReadCloudFile(path, &info);
  const std::vector<Vec> file_normals = cloud.normals;
  if (points_only) cloud.normals.clear();
  implicitfit::NormalOptions no;
  no.viewpoint = info.viewpoint;  // as datasets/normals/oriented_cloud.h does
  c->normals = implicitfit::EnsureOrientedNormals(&cloud, no).action;
  c->name = name;
  c->points = cloud.points;
  c->normals_of_points = cloud.normals;
  PointTruth* truth = new PointTruth;
  truth->points = cloud.points;
  truth->normals = file_normals.empty() ? cloud.normals : file_normals;
  for (size_t i = 0; i < cloud.size(); ++i)
    truth->surface.push_back(TangentPlane(cloud.points[i], truth->normals[i]));
  truth->Build();
  c->truth = [truth](const Vec& x, Vec* n) { return truth->Distance(x, n); };
  c->truth_points = truth->points;
  c->end_to_end = true;
  MeshBoxOfCloud(c);
  return true;
}

}  // namespace bench
