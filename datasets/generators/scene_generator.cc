#include "datasets/generators/scene_generator.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <random>

#include "datasets/generators/model_sampler.h"

namespace implicitfit {
namespace {

using Eigen::Vector3d;

Vector3d RandomUnit(std::mt19937& rng) {
  std::normal_distribution<double> g;
  Vector3d v(g(rng), g(rng), g(rng));
  return v.normalized();
}

// A unit vector within max_angle of `around`.
Vector3d RandomNear(const Vector3d& around, double max_angle, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  const double cos_min = std::cos(max_angle);
  const double c = cos_min + (1 - cos_min) * u(rng), s = std::sqrt(1 - c * c),
               phi = 2 * M_PI * u(rng);
  const Vector3d a = around.unitOrthogonal(), b = around.cross(a);
  return c * around + s * (std::cos(phi) * a + std::sin(phi) * b);
}

void Append(GeneratedScene* scene, const Model& model, NodeType kind, const SampledCloud& s) {
  const int id = static_cast<int>(scene->models.size());
  scene->models.push_back(model);
  scene->kinds.push_back(kind);
  for (size_t i = 0; i < s.cloud.size(); ++i) {
    scene->cloud.points.push_back(s.cloud.points[i]);
    scene->cloud.normals.push_back(s.cloud.normals[i]);
    scene->labels.push_back(id);
  }
}

SampledCloud SampleIn(const Model& m, int count, unsigned seed, const Vector3d& lo,
                      const Vector3d& hi) {
  SampleOptions o;
  o.count = count;
  o.seed = seed;
  o.has_box = true;
  o.box_min = lo;
  o.box_max = hi;
  return SampleModel(m, o);
}

void AddNoiseAndOutliers(GeneratedScene* scene, const GeneratedSceneOptions& options,
                         const Vector3d& lo, const Vector3d& hi, std::mt19937& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  for (size_t i = 0; i < scene->cloud.size(); ++i)
    scene->cloud.points[i] += options.noise * g(rng) * scene->cloud.normals[i];
  const int inliers = static_cast<int>(scene->cloud.size());
  const int outliers =
      static_cast<int>(std::round(options.outliers / (1 - options.outliers) * inliers));
  std::uniform_real_distribution<double> u(0, 1);
  for (int k = 0; k < outliers; ++k) {
    Vector3d p;
    for (int j = 0; j < 3; ++j) p[j] = lo[j] + (hi[j] - lo[j]) * u(rng);
    scene->cloud.points.push_back(p);
    scene->cloud.normals.push_back(RandomUnit(rng));
    scene->labels.push_back(-1);
  }
}

}  // namespace

GeneratedScene GenerateScene(const GeneratedSceneOptions& options) {
  std::mt19937 rng(options.seed);
  std::uniform_real_distribution<double> u(0, 1);
  auto range = [&](double a, double b) { return a + (b - a) * u(rng); };
  GeneratedScene scene;
  unsigned sub_seed = options.seed * 7919u;
  {
    Model ground;
    ground.AddPrimitive(NodeType::kPlane, {0, 0, 1, 0});
    Append(&scene, ground, NodeType::kPlane,
           SampleIn(ground, options.ground_points, ++sub_seed, Vector3d(0, 0, -0.1),
                    Vector3d(4, 3, 0.1)));
  }
  std::vector<int> cells = {0, 1, 2, 3, 4, 5};
  std::shuffle(cells.begin(), cells.end(), rng);
  for (int object = 0; object < 5; ++object) {
    const int cell = cells[object];
    const Vector3d c(4.0 / 3.0 * (cell % 3 + 0.5), 1.5 * (cell / 3 + 0.5), range(0.85, 1.0));
    const int kind_index = options.planes_only ? 4 : object;
    Model m;
    NodeType kind;
    Vector3d lo = c - Vector3d::Constant(0.45), hi = c + Vector3d::Constant(0.45);
    switch (kind_index) {
      case 0: {  // sphere cap
        const double r = range(0.3, 0.45);
        m.AddPrimitive(kind = NodeType::kSphere, {c[0], c[1], c[2], r});
        lo = c - Vector3d::Constant(r + 0.01);
        hi = c + Vector3d::Constant(r + 0.01);
        lo[2] = c[2] - 0.4 * r;
        break;
      }
      case 1: {  // cylinder
        const Vector3d a = RandomUnit(rng);
        m.AddPrimitive(kind = NodeType::kCylinder,
                       {c[0], c[1], c[2], a[0], a[1], a[2], range(0.18, 0.3)});
        break;
      }
      case 2: {  // cone, apex up, opening down
        const double alpha = range(20, 35) * M_PI / 180;
        const Vector3d apex = c + Vector3d(0, 0, 0.35);
        m.AddPrimitive(kind = NodeType::kCone, {apex[0], apex[1], apex[2], 0, 0, -1, alpha});
        const double rmax = 0.7 * std::tan(alpha) + 0.01;
        lo = Vector3d(apex[0] - rmax, apex[1] - rmax, apex[2] - 0.7);
        hi = Vector3d(apex[0] + rmax, apex[1] + rmax, apex[2] - 0.15);
        break;
      }
      case 3: {  // torus
        const Vector3d a = RandomNear(Vector3d::UnitZ(), M_PI / 3, rng);
        const double R = range(0.28, 0.38), r = range(0.08, 0.12);
        m.AddPrimitive(kind = NodeType::kTorus, {c[0], c[1], c[2], a[0], a[1], a[2], R, r});
        lo = c - Vector3d::Constant(R + r + 0.01);
        hi = c + Vector3d::Constant(R + r + 0.01);
        break;
      }
      default: {  // tilted plane patch
        const Vector3d n = RandomNear(Vector3d::UnitZ(), M_PI / 4, rng);
        m.AddPrimitive(kind = NodeType::kPlane, {n[0], n[1], n[2], n.dot(c)});
        lo = c - Vector3d(0.4, 0.4, 0.45);
        hi = c + Vector3d(0.4, 0.4, 0.45);
        break;
      }
    }
    Append(&scene, m, kind, SampleIn(m, options.object_points, ++sub_seed, lo, hi));
  }
  AddNoiseAndOutliers(&scene, options, Vector3d(0, 0, 0), Vector3d(4, 3, 1.6), rng);
  return scene;
}

GeneratedScene GenerateIcosahedron(const GeneratedSceneOptions& options) {
  std::mt19937 rng(options.seed);
  std::uniform_real_distribution<double> u(0, 1);
  const double phi = (1 + std::sqrt(5.0)) / 2;
  std::vector<Vector3d> v;
  for (double a : {-1.0, 1.0})
    for (double b : {-phi, phi}) {
      v.emplace_back(0, a, b);
      v.emplace_back(a, b, 0);
      v.emplace_back(b, 0, a);
    }
  for (auto& p : v) p.normalize();
  // Faces: the 20 triples of mutually adjacent vertices (edge length = the smallest distance).
  double edge = INFINITY;
  for (size_t i = 0; i < v.size(); ++i)
    for (size_t j = i + 1; j < v.size(); ++j) edge = std::min(edge, (v[i] - v[j]).norm());
  auto adjacent = [&](int i, int j) { return (v[i] - v[j]).norm() < edge * 1.01; };
  GeneratedScene scene;
  for (int i = 0; i < 12; ++i)
    for (int j = i + 1; j < 12; ++j)
      for (int k = j + 1; k < 12; ++k) {
        if (!adjacent(i, j) || !adjacent(j, k) || !adjacent(i, k)) continue;
        Vector3d n = (v[j] - v[i]).cross(v[k] - v[i]).normalized();
        if (n.dot(v[i]) < 0) n = -n;
        Model m;
        m.AddPrimitive(NodeType::kPlane, {n[0], n[1], n[2], n.dot(v[i])});
        const int id = static_cast<int>(scene.models.size());
        scene.models.push_back(m);
        scene.kinds.push_back(NodeType::kPlane);
        for (int s = 0; s < options.object_points; ++s) {
          double a = u(rng), b = u(rng);
          if (a + b > 1) a = 1 - a, b = 1 - b;
          scene.cloud.points.push_back(v[i] + a * (v[j] - v[i]) + b * (v[k] - v[i]));
          scene.cloud.normals.push_back(n);
          scene.labels.push_back(id);
        }
      }
  AddNoiseAndOutliers(&scene, options, Vector3d::Constant(-1.2), Vector3d::Constant(1.2), rng);
  return scene;
}

}  // namespace implicitfit
