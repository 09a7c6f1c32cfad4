// Soft C1 on a C0 patch mesh (MeshFitOptions::soft_c1_weight,
// fit/bernstein/bernstein_mesh_fitter.h): on a CAD-like solid with sharp edges (the chamfered
// block, 3 000 points, noise 0.1% of its size), judged against the generating model, not the fit's
// own residuals:
//  - the C0 fit with the C1 rows as penalties stays closer to the model's noise-free points than
//    the C1 fit on the same grid (which rounds every edge over about a cube);
//  - it has no spurious surface: at every lattice point of the grid box farther than 0.15 from
//    the model's surface, f has the model's inside/outside sign; the bare C0 fit (weight 0) does
//    not, which shows what the penalty is for and that the check can fail;
//  - refined (the adaptive fit, one level on 6 cubes, crease leaves' C1 rows at 0.3 of the
//    weight), it stays closer to the model than on the uniform grid, still without a spurious
//    surface;
//  - refined, with PCA normals (a blend of two faces' at a crease), the crease leaves' normal
//    rows at 0.3 of their weight (MeshFitOptions::normals_estimated, sharp_normal_factor) bring
//    it closer to the model than the full weight, still without a spurious surface; with the
//    sampler's true normals the lighter rows are farther, which is why given normals keep the
//    full weight.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "datasets/generators/cad_solids.h"
#include "datasets/generators/model_sampler.h"
#include "datasets/normals/normal_estimation.h"
#include "fit/bernstein/bernstein_mesh_fitter.h"
#include "support/sample_in_box.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

class SoftC1Mesh : public ::testing::Test {
 protected:
  void SetUp() override {
    SampleOptions so =
        testsupport::SampleInBox(3000, 0.001 * 2.0, 21, solid_.box_min, solid_.box_max);
    noisy_ = SampleModel(solid_.truth, so).cloud;
    estimated_ = noisy_;
    estimated_.normals.clear();
    EnsureOrientedNormals(&estimated_);
    so.noise = 0;
    so.count = 1000;
    so.seed = 22;
    clean_ = SampleModel(solid_.truth, so).cloud.points;
  }

  MeshFitResult Fit(int continuity, double soft_c1_weight, int levels = -1, int cells = 4,
                    bool estimated_normals = false, bool lighter_at_creases = false) const {
    MeshFitOptions o;
    o.normals_estimated = lighter_at_creases;
    o.cells = cells;
    o.adaptive = levels >= 0;
    o.max_levels = std::max(levels, 0);
    o.continuity = continuity;
    o.soft_c1_weight = soft_c1_weight;
    const PointCloud& cloud = estimated_normals ? estimated_ : noisy_;
    return FitBernsteinMesh(cloud.points, cloud.normals, o);
  }

  // RMS of f/|grad f| at the model's noise-free points.
  double TruthRms(const MeshFitResult& r) const {
    const Model m = r.ToModel();
    double ss = 0;
    for (const Vec& p : clean_) {
      double v;
      const Vec g = m.Gradient(p, &v);
      ss += v * v / std::max(g.squaredNorm(), 1e-300);
    }
    return std::sqrt(ss / clean_.size());
  }

  // Lattice points (24 per box edge) farther than 0.15 from the model's surface (its value is
  // the largest plane distance, a lower bound of the distance outside and the distance inside)
  // where f's sign differs from the model's.
  int SignErrorsAwayFromTheSurface(const MeshFitResult& r, int* watched) const {
    const Model m = r.ToModel();
    const Vec lo = r.grid.BoxMin(), hi = r.grid.BoxMax();
    int errors = 0;
    *watched = 0;
    constexpr int kSteps = 24;
    for (int i = 0; i <= kSteps; ++i)
      for (int j = 0; j <= kSteps; ++j)
        for (int l = 0; l <= kSteps; ++l) {
          const Vec x = lo + (hi - lo).cwiseProduct(Vec(i, j, l) / kSteps);
          const double truth = solid_.truth.Value(x);
          if (std::abs(truth) < 0.15) continue;
          ++*watched;
          errors += (m.Value(x) > 0) != (truth > 0);
        }
    return errors;
  }

  const CadSolid solid_ = ChamferedBlockSolid();
  PointCloud noisy_;
  PointCloud estimated_;  // noisy_ with PCA normals (datasets/normals), as a raw scan gets
  std::vector<Vec> clean_;
};

