// The fold order of an n-ary blend (fit/tree/blend_order.h). Truth: the generated rounded
// box (six planes -x, +x, -y, +y, -z, +z folded in that order, delta 0.2, epsilon 0.12); its
// noise-free samples (datasets/generators/model_sampler.h) lie on its zero set. The same tree with
// the children reversed is another surface at the corners; the chosen order must give the
// truth's surface back exactly (same parameters: only the order differs).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "datasets/generators/generated_solids.h"
#include "datasets/generators/model_sampler.h"
#include "fit/tree/blend_order.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

double LargestDistance(const Model& m, const std::vector<Vec>& points) {
  double largest = 0;
  for (const Vec& x : points) {
    double f;
    const Vec g = m.Gradient(x, &f);
    largest = std::max(largest, std::abs(f) / g.norm());
  }
  return largest;
}

std::vector<Vec> SurfaceSamples(const GeneratedSolid& s) {
  SampleOptions o;
  o.count = 4000;
  o.seed = 5;
  o.has_box = true;
  o.box_min = s.box_min;
  o.box_max = s.box_max;
  return SampleModel(s.truth, o).cloud.points;
}

TEST(BlendOrder, FindsAnOrderWithTheTruthsCornersFromTheReversedOne) {
  const GeneratedSolid s = RoundedBoxSolid();
  const std::vector<Vec> points = SurfaceSamples(s);
  ASSERT_LT(LargestDistance(s.truth, points), 1e-7);  // the sampler's projection
  Model m = s.truth;
  std::vector<int>& children = m.mutable_nodes()[m.root()].children;
  ASSERT_EQ(children.size(), 6u);
  std::reverse(children.begin(), children.end());
  const double reversed = LargestDistance(m, points);
  std::printf("  reversed order: largest distance to the truth's samples %.5f\n", reversed);
  ASSERT_GT(reversed, 1e-3);  // the order matters at the corners
  EXPECT_TRUE(ChooseChildOrders(&m, points, 0.05));
  EXPECT_LT(LargestDistance(m, points), 1e-7);
  EXPECT_EQ(m.parameters(), s.truth.parameters());  // the search changes no parameter
}

TEST(BlendOrder, LeavesTheTruthsOwnOrderAndBinaryBlendsAlone) {
  const GeneratedSolid s = RoundedBoxSolid();
  const std::vector<Vec> points = SurfaceSamples(s);
  Model m = s.truth;
  EXPECT_FALSE(ChooseChildOrders(&m, points, 0.05));  // no swap can lower a zero cost
  EXPECT_EQ(m.nodes()[m.root()].children, s.truth.nodes()[s.truth.root()].children);
  // The plate with a filleted bore: a binary difference (a smooth box minus a cylinder).
  const GeneratedSolid plate = PlateWithFilletedBoreSolid();
  Model p = plate.truth;
  const std::vector<int> before = p.nodes()[p.root()].children;
  ChooseChildOrders(&p, SurfaceSamples(plate), 0.05);
  EXPECT_EQ(p.nodes()[p.root()].children, before);  // the minuend stays first
}

}  // namespace
}  // namespace implicitfit
