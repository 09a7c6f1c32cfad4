// A concave fillet thinner than the samples' fixed offset (Fit4CAD PC124's stem-to-ball fillet),
// in a generated solid with known truth: a slab (2 x 2 x 0.3, top at z = 0) with a stem
// (cylinder r = 0.3 about z, capped at z = 0.8) and a concave fillet of radius 0.06 between them
// (torus: centre (0, 0, 0.06), axis z, R = 0.36, r = 0.06; the fillet's material is the ring
// 0.3 < rho < 0.36, 0 < z < 0.06 outside the tube, at most 0.06 (sqrt 2 - 1) = 0.025 thick,
// less than t = 1% of the diagonal = 0.030). The ring has the sign vector of the empty space
// above the slab. Checked: with the adaptive offset (fit/reconstruct/offset_samples.h) and the
// fillet's separators (fit/reconstruct/fillet_separators.h) the torus is carved out in the
// expression and every noise-free truth point is within 3 sigma of the result's zero set; without
// either of them the fillet is lost (the largest distance, on the fillet, exceeds 3 sigma).
#include <gtest/gtest.h>

#include <cmath>

#include "datasets/generators/model_sampler.h"
#include "fit/reconstruct/solid_reconstruction.h"
#include "support/largest_truth_distance.h"
#include "support/sample_in_box.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

TEST(ConcaveFillet, StemOnSlab) {
  const double stem = 0.3, rho = 0.06, cap = 0.8, depth = 0.3;
  Model truth;
  std::vector<int> slab_faces;
  for (int a = 0; a < 2; ++a)
    for (int s : {-1, 1}) {
      Vec n = Vec::Zero();
      n[a] = s;
      slab_faces.push_back(truth.AddPrimitive(NodeType::kPlane, {n.x(), n.y(), n.z(), 1.0}));
    }
  slab_faces.push_back(truth.AddPrimitive(NodeType::kPlane, {0, 0, 1, 0}));       // top
  slab_faces.push_back(truth.AddPrimitive(NodeType::kPlane, {0, 0, -1, depth}));  // bottom
  const int slab = truth.AddOperator(NodeType::kIntersection, slab_faces, 0.01, 0.01, 0);
  const int cylinder = truth.AddPrimitive(NodeType::kCylinder, {0, 0, 0, 0, 0, 1, stem});
  const int top = truth.AddPrimitive(NodeType::kPlane, {0, 0, 1, cap});
  const int foot = truth.AddPrimitive(NodeType::kPlane, {0, 0, -1, 0});
  const int post = truth.AddOperator(NodeType::kIntersection, {cylinder, top, foot}, 0.01, 0.01, 0);
  // The fillet: the ring rho < R, 0 < z < rho, minus the tube.
  const int ring_cylinder = truth.AddPrimitive(NodeType::kCylinder, {0, 0, 0, 0, 0, 1, stem + rho});
  const int ring_top = truth.AddPrimitive(NodeType::kPlane, {0, 0, 1, rho});
  const int ring_foot = truth.AddPrimitive(NodeType::kPlane, {0, 0, -1, 0});
  const int ring = truth.AddOperator(NodeType::kIntersection, {ring_cylinder, ring_top, ring_foot},
                                     0.01, 0.01, 0);
  const int tube = truth.AddPrimitive(NodeType::kTorus, {0, 0, rho, 0, 0, 1, stem + rho, rho});
  const int fillet = truth.AddOperator(NodeType::kDifference, {ring, tube}, 0.01, 0.01, 0);
  truth.SetRoot(truth.AddOperator(NodeType::kUnion, {slab, post, fillet}, 0.01, 0.01, 0));

  const Vec box_lo(-1.2, -1.2, -0.5), box_hi(1.2, 1.2, 1.0);
  const double size = 2.0;
  const double sigma = 0.002 * size;
  SampleOptions so = testsupport::SampleInBox(12000, sigma, 31, box_lo, box_hi);
  const SampledCloud sampled = SampleModel(truth, so);
  // Labels: slab faces 0-5, stem 6, cap 7, torus 8: the truth surface within 4 sigma whose
  // outward normal the point's normal matches (the torus's: towards its centre circle).
  std::vector<int> labels;
  int fillet_points = 0;
  for (size_t i = 0; i < sampled.cloud.size(); ++i) {
    const Vec& p = sampled.cloud.points[i];
    const Vec& n = sampled.cloud.normals[i];
    const double r = Vec(p.x(), p.y(), 0).norm();
    const Vec radial = Vec(p.x(), p.y(), 0) / r;
    int label = -1;
    const Vec outward[6] = {-Vec::UnitX(), Vec::UnitX(), -Vec::UnitY(),
                            Vec::UnitY(),  Vec::UnitZ(), -Vec::UnitZ()};
    const double offset[6] = {1, 1, 1, 1, 0, depth};
    for (int k = 0; k < 6; ++k)
      if (std::abs(outward[k].dot(p) - offset[k]) < 4 * sigma && n.dot(outward[k]) > 0.99)
        label = k;
    if (std::abs(r - stem) < 4 * sigma && n.dot(radial) > 0.99 && p.z() > rho) label = 6;
    if (std::abs(p.z() - cap) < 4 * sigma && n.z() > 0.99) label = 7;
    const Vec centre = (stem + rho) * radial + Vec(0, 0, rho);
    if (std::abs((p - centre).norm() - rho) < 4 * sigma &&
        n.dot((centre - p).normalized()) > 0.99 && r < stem + rho && p.z() < rho)
      label = 8;
    fillet_points += label == 8;
    labels.push_back(label);
  }
  ASSERT_GE(fillet_points, 80);
  std::vector<NodeType> kinds(6, NodeType::kPlane);
  kinds.insert(kinds.end(), {NodeType::kCylinder, NodeType::kPlane, NodeType::kTorus});
  const std::vector<SolidPrimitive> scene =
      FitLabelledPrimitives(sampled.cloud.points, sampled.cloud.normals, labels, kinds, 31);
  SampleOptions clean = so;
  clean.noise = 0;
  clean.seed = 32;
  const std::vector<Vec> truth_points = SampleModel(truth, clean).cloud.points;
  struct Variant {
    const char* name;
    bool adaptive, separators;
  };
  for (const Variant& v :
       {Variant{"fixed offset", false, true}, Variant{"no fillet separators", true, false},
        Variant{"adaptive offset and fillet separators", true, true}}) {
    SolidReconstructionOptions options;
    options.seed = 31;
    options.adaptive_offset = v.adaptive;
    options.fillet_separators = v.separators;
    const SolidReconstruction r =
        ReconstructSolid(sampled.cloud.points, sampled.cloud.normals, scene, options);
    ASSERT_TRUE(r.success) << v.name << ": " << r.message << " expression " << r.expression;
    const double largest = LargestTruthDistance(r.model, truth_points);
    std::printf("  %s: expression %s, largest distance of the truth points %.5f (3 sigma %.4f)\n",
                v.name, r.expression.c_str(), largest, 3 * sigma);
    if (v.adaptive && v.separators) {
      EXPECT_NE(r.expression.find("!p8"), std::string::npos) << r.expression;
      EXPECT_LE(largest, 3 * sigma);
    } else {
      EXPECT_GT(largest, 3 * sigma);  // the fillet is lost
    }
  }
}

}  // namespace
}  // namespace implicitfit
