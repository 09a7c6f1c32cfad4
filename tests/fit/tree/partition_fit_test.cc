// `fit --model partition` pipeline (docs/maths.md LP-1, Fig. 13 analogue): a 3 x 3 x 2 grid, cubic
// step, one plane per cell. The truth is a partition model whose cell (i, j, k) holds the plane
// of outward direction (i - 1, j - 1, 2 k - 1) (normalised) at distance 1 from the origin: a
// bipyramid-like closed solid with 18 facets, the cuts at x, y = +-0.45 and z = 0. The cloud is
// sampled from it (5000 points, sigma = 0.002). The fitter knows only the cloud and the grid
// box (so that its equally spaced cuts are the truth's): one sparse linear least-squares start
// (fit/tree/partition_start.h), then the tree fitter. Every plane whose cell holds >= 30 points in
// its core must come back within 0.5 degrees, epsilon within 10%.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "datasets/generators/model_sampler.h"
#include "fit/tree/partition_start.h"
#include "fit/tree/tree_fitter.h"
#include "support/sample_in_box.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

Vec Direction(int i, int j, int k) { return Vec(i - 1, j - 1, 2 * k - 1).normalized(); }

Model Bipyramid(double epsilon) {
  Model m;
  std::vector<int> children;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        const Vec n = Direction(i, j, k);
        children.push_back(m.AddPrimitive(NodeType::kPlane, {n.x(), n.y(), n.z(), 1.0}));
      }
  m.AddPartition({{-0.45, 0.45}, {-0.45, 0.45}, {0.0}}, epsilon, 3, children);
  return m;
}

// Cell index of x in the truth's grid, or -1 within epsilon of a cut (not in a core).
int CoreCell(const Vec& x, double eps) {
  int idx[3];
  const std::vector<double> cuts[3] = {{-0.45, 0.45}, {-0.45, 0.45}, {0.0}};
  for (int k = 0; k < 3; ++k) {
    idx[k] = 0;
    for (double c : cuts[k]) {
      if (std::abs(x[k] - c) < eps) return -1;
      if (x[k] > c) ++idx[k];
    }
  }
  return idx[0] + 3 * (idx[1] + 3 * idx[2]);
}

TEST(PartitionFit, GridOfEighteenPlanesFromTheLinearStartRecoversEveryPlaneAndEpsilon) {
  const double epsilon = 0.15;
  const Model truth = Bipyramid(epsilon);
  SampleOptions so = testsupport::SampleInBox(5000, 0.002, 13, Vec(-2, -2, -1.5), Vec(2, 2, 1.5));
  const SampledCloud s = SampleModel(truth, so);

  PartitionStartOptions po;
  po.cells[0] = po.cells[1] = 3;
  po.cells[2] = 2;
  po.has_box = true;  // cuts at lo + (hi - lo) i / A: -0.45, 0.45 and 0
  po.box_min = Vec(-1.35, -1.35, -1.0);
  po.box_max = Vec(1.35, 1.35, 1.0);
  const PartitionStart start = LinearPartitionStart(s.cloud.points, s.cloud.normals, po);
  ASSERT_TRUE(start.success) << start.message;
  const ModelNode& root = start.model.nodes()[start.model.root()];
  ASSERT_EQ(root.cuts[0].size(), 2u);
  EXPECT_NEAR(root.cuts[0][0], -0.45, 1e-12);
  EXPECT_NEAR(root.cuts[2][0], 0.0, 1e-12);

  const TreeFitResult r = FitModelTree(start.model, s.cloud.points, s.cloud.normals, {});
  ASSERT_TRUE(r.success) << r.message;
  int in_core[18] = {0};
  for (const Vec& x : s.cloud.points) {
    const int c = CoreCell(x, epsilon);
    if (c >= 0) ++in_core[c];
  }
  double worst_start = 0, worst = 0;
  int judged = 0;
  for (int c = 0; c < 18; ++c) {
    if (in_core[c] < 30) continue;
    ++judged;
    const Vec truth_n = Direction(c % 3, (c / 3) % 3, c / 9);
    auto angle = [&](const Model& m) {
      const double* p =
          m.parameters().data() + m.nodes()[m.nodes()[m.root()].children[c]].first_parameter;
      return std::acos(std::min(1.0, Vec(p[0], p[1], p[2]).normalized().dot(truth_n))) * 180 / M_PI;
    };
    worst_start = std::max(worst_start, angle(start.model));
    worst = std::max(worst, angle(r.model));
  }
  const double eps_hat = r.model.parameters()[r.model.nodes()[r.model.root()].first_parameter];
  std::printf(
      "  partition 3x3x2: %d cells judged, worst normal %.4f deg (linear start %.3f deg, rms "
      "%.3g), epsilon %.5f (truth %.2f, start %.3f), rms %.4g\n",
      judged, worst, worst_start, start.linear_rms, eps_hat, epsilon,
      start.model.parameters().back(), r.rms);
  EXPECT_GE(judged, 14);
  EXPECT_LT(worst, 0.5);
  EXPECT_NEAR(eps_hat, epsilon, 0.1 * epsilon);
  EXPECT_LT(r.rms, 1.5 * so.noise);
}

TEST(PartitionFit, RefusesBadOptions) {
  const std::vector<Vec> p = {Vec(0, 0, 0), Vec(1, 0, 0)}, n = {Vec(0, 0, 1), Vec(0, 0, 1)};
  PartitionStartOptions o;
  o.child = "torus";
  EXPECT_THROW(LinearPartitionStart(p, n, o), std::invalid_argument);
  o.child = "plane";
  o.cells[1] = 0;
  EXPECT_THROW(LinearPartitionStart(p, n, o), std::invalid_argument);
}

}  // namespace
}  // namespace implicitfit
