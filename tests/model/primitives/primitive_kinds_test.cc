// The primitive kinds' table (model/primitives/primitive_kinds.h) against the evaluators it describes:
// names, parameter counts, the JSON round trip, and what each field role claims, checked on
// f itself (a position moves the surface with it, a direction means only its direction, a
// positive length or an angle out of range is refused by the reader, the sampling box holds
// surface).
#include "model/primitives/primitive_kinds.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <string>

#include "model/file/model_json.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

// A valid parameter vector and the evaluator's own parameter count, per kind, written here
// from the evaluators' header comments (model/*.h), not from the table.
struct Example {
  std::vector<double> params;
  int evaluator_parameters;
};

std::map<NodeType, Example> Examples() {
  const double q[4] = {0.9, 0.1, 0.2, 0.3};
  const double qn = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  const double a = 0.4;  // the ellipsoid's axes: rotated by a about z
  return {
      {NodeType::kPlane, {{0.3, -0.2, 0.9, 0.4}, PlaneEvaluator::kNumParameters}},
      {NodeType::kSphere, {{0.1, -0.2, 0.3, 0.7}, SphereEvaluator::kNumParameters}},
      {NodeType::kCylinder,
       {{0.1, 0.2, -0.1, 0.2, 0.1, 1.0, 0.5}, CylinderEvaluator::kNumParameters}},
      {NodeType::kCone, {{0.1, 0.0, -0.5, 0.1, -0.2, 1.0, 0.5}, ConeEvaluator::kNumParameters}},
      {NodeType::kTorus,
       {{0.1, 0.1, 0.0, 0.0, 0.3, 1.0, 0.8, 0.25}, TorusEvaluator::kNumParameters}},
      {NodeType::kEllipsoid,
       {{0.1, 0.0, 0.2, 0.6, 0.4, 0.3, std::cos(a), std::sin(a), 0.0, -std::sin(a), std::cos(a),
         0.0},
        EllipsoidEvaluator::kNumParameters}},
      // x^2 + y^2 + z^2 - 0.5 = 0: [a11 a22 a33 a12 a13 a23 b1 b2 b3 c]
      {NodeType::kQuadric,
       {{1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -0.5}, QuadricEvaluator::kNumParameters}},
      {NodeType::kBox,
       {{0.1, -0.1, 0.2, q[0] / qn, q[1] / qn, q[2] / qn, q[3] / qn, 0.4, 0.3, 0.2},
        BoxEvaluator::kNumParameters}},
      {NodeType::kParaboloid,
       {{0.0, 0.1, -0.2, 0.2, 0.0, 1.0, 1.5}, ParaboloidEvaluator::kNumParameters}},
  };
}

Model OneNode(NodeType type, const std::vector<double>& p) {
  Model m;
  m.AddPrimitive(type, p);
  return m;
}

std::vector<Vec> RandomPoints(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  std::vector<Vec> x(n);
  for (Vec& v : x) v = Vec(u(rng), u(rng), u(rng));
  return x;
}

TEST(PrimitiveKinds, EveryPrimitiveKindHasAnExampleAndNamesRoundTrip) {
  const auto examples = Examples();
  EXPECT_EQ(PrimitiveKinds().size(), examples.size());
  for (const PrimitiveKind& kind : PrimitiveKinds()) {
    SCOPED_TRACE(kind.name);
    EXPECT_EQ(examples.count(kind.type), 1u);
    EXPECT_STREQ(NodeTypeName(kind.type), kind.name);
    NodeType back;
    ASSERT_TRUE(NodeTypeFromName(kind.name, &back));
    EXPECT_EQ(back, kind.type);
    EXPECT_EQ(FindPrimitiveKind(kind.type), &kind);
  }
  EXPECT_EQ(FindPrimitiveKind(NodeType::kUnion), nullptr);
  EXPECT_EQ(FindPrimitiveKind(NodeType::kBernsteinPatch), nullptr);
}

TEST(PrimitiveKinds, ParameterCountsAgreeWithTheEvaluators) {
  for (const auto& [type, example] : Examples()) {
    SCOPED_TRACE(NodeTypeName(type));
    const PrimitiveKind* kind = FindPrimitiveKind(type);
    ASSERT_NE(kind, nullptr);
    int sum = 0;
    for (const ParameterField& f : kind->fields) sum += f.size;
    EXPECT_EQ(sum, example.evaluator_parameters);
    EXPECT_EQ(NumParametersOf(type), example.evaluator_parameters);
    EXPECT_EQ(static_cast<int>(example.params.size()), example.evaluator_parameters);
  }
}

TEST(PrimitiveKinds, JsonRoundTripKeepsTheFunctionAndUsesTheFieldNames) {
  for (const auto& [type, example] : Examples()) {
    SCOPED_TRACE(NodeTypeName(type));
    const Model m = OneNode(type, example.params);
    const nlohmann::json j = ModelToJson(m);
    for (const ParameterField& f : FindPrimitiveKind(type)->fields)
      EXPECT_TRUE(j["root"].contains(f.name)) << f.name;
    const Model back = ModelFromJson(nlohmann::json::parse(j.dump()));
    ASSERT_EQ(back.nodes().size(), 1u);
    EXPECT_EQ(back.nodes()[0].type, type);
    for (const Vec& x : RandomPoints(50, 3)) EXPECT_NEAR(back.Value(x), m.Value(x), 1e-12);
  }
}

