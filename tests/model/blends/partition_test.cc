// Soft space partition on a grid (docs/maths.md LP-1 tests 1-4): partition of unity of the bases,
// refusal of cells narrower than 2 epsilon (with the JSON path and the width), f = f_ijk exactly
// away from the cuts, and the smoothness across a cut (C^(n-1), not C^n).
#include <gtest/gtest.h>

#include <random>

#include "model/model.h"
#include "model/file/model_json.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

const std::vector<std::vector<double>> kCuts = {{-0.5, 0.4}, {0.0}, {}};  // 3 x 2 x 1 cells

// One plane per cell with a distinct offset: child (i, j) is z = 0.1 i + 0.3 j, i.e.
// f_ij = z - 0.1 i - 0.3 j.
Model Grid(double epsilon, int order) {
  Model m;
  std::vector<int> children;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i)
      children.push_back(m.AddPrimitive(NodeType::kPlane, {0, 0, 1, 0.1 * i + 0.3 * j}));
  m.AddPartition(kCuts, epsilon, order, children);
  return m;
}

TEST(Partition, BasesAreAPartitionOfUnityBetweenZeroAndOne) {
  const UnitStep& mu = UnitStep::OfOrder(3);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  const double eps = 0.45;  // the narrowest cell is 0.9 = 2 eps wide
  for (int n = 0; n < 100000; ++n) {
    const double t = u(rng);
    int cells[PartitionAxis::kMaxCells];
    double b[PartitionAxis::kMaxCells];
    const int count = PartitionAxis::Factors(kCuts[0], t, eps, mu, cells, b);
    ASSERT_GE(count, 1);
    ASSERT_LE(count, 2);
    double sum = 0;
    for (int i = 0; i < count; ++i) {
      EXPECT_GE(b[i], 0.0);
      EXPECT_LE(b[i], 1.0);
      sum += b[i];
    }
    EXPECT_NEAR(sum, 1.0, 1e-15) << t;
  }
  // Through the model: every child the same plane gives that plane (sum of bases = 1).
  Model same;
  std::vector<int> children;
  for (int c = 0; c < 6; ++c)
    children.push_back(same.AddPrimitive(NodeType::kPlane, {0, 0, 1, 0.25}));
  same.AddPartition(kCuts, 0.3, 3, children);
  for (int n = 0; n < 10000; ++n) {
    const Vec x(u(rng), u(rng), u(rng));
    EXPECT_NEAR(same.Value(x), x.z() - 0.25, 4e-15 * (1 + std::abs(x.z())));
  }
}

TEST(Partition, RefusesACellNarrowerThanTwoEpsilonWithPathAndWidth) {
  // Cells of width 0.9 with epsilon 0.3 (1.5 eps): refused, naming root.cuts[0][1] and 0.9.
  const std::string doc =
      R"({"format": "implicitfit-model", "version": 1, "root": {"type": "partition",
      "cuts": [[-0.5, 0.4], [], []], "epsilon": EPS, "order": 3, "children": [
      {"type": "plane", "normal": [0, 0, 1], "offset": 0}, {"type": "plane", "normal": [0, 0, 1], "offset": 0},
      {"type": "plane", "normal": [0, 0, 1], "offset": 0}]}})";
  auto with = [&](const std::string& eps) {
    std::string s = doc;
    s.replace(s.find("EPS"), 3, eps);
    return ModelFromJson(nlohmann::json::parse(s));
  };
  EXPECT_NO_THROW(with("0.45"));
  try {
    with("0.6");
    FAIL() << "a cell 1.5 epsilon wide was accepted";
  } catch (const ModelFormatError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("root.cuts[0][1]"), std::string::npos) << what;
    EXPECT_NE(what.find("0.9"), std::string::npos) << what;
  }
  EXPECT_THROW(Grid(0.46, 3), std::invalid_argument);
}

TEST(Partition, EqualsTheCellsChildExactlyAwayFromTheCuts) {
  const double eps = 0.2;
  const Model m = Grid(eps, 3);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-2, 2);
  int checked = 0;
  for (int n = 0; n < 5000; ++n) {
    const Vec x(u(rng), u(rng), u(rng));
    if (std::abs(x.x() + 0.5) <= eps || std::abs(x.x() - 0.4) <= eps || std::abs(x.y()) <= eps)
      continue;
    const int i = x.x() < -0.5 ? 0 : (x.x() < 0.4 ? 1 : 2), j = x.y() < 0 ? 0 : 1;
    EXPECT_EQ(m.Value(x), x.z() - (0.1 * i + 0.3 * j));
    ++checked;
  }
  EXPECT_GT(checked, 1000);
}

TEST(Partition, IsOnceDifferentiableAcrossTheBandEdgeForOrderTwoButNotTwice) {
  // Order 2 (C^1): along x through the band edge x = 0.4 + eps of the cut at 0.4 (a knot of
  // mu), the first derivative is continuous and the second jumps.
  const double eps = 0.2, edge = 0.4 + eps, y = 0.5, z = 0.05;
  const Model m = Grid(eps, 2);
  auto f = [&](double x) { return m.Value(Vec(x, y, z)); };
  auto dfdx = [&](double x) { return m.Gradient(Vec(x, y, z)).x(); };
  const double h = 1e-7;
  EXPECT_NEAR(dfdx(edge - h), dfdx(edge + h), 1e-5);
  const double s = 1e-3;  // one-sided second differences
  const double left = (f(edge - 2 * s) - 2 * f(edge - s) + f(edge)) / (s * s);
  const double right = (f(edge) - 2 * f(edge + s) + f(edge + 2 * s)) / (s * s);
  // H_2 pieces: mu'' jumps by 2 / eps^2 at the knot; times the child difference 0.1.
  EXPECT_GT(std::abs(left - right), 0.5 * 0.1 * 2.0 / (eps * eps) * 0.25);
  // The middle of the band (the cut itself, a knot of H_2 at s = 1) is also a knot: still C^1.
  EXPECT_NEAR(dfdx(0.4 - h), dfdx(0.4 + h), 1e-5);
}

TEST(Partition, JsonRoundTrip) {
  const Model m = Grid(0.2, 3);
  const Model back = ModelFromJson(ModelToJson(m));
  EXPECT_EQ(ModelToJson(back), ModelToJson(m));
  EXPECT_EQ(back.Value(Vec(0.35, -0.1, 0.2)), m.Value(Vec(0.35, -0.1, 0.2)));
}

}  // namespace
}  // namespace implicitfit
