// Guo §3 shape control as exact linear equalities on the control points of a degree-k patch
// (docs/maths.md G-3), removed from the free parameters of the patch fitter:
//   through vertex i:        b_{k e_i} = 0                          (x_i on the surface)
//   vertex normal i = n:     b_{k e_i} = 0 and b_{(k-1) e_i + e_j} = (s / k) n . (x_j - x_i) for
//                            the three j != i, one free scale s (by Lemma 1,
//                            grad f(x_i) . (x_j - x_i) = k (b_{(k-1)e_i+e_j} - b_{k e_i}), so
//                            grad f(x_i) = s n)
//   through edge i, j:       b_lambda = 0 for every lambda supported on {i, j} (the edge lies on
//                            the surface)
// The admissible control points are b = N z: N has one unit column per unconstrained control
// point and one column (d_j at the three tied points, normalised) per vertex normal; zero rows
// for the constrained-to-zero points, so those stay exactly 0 under any z. The fitter moves b
// on this subspace through a Ceres manifold (Plus(b, z) = b + N z, Minus = N^T (y - x)).
// Vertices are 0-based here (the command line counts 1..4).
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "model/bernstein/bernstein_patch.h"

namespace ceres {
class Manifold;
}

namespace implicitfit {

struct PatchShapeConstraints {
  struct VertexNormal {
    int vertex = 0;
    Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  };
  std::vector<int> through_vertices;
  std::vector<VertexNormal> vertex_normals;
  std::vector<std::array<int, 2>> through_edges;
  bool empty() const {
    return through_vertices.empty() && vertex_normals.empty() && through_edges.empty();
  }
};

// The basis N (NumBernsteinControlPoints(k) x m, orthonormal columns). Returns false with a
// reason when the constraints are invalid or conflict (a vertex normal's tied control point
// also forced to 0, two vertex normals sharing a control point, a zero normal component set).
bool ShapeConstraintBasis(int k, const Tetrahedron& tet, const PatchShapeConstraints& constraints,
                          Eigen::MatrixXd* basis, std::string* error);

// b + N z with N = basis; owned by the caller's ceres::Problem.
ceres::Manifold* NewLinearSubspaceManifold(const Eigen::MatrixXd& basis);

}  // namespace implicitfit
