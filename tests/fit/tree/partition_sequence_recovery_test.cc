// Li & Phillips Fig. 4 analogue with a partition_sequence (docs/maths.md LP-1, eq. 8), z-extruded.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>

#include "datasets/generators/model_sampler.h"
#include "datasets/meshing/model_mesher.h"
#include "fit/tree/tree_fitter.h"
#include "support/sample_in_box.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

// x = 0, y = 0 and x + y = -1/sqrt(2) make four cells (eq. 8); the cells hold the lines x = 0.8,
// y = 0.8 and x + y = -1.6, the triangular cell a plane far away (fixed: no points there). The
// cloud is sampled from the model (`sample`'s sampler), the model also meshes (`mesh`'s
// mesher: every vertex on the zero set). Start: normals turned 3 degrees, offsets +0.05,
// epsilon 0.06 (truth 0.08); the separators are structure. Every line's normal within 0.5
// degrees, epsilon within 10%.
struct SeqLine {
  Vec n;
  double d;
};
const SeqLine kSeqLines[3] = {
    {Vec(1, 0, 0), 0.8}, {Vec(0, 1, 0), 0.8}, {Vec(-1, -1, 0).normalized(), 1.6 / std::sqrt(2.0)}};

Model Sequence(double epsilon, double turn_rad, double shift) {
  Model m;
  const int s1 = m.AddPrimitive(NodeType::kPlane, {1, 0, 0, 0});
  const int s2 = m.AddPrimitive(NodeType::kPlane, {0, 1, 0, 0});
  const Vec d3 = Vec(-1, -1, 0).normalized();
  const int s3 = m.AddPrimitive(NodeType::kPlane, {d3.x(), d3.y(), 0, 0.5});
  std::vector<int> children;
  for (int c = 0; c < 3; ++c) {
    const Vec n = Eigen::AngleAxisd(turn_rad * (c % 2 ? 1 : -1), Vec::UnitZ()) * kSeqLines[c].n;
    children.push_back(
        m.AddPrimitive(NodeType::kPlane, {n.x(), n.y(), n.z(), kSeqLines[c].d + shift}));
  }
  children.push_back(m.AddPrimitive(NodeType::kPlane, {0, 0, 1, 10.0}));
  m.mutable_nodes().back().fixed = {"normal", "offset"};
  m.AddPartitionSequence({s1, s2, s3}, epsilon, 3, children);
  return m;
}

TEST(PartitionSequenceRecovery, FourCellsOfThreeSeparatorsRecoverEveryLineAndEpsilon) {
  const double epsilon = 0.08;
  const Model truth = Sequence(epsilon, 0.0, 0.0);
  SampleOptions so = testsupport::SampleInBox(5000, 0.002, 12, Vec(-2, -2, -1), Vec(1.5, 1.5, 1));
  const SampledCloud s = SampleModel(truth, so);
  double worst_sample = 0;
  for (size_t i = 0; i < s.cloud.size(); ++i) {  // noise 0.002: |f| / |grad f| within 5 sigma
    double f;
    const double g = truth.Gradient(s.cloud.points[i], &f).norm();
    worst_sample = std::max(worst_sample, std::abs(f) / g);
  }
  EXPECT_LT(worst_sample, 5 * so.noise);

  MeshOptions mo;
  mo.has_box = true;
  mo.box_min = so.box_min;
  mo.box_max = so.box_max;
  const MeshResult mesh = MeshModel(truth, mo);
  EXPECT_GT(mesh.mesh.triangles.size(), 1000u);
  EXPECT_LT(mesh.max_abs_value, 1e-9);

  const TreeFitResult r = FitModelTree(Sequence(0.06, 3.0 * M_PI / 180.0, 0.05), s.cloud.points,
                                       s.cloud.normals, TreeFitOptions{});
  ASSERT_TRUE(r.success) << r.message;
  const std::vector<double>& p = r.model.parameters();
  double worst_deg = 0;
  for (int c = 0; c < 3; ++c) {
    const int b = r.model.nodes()[3 + c].first_parameter;
    const Vec n = Vec(p[b], p[b + 1], p[b + 2]).normalized();
    worst_deg = std::max(worst_deg, std::acos(std::min(1.0, n.dot(kSeqLines[c].n))) * 180 / M_PI);
  }
  for (int j = 0; j < 12; ++j) EXPECT_EQ(p[j], truth.parameters()[j]) << "separators are fixed";
  const double eps_hat = p[r.model.nodes()[r.model.root()].first_parameter];
  std::printf("  partition_sequence: worst normal %.4f deg, epsilon %.5f (truth %.2f), rms %.4g\n",
              worst_deg, eps_hat, epsilon, r.rms);
  EXPECT_LT(worst_deg, 0.5);
  EXPECT_NEAR(eps_hat, epsilon, 0.1 * epsilon);
}

}  // namespace
}  // namespace implicitfit
