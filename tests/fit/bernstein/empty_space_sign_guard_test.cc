// fit/bernstein/empty_space_sign_guard.h on meshes built tetrahedron by tetrahedron from quadrics
// (model/bernstein/bernstein_conversion.h), with closed-form zero sets: the unit sphere is the "data".
#include "fit/bernstein/empty_space_sign_guard.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "model/bernstein/bernstein_conversion.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

CartesianQuadric Sphere(const Vec& centre, double radius) {
  CartesianQuadric q;
  q.A = Eigen::Matrix3d::Identity();
  q.b = -centre;
  q.c = centre.squaredNorm() - radius * radius;
  return q;
}

// Control points of the mesh whose tetrahedron t carries quadric(t), at degree 2.
std::vector<double> Mesh(const BernsteinGrid& grid,
                         const std::function<CartesianQuadric(long long)>& quadric) {
  std::vector<double> b;
  for (long long t = 0; t < grid.NumTetrahedra(); ++t) {
    const std::vector<double> bt = QuadricToBernstein(quadric(t), grid.TetrahedronOf(t), 2);
    b.insert(b.end(), bt.begin(), bt.end());
  }
  return b;
}

class EmptySpaceSignGuardTest : public ::testing::Test {
 protected:
  void SetUp() override {
    grid_.origin = Vec::Constant(-2);
    grid_.cell = 1;
    grid_.cells = {4, 4, 4};
    for (int i = 0; i < 40; ++i)
      for (int j = 0; j < 20; ++j) {
        const double phi = 2 * M_PI * i / 40, theta = M_PI * (j + 0.5) / 20;
        points_.emplace_back(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                             std::cos(theta));
      }
  }
  BernsteinGrid grid_;
  std::vector<Vec> points_;
};

TEST_F(EmptySpaceSignGuardTest, SamplesLieOutsideTheBand) {
  const EmptySpaceSignGuard guard(grid_, points_, 0.2, 6);
  // 25^3 lattice points; those within 0.2 of the sampled sphere are dropped (about the shell
  // 0.8 < |x| < 1.2 less the gaps between the 800 points: at least its 4/3 pi (1.2^3 - 0.8^3)
  // volume / (1/6)^3 x 0.8 lattice points).
  EXPECT_LT(guard.size(), 25 * 25 * 25 - 0.8 * 4.0 / 3 * M_PI * (1.728 - 0.512) * 216);
  EXPECT_GT(guard.size(),
            25 * 25 * 25 - 4.0 / 3 * M_PI * (1.3 * 1.3 * 1.3 - 0.7 * 0.7 * 0.7) * 216);
}

TEST_F(EmptySpaceSignGuardTest, SurfaceMovingNearTheDataChangesNothing) {
  EmptySpaceSignGuard guard(grid_, points_, 0.2, 6);
  guard.Record(2, Mesh(grid_, [](long long) { return Sphere(Vec::Zero(), 1.0); }));
  EXPECT_EQ(guard.Changes(2, Mesh(grid_, [](long long) { return Sphere(Vec::Zero(), 1.02); })), 0);
  EXPECT_EQ(guard.Changes(2, Mesh(grid_, [](long long) { return Sphere(Vec(0.02, 0, 0), 1); })), 0);
}

TEST_F(EmptySpaceSignGuardTest, SmallBlobBetweenSamplesIsCaught) {
  // A blob of radius 0.05 centred between samples (spacing 1/6: the nearest sample is
  // sqrt(3)/12 = 0.144 away), in the cube [1, 2]^3 far from the sphere: no sample lies inside it,
  // so a sign check alone misses it, but the samples around it were clear of the zero set
  // (|x| >= 1.73: first-order distance (|x|^2 - 1) / (2 |x|) >= 0.58 > 2 rho = 0.29) and are now
  // within rho = 0.144 of it.
  const Vec centre = Vec::Constant(1.5 + 1.0 / 12);
  EmptySpaceSignGuard guard(grid_, points_, 0.2, 6);
  guard.Record(2, Mesh(grid_, [](long long) { return Sphere(Vec::Zero(), 1.0); }));
  const long long blob_cube = (3 * 4 + 3) * 4 + 3;
  const std::vector<double> with_blob = Mesh(grid_, [&](long long t) {
    return t / 6 == blob_cube ? Sphere(centre, 0.05) : Sphere(Vec::Zero(), 1.0);
  });
  // No sample inside the blob: f > 0 at every sample of that cube.
  for (int i = 0; i <= 6; ++i)
    for (int j = 0; j <= 6; ++j)
      for (int l = 0; l <= 6; ++l)
        ASSERT_GT(Sphere(centre, 0.05)(Vec(1 + i / 6.0, 1 + j / 6.0, 1 + l / 6.0)), 0.0);
  EXPECT_GT(guard.Changes(2, with_blob), 0);
  // Tripped() names the samples: all near the blob (within 2 rho + its radius of its centre,
  // rho = sqrt(3)/12), and none changed sign.
  const std::vector<EmptySpaceSignGuard::Trip> tripped = guard.Tripped(2, with_blob);
  EXPECT_EQ(static_cast<long long>(tripped.size()), guard.Changes(2, with_blob));
  for (const EmptySpaceSignGuard::Trip& t : tripped) {
    EXPECT_LT((t.x - centre).norm(), 0.05 + std::sqrt(3.0) / 6);
    EXPECT_FALSE(t.sign_changed);
  }
  // The far side of the box turning inside out is a plain sign change.
  const std::vector<double> flipped = Mesh(grid_, [&](long long t) {
    CartesianQuadric q = Sphere(Vec::Zero(), 1.0);
    if (t / 6 == blob_cube) q.A *= -1, q.b *= -1, q.c *= -1;
    return q;
  });
  EXPECT_GT(guard.Changes(2, flipped), 0);
  // Every sample of that cube's interior changed sign (and every change lies in the cube).
  long long changed = 0;
  for (const EmptySpaceSignGuard::Trip& t : guard.Tripped(2, flipped))
    if (t.sign_changed) {
      ++changed;
      EXPECT_TRUE((t.x.array() >= 1 - 1e-12).all()) << t.x.transpose();
    }
  EXPECT_GE(changed, 5 * 5 * 5);
}

