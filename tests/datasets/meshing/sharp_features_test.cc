// Sharp edges and corners in meshes of zero sets (datasets/meshing/sharp_features.h through
// datasets/meshing/model_mesher.h), judged against closed forms: a sharp box (six planes, order-0
// intersection) whose corners and edges are known exactly, and a sharp half ball whose crease is
// the unit circle in z = 0. Distances from the true creases to the mesh are exact point-triangle
// distances (brute force over every triangle). The same meshes without step 5 (plain marching
// cubes) must miss the creases by a good part of a cell: the checks can fail.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "datasets/meshing/model_mesher.h"
#include "support/axis_box.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

// Closest point on triangle abc to p, by minimising over the interior (barycentric solve) and
// the three edges (clamped projections): written independently of the bench's version.
double PointTriangleDistance(const Vec& p, const Vec& a, const Vec& b, const Vec& c) {
  const Vec n = (b - a).cross(c - a);
  const double n2 = n.squaredNorm();
  double best = std::numeric_limits<double>::infinity();
  if (n2 > 0) {
    const Vec q = p - n * (n.dot(p - a) / n2);  // projection onto the plane
    const double wa = (b - q).cross(c - q).dot(n) / n2, wb = (c - q).cross(a - q).dot(n) / n2;
    if (wa >= 0 && wb >= 0 && wa + wb <= 1) best = (p - q).norm();
  }
  const Vec ends[3][2] = {{a, b}, {b, c}, {c, a}};
  for (const auto& e : ends) {
    const Vec d = e[1] - e[0];
    const double s =
        d.squaredNorm() > 0 ? std::clamp((p - e[0]).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    best = std::min(best, (p - (e[0] + s * d)).norm());
  }
  return best;
}

double DistanceToMesh(const Vec& p, const TriangleMesh& mesh) {
  double best = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3i& t : mesh.triangles)
    best = std::min(best, PointTriangleDistance(p, mesh.vertices[t[0]], mesh.vertices[t[1]],
                                                mesh.vertices[t[2]]));
  return best;
}

// Every undirected edge in exactly two triangles, every directed edge in one; V - E + F.
void ExpectWatertight(const TriangleMesh& mesh, long euler) {
  std::map<std::pair<int, int>, int> uses, directed;
  for (const Eigen::Vector3i& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      ++uses[{std::min(a, b), std::max(a, b)}];
      ++directed[{a, b}];
    }
  long bad = 0, bad_directed = 0;
  for (const auto& [e, n] : uses) bad += n != 2;
  for (const auto& [e, n] : directed) bad_directed += n != 1;
  EXPECT_EQ(bad, 0);
  EXPECT_EQ(bad_directed, 0);
  std::vector<char> used(mesh.vertices.size(), 0);
  for (const Eigen::Vector3i& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) used[t[k]] = 1;
  EXPECT_EQ(std::count(used.begin(), used.end(), 0), 0) << "unreferenced vertices";
  EXPECT_EQ(static_cast<long>(mesh.vertices.size()) - static_cast<long>(uses.size()) +
                static_cast<long>(mesh.triangles.size()),
            euler);
}

double SignedVolume(const TriangleMesh& mesh) {
  double volume = 0;
  for (const Eigen::Vector3i& t : mesh.triangles)
    volume += mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]])) / 6;
  return volume;
}

const Vec kHalf(1.0, 0.6, 0.45);  // the box's half sides

Model SharpBox() { return testsupport::AxisBox(kHalf, 0.0, 0.0, 0); }

MeshOptions Options(bool sharp) {
  MeshOptions options;
  options.has_box = true;
  options.box_min = Vec::Constant(-1.5);
  options.box_max = Vec::Constant(1.5);
  options.cell = 0.07;
  options.sharp_features = sharp;
  return options;
}

