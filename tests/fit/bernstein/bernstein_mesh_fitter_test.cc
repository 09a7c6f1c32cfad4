// Recovery tests of the patch-mesh fit (docs/maths.md G-1 test 5): clouds sampled from known closed
// surfaces with normal noise sigma; the fitted zero set is judged by the RMS of f/|grad f| over
// the cloud and, independently, by the distance of noise-free truth points to the fitted zero
// set (Newton projection onto f = 0 through the generic Model value and gradient).
#include "fit/bernstein/bernstein_mesh_fitter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "datasets/meshing/model_mesher.h"
#include "datasets/generators/model_sampler.h"
#include "model/certificates/bernstein_mesh_certificate.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

SampledCloud Sample(const Model& truth, int count, double noise, unsigned seed) {
  SampleOptions so;
  so.count = count;
  so.noise = noise;
  so.seed = seed;
  return SampleModel(truth, so);
}

// RMS distance from points to the zero set of m, by Newton projection (first-order distance
// |f|/|grad f| is what the fit minimises; the projection measures the true gap).
double RmsDistanceToZeroSet(const Model& m, const std::vector<Vec>& points) {
  double ss = 0;
  for (const Vec& p : points) {
    Vec x = p;
    for (int it = 0; it < 30; ++it) {
      double f;
      const Vec g = m.Gradient(x, &f);
      if (!(g.squaredNorm() > 0)) break;
      x -= f * g / g.squaredNorm();
      if (std::abs(f) < 1e-13) break;
    }
    ss += (x - p).squaredNorm();
  }
  return std::sqrt(ss / points.size());
}

BernsteinGrid CubicGrid(double half, int n) {
  BernsteinGrid g;
  g.origin = Vec::Constant(-half);
  g.cell = 2 * half / n;
  g.cells = {n, n, n};
  return g;
}

TEST(BernsteinMeshFitter, ConvexEllipsoidIsCertifiedOnTheBox) {
  Model truth;
  truth.AddPrimitive(NodeType::kEllipsoid, {0, 0, 0, 1.0, 0.7, 0.5, 1, 0, 0, 0, 1, 0});
  const double sigma = 0.002;
  const SampledCloud noisy = Sample(truth, 20000, sigma, 3);
  MeshFitOptions o;
  o.degree = 3;
  o.continuity = 1;
  o.convex = true;
  o.has_grid = true;
  o.grid = CubicGrid(1.1, 3);
  const MeshFitResult r = FitBernsteinMesh(noisy.cloud.points, noisy.cloud.normals, o);
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_EQ(r.tetrahedra, 162);
  EXPECT_TRUE(r.certified_convex);
  EXPECT_LE(r.rms, 1.5 * sigma);
  // The unconstrained fit, reported for comparison, also recovers the ellipsoid.
  EXPECT_GT(r.unconstrained_rms, 0.0);
  EXPECT_LE(r.unconstrained_rms, 1.5 * sigma);
  const Model m = r.ToModel();
  const MeshConvexityCertificate cert = CertifyMeshConvexity(3, r.grid, m.parameters().data());
  EXPECT_TRUE(cert.convex_on_box);
  EXPECT_LE(cert.c1_defect, 1e-9);
  const SampledCloud clean = Sample(truth, 2000, 0.0, 4);
  const double truth_rms = RmsDistanceToZeroSet(m, clean.cloud.points);
  EXPECT_LE(truth_rms, sigma);
  std::printf("ellipsoid: rms %.3g (sigma %.3g), truth distance rms %.3g, %d iterations, %.2f s\n",
              r.rms, sigma, truth_rms, r.iterations, r.seconds);
}

