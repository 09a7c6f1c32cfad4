// The adaptive patch-mesh fit (fit/bernstein/adaptive_mesh_fitter.h): its building blocks against
// independent evaluations, and one small end-to-end fit on a CAD-like solid with sharp edges.
//  - re-expression on a refined grid is exact: the finer mesh evaluates to the coarser one at
//    random points (evaluated tetrahedron by tetrahedron by de Casteljau, not by the re-expression
//    matrices);
//  - the leaf residuals of a linear f (control points = f at the domain points) are the closed
//    form |f(p)| / |grad f|;
//  - the crease detector flags the leaves that hold the edge of two perpendicular planes and no
//    others;
//  - the continuity projection on a refined grid lands in the continuity space and keeps what
//    is already in it (the chamfered block's creases refined once on the fitter's 8-cube grid:
//    the QR route leaves a C1 defect of 1.8e-11 there, and 1.06 on the grid the fitter refined
//    from its residuals);
//  - on the chamfered block (3 000 points), refining lowers the RMS residual below the uniform
//    grid's, and the refined zero set stays closer to the generating model.
#include "fit/bernstein/adaptive_mesh_fitter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "datasets/generators/cad_solids.h"
#include "datasets/generators/model_sampler.h"
#include "fit/bernstein/continuity_projection.h"
#include "model/bernstein/bernstein_mesh_continuity.h"
#include "model/bernstein/bernstein_conversion.h"
#include "model/bernstein/bernstein_mesh.h"
#include "model/bernstein/bernstein_patch.h"
#include "model/bernstein/grid_refinement.h"
#include "support/sample_in_box.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

BernsteinGrid Grid(int n, double h) {
  BernsteinGrid g;
  g.origin = Vec::Zero();
  g.cell = h;
  g.cells = {n, n, n};
  g.refinement = UniformRefinement(g.cells);
  return g;
}

double ValueAt(int k, const BernsteinGrid& grid, const std::vector<double>& b, const Vec& x) {
  double tau[4];
  const long long t = grid.Locate(x.data(), tau);
  return BernsteinPatch::EvaluateBarycentric(k, b.data() + t * NumBernsteinControlPoints(k), tau);
}

TEST(AdaptiveMeshFitter, ReexpressionOnARefinedGridIsExact) {
  const int k = 3;
  const BernsteinGrid coarse = Grid(2, 1.0);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> b(static_cast<size_t>(coarse.NumTetrahedra() * NumBernsteinControlPoints(k)));
  for (double& v : b) v = u(rng);
  // Split leaf 0, then one of its children: two levels below the base (balanced).
  BernsteinGrid finer = coarse;
  std::vector<bool> split(static_cast<size_t>(coarse.NumLeaves()), false);
  split[0] = true;
  finer.refinement = SplitLeaves(coarse.cells, coarse.refinement, split);
  std::vector<bool> again(static_cast<size_t>(finer.NumLeaves()), false);
  again[7] = true;
  again = BalanceSplits(finer.cells, finer.refinement, again);
  finer.refinement = SplitLeaves(finer.cells, finer.refinement, again);
  ASSERT_EQ(finer.MaxLevel(), 2);
  const std::vector<double> fine_b = ReexpressOnFinerGrid(k, coarse, b, finer);
  ASSERT_EQ(fine_b.size(),
            static_cast<size_t>(finer.NumTetrahedra() * NumBernsteinControlPoints(k)));
  double worst = 0;
  std::uniform_real_distribution<double> box(0.0, 2.0);
  for (int i = 0; i < 400; ++i) {
    const Vec x(box(rng) * (i % 2 ? 0.5 : 1.0), box(rng) * (i % 2 ? 0.5 : 1.0), box(rng));
    worst = std::max(worst, std::abs(ValueAt(k, coarse, b, x) - ValueAt(k, finer, fine_b, x)));
  }
  EXPECT_LE(worst, 1e-11);
}

