// A mesh of Bernstein–Bézier patches over the Kuhn split of a box grid (docs/maths.md G-1).
//
// Grid. origin o, cube edge h, nx x ny x nz cubes; cube (i, j, l) has corner
// c = o + h (i, j, l) and index cube = (l ny + j) nx + i. Every cube is split the same way
// (Kuhn / Freudenthal) into 6 tetrahedra, one per permutation pi of the axes, in the order
//   pi = 012, 021, 102, 120, 201, 210  (kKuhnPermutations),
// with vertices, in the order of the patch's barycentric coordinates tau1..tau4,
//   x1 = c, x2 = c + h e_pi0, x3 = c + h (e_pi0 + e_pi1), x4 = c + h (1, 1, 1).
// Tetrahedron index t = 6 cube + permutation; its control points are the t-th run of
// NumBernsteinControlPoints(k) values (docs/design.md order), so the mesh has
// 6 nx ny nz NumBernsteinControlPoints(k) parameters.
//
// Point location is O(1): with local coordinates u = (x - c)/h in [0, 1]^3 the point lies in
// the tetrahedron of the permutation that sorts u descending (u_pi0 >= u_pi1 >= u_pi2), and
//   tau1 = 1 - u_pi0, tau2 = u_pi0 - u_pi1, tau3 = u_pi1 - u_pi2, tau4 = u_pi2.
// f(x) = sum_lambda b^t_lambda B^k_lambda(tau) (model/bernstein/bernstein_patch.h).
// Outside the grid box: x is clamped onto the box, the clamped point is located, and that
// (boundary) tetrahedron's polynomial is evaluated at x itself (extrapolation of the nearest
// boundary tetrahedron's polynomial: its tau may be negative; f stays continuous in x).
// Ties on shared faces pick the first permutation in sorted order; with C0 continuity both
// sides give the same value there.
// Adaptive grids (model/bernstein/grid_refinement.h): with a refinement every base cube holds an
// octree whose leaves are Kuhn-split the same way (leaf q: tetrahedra 6 q + permutation); point
// location descends the octree from the base cube (O(depth)). Lattice coordinates are then in
// units of h / 2^max_level. Sharp faces (c0 bits): faces across which the mesh is only asked to
// be C0 (creases); bit o of sharp[t] marks the face of tetrahedron t opposite its vertex o.
// Templated on the scalar (double, Ceres Jet, Dual3); the cell choice uses the value part.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "model/bernstein/bernstein_patch.h"
#include "model/bernstein/grid_refinement.h"
#include "model/scalar.h"

namespace implicitfit {

constexpr int kKuhnPermutations[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                         {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};

struct BernsteinGrid {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  double cell = 1.0;                     // base cube edge h > 0
  std::array<int, 3> cells = {1, 1, 1};  // base cubes nx, ny, nz >= 1
  GridRefinement refinement;             // empty: uniform (every base cube a leaf)
  std::vector<unsigned char> sharp;      // empty, or per tetrahedron: bit o = face opposite o is C0

  bool refined() const { return !refinement.empty(); }
  int MaxLevel() const { return refinement.max_level; }
  long long NumCubes() const { return 1LL * cells[0] * cells[1] * cells[2]; }  // base cubes
  long long NumLeaves() const {
    return refined() ? static_cast<long long>(refinement.leaves.size()) : NumCubes();
  }
  long long NumTetrahedra() const { return 6 * NumLeaves(); }
  Eigen::Vector3d BoxMin() const { return origin; }
  Eigen::Vector3d BoxMax() const {
    return origin + cell * Eigen::Vector3d(cells[0], cells[1], cells[2]);
  }
  // Edge of the lattice unit: h / 2^max_level.
  double LatticeUnit() const { return std::ldexp(cell, -MaxLevel()); }
  // Level, and lattice coordinates of the lower corner, of leaf q (level 0 for a uniform grid).
  std::array<int, 4> Leaf(long long q) const;
  // Integer lattice coordinates of the 4 vertices of tetrahedron t (units of LatticeUnit()).
  std::array<std::array<int, 3>, 4> LatticeVertices(long long t) const;
  // The tetrahedron t as a Tetrahedron (vertices x1..x4 as above).
  Tetrahedron TetrahedronOf(long long t) const;
  int LevelOf(long long t) const { return refined() ? refinement.leaves[t / 6][0] : 0; }
  bool IsSharp(long long t, int face) const {
    return !sharp.empty() && ((sharp[static_cast<size_t>(t)] >> face) & 1);
  }
  bool HasSharpFaces() const {
    for (unsigned char s : sharp)
      if (s) return true;
    return false;
  }

  // Tetrahedron index of x (clamped onto the box) and the barycentric coordinates of x itself
  // in that tetrahedron.
  template <typename T>
  long long Locate(const T* x, T* tau) const {
    int cube[3];
    T u[3];
    double uv[3];
    for (int a = 0; a < 3; ++a) {
      const double s = (ValueOf(x[a]) - origin[a]) / cell;
      cube[a] = static_cast<int>(std::clamp(std::floor(s), 0.0, double(cells[a] - 1)));
      uv[a] = std::clamp(s - cube[a], 0.0, 1.0);
    }
    long long leaf = (1LL * cube[2] * cells[1] + cube[1]) * cells[0] + cube[0];
    double h = cell;
    double corner[3] = {origin[0] + cell * cube[0], origin[1] + cell * cube[1],
                        origin[2] + cell * cube[2]};
    if (refined()) {
      int node = refinement.root[leaf];
      while (refinement.node[node] >= 0) {
        int o = 0;
        h *= 0.5;
        for (int a = 0; a < 3; ++a) {
          const int b = uv[a] >= 0.5 ? 1 : 0;
          uv[a] = std::min(1.0, 2.0 * uv[a] - b);
          corner[a] += b * h;
          o |= b << a;
        }
        node = refinement.node[node] + o;
      }
      leaf = -1 - refinement.node[node];
    }
    for (int a = 0; a < 3; ++a) {
      u[a] = (x[a] - corner[a]) / h;
      uv[a] = std::clamp(ValueOf(u[a]), 0.0, 1.0);
    }
    int p = 0;
    for (; p < 5; ++p) {
      const int* pi = kKuhnPermutations[p];
      if (uv[pi[0]] >= uv[pi[1]] && uv[pi[1]] >= uv[pi[2]]) break;
    }
    const int* pi = kKuhnPermutations[p];
    tau[0] = 1.0 - u[pi[0]];
    tau[1] = u[pi[0]] - u[pi[1]];
    tau[2] = u[pi[1]] - u[pi[2]];
    tau[3] = u[pi[2]];
    return 6 * leaf + p;
  }
};

class BernsteinMesh {
 public:
  // f(x); control_points: all tetrahedra's, tetrahedron after tetrahedron.
  template <typename T>
  static T Evaluate(int k, const BernsteinGrid& grid, const T* control_points, const T* x) {
    T tau[4];
    const long long t = grid.Locate(x, tau);
    return BernsteinPatch::EvaluateBarycentric(k, control_points + t * NumBernsteinControlPoints(k),
                                               tau);
  }
};

}  // namespace implicitfit
