#include "model/bernstein_mesh_certificate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "model/bernstein_mesh_continuity.h"

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
  out.convex_on_box =
      out.domain_convex && out.c1 && out.certified_tetrahedra == out.tetrahedra;
  return out;
}

MeshSamplingResult MeshTangentPlaneTest(int k, const BernsteinGrid& grid, const double* b,
                                        const MeshSamplingOptions& options) {
  MeshSamplingResult result;
  const Eigen::Vector3d lo = grid.BoxMin(), hi = grid.BoxMax();
  const double diagonal = (hi - lo).norm();
  const long long n = NumBernsteinControlPoints(k);
  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto random_point = [&]() {
    return Eigen::Vector3d(lo[0] + u(rng) * (hi[0] - lo[0]), lo[1] + u(rng) * (hi[1] - lo[1]),
                           lo[2] + u(rng) * (hi[2] - lo[2]));
  };
  auto f = [&](const Eigen::Vector3d& x) { return BernsteinMesh::Evaluate(k, grid, b, x.data()); };
  std::vector<Eigen::Vector3d> points, normals;
  for (int s = 0; s < options.segments; ++s) {
    const Eigen::Vector3d a = random_point(), c = random_point();
    Eigen::Vector3d x0 = a;
    double f0 = f(x0);
    for (int step = 1; step <= options.steps; ++step) {
      const Eigen::Vector3d x1 = a + (c - a) * (double(step) / options.steps);
      const double f1 = f(x1);
      if ((f0 < 0.0) != (f1 < 0.0)) {
        Eigen::Vector3d l = x0, h = x1;
        for (int it = 0; it < 60; ++it) {
          const Eigen::Vector3d mid = 0.5 * (l + h);
          if ((f(mid) < 0.0) == (f0 < 0.0)) l = mid; else h = mid;
        }
        const Eigen::Vector3d p = 0.5 * (l + h);
        double tau[4];
        const long long t = grid.Locate(p.data(), tau);
        Eigen::Vector3d g;
        BernsteinPatch::Derivatives(k, grid.TetrahedronOf(t), b + t * n, p.data(), &g);
        if (g.norm() > 0.0) {
          points.push_back(p);
          normals.push_back(g.normalized());
        }
      }
      x0 = x1;
      f0 = f1;
    }
  }
  result.zero_points = static_cast<int>(points.size());
  const double allowed = options.tolerance * diagonal;
  for (size_t i = 0; i < points.size(); ++i) {
    double worst = 0.0;
    for (size_t j = 0; j < points.size(); ++j) worst = std::max(worst, (points[j] - points[i]).dot(normals[i]));
    result.worst_excursion = std::max(result.worst_excursion, worst / diagonal);
    if (worst > allowed) ++result.violations;
  }
  return result;
}

}  // namespace implicitfit
