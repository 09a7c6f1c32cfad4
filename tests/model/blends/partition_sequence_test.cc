// Sequential soft partition by separator planes (docs/maths.md LP-1, eq. 7-8): the bases sum to 1
// for random planes, lie in [0, 1]; a cell's width (twice its inscribed radius) against closed
// forms; refusal of a cell narrower than 2 epsilon (JSON path and width); f = f_j exactly in the
// cell's core; JSON round trip and parameter names.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "model/model.h"
#include "model/file/model_json.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

std::vector<SeparatorPlane> RandomPlanes(int m, std::mt19937& rng) {
  std::normal_distribution<double> g;
  std::vector<SeparatorPlane> s;
  for (int i = 0; i < m; ++i) s.push_back({Vec(g(rng), g(rng), g(rng)).normalized(), 0.3 * g(rng)});
  return s;
}

TEST(PartitionSequence, BasesSumToOneAndLieBetweenZeroAndOneForRandomPlanes) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const UnitStep& mu = UnitStep::OfOrder(3);
  for (int n = 0; n < 100000; ++n) {
    const int m = 1 + n % 5;
    const std::vector<SeparatorPlane> s = RandomPlanes(m, rng);
    const Vec x(u(rng), u(rng), u(rng));
    const double eps = 0.05 + 0.2 * (u(rng) + 1.0);
    auto sep = [&](int j) { return s[j].normal.dot(x) - s[j].offset; };
    double sum = 0.0;
    for (int k = 0; k <= m; ++k) {  // w_k: the child values are the indicator of k
      const double w =
          PartitionSequence::Evaluate(mu, eps, m, sep, [&](int j) { return j == k ? 1.0 : 0.0; });
      ASSERT_GE(w, 0.0);
      ASSERT_LE(w, 1.0);
      sum += w;
    }
    ASSERT_NEAR(sum, 1.0, 1e-15) << n;
  }
}

TEST(PartitionSequence, CellWidthIsTwiceTheInscribedRadius) {
  // A slab between two parallel planes 0.7 apart: x <= 0.2 (inside s_1) and x >= -0.5
  // (outside s_2, whose normal is +x with offset -0.5): cell 1, width 0.7. Cell 0 (x > 0.2) and
  // cell 2 (x < -0.5) are half-spaces: infinite.
  const std::vector<SeparatorPlane> slab = {{Vec(1, 0, 0), 0.2}, {Vec(1, 0, 0), -0.5}};
  EXPECT_NEAR(PartitionSequenceCellWidth(slab, 1), 0.7, 1e-9);
  EXPECT_TRUE(std::isinf(PartitionSequenceCellWidth(slab, 0)));
  EXPECT_TRUE(std::isinf(PartitionSequenceCellWidth(slab, 2)));
  // A regular tetrahedron with inradius r around c: cell 3 = {s_1, s_2, s_3 < 0, s_4 > 0}, the
  // fourth face given as the plane of outward normal -n_4 (its outside is the tetrahedron's
  // inside). Inradius of a regular tetrahedron = 3 V / A (closed form r by construction).
  const double r = 0.35;
  const Vec c(0.1, -0.2, 0.3);
  const Vec v[4] = {Vec(1, 1, 1), Vec(1, -1, -1), Vec(-1, 1, -1), Vec(-1, -1, 1)};
  std::vector<SeparatorPlane> tet;
  for (int k = 0; k < 4; ++k) {
    const Vec n = -v[k].normalized();  // the face opposite vertex k
    const double d = n.dot(c) + r;
    tet.push_back(k < 3 ? SeparatorPlane{n, d} : SeparatorPlane{-n, -d});
  }
  EXPECT_NEAR(PartitionSequenceCellWidth(tet, 3), 2 * r, 1e-9);
  EXPECT_TRUE(PartitionSequenceCoreIsNonEmpty(tet, 3, 0.999 * r));
  EXPECT_FALSE(PartitionSequenceCoreIsNonEmpty(tet, 3, 1.001 * r));
  double width = 0;
  EXPECT_EQ(NarrowPartitionSequenceCell(tet, 0.36, &width), 3);
  EXPECT_NEAR(width, 2 * r, 1e-9);
  EXPECT_EQ(NarrowPartitionSequenceCell(tet, 0.34, &width), -1);
}

std::string SlabDocument(double gap, double epsilon) {
  return R"({"format": "implicitfit-model", "version": 1, "root": {"type": "partition_sequence",
    "separators": [{"type": "plane", "normal": [1, 0, 0], "offset": 0.2},
                   {"type": "plane", "normal": [1, 0, 0], "offset": )" +
         std::to_string(0.2 - gap) + R"(}],
    "epsilon": )" +
         std::to_string(epsilon) +
         R"(, "order": 3,
    "children": [{"type": "plane", "normal": [0, 0, 1], "offset": 0},
                 {"type": "plane", "normal": [0, 0, 1], "offset": 0.1},
                 {"type": "sphere", "center": [-2, 0, 0], "radius": 0.5}]}})";
}

