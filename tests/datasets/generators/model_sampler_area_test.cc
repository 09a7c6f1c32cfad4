// `sample` draws uniformly by surface area: the share of points on each face of shapes whose
// face areas are known in closed form (half ball: disk pi r^2 of 3 pi r^2; capped cylinder:
// caps 2 pi r^2 of 2 pi r (r + H); box a x b x c: faces 2bc, 2ac, 2ab of 2(ab + bc + ac)).
// Tolerance: 4 binomial standard deviations plus 1% for the mesh-cell-sized band at creases.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "datasets/generators/model_sampler.h"
#include "support/axis_box.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

double ShareOf(const PointCloud& cloud, const std::function<bool(const Vec&)>& on_face) {
  int n = 0;
  for (const Vec& p : cloud.points) n += on_face(p);
  return static_cast<double>(n) / cloud.size();
}

void ExpectShare(double share, double expected, int count) {
  EXPECT_NEAR(share, expected, 4 * std::sqrt(expected * (1 - expected) / count) + 0.01);
}

SampleOptions Options(int count, unsigned seed) {
  SampleOptions o;
  o.count = count;
  o.seed = seed;
  return o;
}

TEST(SampleByArea, HalfBallDiskGetsAThird) {
  Model m;  // unit ball intersect z <= 0, sharp
  const int s = m.AddPrimitive(NodeType::kSphere, {0, 0, 0, 1});
  const int p = m.AddPrimitive(NodeType::kPlane, {0, 0, 1, 0});
  m.SetRoot(m.AddOperator(NodeType::kIntersection, {s, p}, 0.1, 0.1, 0));
  const int count = 20000;
  const SampledCloud c = SampleModel(m, Options(count, 7));
  ASSERT_EQ(c.cloud.size(), static_cast<size_t>(count));
  for (const Vec& x : c.cloud.points) ASSERT_LT(std::abs(m.Value(x)), 1e-9);
  const double disk = ShareOf(c.cloud, [](const Vec& x) { return std::abs(x.z()) < 1e-9; });
  ExpectShare(disk, 1.0 / 3.0, count);
  std::printf("  disk share %.4f (area share 0.3333)\n", disk);
}

TEST(SampleByArea, CappedCylinderCapsGetTheirArea) {
  const double r = 0.5, half_height = 1.0;
  Model m;
  const int cyl = m.AddPrimitive(NodeType::kCylinder, {0, 0, 0, 0, 0, 1, r});
  const int top = m.AddPrimitive(NodeType::kPlane, {0, 0, 1, half_height});
  const int bottom = m.AddPrimitive(NodeType::kPlane, {0, 0, -1, half_height});
  m.SetRoot(m.AddOperator(NodeType::kIntersection, {cyl, top, bottom}, 0.1, 0.1, 0));
  SampleOptions o = Options(20000, 11);
  o.has_box = true;
  o.box_min = Vec(-0.6, -0.6, -1.1);
  o.box_max = Vec(0.6, 0.6, 1.1);
  const SampledCloud c = SampleModel(m, o);
  const double caps = ShareOf(
      c.cloud, [&](const Vec& x) { return std::abs(std::abs(x.z()) - half_height) < 1e-9; });
  ExpectShare(caps, 2 * r * r / (2 * r * (r + 2 * half_height)), o.count);
  std::printf("  cap share %.4f (area share %.4f)\n", caps, r / (r + 2 * half_height));
}

TEST(SampleByArea, BoxFacesGetTheirAreasAlsoInAPartialView) {
  const Vec half(1.0, 0.5, 0.25);  // a 2 x 1 x 0.5 box
  const Model m = testsupport::AxisBox(half, 0.1, 0.1, 0);
  SampleOptions o = Options(20000, 5);
  o.has_box = true;
  o.box_min = -1.2 * half;
  o.box_max = 1.2 * half;
  const Vec area(half.y() * half.z(), half.x() * half.z(), half.x() * half.y());  // per face, / 4
  for (bool partial : {false, true}) {
    if (partial) {  // the view sees the +x, +y and +z faces only
      o.view_dir = Vec(1, 1, 1);
      o.view_angle_deg = 60.0;
    }
    const SampledCloud c = SampleModel(m, o);
    const double total = partial ? area.sum() : 2 * area.sum();
    for (int a = 0; a < 3; ++a) {
      const double share =
          ShareOf(c.cloud, [&](const Vec& x) { return std::abs(std::abs(x[a]) - half[a]) < 1e-9; });
      ExpectShare(share, (partial ? 1 : 2) * area[a] / total, o.count);
      std::printf("  %s axis %d share %.4f (area share %.4f)\n", partial ? "partial" : "whole", a,
                  share, (partial ? 1 : 2) * area[a] / total);
    }
  }
}

}  // namespace
}  // namespace implicitfit