TEST(SharpFeatures, BoxCornersAndEdgesAreOnTheMesh) {
  const Model box = SharpBox();
  ASSERT_LT(box.Value(Vec(0.99, 0.59, 0.44)), 0);  // the planes face out (sign check)
  ASSERT_GT(box.Value(Vec(1.01, 0, 0)), 0);
  const MeshResult sharp = MeshModel(box, Options(true));
  const MeshResult plain = MeshModel(box, Options(false));
  const double h = sharp.cell;
  ExpectWatertight(sharp.mesh, 2);
  ExpectWatertight(plain.mesh, 2);
  EXPECT_GT(sharp.feature_points, 0);
  // Corners: a mesh vertex at each of the eight (tangent planes of exact planes meet there).
  for (int c = 0; c < 8; ++c) {
    const Vec corner((c & 1 ? 1 : -1) * kHalf.x(), (c & 2 ? 1 : -1) * kHalf.y(),
                     (c & 4 ? 1 : -1) * kHalf.z());
    double nearest = std::numeric_limits<double>::infinity();
    for (const Vec& v : sharp.mesh.vertices) nearest = std::min(nearest, (v - corner).norm());
    EXPECT_LT(nearest, 1e-9) << "corner " << corner.transpose();
  }
  // Edges: 25 points along each of the 12, their distance to the mesh.
  double worst_sharp = 0, worst_plain = 0;
  for (int axis = 0; axis < 3; ++axis)
    for (int s1 : {-1, 1})
      for (int s2 : {-1, 1})
        for (int i = 0; i <= 24; ++i) {
          Vec p;
          const int b = (axis + 1) % 3, c = (axis + 2) % 3;
          p[axis] = kHalf[axis] * (-1 + 2.0 * i / 24);
          p[b] = s1 * kHalf[b];
          p[c] = s2 * kHalf[c];
          worst_sharp = std::max(worst_sharp, DistanceToMesh(p, sharp.mesh));
          worst_plain = std::max(worst_plain, DistanceToMesh(p, plain.mesh));
        }
  std::printf("  box edges: worst distance %.2e h (marching cubes alone %.2f h)\n", worst_sharp / h,
              worst_plain / h);
  EXPECT_LT(worst_sharp, 1e-6 * h);
  EXPECT_GT(worst_plain, 0.2 * h);
  // Volume: exact faces and creases give the box's volume to rounding.
  const double volume = 8 * kHalf.prod();
  EXPECT_NEAR(SignedVolume(sharp.mesh), volume, 1e-9 * volume);
  EXPECT_LT(SignedVolume(plain.mesh), volume - 1e-3 * volume);
  // Normals: unit; grid-edge vertices on a face keep grad f (a face's normal).
  for (const Vec& n : sharp.mesh.normals) EXPECT_NEAR(n.norm(), 1.0, 1e-12);
}

TEST(SharpFeatures, HalfBallCreaseIsTheUnitCircle) {
  Model half;
  const int s = half.AddPrimitive(NodeType::kSphere, {0, 0, 0, 1});
  const int p = half.AddPrimitive(NodeType::kPlane, {0, 0, -1, 0});
  half.SetRoot(half.AddOperator(NodeType::kIntersection, {s, p}, 0.0, 0.0, 0));
  const MeshResult sharp = MeshModel(half, Options(true));
  const MeshResult plain = MeshModel(half, Options(false));
  const double h = sharp.cell;
  ExpectWatertight(sharp.mesh, 2);
  double worst_sharp = 0, worst_plain = 0;
  for (int i = 0; i < 200; ++i) {
    const double t = 2 * M_PI * i / 200;
    const Vec x(std::cos(t), std::sin(t), 0.0);
    worst_sharp = std::max(worst_sharp, DistanceToMesh(x, sharp.mesh));
    worst_plain = std::max(worst_plain, DistanceToMesh(x, plain.mesh));
  }
  std::printf("  half-ball crease: worst distance %.2e h (marching cubes alone %.3f h)\n",
              worst_sharp / h, worst_plain / h);
  // Tangent planes of the sphere at vertices within ~2 cells of the crease miss it by about
  // (2 h)^2 / (2 r) = 0.14 h here (h = 0.07, r = 1); the chord between crease points adds
  // h^2 / (8 r) more.
  EXPECT_LT(worst_sharp, 0.15 * h);
  EXPECT_GT(worst_plain, 0.2 * h);
  // Every mesh vertex on the solid's boundary to first order: grid-edge vertices to rounding,
  // feature points within the bound above.
  for (const Vec& v : sharp.mesh.vertices) {
    const double on_sphere = std::abs(v.norm() - 1.0), on_plane = std::abs(v.z());
    const double off = std::max(v.norm() - 1.0, -v.z());  // z >= 0 is material
    EXPECT_LT(std::min(on_sphere, on_plane), 0.15 * h);
    EXPECT_LT(std::abs(off), 0.15 * h);
  }
}

}  // namespace
}  // namespace implicitfit
