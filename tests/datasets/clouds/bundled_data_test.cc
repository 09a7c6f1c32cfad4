// The sample clouds in datasets/data: counts and normals as datasets/data/README.md states, the
// single sphere re-derived from the ten-sphere scan, and the total size kept small.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>

#include "datasets/clouds/cloud_file.h"

namespace implicitfit {
namespace {

const std::string kBundled = std::string(IMPLICITFIT_SOURCE_DIR) + "/datasets/data/";

TEST(BundledData, CountsAndNormalsAreAsDocumented) {
  struct Expected {
    const char* file;
    size_t points;
    bool normals;
  };
  off_t total = 0;
  for (const Expected& e :
       {Expected{"cgal_sphere_single.xyz", 422, true}, Expected{"cgal_spheres_10.ply", 5969, true},
        Expected{"cgal_fin90_two_planes_crease.xyz", 757, true},
        Expected{"pcl_milk_carton_kinect.pcd", 13704, false}}) {
    const PointCloud c = ReadCloudFile(kBundled + e.file);
    EXPECT_EQ(c.size(), e.points) << e.file;
    EXPECT_EQ(c.has_normals(), e.normals) << e.file;
    struct stat st;
    ASSERT_EQ(::stat((kBundled + e.file).c_str(), &st), 0);
    total += st.st_size;
  }
  EXPECT_LT(total, 1 << 20);
}

TEST(BundledData, SingleSphereIsTheSubsetOfTheTenSphereScanOnItsReferenceSphere) {
  // Reference sphere (shared data reference_spheres.txt, fifth row).
  const Eigen::Vector3d centre(0.708719, -0.108057, -0.699764);
  const double radius = 0.115973;
  const PointCloud all = ReadCloudFile(kBundled + "cgal_spheres_10.ply");
  PointCloud expected;
  for (size_t i = 0; i < all.size(); ++i)
    if (std::abs((all.points[i] - centre).norm() - radius) < 1e-6) {
      expected.points.push_back(all.points[i]);
      expected.normals.push_back(all.normals[i]);
    }
  const PointCloud single = ReadCloudFile(kBundled + "cgal_sphere_single.xyz");
  ASSERT_EQ(single.size(), expected.size());
  for (size_t i = 0; i < single.size(); ++i) {
    EXPECT_EQ(single.points[i], expected.points[i]) << i;  // %.17g round-trips doubles
    EXPECT_LT((single.normals[i] - expected.normals[i]).norm(), 1e-15) << i;
    // Outward: along p - c.
    EXPECT_GT(single.normals[i].dot((single.points[i] - centre).normalized()), 1 - 1e-6) << i;
  }
}

}  // namespace
}  // namespace implicitfit