// An open scan: the data is the sphere's cap z > 0.3; its lower part is the closure in empty
// space, which the fit may move. Moving it by 0.1 < rho (= sqrt(3)/12 = 0.144) crosses samples
// but trips nothing (they were within 2 rho of the recorded zero set); moving it by 0.5 brings
// it within rho of samples that were clear.
TEST_F(EmptySpaceSignGuardTest, ClosureMayMoveALittleButNotFar) {
  std::vector<Vec> cap;
  for (const Vec& p : points_)
    if (p.z() > 0.3) cap.push_back(p);
  EmptySpaceSignGuard guard(grid_, cap, 0.2, 6);
  guard.Record(2, Mesh(grid_, [](long long) { return Sphere(Vec::Zero(), 1.0); }));
  const std::vector<double> moved =
      Mesh(grid_, [](long long) { return Sphere(Vec(0, 0, -0.1), 1); });
  // The move crosses samples: some sample's sign differs (the guard ignores them).
  long long crossed = 0;
  for (int i = 0; i <= 24; ++i)
    for (int j = 0; j <= 24; ++j)
      for (int l = 0; l <= 24; ++l) {
        const Vec x = Vec::Constant(-2) + Vec(i, j, l) / 6.0;
        crossed +=
            (Sphere(Vec::Zero(), 1)(x) > 0) != (Sphere(Vec(0, 0, -0.1), 1)(x) > 0) && x.z() < -0.2;
      }
  ASSERT_GT(crossed, 0);
  EXPECT_EQ(guard.Changes(2, moved), 0);
  EXPECT_GT(guard.Changes(2, Mesh(grid_, [](long long) { return Sphere(Vec(0, 0, -0.5), 1); })), 0);
}

TEST(EmptySpaceSignGuard, ChangesBeforeRecordThrows) {
  BernsteinGrid grid;
  const EmptySpaceSignGuard guard(grid, {Vec::Zero()}, 0.1, 2);
  EXPECT_THROW(guard.Changes(2, std::vector<double>(60, 1.0)), std::logic_error);
}

// WatchedNear: the lattice points (spacing 1/6 from the box corner) within 0.3 (max-norm) of
// (1.5, 0, 0), farther than the band 0.2 from every data point (brute force) and clear of the
// recorded unit sphere: first-order distance (|x|^2 - 1) / (2|x|) > 2 rho, rho = sqrt(3)/12.
TEST_F(EmptySpaceSignGuardTest, WatchedNearAreTheClearSamplesAroundTheCentres) {
  EmptySpaceSignGuard guard(grid_, points_, 0.2, 6);
  guard.Record(2, Mesh(grid_, [](long long) { return Sphere(Vec::Zero(), 1.0); }));
  const Vec centre(1.5, 0, 0);
  const double rho = std::sqrt(3.0) / 12;
  std::vector<Vec> expected;
  for (int l = 0; l <= 24; ++l)
    for (int j = 0; j <= 24; ++j)
      for (int i = 0; i <= 24; ++i) {
        const Vec x = Vec::Constant(-2) + Vec(i, j, l) / 6.0;
        if ((x - centre).lpNorm<Eigen::Infinity>() > 0.3 + 1e-9) continue;
        bool near = false;
        for (const Vec& p : points_) near |= (p - x).norm() <= 0.2;
        if (!near && (x.squaredNorm() - 1) / (2 * x.norm()) > 2 * rho) expected.push_back(x);
      }
  ASSERT_GT(expected.size(), 20u);
  const std::vector<Vec> near = guard.WatchedNear({centre}, 0.3 + 1e-9);
  EXPECT_EQ(near.size(), expected.size());
  for (const Vec& e : expected) {
    bool found = false;
    for (const Vec& x : near) found |= (e - x).norm() < 1e-12;
    EXPECT_TRUE(found) << e.transpose();
  }
  // A second centre adds samples, never loses one.
  EXPECT_GT(guard.WatchedNear({centre, Vec(-1.5, 0, 0)}, 0.3 + 1e-9).size(), near.size());
}

}  // namespace
}  // namespace implicitfit
