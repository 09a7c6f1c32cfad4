#include "model/certificates/bernstein_mesh_certificate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "model/bernstein/bernstein_mesh_continuity.h"
#include "model/certificates/tangent_plane_test.h"

namespace implicitfit {

MeshConvexityCertificate CertifyMeshConvexity(int k, const BernsteinGrid& grid, const double* b) {
  MeshConvexityCertificate out;
  const long long n = NumBernsteinControlPoints(k);
  out.tetrahedra = grid.NumTetrahedra();
  out.min_eigenvalue = std::numeric_limits<double>::infinity();
  out.per_tetrahedron.reserve(static_cast<size_t>(out.tetrahedra));
  for (long long t = 0; t < out.tetrahedra; ++t) {
    out.per_tetrahedron.push_back(CertifyConvexity(k, b + t * n));
    const ConvexityCertificate& c = out.per_tetrahedron.back();
    out.certified_tetrahedra += c.convex;
    if (!(c.min_eigenvalue >= out.min_eigenvalue)) {
      out.min_eigenvalue = c.min_eigenvalue;
      out.worst_tetrahedron = t;
    }
  }
  out.c1_defect = ContinuityDefect(grid, k, 1, b);
  out.c1 = out.c1_defect <= kMaxContinuityDefect;
  out.convex_on_box = out.domain_convex && out.c1 && out.certified_tetrahedra == out.tetrahedra;
  return out;
}

MeshSamplingResult MeshTangentPlaneTest(int k, const BernsteinGrid& grid, const double* b,
                                        const MeshSamplingOptions& options) {
  const Eigen::Vector3d lo = grid.BoxMin(), hi = grid.BoxMax();
  const long long n = NumBernsteinControlPoints(k);
  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto random_point = [&]() {
    return Eigen::Vector3d(lo[0] + u(rng) * (hi[0] - lo[0]), lo[1] + u(rng) * (hi[1] - lo[1]),
                           lo[2] + u(rng) * (hi[2] - lo[2]));
  };
  auto value = [&](const Eigen::Vector3d& x) {
    return BernsteinMesh::Evaluate(k, grid, b, x.data());
  };
  // The gradient of the tetrahedron holding p (segments cross tetrahedra: the whole box is tested).
  auto gradient = [&](const Eigen::Vector3d& p) {
    double tau[4];
    const long long t = grid.Locate(p.data(), tau);
    Eigen::Vector3d g;
    BernsteinPatch::Derivatives(k, grid.TetrahedronOf(t), b + t * n, p.data(), &g);
    return g;
  };
  TangentPlaneTestOptions o;
  o.segments = options.segments;
  o.steps = options.steps;
  o.tolerance = options.tolerance;
  o.seed = options.seed;
  const TangentPlaneTestResult r =
      TangentPlaneTestCore(random_point, value, gradient, (hi - lo).norm(), 0.0, o);
  MeshSamplingResult result;
  result.zero_points = r.zero_points;
  result.violations = r.violations;
  result.worst_excursion = r.worst_excursion;
  return result;
}

}  // namespace implicitfit