TEST(AdaptiveMeshFitter, LeafResidualsOfALinearFunction) {
  const int k = 3;
  const BernsteinGrid grid = Grid(2, 1.0);
  const Vec a(1.0, 2.0, -2.0);  // f(x) = a . x - 0.5, |grad f| = 3
  const auto f = [&](const Vec& x) { return a.dot(x) - 0.5; };
  const std::vector<std::array<int, 4>> lambda = BernsteinMultiIndices(k);
  const long long n = NumBernsteinControlPoints(k);
  std::vector<double> b(static_cast<size_t>(grid.NumTetrahedra() * n));
  for (long long t = 0; t < grid.NumTetrahedra(); ++t) {
    const Tetrahedron tet = grid.TetrahedronOf(t);
    for (long long j = 0; j < n; ++j) {
      Vec x = Vec::Zero();
      for (int i = 0; i < 4; ++i) x += lambda[j][i] * tet.vertex(i);
      b[t * n + j] = f(x / k);
    }
  }
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(0.01, 0.99);
  std::vector<Vec> points;
  for (int i = 0; i < 300; ++i) points.push_back(Vec(u(rng), u(rng), u(rng)) * (i % 3 ? 1.0 : 2.0));
  std::vector<double> rms;
  std::vector<int> count;
  LeafResiduals(k, grid, b, points, &rms, &count);
  std::vector<double> ss(8, 0.0);
  std::vector<int> expected_count(8, 0);
  for (const Vec& p : points) {
    const int q = (p.z() >= 1) * 4 + (p.y() >= 1) * 2 + (p.x() >= 1);
    ss[q] += std::pow(f(p) / 3.0, 2);
    ++expected_count[q];
  }
  for (int q = 0; q < 8; ++q) {
    EXPECT_EQ(count[q], expected_count[q]) << q;
    const double expected = expected_count[q] ? std::sqrt(ss[q] / expected_count[q]) : 0.0;
    EXPECT_NEAR(rms[q], expected, 1e-12) << q;
  }
}

TEST(AdaptiveMeshFitter, CreaseLeavesHoldTheEdgeOfTwoPlanes) {
  // Planes x = 1.3 (normal +x, y < 1.3) and y = 1.3 (normal +y, x < 1.3) on a 4^3 grid of edge
  // 1: the edge x = y = 1.3 runs through the leaves (1, 1, l); all other leaves see one plane.
  const BernsteinGrid grid = Grid(4, 1.0);
  std::vector<Vec> points, normals;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> s(0.0, 1.3), z(0.0, 4.0);
  for (int i = 0; i < 4000; ++i) {
    points.push_back(Vec(1.3, s(rng), z(rng)));
    normals.push_back(Vec::UnitX());
    points.push_back(Vec(s(rng), 1.3, z(rng)));
    normals.push_back(Vec::UnitY());
  }
  const std::vector<bool> crease = CreaseLeaves(grid, points, normals, 40.0);
  for (long long q = 0; q < grid.NumLeaves(); ++q) {
    const std::array<int, 4> leaf = grid.Leaf(q);
    EXPECT_EQ(crease[q], leaf[1] == 1 && leaf[2] == 1) << leaf[1] << " " << leaf[2];
  }
}

// A global quadric is C-infinity: on a refined grid (hanging faces, sharp or not) its control
// points already lie in the continuity space, so the exact projection must leave them unchanged.
TEST(AdaptiveMeshFitter, ProjectionKeepsAGlobalQuadricOnARefinedGrid) {
  const int k = 3;
  CartesianQuadric q;
  q.A << 1.0, 0.2, -0.1, 0.2, 0.5, 0.3, -0.1, 0.3, 0.8;
  q.b << 0.1, -0.2, 0.3;
  q.c = -0.7;
  BernsteinGrid grid = Grid(3, 1.0);
  std::vector<bool> split(static_cast<size_t>(grid.NumLeaves()), false);
  split[13] = split[0] = true;
  split = BalanceSplits(grid.cells, grid.refinement, split);
  grid.refinement = SplitLeaves(grid.cells, grid.refinement, split);
  const long long n = NumBernsteinControlPoints(k);
  for (int sharp = 0; sharp < 2; ++sharp) {
    grid.sharp.clear();
    if (sharp) {
      grid.sharp.assign(static_cast<size_t>(grid.NumTetrahedra()), 0);
      for (int p = 0; p < 6; ++p) grid.sharp[6 * 3 + p] = 0xF;
    }
    std::vector<double> b(static_cast<size_t>(grid.NumTetrahedra() * n));
    for (long long t = 0; t < grid.NumTetrahedra(); ++t) {
      const std::vector<double> bt = QuadricToBernstein(q, grid.TetrahedronOf(t), k);
      std::copy(bt.begin(), bt.end(), b.begin() + t * n);
    }
    std::vector<double> projected = b;
    const ContinuityProjector projector(grid, k, 1);
    projector.Project(&projected);
    double worst = 0;
    for (size_t i = 0; i < b.size(); ++i) worst = std::max(worst, std::abs(projected[i] - b[i]));
    EXPECT_LE(worst, 1e-9) << "sharp " << sharp;
  }
}