TEST_F(SoftC1Mesh, FollowsTheEdgesOfAChamferedBlockWithoutSpuriousSurfaces) {
  const MeshFitResult c1 = Fit(1, 0.0);
  const MeshFitResult soft = Fit(0, 1.0);
  const MeshFitResult bare = Fit(0, 0.0);
  ASSERT_TRUE(c1.success) << c1.message;
  ASSERT_TRUE(soft.success) << soft.message;
  ASSERT_TRUE(bare.success) << bare.message;
  const double c1_truth = TruthRms(c1), soft_truth = TruthRms(soft);
  int watched = 0;
  const int soft_errors = SignErrorsAwayFromTheSurface(soft, &watched);
  const int bare_errors = SignErrorsAwayFromTheSurface(bare, &watched);
  std::printf(
      "chamfered block, 4 cubes: distance to the model's points (RMS) C1 %.4g, C0 + soft C1 %.4g; "
      "sign errors away from the surface (of %d lattice points): soft %d, bare C0 %d\n",
      c1_truth, soft_truth, watched, soft_errors, bare_errors);
  EXPECT_LT(soft_truth, 0.7 * c1_truth);
  EXPECT_GT(watched, 1000);
  EXPECT_EQ(soft_errors, 0);
  EXPECT_GT(bare_errors, 0);
  EXPECT_EQ(soft.box_sign_errors, 0);
}

TEST_F(SoftC1Mesh, RefinedAtTheCreasesItStaysCloserToTheModel) {
  // 6 cubes: on 4 the refined round grows surface off the data (3 guard samples) and is dropped.
  const int cells = 6;
  const MeshFitResult uniform = Fit(0, 1.0, -1, cells);
  const MeshFitResult refined = Fit(0, 1.0, 1, cells);
  ASSERT_TRUE(uniform.success) << uniform.message;
  ASSERT_TRUE(refined.success) << refined.message;
  EXPECT_EQ(refined.levels, 1);
  EXPECT_GT(refined.sharp_faces, 0);
  int watched = 0;
  const int errors = SignErrorsAwayFromTheSurface(refined, &watched);
  const double uniform_truth = TruthRms(uniform), refined_truth = TruthRms(refined);
  std::printf(
      "chamfered block, C0 + soft C1: distance to the model's points (RMS) uniform %d cubes %.4g, "
      "one level %.4g (%lld leaves, %lld sharp faces); sign errors away from the surface %d of "
      "%d\n",
      cells, uniform_truth, refined_truth, refined.leaves, refined.sharp_faces, errors, watched);
  EXPECT_LT(refined_truth, 0.9 * uniform_truth);
  EXPECT_EQ(errors, 0);
}

TEST_F(SoftC1Mesh, LighterNormalRowsAtTheCreasesHelpEstimatedNormalsOnly) {
  // One level on 4 cubes (seconds). normals_estimated makes the crease leaves' normal rows
  // sharp_normal_factor (0.3) of their weight.
  const int cells = 4;
  const MeshFitResult est_full = Fit(0, 1.0, 1, cells, true, false);
  const MeshFitResult est_light = Fit(0, 1.0, 1, cells, true, true);
  const MeshFitResult true_full = Fit(0, 1.0, 1, cells, false, false);
  const MeshFitResult true_light = Fit(0, 1.0, 1, cells, false, true);
  for (const MeshFitResult* r : {&est_full, &est_light, &true_full, &true_light})
    ASSERT_TRUE(r->success) << r->message;
  EXPECT_EQ(est_light.levels, 1);
  EXPECT_GT(est_light.sharp_faces, 0);
  int watched = 0;
  const int errors = SignErrorsAwayFromTheSurface(est_light, &watched);
  const double ef = TruthRms(est_full), el = TruthRms(est_light), tf = TruthRms(true_full),
               tl = TruthRms(true_light);
  std::printf(
      "chamfered block, one level on %d cubes: distance to the model's points (RMS), normal rows "
      "of the crease leaves at full weight / at 0.3: PCA normals %.4g / %.4g, true normals %.4g "
      "/ %.4g; sign errors away from the surface (PCA, 0.3) %d of %d\n",
      cells, ef, el, tf, tl, errors, watched);
  // Estimated normals are blends at the creases: lighter rows there bring the fit closer.
  EXPECT_LT(el, 0.9 * ef);
  EXPECT_EQ(errors, 0);
  // True normals are right there: lighter rows would lose (why they keep the full weight).
  EXPECT_GT(tl, 1.1 * tf);
}

}  // namespace
}  // namespace implicitfit