TEST(PartitionSequence, RefusesACellNarrowerThanTwoEpsilonWithPathAndWidth) {
  EXPECT_NO_THROW(ModelFromJson(nlohmann::json::parse(SlabDocument(0.6, 0.3))));  // 2 eps
  try {
    ModelFromJson(nlohmann::json::parse(SlabDocument(0.45, 0.3)));  // 1.5 eps
    FAIL() << "a cell 1.5 eps wide was accepted";
  } catch (const std::exception& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("root.children[1]"), std::string::npos) << what;
    EXPECT_NE(what.find("0.45"), std::string::npos) << what;
    EXPECT_NE(what.find("less than 2 epsilon = 0.6"), std::string::npos) << what;
  }
  // Not a plane as separator.
  std::string doc = SlabDocument(0.6, 0.3);
  doc.replace(doc.find("\"plane\""), 7, "\"sphere\"");
  EXPECT_THROW(ModelFromJson(nlohmann::json::parse(doc)), std::exception);
}

// Three cells: x > 0 (cell 0, plane z = 0.3), x < 0 and y > 0 (cell 1, a tilted plane),
// x < 0 and y < 0 (cell 2, a sphere inside that cell's core).
Model ThreeCells(double epsilon, int order) {
  Model m;
  const int s1 = m.AddPrimitive(NodeType::kPlane, {1, 0, 0, 0});
  const int s2 = m.AddPrimitive(NodeType::kPlane, {0, 1, 0, 0});
  const int c0 = m.AddPrimitive(NodeType::kPlane, {0, 0, 1, 0.3});
  const int c1 = m.AddPrimitive(NodeType::kPlane, {0.2, 0.1, 1, 0.1});
  const int c2 = m.AddPrimitive(NodeType::kSphere, {-1.5, -1.5, 0, 0.8});
  m.AddPartitionSequence({s1, s2}, epsilon, order, {c0, c1, c2});
  return m;
}

TEST(PartitionSequence, EqualsTheCellsChildExactlyInItsCore) {
  const double eps = 0.2;
  const Model m = ThreeCells(eps, 3);
  const Model parts[3] = {[] {
                            Model p;
                            p.AddPrimitive(NodeType::kPlane, {0, 0, 1, 0.3});
                            return p;
                          }(),
                          [] {
                            Model p;
                            p.AddPrimitive(NodeType::kPlane, {0.2, 0.1, 1, 0.1});
                            return p;
                          }(),
                          [] {
                            Model p;
                            p.AddPrimitive(NodeType::kSphere, {-1.5, -1.5, 0, 0.8});
                            return p;
                          }()};
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-3, 3);
  int checked[3] = {0, 0, 0};
  for (int n = 0; n < 20000; ++n) {
    const Vec x(u(rng), u(rng), u(rng));
    int cell = -1;
    if (x.x() >= eps) cell = 0;
    if (x.x() <= -eps && x.y() >= eps) cell = 1;
    if (x.x() <= -eps && x.y() <= -eps) cell = 2;
    if (cell < 0) continue;
    EXPECT_EQ(m.Value(x), parts[cell].Value(x)) << x.transpose();
    ++checked[cell];
  }
  for (int c = 0; c < 3; ++c) EXPECT_GT(checked[c], 1000);
  // In the band the value is a true mix: at x = 0 (beta_1 = 1/2), y = 1 (beta_2 = 0),
  // f = (f_0 + f_1) / 2.
  const Vec x(0.0, 1.0, 0.5);
  EXPECT_NEAR(m.Value(x), 0.5 * (parts[0].Value(x) + parts[1].Value(x)), 1e-15);
}

TEST(PartitionSequence, JsonRoundTripAndParameterNames) {
  const Model m = ThreeCells(0.2, 3);
  const nlohmann::json j = ModelToJson(m);
  EXPECT_EQ(j["root"]["type"], "partition_sequence");
  EXPECT_EQ(j["root"]["separators"].size(), 2u);
  EXPECT_EQ(j["root"]["children"].size(), 3u);
  EXPECT_EQ(j["root"]["children"][2]["type"], "sphere");
  const Model back = ModelFromJson(j);
  EXPECT_EQ(ModelToJson(back), j);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-3, 3);
  for (int n = 0; n < 1000; ++n) {
    const Vec x(u(rng), u(rng), u(rng));
    EXPECT_EQ(back.Value(x), m.Value(x));
  }
  const std::vector<std::string> names = m.ParameterNames();
  EXPECT_EQ(names[0], "root.separators[0].normal[0]");
  EXPECT_EQ(names[8], "root.children[0].normal[0]");
  EXPECT_EQ(names.back(), "root.epsilon");
}

}  // namespace
}  // namespace implicitfit