// Random control points on the chamfered block's grid (the fitter's 8 cubes) with the leaves
// that hold its creases split once (noise-free points, exact normals): the projection must leave
// no C1 defect and, applied again, change nothing; a C1 mesh of the base grid re-expressed on
// the refined one (in the space: the splits are nested) must stay where it is.
TEST(AdaptiveMeshFitter, ProjectionOnTheChamferedBlocksRefinedGrid) {
  const int k = 3;
  const CadSolid solid = ChamferedBlockSolid();
  SampleOptions so = testsupport::SampleInBox(20000, 0.0, 23, solid.box_min, solid.box_max);
  const SampledCloud cloud = SampleModel(solid.truth, so);
  const BernsteinGrid base = MeshGridForCloud(cloud.cloud.points, 8, 0.0, 0.1);
  BernsteinGrid grid = base;
  grid.refinement = UniformRefinement(grid.cells);
  std::vector<bool> split = CreaseLeaves(grid, cloud.cloud.points, cloud.cloud.normals, 40.0);
  split = BalanceSplits(grid.cells, grid.refinement, split);
  long long splits = 0;
  for (bool s : split) splits += s;
  grid.refinement = SplitLeaves(grid.cells, grid.refinement, split);
  ASSERT_EQ(grid.MaxLevel(), 1);
  const long long n = NumBernsteinControlPoints(k);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> b(static_cast<size_t>(grid.NumTetrahedra() * n));
  for (double& v : b) v = u(rng);
  const ContinuityProjector projector(grid, k, 1);
  const double defect = projector.Project(&b);
  EXPECT_LE(defect, 1e-12);
  EXPECT_LE(ContinuityDefect(grid, k, 1, b.data()), 1e-12);
  const auto largest_change = [&](const std::vector<double>& before) {
    std::vector<double> after = before;
    projector.Project(&after);
    double worst = 0, scale = 0;
    for (size_t i = 0; i < before.size(); ++i) {
      worst = std::max(worst, std::abs(after[i] - before[i]));
      scale = std::max(scale, std::abs(before[i]));
    }
      return worst / scale;
  };
  EXPECT_LE(largest_change(b), 1e-12);
  std::vector<double> coarse(static_cast<size_t>(base.NumTetrahedra() * n));
  for (double& v : coarse) v = u(rng);
  ContinuityProjector(base, k, 1).Project(&coarse);
  BernsteinGrid uniform = base;
  uniform.refinement = UniformRefinement(uniform.cells);
  EXPECT_LE(largest_change(ReexpressOnFinerGrid(k, uniform, coarse, grid)), 1e-12);
  std::printf("%lld of %lld leaves split, %lld tetrahedra, defect %.3g\n", splits,
              base.NumLeaves(), grid.NumTetrahedra(), defect);
}

TEST(AdaptiveMeshFitter, RefinementLowersTheResidualOnAChamferedBlock) {
  const CadSolid solid = ChamferedBlockSolid();
  SampleOptions so = testsupport::SampleInBox(3000, 0.001 * 2.0, 21, solid.box_min, solid.box_max);
  const SampledCloud cloud = SampleModel(solid.truth, so);
  MeshFitOptions o;
  o.cells = 4;
  const MeshFitResult uniform = FitBernsteinMesh(cloud.cloud.points, cloud.cloud.normals, o);
  ASSERT_TRUE(uniform.success) << uniform.message;
  o.adaptive = true;
  o.max_levels = 0;  // the base round only: the same space as the uniform grid, the same fit
  const MeshFitResult base = FitBernsteinMesh(cloud.cloud.points, cloud.cloud.normals, o);
  ASSERT_TRUE(base.success) << base.message;
  EXPECT_NEAR(base.rms, uniform.rms, 1e-3 * uniform.rms);
  std::printf("base round rms %.6g, uniform rms %.6g\n", base.rms, uniform.rms);
  o.max_levels = 1;
  const MeshFitResult refined = FitBernsteinMesh(cloud.cloud.points, cloud.cloud.normals, o);
  ASSERT_TRUE(refined.success) << refined.message;
  EXPECT_EQ(refined.levels, 1);
  EXPECT_GT(refined.leaves, uniform.tetrahedra / 6);
  EXPECT_GT(refined.sharp_faces, 0);
  EXPECT_LT(refined.rms, 0.8 * uniform.rms);
  // Independently of the fit's residual: noise-free points of the model, RMS of f/|grad f|.
  so.noise = 0;
  so.count = 1000;
  so.seed = 22;
  const SampledCloud clean = SampleModel(solid.truth, so);
  const auto truth_rms = [&](const MeshFitResult& r) {
    const Model m = r.ToModel();
    double ss = 0;
    for (const Vec& p : clean.cloud.points) {
      double v;
      const Vec g = m.Gradient(p, &v);
      ss += v * v / std::max(g.squaredNorm(), 1e-300);
    }
    return std::sqrt(ss / clean.cloud.points.size());
  };
  EXPECT_LT(truth_rms(refined), truth_rms(uniform));
  std::printf(
      "chamfered block: uniform rms %.3g (%lld patches), adaptive rms %.3g (%lld leaves, "
      "%lld sharp faces), %.2f s + %.2f s\n",
      uniform.rms, uniform.tetrahedra, refined.rms, refined.leaves, refined.sharp_faces,
      uniform.seconds, refined.seconds);
}

}  // namespace
}  // namespace implicitfit
