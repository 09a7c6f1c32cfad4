// The mesh job on a sphere, through the public header only: every vertex lies on the sphere
// within a tolerance of the cell size, with the radial normal.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "implicitfit/mesh.h"
#include "implicitfit/model.h"

namespace implicitfit {
namespace {

TEST(MeshJob, SphereVerticesLieOnTheSphereWithinTheCellTolerance) {
  const Eigen::Vector3d c(0.3, -0.2, 0.1);
  const double r = 1.5, h = 0.1;
  Model sphere;
  sphere.AddPrimitive(NodeType::kSphere, {c.x(), c.y(), c.z(), r});
  MeshJobOptions options;
  options.mesh.cell = h;
  options.mesh.has_box = true;
  options.mesh.box_min = c - Eigen::Vector3d::Constant(r + 3 * h);
  options.mesh.box_max = c + Eigen::Vector3d::Constant(r + 3 * h);
  std::string error;
  ASSERT_TRUE(options.IsValid(&error)) << error;
  const MeshJobResult job = MeshModelJob(sphere, options);
  ASSERT_TRUE(job.success) << job.message;
  const TriangleMesh& mesh = job.result.mesh;
  // A triangle inside a grid cube of edge h has an area of at most (sqrt(3) / 2) h^2, so a mesh
  // of the whole sphere (area ~ 4 pi r^2 = 28.3) needs more than 3 000 of them.
  ASSERT_GT(mesh.triangles.size(), 3000u);
  ASSERT_EQ(mesh.normals.size(), mesh.vertices.size());
  // Each vertex is the root of f on a grid edge of length h crossing the sphere. Even the linear
  // interpolation of the distance along the edge is within h^2 / (8 rho) of the root (the
  // distance to the centre along a line has second derivative <= 1 / rho, rho >= r - h the
  // line's distance to the centre); the mesher refines the root, so this bound holds with room.
  const double tolerance = h * h / (8 * (r - h));
  double worst = 0;
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Eigen::Vector3d d = mesh.vertices[i] - c;
    worst = std::max(worst, std::abs(d.norm() - r));
    // grad f of a sphere is radial: the outward unit normal is d / |d|.
    EXPECT_LT((mesh.normals[i] - d.normalized()).norm(), 1e-6) << "vertex " << i;
  }
  EXPECT_LE(worst, tolerance);
  // The triangles are chords of the sphere with edges <= sqrt(2) h: a flat triangle of
  // circumradius rho on a sphere of radius r has (1 - rho^2 / (4 r^2)) of its cap's area, so the
  // mesh's area is 4 pi r^2 within 2 h^2 / (4 r^2) < 0.3% (within 1% if the mesh is closed).
  double area = 0;
  for (const Eigen::Vector3i& t : mesh.triangles)
    area += 0.5 * (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                      .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]])
                      .norm();
  EXPECT_NEAR(area, 4 * M_PI * r * r, 0.01 * 4 * M_PI * r * r);
  const nlohmann::json report = job.ToJson();
  EXPECT_EQ(report["job"], "mesh");
  EXPECT_EQ(report["vertices"], mesh.vertices.size());
  EXPECT_EQ(report["triangles"], mesh.triangles.size());
  EXPECT_DOUBLE_EQ(report["cell"].get<double>(), h);
  EXPECT_NE(job.BriefReport().find("triangles " + std::to_string(mesh.triangles.size())),
            std::string::npos);
}

TEST(MeshJob, InvalidOptionsAreRefused) {
  MeshJobOptions options;
  options.mesh.cell = -1;
  std::string error;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_EQ(error.rfind("cell", 0), 0u) << error;
  Model sphere;
  sphere.AddPrimitive(NodeType::kSphere, {0, 0, 0, 1});
  EXPECT_THROW(MeshModelJob(sphere, options), std::invalid_argument);
}

}  // namespace
}  // namespace implicitfit
