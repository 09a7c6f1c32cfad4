// The design job through the public header only, on the six faces of a cube, where the design
// has a closed form: one representative per face at its centre with its normal, the plane of the
// face through it, and the smooth intersection exact (the planes themselves) near the centres.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "implicitfit/design.h"
#include "implicitfit/model.h"

namespace implicitfit {
namespace {

// The faces of the cube [-1, 1]^3, each a 9 x 9 grid of cell centres u_i = -1 + (2 i + 1) / 9
// (u_4 = 0: the face centre is a point), normals outward. Returns the face centres (= normals).
std::vector<Eigen::Vector3d> CubeFaces(std::vector<Eigen::Vector3d>* points,
                                       std::vector<Eigen::Vector3d>* normals) {
  std::vector<Eigen::Vector3d> centres;
  for (int axis = 0; axis < 3; ++axis)
    for (double side : {-1.0, 1.0}) {
      Eigen::Vector3d n = Eigen::Vector3d::Zero();
      n[axis] = side;
      centres.push_back(n);
      for (int i = 0; i < 9; ++i)
        for (int j = 0; j < 9; ++j) {
          Eigen::Vector3d p = n;
          p[(axis + 1) % 3] = -1 + (2 * i + 1) / 9.0;
          p[(axis + 2) % 3] = -1 + (2 * j + 1) / 9.0;
          points->push_back(p);
          normals->push_back(n);
        }
    }
  return centres;
}

TEST(DesignJob, SixPlanesOfACubeMatchTheClosedForm) {
  std::vector<Eigen::Vector3d> points, normals;
  const std::vector<Eigen::Vector3d> centres = CubeFaces(&points, &normals);
  DesignJobOptions options;
  options.design.count = 6;
  options.design.delta = 0.1;
  options.design.epsilon = 0.05;
  std::string error;
  ASSERT_TRUE(options.IsValid(&error)) << error;
  const DesignJobResult job = DesignModelJob(points, normals, options);
  ASSERT_TRUE(job.success) << job.message;
  EXPECT_EQ(job.representatives, 6);
  EXPECT_EQ(job.points, points.size());
  EXPECT_EQ(job.delta, 0.1);
  EXPECT_EQ(job.epsilon, 0.05);
  // Representatives: k-means on (x / L, 2 n) separates the faces (normals of two faces differ by
  // >= 2 sqrt(2) in the features, positions on one face by < 1); a face's cluster mean is its
  // centre, a grid point, so the representative is the centre c with normal n = c, and its
  // plane is n . x = 1. At x = c + t n (|t| <= 0.2) that plane's value is t, every other
  // plane's <= -1, and the base's 1 + t - R: the points' covariance is isotropic, so the base is
  // a sphere of radius R = 1.25 x their reach sqrt(1 + 2 (8/9)^2) = 2.008. Li & Phillips'
  // smooth max (docs/maths.md) exceeds the max by (S_abs(t) - |t|) / 2 <= delta / 4, so six
  // folds keep the other children below -0.8 + 6 delta / 4 = -0.65, and the smooth max equals
  // the max where the two differ by >= delta + epsilon = 0.15: f(c + t n) = t, grad f = n.
  for (const Eigen::Vector3d& c : centres)
    for (double t : {-0.2, -0.05, 0.0, 0.05, 0.2}) {
      double f;
      const Eigen::Vector3d g = job.model.Gradient(c + t * c, &f);
      EXPECT_NEAR(f, t, 1e-12) << "face " << c.transpose() << " t " << t;
      EXPECT_LT((g - c).norm(), 1e-12) << "face " << c.transpose();
    }
  // Inside the cube, away from the faces, the model is negative; outside beyond the faces it is
  // positive (a plane's value there is the distance to the face, over delta + epsilon).
  EXPECT_LT(job.model.Value(Eigen::Vector3d(0.5, -0.3, 0.2)), 0);
  EXPECT_GT(job.model.Value(Eigen::Vector3d(0.2, 1.5, 0.1)), 0);
  EXPECT_EQ(job.BriefReport(), "486 points (given normals), 6 plane representatives");
  const nlohmann::json report = job.ToJson();
  EXPECT_EQ(report["job"], "design");
  EXPECT_EQ(report["representatives"], 6);
  EXPECT_EQ(report["settings"]["count"], 6);
}

TEST(DesignJob, DefaultBlendIsTwoPercentOfTheBoxDiagonal) {
  std::vector<Eigen::Vector3d> points, normals;
  CubeFaces(&points, &normals);
  DesignJobOptions options;
  options.design.count = 6;
  const DesignJobResult job = DesignModelJob(points, normals, options, "estimated");
  // The points span [-1, 1]^3: diagonal 2 sqrt(3); delta 2% of it, epsilon delta / 2.
  EXPECT_NEAR(job.delta, 0.04 * std::sqrt(3.0), 1e-15);
  EXPECT_NEAR(job.epsilon, 0.02 * std::sqrt(3.0), 1e-15);
  EXPECT_EQ(job.ToJson()["normals"], "estimated");
}

TEST(DesignJob, InvalidOptionsAndTooFewPointsAreRefused) {
  DesignJobOptions options;
  options.design.primitive = "cone";
  std::string error;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_EQ(error, "primitive 'cone': expected plane or paraboloid");
  options.design.primitive = "plane";
  options.design.delta = 0.1;
  options.design.epsilon = 0.2;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_EQ(error.rfind("epsilon", 0), 0u) << error;
  options.design.epsilon = 0;
  options.design.count = 5;
  const std::vector<Eigen::Vector3d> four(4, Eigen::Vector3d::UnitX());
  EXPECT_THROW(DesignModelJob(four, four, options), std::invalid_argument);
}

}  // namespace
}  // namespace implicitfit
