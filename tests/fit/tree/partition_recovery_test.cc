// Li & Phillips Fig. 10 analogue (docs/maths.md LP-1 test 5), as a z-extrusion: cuts x, y = +-0.5
// make nine cells; the eight outer cells hold the lines of an octagon (normals in the xy plane),
// the centre cell a plane far from the zero set (fixed: it has no points). 5000 samples,
// sigma = 0.002; the start turns every outer normal by 3 degrees and moves it by 0.05; the fit
// must recover every normal within 0.5 degrees and epsilon within 10%.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>

#include "datasets/generators/model_sampler.h"
#include "fit/tree/tree_fitter.h"
#include "support/sample_in_box.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

struct Line {
  Vec n;
  double d;
};

// Cell (i, j), i, j in 0..2 (x fastest); the centre (1, 1) gets no line.
Line OctagonLine(int i, int j) {
  const double s = std::sqrt(0.5);
  const int dx = i - 1, dy = j - 1;
  if (dx != 0 && dy != 0) return {Vec(dx * s, dy * s, 0), 1.5 * s};
  return {Vec(dx, dy, 0), 1.0};
}

Model Octagon(double epsilon, double turn_rad, double shift) {
  Model m;
  std::vector<int> children;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      if (i == 1 && j == 1) {
        children.push_back(m.AddPrimitive(NodeType::kPlane, {0, 0, 1, 10.0}));
        m.mutable_nodes().back().fixed = {"normal", "offset"};
        continue;
      }
      const Line l = OctagonLine(i, j);
      const Vec n = Eigen::AngleAxisd(turn_rad * ((i + j) % 2 ? 1 : -1), Vec::UnitZ()) * l.n;
      children.push_back(m.AddPrimitive(NodeType::kPlane, {n.x(), n.y(), n.z(), l.d + shift}));
    }
  m.AddPartition({{-0.5, 0.5}, {-0.5, 0.5}, {}}, epsilon, 3, children);
  return m;
}

TEST(PartitionRecovery, OctagonOfNineCellsRecoversEveryLineAndEpsilon) {
  const double epsilon = 0.15;
  const Model truth = Octagon(epsilon, 0.0, 0.0);
  SampleOptions so =
      testsupport::SampleInBox(5000, 0.002, 10, Vec(-1.5, -1.5, -1), Vec(1.5, 1.5, 1));
  const SampledCloud s = SampleModel(truth, so);
  const TreeFitResult r = FitModelTree(Octagon(0.12, 3.0 * M_PI / 180.0, 0.05), s.cloud.points,
                                       s.cloud.normals, TreeFitOptions{});
  ASSERT_TRUE(r.success) << r.message;
  const std::vector<double>& p = r.model.parameters();
  double worst_deg = 0;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      if (i == 1 && j == 1) continue;
      const int node = i + 3 * j;
      const int b = r.model.nodes()[node].first_parameter;
      const Vec n = Vec(p[b], p[b + 1], p[b + 2]).normalized();
      worst_deg =
          std::max(worst_deg, std::acos(std::min(1.0, n.dot(OctagonLine(i, j).n))) * 180.0 / M_PI);
    }
  const double eps_hat = p[r.model.nodes()[r.model.root()].first_parameter];
  std::printf("  partition octagon: worst normal %.4f deg, epsilon %.5f (truth %.2f), rms %.4g\n",
              worst_deg, eps_hat, epsilon, r.rms);
  EXPECT_LT(worst_deg, 0.5);
  EXPECT_NEAR(eps_hat, epsilon, 0.1 * epsilon);
}

}  // namespace
}  // namespace implicitfit