// Degree 4: at 4x4x4 cubes (edge 0.725 for a tube of radius 0.35) C1 cubics stop at RMS
// 0.0044 = 2.2 sigma (truth distance 0.0038: the space, not the optimiser); quartics reach sigma.
TEST(BernsteinMeshFitter, TorusUnconstrained) {
  Model truth;
  truth.AddPrimitive(NodeType::kTorus, {0, 0, 0, 0, 0, 1, 1.0, 0.35});
  const double sigma = 0.002;
  const SampledCloud noisy = Sample(truth, 20000, sigma, 5);
  MeshFitOptions o;
  o.degree = 4;
  o.continuity = 1;
  o.has_grid = true;
  o.grid = CubicGrid(1.45, 4);
  // Without the far-field rows: the Ceres fallback reaches 2 sigma but puts sign errors in empty
  // space, which the far-field check rejects (then RMS 0.0057); known limitation.
  o.far_field_weight = 0;
  const MeshFitResult r = FitBernsteinMesh(noisy.cloud.points, noisy.cloud.normals, o);
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_EQ(r.tetrahedra, 384);
  EXPECT_LE(r.rms, 2 * sigma);
  EXPECT_LE(r.continuity_defect, 1e-9);
  const Model m = r.ToModel();
  const SampledCloud clean = Sample(truth, 2000, 0.0, 6);
  const double truth_rms = RmsDistanceToZeroSet(m, clean.cloud.points);
  EXPECT_LE(truth_rms, 2 * sigma);
  std::printf("torus: rms %.3g (sigma %.3g), truth distance rms %.3g, %d iterations, %.2f s\n",
              r.rms, sigma, truth_rms, r.iterations, r.seconds);
}

// Union of two spheres (radius 0.6 at x = -+0.4, smooth union delta = epsilon = 0.1, order 3):
// a non-convex closed surface with a saddle-shaped neck. Default grid (8 cubes along the
// longest edge), k = 3, C1. Truth from the generator: the noise-free points lie within 2 sigma
// (RMS) of the fitted zero set; the refinement improves on the linear start; the sign is right
// away from the surface (inside at both centres and at the neck, outside at the grid box's
// corners), so no spurious sheet reaches the box.
TEST(BernsteinMeshFitter, UnionOfTwoSpheres) {
  Model truth;
  const int a = truth.AddPrimitive(NodeType::kSphere, {-0.4, 0, 0, 0.6});
  const int b = truth.AddPrimitive(NodeType::kSphere, {0.4, 0, 0, 0.6});
  truth.AddOperator(NodeType::kUnion, {a, b}, 0.1, 0.1, 3);
  const double sigma = 0.002;
  const SampledCloud noisy = Sample(truth, 20000, sigma, 7);
  MeshFitOptions o;
  o.degree = 3;
  o.continuity = 1;
  const MeshFitResult r = FitBernsteinMesh(noisy.cloud.points, noisy.cloud.normals, o);
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_LT(r.rms, r.initial_rms);
  EXPECT_FALSE(r.kept_initialisation);
  EXPECT_LE(r.rms, 2 * sigma);
  EXPECT_LE(r.continuity_defect, 1e-9);
  const Model m = r.ToModel();
  const SampledCloud clean = Sample(truth, 2000, 0.0, 8);
  const double truth_rms = RmsDistanceToZeroSet(m, clean.cloud.points);
  EXPECT_LE(truth_rms, 2 * sigma);
  for (const Vec& inside : {Vec(-0.4, 0, 0), Vec(0.4, 0, 0), Vec(0, 0, 0)}) {
    ASSERT_LT(truth.Value(inside), 0.0);
    EXPECT_LT(m.Value(inside), 0.0) << inside.transpose();
  }
  const Vec lo = r.grid.BoxMin(), hi = r.grid.BoxMax();
  for (int c = 0; c < 8; ++c) {
    const Vec corner((c & 1) ? hi.x() : lo.x(), (c & 2) ? hi.y() : lo.y(),
                     (c & 4) ? hi.z() : lo.z());
    ASSERT_GT(truth.Value(corner), 0.0);
    EXPECT_GT(m.Value(corner), 0.0) << corner.transpose();
  }
  std::printf(
      "union: rms %.3g (start %.3g, sigma %.3g), truth distance rms %.3g, %lld patches, %.2f s\n",
      r.rms, r.initial_rms, sigma, truth_rms, r.tetrahedra, r.seconds);
}

