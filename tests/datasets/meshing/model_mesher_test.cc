// Meshes of zero sets (datasets/meshing/model_mesher): geometry against closed forms (the sphere's
// and torus's distance functions), topology by counting (every edge in exactly two triangles, the
// Euler characteristic V - E + F of the closed surface: sphere 2, torus 0).
#include "datasets/meshing/model_mesher.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

#include "support/axis_box.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

struct Topology {
  long vertices = 0, edges = 0, faces = 0;
  long edges_not_in_two_triangles = 0;
  long edges_used_twice_in_one_direction = 0;  // inconsistent orientation
  long euler() const { return vertices - edges + faces; }
};

Topology Count(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> uses;      // undirected edge -> triangles
  std::map<std::pair<int, int>, int> directed;  // directed edge -> triangles
  for (const Eigen::Vector3i& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      ++uses[{std::min(a, b), std::max(a, b)}];
      ++directed[{a, b}];
    }
  Topology topo;
  topo.vertices = static_cast<long>(mesh.vertices.size());
  topo.faces = static_cast<long>(mesh.triangles.size());
  topo.edges = static_cast<long>(uses.size());
  for (const auto& [edge, n] : uses) topo.edges_not_in_two_triangles += n != 2;
  for (const auto& [edge, n] : directed) topo.edges_used_twice_in_one_direction += n != 1;
  return topo;
}

void ExpectClosedSurface(const TriangleMesh& mesh, long euler) {
  const Topology topo = Count(mesh);
  EXPECT_GT(topo.faces, 100);
  EXPECT_EQ(topo.edges_not_in_two_triangles, 0);
  EXPECT_EQ(topo.edges_used_twice_in_one_direction, 0);
  EXPECT_EQ(topo.euler(), euler) << "V " << topo.vertices << " E " << topo.edges << " F "
                                 << topo.faces;
}

TEST(ModelMesher, SphereVerticesOnTheSphereNormalsRadialClosedGenusZero) {
  const Vec c(0.3, -0.2, 0.1);
  const double r = 0.8;
  Model m;
  m.SetRoot(m.AddPrimitive(NodeType::kSphere, {c.x(), c.y(), c.z(), r}));
  MeshOptions options;
  options.cell = 0.05;
  const MeshResult result = MeshModel(m, options);
  ExpectClosedSurface(result.mesh, 2);
  double worst = 0, worst_normal = 0;
  for (size_t v = 0; v < result.mesh.vertices.size(); ++v) {
    const Vec d = result.mesh.vertices[v] - c;
    worst = std::max(worst, std::abs(d.norm() - r));
    worst_normal = std::max(worst_normal, (result.mesh.normals[v] - d.normalized()).norm());
  }
  // Contouring tolerance: the root on each grid edge to 1e-9 of a cell.
  EXPECT_LT(worst, 1e-9 * options.cell);
  EXPECT_LT(worst_normal, 1e-9);
  // Triangles face outward: the signed volume (divergence theorem) is the ball's, to within
  // the chordal error of cells of 0.05 on radius 0.8 (a few percent).
  double volume = 0;
  for (const Eigen::Vector3i& t : result.mesh.triangles)
    volume += (result.mesh.vertices[t[0]] - c)
                  .dot((result.mesh.vertices[t[1]] - c).cross(result.mesh.vertices[t[2]] - c)) /
              6;
  EXPECT_NEAR(volume, 4.0 / 3.0 * M_PI * r * r * r, 0.02 * 4.0 / 3.0 * M_PI * r * r * r);
}

TEST(ModelMesher, TorusClosedGenusOne) {
  Model m;
  const double R = 1.0, r = 0.3;
  m.SetRoot(m.AddPrimitive(NodeType::kTorus, {0.1, 0.2, 0.3, 1, 1, 0, R, r}));
  const MeshResult result = MeshModel(m);
  ExpectClosedSurface(result.mesh, 0);
  const Vec c(0.1, 0.2, 0.3), a = Vec(1, 1, 0).normalized();
  double worst = 0;
  for (const Vec& x : result.mesh.vertices) {
    const Vec d = x - c;
    const double h = d.dot(a), rho = (d - h * a).norm();
    worst = std::max(worst, std::abs(std::hypot(rho - R, h) - r));
  }
  EXPECT_LT(worst, 1e-9 * result.cell);
}

