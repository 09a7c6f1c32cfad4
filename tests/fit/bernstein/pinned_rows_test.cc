// Pinned empty-space rows of the patch-mesh fit (MeshFitStart::pins,
// fit/bernstein/bernstein_mesh_fitter.h): no step of the fit may add a sign error at a pin.
// The data are 800 points on the unit sphere (Fibonacci lattice); the start is the sphere of
// radius 1.5 (a single quadric on every tetrahedron, exact at degree 3), so f < 0 at |x| = 1.3,
// between the data and the start's zero set. Fitting pulls the zero set in to the data, and f
// turns positive there unless it is pinned: with pins (targets the start's values) f must stay
// negative at every pin.
#include <gtest/gtest.h>

#include <cmath>

#include "fit/bernstein/bernstein_mesh_fitter.h"
#include "model/bernstein/bernstein_conversion.h"
#include "support/fibonacci_sphere.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

class PinnedRows : public ::testing::Test {
 protected:
  void SetUp() override {
    grid_.origin = Vec::Constant(-2);
    grid_.cell = 1;
    grid_.cells = {4, 4, 4};
    points_ = testsupport::FibonacciSphere(800);
    CartesianQuadric start;  // |x|^2 - 1.5^2
    start.A = Eigen::Matrix3d::Identity();
    start.c = -2.25;
    for (long long t = 0; t < grid_.NumTetrahedra(); ++t) {
      const std::vector<double> bt = QuadricToBernstein(start, grid_.TetrahedronOf(t), 3);
      start_.control_points.insert(start_.control_points.end(), bt.begin(), bt.end());
    }
    // The six points at |x| = 1.3 on the axes: 0.3 from the data, farther than the fit's band
    // (2 x 1% of the box diagonal, 0.14).
    for (int a = 0; a < 3; ++a)
      for (double s : {-1.3, 1.3}) {
        FarFieldRow r;
        r.x = Vec::Zero();
        r.x[a] = s;
        r.target = s * s - 2.25;  // the start's value, -0.56
        pins_.push_back(r);
      }
    options_.degree = 3;
    options_.continuity = 1;
  }
  double F(const MeshFitResult& fit, const Vec& x) const {
    return BernsteinMesh::Evaluate(3, fit.grid, fit.control_points.data(), x.data());
  }
  BernsteinGrid grid_;
  std::vector<Vec> points_;
  MeshFitStart start_;
  std::vector<FarFieldRow> pins_;
  MeshFitOptions options_;
};

TEST_F(PinnedRows, WithoutPinsTheZeroSetMovesToTheData) {
  const MeshFitResult fit = FitBernsteinMeshOnGrid(points_, points_, options_, grid_, &start_);
  ASSERT_TRUE(fit.success) << fit.message;
  EXPECT_LT(fit.rms, 0.5 * fit.initial_rms);  // the start is 0.5 off every point
  int positive = 0;
  for (const FarFieldRow& r : pins_) positive += F(fit, r.x) > 0;
  EXPECT_EQ(positive, 6);
}

TEST_F(PinnedRows, NoStepAddsASignErrorAtAPin) {
  start_.pins = pins_;
  const MeshFitResult fit = FitBernsteinMeshOnGrid(points_, points_, options_, grid_, &start_);
  ASSERT_TRUE(fit.success) << fit.message;
  for (const FarFieldRow& r : pins_) EXPECT_LT(F(fit, r.x), 0) << r.x.transpose();
}

}  // namespace
}  // namespace implicitfit