// The patch-mesh fit closes the zero set of an open scan inside its grid box (issue 11: oni's
// unscanned base left the box and the mesh was cut open there). Cloud: the unit sphere without
// its bottom cap (z > -0.3: a hole of radius 0.95), noise-free, outward normals. Judged
// independently of the fitter: f > 0 at every sample of a 31 x 31 lattice on each box face
// (then {f <= 0} cannot reach the box), the marching-cubes mesh of the zero set on the box is
// watertight (every edge in exactly two triangles), its cap closes near the rim plane, and the
// scanned part is still fitted (the data points' distance to the zero set, by Newton
// projection).
TEST(BernsteinMeshClosing, OpenScanClosesInsideTheBox) {
  Model sphere;
  sphere.AddPrimitive(NodeType::kSphere, {0, 0, 0, 1.0});
  const SampledCloud sampled = Sample(sphere, 3000, 0.0, 11);
  std::vector<Vec> points, normals;
  for (size_t i = 0; i < sampled.cloud.points.size(); ++i)
    if (sampled.cloud.points[i].z() > -0.3) {
      points.push_back(sampled.cloud.points[i]);
      normals.push_back(sampled.cloud.normals[i]);
    }
  ASSERT_GT(points.size(), 1500u);
  MeshFitOptions o;
  o.cells = 5;
  const MeshFitResult r = FitBernsteinMesh(points, normals, o);
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_EQ(r.box_sign_errors, 0);
  const Model m = r.ToModel();

  const Vec lo = r.grid.BoxMin(), hi = r.grid.BoxMax();
  // The box's bottom face lies at least 10% of the longest extent (0.2) below the data.
  EXPECT_GE(-0.3 - lo.z(), 0.2 - 1e-9);
  long non_positive = 0;
  for (int a = 0; a < 3; ++a)
    for (int side = 0; side < 2; ++side)
      for (int i = 0; i <= 30; ++i)
        for (int j = 0; j <= 30; ++j) {
          Vec x;
          const int b = (a + 1) % 3, c = (a + 2) % 3;
          x[a] = side ? hi[a] : lo[a];
          x[b] = lo[b] + (hi[b] - lo[b]) * i / 30.0;
          x[c] = lo[c] + (hi[c] - lo[c]) * j / 30.0;
          non_positive += !(m.Value(x) > 0);
        }
  EXPECT_EQ(non_positive, 0);

  MeshOptions mo;
  mo.has_box = true;
  mo.box_min = lo;
  mo.box_max = hi;
  mo.cell = (hi - lo).maxCoeff() / 64;
  const TriangleMesh mesh = MeshModel(m, mo).mesh;
  ASSERT_FALSE(mesh.triangles.empty());
  std::map<std::pair<int, int>, int> uses;
  for (const Eigen::Vector3i& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      ++uses[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
  long bad_edges = 0;
  for (const auto& [edge, count] : uses) bad_edges += count != 2;
  EXPECT_EQ(bad_edges, 0);
  // The lowest mesh vertex: the cap closes at the rim (z = -0.3), not farther down: the
  // far-field signs come from the winding number, whose level 1/2 spans a planar rim with the
  // flat disk (fit/bernstein/winding_number.h): -0.391 measured; with the nearest point's tangent plane
  // the cap bulged to z = -0.487 (-0.504 before the far-field relaxation), fails.
  double lowest = hi.z();
  for (const Vec& v : mesh.vertices) lowest = std::min(lowest, v.z());
  EXPECT_LT(lowest, -0.3);
  EXPECT_GT(lowest, -0.4);

  const double data_rms = RmsDistanceToZeroSet(m, points);
  EXPECT_LE(data_rms, 0.01);  // 1% of the radius (5 cubes across the box)
  std::printf("open sphere: %zu points, rms %.3g, data distance rms %.3g, lowest vertex %.3f\n",
              points.size(), r.rms, data_rms, lowest);
}

}  // namespace
}  // namespace implicitfit