// Closed solids of other kinds: a sharp half ball (sphere intersect plane), a rounded box
// (six planes, smooth intersection), a Bernstein patch whose zero set is a closed ellipsoid.
TEST(ModelMesher, SharpBlendAndPatchSolidsAreWatertight) {
  Model half;
  {
    const int s = half.AddPrimitive(NodeType::kSphere, {0, 0, 0, 1});
    const int p = half.AddPrimitive(NodeType::kPlane, {0, 0, -1, 0});
    half.SetRoot(half.AddOperator(NodeType::kIntersection, {s, p}, 0.1, 0.1, 0));
  }
  Model rounded = testsupport::AxisBox(Eigen::Vector3d(1.0, 0.6, 0.6), 0.2, 0.15, 3);
  Model patch;
  {
    // q(x) = |x|^2 - 1 written as a degree-2 Bernstein polynomial over a big tetrahedron:
    // interpolate it exactly through the 10 quadratic Lagrange nodes? Easier: its control points
    // from the blossom, b(e_i + e_j) = B(v_i, v_j) = v_i . v_j - 1.
    const Tetrahedron tet{Vec(0, 0, 3), Vec(2.83, 0, -1), Vec(-1.41, 2.45, -1),
                          Vec(-1.41, -2.45, -1)};
    std::vector<double> b;
    for (int i = 0; i < 4; ++i)
      for (int j = i; j < 4; ++j) b.push_back(tet.vertex(i).dot(tet.vertex(j)) - 1.0);
    patch.SetRoot(patch.AddBernsteinPatch(2, tet, b));
    EXPECT_NEAR(patch.Value(Vec(0.3, 0.4, 0.5)), 0.5 - 1.0, 1e-9);  // the blossom is right
  }
  for (const Model* m : {&half, &rounded, &patch}) {
    MeshOptions options;
    options.has_box = true;
    options.box_min = Vec::Constant(-1.5);
    options.box_max = Vec::Constant(1.5);
    options.cell = 0.04;
    const MeshResult result = MeshModel(*m, options);
    ExpectClosedSurface(result.mesh, 2);
    EXPECT_LT(result.max_abs_value, 1e-9);
    for (const Vec& n : result.mesh.normals) EXPECT_NEAR(n.norm(), 1.0, 1e-12);
  }
}

TEST(ModelMesher, OpenSurfaceEndsAtTheBoxAndBadBoxesAreRefused) {
  Model plane;
  plane.SetRoot(plane.AddPrimitive(NodeType::kPlane, {0, 0, 1, 0.25}));
  MeshOptions options;
  options.has_box = true;
  options.box_min = Vec(-1, -1, -1);
  options.box_max = Vec(1, 1, 1);
  options.cell = 0.1;
  const MeshResult result = MeshModel(plane, options);
  ASSERT_FALSE(result.mesh.triangles.empty());
  double area = 0;
  for (const Eigen::Vector3i& t : result.mesh.triangles)
    area += 0.5 * (result.mesh.vertices[t[1]] - result.mesh.vertices[t[0]])
                      .cross(result.mesh.vertices[t[2]] - result.mesh.vertices[t[0]])
                      .norm();
  EXPECT_NEAR(area, 4.0, 1e-9);
  for (const Vec& x : result.mesh.vertices) EXPECT_NEAR(x.z(), 0.25, 1e-12);
  options.box_max = Vec(1, -2, 1);
  EXPECT_THROW(MeshModel(plane, options), std::invalid_argument);
  options.box_max = Vec(1, 1, 1);
  options.cell = 1e-4;
  EXPECT_THROW(MeshModel(plane, options), std::invalid_argument);
}

}  // namespace
}  // namespace implicitfit
