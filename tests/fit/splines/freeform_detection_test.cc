// detect --freeform's stage (fit/splines/freeform_detection.h) on generated clouds: a wavy sheet
// left unassigned beside a labelled plane becomes B-spline surface primitives that hold >= 95% of
// its points, none of the plane's, with RMS <= 2 sigma; the same sheet with a noise that grows
// five-fold across it (a stereo scan's depth noise grows with the range) is still >= 90%
// assigned, each patch's RMS within 2x the RMS of the true noise over its points; uniform random
// points give none.
#include "fit/splines/freeform_detection.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <string>

#include "datasets/normals/neighbourhoods.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

// The sheet's points (from sheet_begin on) that got a patch's label (>= 1); the plane's points
// (before sheet_begin) must keep their label 0.
int SheetPointsAssigned(const std::vector<int>& labels, int sheet_begin) {
  int assigned = 0;
  for (int i = 0; i < static_cast<int>(labels.size()); ++i) {
    if (i < sheet_begin)
      EXPECT_EQ(labels[i], 0) << "plane point " << i;
    else
      assigned += labels[i] >= 1;
  }
  return assigned;
}

TEST(FreeformDetection, WavySheetBecomesSplineSurfaces) {
  const double sigma = 0.003;
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> noise(0.0, sigma);
  std::vector<Vec> points, normals;
  std::vector<int> labels;
  const int sheet_points = 3000;
  for (int i = 0; i < 2000; ++i) {  // the plane z = 0 over [-1, 1]^2, labelled 0
    points.emplace_back(u(rng), u(rng), noise(rng));
    normals.emplace_back(0, 0, 1);
    labels.push_back(0);
  }
  const int sheet_begin = static_cast<int>(points.size());
  for (int i = 0; i < sheet_points; ++i) {  // z = 0.5 + 0.15 sin(2x) cos(3y) over [2, 4] x [-1, 1]
    const double x = 3 + u(rng), y = u(rng);
    const double z = 0.5 + 0.15 * std::sin(2 * x) * std::cos(3 * y);
    const Vec n = Vec(-0.3 * std::cos(2 * x) * std::cos(3 * y),
                      0.45 * std::sin(2 * x) * std::sin(3 * y), 1.0).normalized();
    points.push_back(Vec(x, y, z) + noise(rng) * n);
    normals.push_back(n);
    labels.push_back(-1);
  }
  const Neighbourhoods nb = FindNeighbourhoods(points);
  FreeformOptions o;
  o.noise = sigma;
  o.threshold = 3 * sigma;
  o.normal_angle_deg = 20;
  o.min_points = 20;
  std::vector<std::string> told;  // the progress lines: the start and the end at least
  o.progress = [&told](const std::string& line) { told.push_back(line); };
  std::vector<double> residuals;
  const FreeformResult r = DetectFreeformSurfaces(points, normals, nb.indices, o, 1, &labels, &residuals);
  ASSERT_GE(told.size(), 2u);
  EXPECT_NE(told.front().find("smooth regions"), std::string::npos) << told.front();
  EXPECT_NE(told.back().find(std::to_string(r.surfaces.size()) + " surfaces"), std::string::npos)
      << told.back();
  ASSERT_GE(r.surfaces.size(), 1u);
  const int assigned = SheetPointsAssigned(labels, sheet_begin);
  EXPECT_GE(assigned, 0.95 * sheet_points);
  for (const FreeformSurface& s : r.surfaces) {
    EXPECT_LE(s.rms_distance, 2 * sigma);
    EXPECT_EQ(s.normal_side, "outward");
    EXPECT_EQ(s.model.nodes()[0].type, NodeType::kBSplineSurface);
    for (int i : s.points) EXPECT_NEAR(residuals[i], s.model.Value(points[i]), 1e-12);
  }
  RecordProperty("surfaces", static_cast<int>(r.surfaces.size()));
}

// sigma(x) = sigma0 (1 + 2 (x - 2)) over x in [2, 4]: sigma0 at one end, 5 sigma0 at the other,
// while the detection's sigma and tau are sigma0's (the labelled plane's, as the median over a
// scan is its near part's). With the detection's bands alone the far half lies outside tau.
TEST(FreeformDetection, SheetWithGrowingNoiseIsAssigned) {
  const double sigma0 = 0.002;
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> unit(0.0, 1.0);
  std::vector<Vec> points, normals;
  std::vector<int> labels;
  std::vector<double> true_sigma;
  for (int i = 0; i < 2000; ++i) {  // the plane z = 0 over [-1, 1]^2, labelled 0
    points.emplace_back(u(rng), u(rng), sigma0 * unit(rng));
    normals.emplace_back(0, 0, 1);
    labels.push_back(0);
    true_sigma.push_back(sigma0);
  }
  const int sheet_begin = static_cast<int>(points.size());
  const int sheet_points = 4000;
  for (int i = 0; i < sheet_points; ++i) {  // z = 0.5 + 0.15 sin(2x) cos(3y) over [2, 4] x [-1, 1]
    const double x = 3 + u(rng), y = u(rng);
    const double z = 0.5 + 0.15 * std::sin(2 * x) * std::cos(3 * y);
    const Vec n =
        Vec(-0.3 * std::cos(2 * x) * std::cos(3 * y), 0.45 * std::sin(2 * x) * std::sin(3 * y), 1.0)
            .normalized();
    const double sigma = sigma0 * (1 + 2 * (x - 2));
    points.push_back(Vec(x, y, z) + sigma * unit(rng) * n);
    normals.push_back(n);
    labels.push_back(-1);
    true_sigma.push_back(sigma);
  }
  const Neighbourhoods nb = FindNeighbourhoods(points);
  FreeformOptions o;
  o.noise = sigma0;
  o.threshold = 3 * sigma0;
  o.normal_angle_deg = 20;
  o.spacing = nb.spacing;
  o.min_points = 20;
  std::vector<double> residuals;
  const FreeformResult r =
      DetectFreeformSurfaces(points, normals, nb.indices, o, 1, &labels, &residuals);
  ASSERT_GE(r.surfaces.size(), 1u);
  const int assigned = SheetPointsAssigned(labels, sheet_begin);
  EXPECT_GE(assigned, 0.90 * sheet_points);
  for (const FreeformSurface& s : r.surfaces) {
    double truth2 = 0;
    for (int i : s.points) truth2 += true_sigma[i] * true_sigma[i];
    EXPECT_LE(s.rms_distance, 2 * std::sqrt(truth2 / s.points.size()));
  }
  RecordProperty("assigned", assigned);
}

TEST(FreeformDetection, RandomPointsGiveNoSurface) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec> points, normals;
  for (int i = 0; i < 3000; ++i) {
    points.emplace_back(u(rng), u(rng), u(rng));
    normals.push_back(Vec(u(rng), u(rng), u(rng)).normalized());
  }
  std::vector<int> labels(points.size(), -1);
  std::vector<double> residuals;
  const Neighbourhoods nb = FindNeighbourhoods(points);
  FreeformOptions o;
  o.noise = 0.01;
  o.threshold = 0.03;
  o.normal_angle_deg = 20;
  o.min_points = 30;
  const FreeformResult r = DetectFreeformSurfaces(points, normals, nb.indices, o, 0, &labels, &residuals);
  EXPECT_TRUE(r.surfaces.empty());
  for (int l : labels) EXPECT_EQ(l, -1);
}

}  // namespace
}  // namespace implicitfit