// A kPosition / kAxisPoint field moved by t (and a plane offset by n . t) moves the
// surface by t: f'(x + t) = f(x). The quadric has no such field (its coefficients mix position
// and shape) and is left out.
TEST(PrimitiveKinds, PositionRolesMoveTheSurface) {
  const Vec t(0.3, -0.7, 1.1);
  for (const auto& [type, example] : Examples()) {
    if (type == NodeType::kQuadric) continue;
    SCOPED_TRACE(NodeTypeName(type));
    const std::vector<ParameterField>& fields = FindPrimitiveKind(type)->fields;
    std::vector<double> moved = example.params;
    int k = 0, moved_fields = 0;
    for (const ParameterField& f : fields) {
      if (f.role == FieldRole::kPosition || f.role == FieldRole::kAxisPoint) {
        for (int j = 0; j < 3; ++j) moved[k + j] += t[j];
        ++moved_fields;
      }
      if (f.role == FieldRole::kPlaneOffset) {
        int d = 0;
        ASSERT_TRUE(FindFieldWithRole(fields, FieldRole::kDirection, &d));
        const Vec n(moved[d], moved[d + 1], moved[d + 2]);
        moved[k] += n.dot(t);
        ++moved_fields;
      }
      k += f.size;
    }
    EXPECT_EQ(moved_fields, 1);
    const Model a = OneNode(type, example.params), b = OneNode(type, moved);
    for (const Vec& x : RandomPoints(40, 5)) EXPECT_NEAR(b.Value(x + t), a.Value(x), 1e-12);
  }
}

// A kDirection field scaled by s > 0 (the plane's offset with it, as in n . x = d) leaves f
// unchanged: only its direction counts.
TEST(PrimitiveKinds, DirectionRolesMeanOnlyADirection) {
  int checked = 0;
  for (const auto& [type, example] : Examples()) {
    const std::vector<ParameterField>& fields = FindPrimitiveKind(type)->fields;
    int d = 0;
    if (!FindFieldWithRole(fields, FieldRole::kDirection, &d)) continue;
    SCOPED_TRACE(NodeTypeName(type));
    std::vector<double> scaled = example.params;
    for (int j = 0; j < 3; ++j) scaled[d + j] *= 2.5;
    int offset = 0;
    if (FindFieldWithRole(fields, FieldRole::kPlaneOffset, &offset)) scaled[offset] *= 2.5;
    const Model a = OneNode(type, example.params), b = OneNode(type, scaled);
    for (const Vec& x : RandomPoints(40, 7)) EXPECT_NEAR(b.Value(x), a.Value(x), 1e-12);
    ++checked;
  }
  EXPECT_EQ(checked, 5);  // plane, cylinder, cone, torus, paraboloid
}

// The reader refuses what the roles forbid: a zero direction, a length <= 0, an angle outside
// (0, pi/2); the message names the field.
TEST(PrimitiveKinds, JsonReaderEnforcesTheRoles) {
  int refused = 0;
  for (const auto& [type, example] : Examples()) {
    SCOPED_TRACE(NodeTypeName(type));
    const nlohmann::json good = ModelToJson(OneNode(type, example.params));
    for (const ParameterField& f : FindPrimitiveKind(type)->fields) {
      std::vector<double> bad_values;
      if (f.role == FieldRole::kPositiveLength) bad_values = {0.0, -0.3};
      if (f.role == FieldRole::kAngle) bad_values = {0.0, M_PI / 2, 2.0};
      for (double bad : bad_values) {
        nlohmann::json j = good;
        if (f.size == 1)
          j["root"][f.name] = bad;
        else
          j["root"][f.name][f.size - 1] = bad;
        try {
          ModelFromJson(j);
          ADD_FAILURE() << f.name << " = " << bad << " was accepted";
        } catch (const ModelFormatError& e) {
          EXPECT_NE(std::string(e.what()).find(f.name), std::string::npos) << e.what();
          ++refused;
        }
      }
      if (f.role == FieldRole::kDirection) {
        nlohmann::json j = good;
        j["root"][f.name] = {0.0, 0.0, 0.0};
        EXPECT_THROW(ModelFromJson(j), ModelFormatError) << f.name;
        ++refused;
      }
    }
  }
  // sphere 2, cylinder 2 + 1, cone 3 + 1, torus 4 + 1, ellipsoid 2, box 2, plane 1,
  // paraboloid 1
  EXPECT_EQ(refused, 20);
}

// The sampling box holds surface: f changes sign on a grid over it.
TEST(PrimitiveKinds, SamplingBoxHoldsSurface) {
  for (const auto& [type, example] : Examples()) {
    SCOPED_TRACE(NodeTypeName(type));
    Vec lo, hi;
    FindPrimitiveKind(type)->sampling_box(example.params.data(), &lo, &hi);
    ASSERT_TRUE(lo.allFinite() && hi.allFinite());
    ASSERT_TRUE((hi - lo).minCoeff() > 0);
    const Model m = OneNode(type, example.params);
    double fmin = INFINITY, fmax = -INFINITY;
    const int n = 16;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j)
        for (int k = 0; k <= n; ++k) {
          const Vec x = lo + (hi - lo).cwiseProduct(Vec(i, j, k) / n);
          const double f = m.Value(x);
          fmin = std::min(fmin, f);
          fmax = std::max(fmax, f);
        }
    EXPECT_LT(fmin, 0.0);
    EXPECT_GT(fmax, 0.0);
  }
}

}  // namespace
}  // namespace implicitfit
